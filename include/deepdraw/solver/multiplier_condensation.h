// Exact elimination of the contact multipliers from the Newton system
// [u | lambda | z] (doc/theory_contact.md §4.1, doc/decisions.md D90): the
// condensed system has the displacements and the tool positions only, and
// its solution gives the same Newton step as the whole system.
#ifndef deepdraw_solver_multiplier_condensation_h
#define deepdraw_solver_multiplier_condensation_h

#include <array>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    // The unknowns of one contact pair: the three displacement dofs of its
    // node and its three multipliers (same component order), and its
    // augmentation r > 0.
    struct MultiplierBlock
    {
      std::array<types::global_dof_index, 3> displacement;
      std::array<types::global_dof_index, 3> multiplier;
      double                                 augmentation = 1.;
    };

    // For a pair, the node rows and the multiplier rows of the Newton system
    // read (x: displacements and tool positions)
    //   A_u x + B dlambda = b_u,   A_l x + C dlambda = b_l,
    // where for the Alart–Curnier law B = -D and C = (I - D)/r (D =
    // dP/dlambda^, doc/theory_contact.md). B and C commute, so r (C A_u - B
    // A_l) x = r (C b_u - B b_l) is free of dlambda, and (r C - B) = I gives
    //   dlambda = (r C - B)^-1 (r (b_l - A_l x) - (b_u - A_u x))     (Eq. 4.2)
    // exactly. The node's rows are replaced by the first equation, the tool
    // rows take dlambda substituted. Blocks are read from the assembled
    // matrix, so constrained components (a prescribed u with its multiplier)
    // drop out as the constraints left them. A node with two coupled pairs
    // (touching two tools) cannot be condensed this way: condense() then
    // returns false and the caller solves the whole system.
    class MultiplierCondensation
    {
    public:
      // `pattern`: the whole system's; the first n_displacements unknowns
      // are the displacements, `tool_positions` the unknowns z (bordered);
      // `constrained`: true for constrained unknowns (rows and columns with
      // the diagonal only). `owned_rows` (under mpirun, D214): the rows of
      // the whole system this rank owns; it condenses its own nodes and
      // pairs, and the tool rows are summed over the ranks. Empty: all.
      void
      initialize(const SparsityPattern                      &pattern,
                 types::global_dof_index                     n_displacements,
                 const std::vector<MultiplierBlock>         &blocks,
                 const std::vector<types::global_dof_index> &tool_positions,
                 const std::vector<bool>                    &constrained,
                 const std::vector<bool>                    &owned_rows = {});

      // Builds the condensed matrix and right-hand side from the whole
      // system; false if some node has two coupled pairs or a block does not
      // have the structure above (then nothing is usable). Under mpirun
      // every rank calls it and all return the same.
      bool
      condense(const SparseMatrix<double> &matrix, const Vector<double> &rhs);

      // The rows of the condensed matrix this rank owns (its displacement
      // rows; the tool rows on rank 0). Empty: all.
      std::vector<bool>
      owned_condensed_rows() const;

      const SparseMatrix<double> &
      matrix() const;
      const Vector<double> &
      rhs() const;
      // The tool positions in the condensed numbering (after the
      // displacements), for LinearSolver's bordered unknowns.
      std::vector<types::global_dof_index>
      condensed_tool_positions() const;

      // The whole solution from the condensed one (Eq. 4.2 for the
      // multipliers; constrained multipliers rhs_i / A_ii).
      void
      expand(const SparseMatrix<double> &matrix,
             const Vector<double>       &rhs,
             const Vector<double>       &condensed_solution,
             Vector<double>             &solution) const;

      // Pairs condensed at the last successful condense().
      unsigned int
      n_coupled_pairs() const;
      // The displacement unknowns of the nodes of those pairs (stick or
      // slip), whose condensed rows replaced the node's own.
      std::vector<std::array<types::global_dof_index, 3>>
      coupled_nodes() const;

    private:
      // Block k restricted to its free (unconstrained) components: the
      // row combination X (node rows) + Y (multiplier rows) that eliminates
      // dlambda, and dlambda = P_l (b_l - A_l x) + P_u (b_u - A_u x).
      // Coupled (B != 0): X = r C, Y = -r B, P_l = r E^-1, P_u = -E^-1;
      // otherwise (an open pair) the node rows are kept, P_l = C^-1, P_u = 0.
      // The matrices are n_free x n_free in fixed 3 x 3 storage: condense()
      // runs per Newton iteration over every surface node (D96).
      struct LocalBlocks
      {
        std::array<unsigned int, 3>          free{};
        unsigned int                         n_free = 0;
        std::array<std::array<double, 3>, 3> X{}, Y{}, P_l{}, P_u{};
        bool                                 coupled = false;
      };
      // Where the entries of B and C of a block, and the coupling of the
      // tool rows to its multipliers, are stored in the whole matrix
      // (SparsityPattern::invalid_entry: not in the pattern, zero).
      struct BlockPositions
      {
        std::array<std::array<std::size_t, 3>, 3> B, C;
        std::vector<std::array<std::size_t, 3>>   tool_row;
      };
      bool
      read_blocks(const SparseMatrix<double> &matrix,
                  unsigned int                k,
                  LocalBlocks                &local) const;
      // condense() on this rank's rows and pairs.
      bool
      condense_owned(const SparseMatrix<double> &matrix,
                     const Vector<double>       &rhs);
      bool
      owns(const types::global_dof_index i) const
      {
        return owned.empty() || owned[i];
      }
      // Row i (no coupled pair) copied in step, the multiplier columns
      // checked to be zero; false if one is not.
      bool
      copy_row(const SparseMatrix<double> &matrix, types::global_dof_index i);

      types::global_dof_index              n_u = 0;
      std::vector<MultiplierBlock>         blocks;
      std::vector<types::global_dof_index> tool_position_dofs;
      std::vector<bool>                    is_constrained;
      std::vector<bool>                    owned;
      // Block of each multiplier unknown, the pairs of each node (by its
      // first displacement dof).
      std::vector<std::vector<unsigned int>> blocks_of_node;
      // Condensed index of every unknown (invalid for multipliers).
      std::vector<types::global_dof_index> condensed_of;
      std::vector<LocalBlocks>             local_blocks;
      std::vector<BlockPositions>          positions;
      SparsityPattern                      condensed_pattern;
      SparseMatrix<double>                 condensed_matrix;
      Vector<double>                       condensed_rhs;
      unsigned int                         coupled_pairs = 0;
    };
  } // namespace solver
} // namespace deepdraw

#endif
