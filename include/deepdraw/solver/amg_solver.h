// GMRES preconditioned by smoothed-aggregation algebraic multigrid (Trilinos
// ML) for the condensed Newton system of large sheets (issue 30; D193,
// doc/theory.md §5): the near-null space is the six rigid-body motions of
// the current configuration, and the rows of contact nodes in stick or slip
// are scaled by the inverse of their 3 x 3 diagonal block first, since a
// slip row can have a negative diagonal that smoothed aggregation does not
// survive (D96).
#ifndef deepdraw_solver_amg_solver_h
#define deepdraw_solver_amg_solver_h

#include <Epetra_CrsMatrix.h>
#include <array>
#include <deal.II/base/point.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    struct AmgParameters
    {
      // GMRES stops at |b - A x| <= relative_tolerance |b| (the true
      // residual: right preconditioning).
      double       relative_tolerance = 1e-8;
      unsigned int max_iterations     = 300;
      // Levels are added until one has at most this many unknowns, which
      // is then factorised (KLU).
      unsigned int coarse_size = 2000;
    };

    // GMRES with right preconditioning (it minimises the true residual,
    // which is checked once more) to |b - A x| <= relative_tolerance |b|;
    // false if it did not get there. `iterations` gets its count.
    template <typename Preconditioner>
    bool
    solve_by_gmres(const SparseMatrix<double> &matrix,
                   const Preconditioner       &preconditioner,
                   const AmgParameters        &parameters,
                   const Vector<double>       &rhs,
                   Vector<double>             &solution,
                   unsigned int               &iterations)
    {
      // The Krylov space GMRES keeps before it restarts.
      constexpr unsigned int krylov_vectors = 60;
      const double target = parameters.relative_tolerance * rhs.l2_norm();
      solution.reinit(rhs.size());
      iterations = 0;
      if (target == 0.)
        return true;
      SolverControl control(parameters.max_iterations, target, false, false);
      SolverGMRES<Vector<double>> gmres(
        control,
        typename SolverGMRES<Vector<double>>::AdditionalData(krylov_vectors + 2,
                                                             true));
      try
      {
        gmres.solve(matrix, solution, rhs, preconditioner);
      }
      catch (const SolverControl::NoConvergence &)
      {
        iterations = control.last_step();
        return false;
      }
      iterations = control.last_step();
      Vector<double> residual(rhs.size());
      return matrix.residual(residual, solution, rhs) <= 1.01 * target;
    }

    class AmgSolver
    {
    public:
      explicit AmgSolver(const AmgParameters &parameters);
      ~AmgSolver();

      // Point and component (0, 1, 2) of each displacement unknown; the
      // unknowns of the matrix beyond them get no rigid-body motion.
      void
      set_rigid_body_modes(const std::vector<Point<3>>      &points,
                           const std::vector<unsigned char> &components);
      // The three unknowns of each node whose rows are scaled by the
      // inverse of their diagonal block before the hierarchy is built.
      void
      set_scaled_nodes(
        const std::vector<std::array<types::global_dof_index, 3>> &nodes);

      // Builds the hierarchy of `matrix`, which must outlive the solves.
      void
      initialize(const SparseMatrix<double> &matrix);
      // GMRES to the tolerance; false if it did not get there.
      bool
      solve(const Vector<double> &rhs, Vector<double> &solution);

      unsigned int
      last_iterations() const
      {
        return iterations;
      }

      // The preconditioner: the hierarchy of the scaled matrix applied to
      // the scaled vector, an approximate inverse of the matrix itself.
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const;

    private:
      // The nodes of set_scaled_nodes() whose diagonal block is regular,
      // with its inverse; node_of_row gives each row's (or -1).
      std::vector<int>
      invert_diagonal_blocks(const SparseMatrix<double> &matrix);
      void
      build_scaled_matrix(const SparseMatrix<double> &matrix);
      void
      build_null_space(types::global_dof_index n);

      AmgParameters                                       parameters;
      std::vector<Point<3>>                               points;
      std::vector<unsigned char>                          components;
      std::vector<std::array<types::global_dof_index, 3>> candidate_nodes;
      struct ScaledNode
      {
        std::array<types::global_dof_index, 3> unknowns;
        // The inverse of its diagonal block, row-major.
        std::array<double, 9> inverse;
      };
      std::vector<ScaledNode>           scaled_nodes;
      const SparseMatrix<double>       *matrix = nullptr;
      std::unique_ptr<Epetra_Map>       map;
      std::unique_ptr<Epetra_CrsMatrix> scaled_matrix;
      std::vector<double>               null_space;
      TrilinosWrappers::PreconditionAMG hierarchy;
      mutable Vector<double>            scaled_vector;
      unsigned int                      iterations = 0;
    };
  } // namespace solver
} // namespace deepdraw

#endif
