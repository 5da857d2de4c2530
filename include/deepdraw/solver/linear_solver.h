// Direct solution of the (unsymmetric) Newton system: UMFPACK through
// deal.II, or MUMPS / KLU through Trilinos Amesos (doc/theory.md §5, D27-D35).
#ifndef deepdraw_solver_linear_solver_h
#define deepdraw_solver_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <string>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    struct LinearSolverParameters
    {
      std::string type = "UMFPACK";

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    class LinearSolver
    {
    public:
      explicit LinearSolver(const LinearSolverParameters &parameters);
      ~LinearSolver();
      // Solves matrix * solution = rhs. Throws std::runtime_error if the
      // factorisation fails (e.g. a singular matrix: missing supports).
      //
      // `bordered` lists unknowns with dense rows and columns (the position
      // of a force-controlled tool couples to every pair of that tool).
      // They are split off, A = [M C; D E], and eliminated by the Schur
      // complement S = E - D M^-1 C: the sparse factorisation then only
      // sees M, whose fill-in a dense row would otherwise ruin (a 10x
      // slower factorisation on the square cup).
      void
      solve(const SparseMatrix<double>                 &matrix,
            const Vector<double>                       &rhs,
            Vector<double>                             &solution,
            const std::vector<types::global_dof_index> &bordered = {});

    private:
      struct Implementation;
      LinearSolverParameters          parameters;
      std::unique_ptr<Implementation> implementation;
    };
  } // namespace solver
} // namespace deepdraw

#endif
