#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deepdraw/solver/linear_solver.h>
#include <stdexcept>

namespace deepdraw
{
  namespace solver
  {
    void
    LinearSolverParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      prm.declare_entry("Type",
                        "UMFPACK",
                        Patterns::Selection("UMFPACK|MUMPS|KLU"),
                        "Direct solver of the Newton system: UMFPACK "
                        "(SuiteSparse, through deal.II), MUMPS or KLU "
                        "(through Trilinos Amesos).");
      prm.leave_subsection();
    }


    void
    LinearSolverParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      type = prm.get("Type");
      prm.leave_subsection();
    }


    struct LinearSolver::Implementation
    {
      SparseDirectUMFPACK            umfpack;
      TrilinosWrappers::SparseMatrix trilinos_matrix;
    };


    LinearSolver::LinearSolver(const LinearSolverParameters &parameters)
        : parameters(parameters)
        , implementation(std::make_unique<Implementation>())
    {
    }


    LinearSolver::~LinearSolver() = default;


    void
    LinearSolver::solve(const SparseMatrix<double> &matrix,
                        const Vector<double>       &rhs,
                        Vector<double>             &solution)
    {
      try
      {
        if (parameters.type == "UMFPACK")
        {
          implementation->umfpack.initialize(matrix);
          implementation->umfpack.vmult(solution, rhs);
          return;
        }

        implementation->trilinos_matrix.reinit(matrix);
        const IndexSet                all = complete_index_set(matrix.m());
        TrilinosWrappers::MPI::Vector trilinos_rhs(all, MPI_COMM_SELF);
        TrilinosWrappers::MPI::Vector trilinos_solution(all, MPI_COMM_SELF);
        for (unsigned int i = 0; i < rhs.size(); ++i)
          trilinos_rhs[i] = rhs[i];
        trilinos_rhs.compress(VectorOperation::insert);

        SolverControl                                  control(1, 0);
        TrilinosWrappers::SolverDirect::AdditionalData data(
          false,
          parameters.type == "MUMPS" ? "Amesos_Mumps" : "Amesos_Klu");
        TrilinosWrappers::SolverDirect direct(control, data);
        direct.solve(implementation->trilinos_matrix,
                     trilinos_solution,
                     trilinos_rhs);
        for (unsigned int i = 0; i < solution.size(); ++i)
          solution[i] = trilinos_solution[i];
      }
      catch (const std::exception &error)
      {
        throw std::runtime_error(
          "the linear solver (" + parameters.type
          + ") failed; the stiffness matrix is probably singular (are "
            "rigid-body motions prevented by the boundary conditions?): "
          + error.what());
      }
    }
  } // namespace solver
} // namespace deepdraw
