// Direct solution of the (unsymmetric) Newton system: MUMPS or UMFPACK
// called directly with their analyses kept, or KLU through Trilinos Amesos
// (doc/theory.md §5, D27-D35, D96).
#ifndef deepdraw_solver_linear_solver_h
#define deepdraw_solver_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/solver/amg_solver.h>
#include <deepdraw/solver/multiplier_condensation.h>
#include <memory>
#include <string>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    struct BorderedFactorization;
    class BorderedAmgSolver;

    struct LinearSolverParameters
    {
      std::string type = "MUMPS";
      // Unknowns with a diagonal row and column (open contact pairs,
      // constrained dofs) may be left out of the factorisation (D60); off
      // by default, it was slower (D64).
      bool leave_out_decoupled = false;
      // The contact multipliers are eliminated exactly before the
      // factorisation (D90).
      bool condense_multipliers = true;
      // Within an increment, later Newton systems are solved by GMRES with
      // the increment's last factorisation as right preconditioner, to the
      // Eisenstat-Walker forcing term (between `smallest_forcing_term` and
      // `forcing_term`); a system that needs more than gmres_budget()
      // iterations is factorised (D185, D228). `automatic`: only for
      // systems of at least `reuse_threshold` unknowns, where it was
      // measured to pay (D206).
      enum class Reuse
      {
        never,
        always,
        automatic
      };
      Reuse        reuse                 = Reuse::automatic;
      unsigned int reuse_threshold       = 20000;
      double       forcing_term          = 0.1;
      double       smallest_forcing_term = 0.1;
      // GMRES iterations with kept factors before a system is factorised
      // afresh; `automatic_reuse_iterations`: gmres_budget() (D228).
      static constexpr unsigned int automatic_reuse_iterations = 0;
      unsigned int reuse_iterations = automatic_reuse_iterations;
      // MUMPS' factors in single precision, each solve refined by GMRES in
      // double: a fresh factorisation's to `single_precision_tolerance`, a
      // kept one's to the forcing term; a system the refinement does not
      // solve is factorised again in double. Never in the first increment
      // of a stage. `automatic`: where `Reuse factorisation = auto` reuses
      // them, on systems of at least `reuse_threshold` unknowns (D226).
      enum class Precision
      {
        double_only,
        single,
        automatic
      };
      Precision precision                  = Precision::automatic;
      double    single_precision_tolerance = 1e-3;
      // Type AMG: the condensed system by GMRES with smoothed aggregation
      // (D193); the systems that cannot be condensed, and those GMRES does
      // not solve, by MUMPS.
      AmgParameters amg;

      bool
      iterative() const
      {
        return type == "AMG";
      }

      // Whether a factorised system of n unknowns is solved with the kept
      // factorisation where it can be.
      bool
      reuses_factorization(const std::size_t n) const
      {
        return !iterative()
               && (reuse == Reuse::always
                   || (reuse == Reuse::automatic && n >= reuse_threshold));
      }

      // Whether a system of n unknowns that `type` factorises is
      // factorised in single precision (outside a stage's first increment).
      bool
      single_precision(const std::string &type, const std::size_t n) const
      {
        return type == "MUMPS"
               && (precision == Precision::single
                   || (precision == Precision::automatic
                       && reuse == Reuse::automatic
                       && reuses_factorization(n)));
      }

      // The GMRES iterations allowed with kept factors on a system of n
      // unknowns: `reuse_iterations`, or where automatic
      // max(10, 10 (n / 23 409)^0.4), the measured break-even growing with
      // the cost of a factorisation against an iteration (D227, D228).
      unsigned int
      gmres_budget(std::size_t n) const;

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
      // slower factorisation on the square cup, D23).
      //
      // `decoupled` lists unknowns whose row and column hold nothing but
      // the diagonal entry (the multipliers of open contact pairs, the
      // constrained dofs): their solution is rhs_i / A_ii, and M leaves
      // them out (D60). The pattern of M, and with it the ordering of the
      // factorisation, is kept while every unknown it leaves out is still
      // decoupled, and rebuilt when one is not or when a quarter of the
      // unknowns it keeps have become decoupled. An unknown listed but
      // found coupled (a nonzero off-diagonal entry) is kept in M: the
      // solution stays exact either way.
      void
      solve(const SparseMatrix<double>                 &matrix,
            const Vector<double>                       &rhs,
            Vector<double>                             &solution,
            const std::vector<types::global_dof_index> &bordered  = {},
            const std::vector<types::global_dof_index> &decoupled = {});

      // The structure of the contact pairs of the systems solve() will be
      // given (MultiplierCondensation::initialize): with
      // `Condense contact multipliers`, solve() then factorises the
      // condensed system whenever it can and falls back to the whole one
      // (then `bordered` and `decoupled` apply) when not. Call again when
      // the pattern changes.
      //
      // `owned_rows` (under mpirun, D214): the rows of the matrices given
      // to solve() that this rank owns and has complete; the others are
      // not read. Empty: every row (one rank, or a replicated matrix).
      void
      set_multiplier_blocks(
        const SparsityPattern                      &pattern,
        types::global_dof_index                     n_displacements,
        const std::vector<MultiplierBlock>         &blocks,
        const std::vector<types::global_dof_index> &tool_positions,
        const std::vector<bool>                    &constrained,
        const std::vector<bool>                    &owned_rows = {});

      // The next solve starts afresh: it leaves out exactly the decoupled
      // unknowns it is given and UMFPACK analyses the pattern anew (its
      // analysis depends on the values), whatever the last one did. MUMPS
      // keeps its analysis, which depends on the pattern alone (D97).
      // Called at the start of each increment, so that the systems of an
      // increment, and with them its results, depend only on the state it
      // starts from (a resumed run repeats the same arithmetic, D55, D64).
      // `continues_stage`: the increment follows a converged one of the
      // same stage, so that single-precision factors may serve it (the
      // first increment of a stage factorises in double, D226).
      void
      reset_reduction(bool continues_stage = false);

      // Type AMG: the point and component of each displacement unknown in
      // the current configuration, for the rigid-body modes.
      void
      set_rigid_body_modes(const std::vector<Point<3>>      &points,
                           const std::vector<unsigned char> &components);

      // Counts since construction, and the sizes of the last solve.
      struct Statistics
      {
        types::global_dof_index unknowns            = 0;
        types::global_dof_index factorized_unknowns = 0;
        unsigned int            factorizations      = 0;
        // Patterns of the reduced matrix built, orderings computed.
        unsigned int reductions             = 0;
        unsigned int symbolic_analyses      = 0;
        unsigned int numeric_factorizations = 0;
        // Solves of the condensed system (D90); the rest were whole.
        unsigned int condensed_solves = 0;
        // Solves by GMRES with kept factors, and its iterations (D185).
        unsigned int reused_solves    = 0;
        unsigned int gmres_iterations = 0;
        // Factorisations in single precision, and the systems their
        // refinement did not solve, factorised again in double (D226).
        unsigned int single_precision_factorizations = 0;
        unsigned int single_precision_fallbacks      = 0;
        // Type AMG: hierarchies built, condensed systems solved by GMRES,
        // and condensed systems solved by MUMPS instead (D193).
        unsigned int amg_hierarchies = 0;
        unsigned int amg_solves      = 0;
        unsigned int amg_fallbacks   = 0;
      };
      Statistics
      statistics() const;

    private:
      void
      solve_with(BorderedFactorization                      &data,
                 const std::string                          &type,
                 const SparseMatrix<double>                 &matrix,
                 const Vector<double>                       &rhs,
                 Vector<double>                             &solution,
                 const std::vector<types::global_dof_index> &bordered,
                 const std::vector<types::global_dof_index> &decoupled);
      // GMRES with data's kept factors to the forcing term; false if it
      // did not get there (the caller factorises).
      bool
      solve_with_kept_factors(BorderedFactorization      &data,
                              const SparseMatrix<double> &matrix,
                              const Vector<double>       &rhs,
                              Vector<double>             &solution);
      // Factorises in single precision and refines the solve to the
      // single precision tolerance; false if that fails (the caller
      // factorises in double).
      bool
      solve_in_single_precision(
        BorderedFactorization                      &data,
        const std::string                          &type,
        const SparseMatrix<double>                 &matrix,
        const Vector<double>                       &rhs,
        Vector<double>                             &solution,
        const std::vector<types::global_dof_index> &bordered,
        const std::vector<types::global_dof_index> &decoupled);
      // GMRES right preconditioned with data's last factors, from
      // `solution` as it is, to |b - A x| <= relative_target |b| in at most
      // Reuse iterations; false if it did not get there.
      bool
      gmres_with_factors(BorderedFactorization      &data,
                         const SparseMatrix<double> &matrix,
                         const Vector<double>       &rhs,
                         Vector<double>             &solution,
                         double                      relative_target);
      void
      update_forcing_term(double residual_norm);
      // The condensed system by AMG, or by MUMPS where GMRES fails; true
      // when GMRES solved it (nothing factorised).
      bool
      solve_condensed_iteratively(Vector<double> &condensed_solution);
      // The direct solver of the systems AMG does not take.
      std::string
      direct_type() const;

      LinearSolverParameters parameters;
      // The whole system's factorisation and that of the condensed one,
      // each with its own pattern and ordering.
      std::unique_ptr<BorderedFactorization>  implementation;
      std::unique_ptr<BorderedFactorization>  condensed_implementation;
      std::unique_ptr<MultiplierCondensation> condensation;
      // Type AMG: the condensed system's iterative solver.
      std::unique_ptr<BorderedAmgSolver> amg;
      Statistics                         solve_statistics;
      // Eisenstat-Walker: this solve's forcing term and the last |F|.
      double forcing_term           = 0.;
      double previous_residual_norm = 0.;
      // Whether this increment may factorise in single precision.
      bool single_precision_allowed = false;
    };
  } // namespace solver
} // namespace deepdraw

#endif
