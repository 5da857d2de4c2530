// The Newton system of an increment: its matrix, its right-hand side and
// its solution, behind one interface (doc/architecture.md, "Linear
// algebra", D100). The problem sets it up for a mesh and a contact set-up,
// the assembly adds into matrix() and rhs(), and solve() gives the
// correction. The serial implementation keeps a deal.II SparseMatrix and
// solves it with solver::LinearSolver (MUMPS, UMFPACK or KLU, the contact
// multipliers condensed out).
#ifndef deepdraw_linear_algebra_newton_linear_system_h
#define deepdraw_linear_algebra_newton_linear_system_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deepdraw/linear_algebra/system_matrix.h>
#include <deepdraw/solver/linear_solver.h>
#include <deepdraw/solver/multiplier_condensation.h>
#include <functional>
#include <memory>
#include <vector>

namespace deepdraw
{
  namespace linear_algebra
  {
    // What a Newton system is set up from: the displacement dofs (coupled
    // cell by cell), the constraints that the assembly distributes through,
    // the number of all unknowns (displacements, then contact forces and
    // tool positions) and the couplings of the contact rows.
    struct SystemLayout
    {
      const DoFHandler<3>                          *dof_handler = nullptr;
      const AffineConstraints<double>              *constraints = nullptr;
      types::global_dof_index                       n_unknowns  = 0;
      std::function<void(DynamicSparsityPattern &)> add_contact_couplings;
      // The contact pairs and force-controlled tools, for the exact
      // elimination of the multipliers (solver::MultiplierCondensation).
      std::vector<solver::MultiplierBlock> multiplier_blocks;
      std::vector<types::global_dof_index> tool_positions;
    };

    class NewtonLinearSystem
    {
    public:
      virtual ~NewtonLinearSystem() = default;

      // A new pattern for a new mesh or contact set-up; the matrix and the
      // right-hand side are sized and zero.
      virtual void
      reinit(const SystemLayout &layout)
        = 0;

      // Zeroes the right-hand side and, with matrix = true, the matrix.
      virtual void
      zero(bool matrix)
        = 0;

      virtual SystemMatrix &
      matrix()
        = 0;
      virtual Vector &
      rhs()
        = 0;
      virtual const Vector &
      rhs() const = 0;

      // Solves matrix * solution = rhs (solver::LinearSolver::solve: the
      // bordered and decoupled unknowns as there). Throws
      // std::runtime_error if the factorisation fails.
      virtual void
      solve(Vector                                     &solution,
            const std::vector<types::global_dof_index> &bordered,
            const std::vector<types::global_dof_index> &decoupled)
        = 0;

      // The next solve starts afresh (solver::LinearSolver::reset_reduction;
      // `continues_stage`: the increment follows a converged one of the
      // same stage).
      virtual void
      reset_reduction(bool continues_stage)
        = 0;

      virtual solver::LinearSolver::Statistics
      statistics() const = 0;

      // The assembled matrix as a full matrix (tests of the tangent); split
      // by rows, the rows this rank owns (the others zero).
      virtual void
      copy_to(FullMatrix<double> &full) const = 0;
    };

    // The serial system: one process holds the whole matrix.
    std::unique_ptr<NewtonLinearSystem>
    make_serial_system(const solver::LinearSolverParameters &parameters);
    // The system of this run: serial on one rank; under mpirun split by
    // rows, each rank completing the rows it owns (D214).
    std::unique_ptr<NewtonLinearSystem>
    make_system(const solver::LinearSolverParameters &parameters);
  } // namespace linear_algebra
} // namespace deepdraw

#endif
