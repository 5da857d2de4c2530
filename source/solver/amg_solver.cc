#include <Epetra_Map.h>
#include <Epetra_MpiComm.h>
#include <algorithm>
#include <deal.II/lac/full_matrix.h>
#include <deepdraw/solver/amg_solver.h>
#include <ml_MultiLevelPreconditioner.h>
#include <mpi.h>
#include <stdexcept>

namespace deepdraw
{
  namespace solver
  {
    namespace
    {
      // One matrix row as (column, value) pairs.
      using Row = std::vector<std::pair<int, double>>;

      void
      append_row(const SparseMatrix<double>   &matrix,
                 const types::global_dof_index i,
                 const double                  factor,
                 Row                          &row)
      {
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          row.emplace_back(int(entry->column()), factor * entry->value());
      }

      // Sums the values of equal columns; the row ends up sorted.
      void
      merge_columns(Row &row)
      {
        std::sort(row.begin(), row.end());
        std::size_t last = 0;
        for (std::size_t k = 1; k < row.size(); ++k)
          if (row[k].first == row[last].first)
            row[last].second += row[k].second;
          else
            row[++last] = row[k];
        if (!row.empty())
          row.resize(last + 1);
      }
    } // namespace


    AmgSolver::AmgSolver(const AmgParameters &parameters)
        : parameters(parameters)
    {
      int initialized = 0;
      MPI_Initialized(&initialized);
      if (!initialized)
        throw std::runtime_error("Trilinos ML needs MPI to be initialised");
    }


    AmgSolver::~AmgSolver() = default;


    void
    AmgSolver::set_rigid_body_modes(
      const std::vector<Point<3>>      &points,
      const std::vector<unsigned char> &components)
    {
      AssertDimension(points.size(), components.size());
      this->points     = points;
      this->components = components;
    }


    void
    AmgSolver::set_scaled_nodes(
      const std::vector<std::array<types::global_dof_index, 3>> &nodes)
    {
      candidate_nodes = nodes;
    }


    void
    AmgSolver::build_null_space(const types::global_dof_index n)
    {
      // Column-major, six vectors of n: translations along x, y, z, then
      // the rotations about x, y, z (omega x p, the point taken relative to
      // the centroid so that the vectors are of similar size).
      null_space.assign(6 * n, 0.);
      Point<3> centre;
      for (const Point<3> &p : points)
        centre += p / double(points.size());
      const types::global_dof_index n_points
        = std::min<types::global_dof_index>(n, points.size());
      for (types::global_dof_index i = 0; i < n_points; ++i)
      {
        const unsigned int c  = components[i];
        const Tensor<1, 3> p  = points[i] - centre;
        null_space[c * n + i] = 1.;
        for (unsigned int axis = 0; axis < 3; ++axis)
        {
          Tensor<1, 3> omega;
          omega[axis]                    = 1.;
          null_space[(3 + axis) * n + i] = cross_product_3d(omega, p)[c];
        }
      }
    }


    std::vector<int>
    AmgSolver::invert_diagonal_blocks(const SparseMatrix<double> &matrix)
    {
      std::vector<int> node_of_row(matrix.m(), -1);
      scaled_nodes.clear();
      for (const auto &unknowns : candidate_nodes)
      {
        FullMatrix<double> block(3, 3);
        for (unsigned int r = 0; r < 3; ++r)
          for (unsigned int s = 0; s < 3; ++s)
            block(r, s) = matrix.el(unknowns[r], unknowns[s]);
        if (block.determinant() == 0.)
          continue; // left unscaled
        block.gauss_jordan();
        ScaledNode node{unknowns, {}};
        for (unsigned int r = 0; r < 3; ++r)
        {
          node_of_row[unknowns[r]] = scaled_nodes.size();
          for (unsigned int s = 0; s < 3; ++s)
            node.inverse[3 * r + s] = block(r, s);
        }
        scaled_nodes.push_back(node);
      }
      return node_of_row;
    }


    void
    AmgSolver::build_scaled_matrix(const SparseMatrix<double> &matrix)
    {
      const types::global_dof_index n    = matrix.m();
      const std::vector<int> node_of_row = invert_diagonal_blocks(matrix);
      std::vector<int>       row_lengths(n);
      for (types::global_dof_index i = 0; i < n; ++i)
        row_lengths[i] = 3 * matrix.get_row_length(i);
      scaled_matrix
        = std::make_unique<Epetra_CrsMatrix>(Copy, *map, row_lengths.data());
      Row                 row;
      std::vector<int>    columns;
      std::vector<double> values;
      for (types::global_dof_index i = 0; i < n; ++i)
      {
        row.clear();
        const int k = node_of_row[i];
        if (k < 0)
          append_row(matrix, i, 1., row);
        else
        {
          // Row r of the node: sum over s of inverse(r, s) times row s.
          const ScaledNode  &node = scaled_nodes[k];
          const unsigned int r
            = std::find(node.unknowns.begin(), node.unknowns.end(), i)
              - node.unknowns.begin();
          for (unsigned int s = 0; s < 3; ++s)
            append_row(matrix, node.unknowns[s], node.inverse[3 * r + s], row);
          merge_columns(row);
        }
        columns.resize(row.size());
        values.resize(row.size());
        for (std::size_t e = 0; e < row.size(); ++e)
        {
          columns[e] = row[e].first;
          values[e]  = row[e].second;
        }
        const int status = scaled_matrix->InsertGlobalValues(int(i),
                                                             int(row.size()),
                                                             values.data(),
                                                             columns.data());
        AssertThrow(status >= 0, ExcMessage("Epetra refused a matrix row"));
      }
      scaled_matrix->FillComplete();
    }


    void
    AmgSolver::initialize(const SparseMatrix<double> &matrix)
    {
      // The old hierarchy refers to the old scaled matrix: release it first.
      hierarchy.clear();
      this->matrix = &matrix;
      const int n  = int(matrix.m());
      if (map == nullptr || map->NumGlobalElements() != n)
        map = std::make_unique<Epetra_Map>(n, 0, Epetra_MpiComm(MPI_COMM_SELF));
      build_scaled_matrix(matrix);
      build_null_space(matrix.m());

      // Smoothed aggregation for 3 unknowns per node with the rigid-body
      // modes (ML's users' guide, "SA" defaults), symmetric Gauss-Seidel
      // smoothing, one sweep (the matrix is not symmetric: Chebyshev
      // smoothing diverged on it; D193).
      Teuchos::ParameterList list;
      ML_Epetra::SetDefaults("SA", list);
      list.set("ML output", 0);
      list.set("max levels", 10);
      // The prolongator's damping needs the largest eigenvalue of D^-1 A;
      // ML's default estimate (CG) assumes symmetry and returned 1e17-1e19
      // here, which switched the smoothing of the prolongator off (D193).
      list.set("eigen-analysis: type", "power-method");
      list.set("aggregation: type", "Uncoupled");
      list.set("aggregation: threshold", 0.);
      list.set("smoother: type", "symmetric Gauss-Seidel");
      list.set("smoother: sweeps", 1);
      list.set("coarse: type", "Amesos-KLU");
      list.set("coarse: max size", int(parameters.coarse_size));
      list.set("PDE equations", 3);
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", 6);
      list.set("null space: vectors", null_space.data());
      hierarchy.initialize(*scaled_matrix, list);
      scaled_vector.reinit(matrix.m());
    }


    void
    AmgSolver::vmult(Vector<double> &dst, const Vector<double> &src) const
    {
      scaled_vector = src;
      for (const ScaledNode &node : scaled_nodes)
        for (unsigned int r = 0; r < 3; ++r)
        {
          double value = 0.;
          for (unsigned int s = 0; s < 3; ++s)
            value += node.inverse[3 * r + s] * src[node.unknowns[s]];
          scaled_vector[node.unknowns[r]] = value;
        }
      hierarchy.vmult(dst, scaled_vector);
    }


    bool
    AmgSolver::solve(const Vector<double> &rhs, Vector<double> &solution)
    {
      Assert(matrix != nullptr, ExcInternalError());
      return solve_by_gmres(*matrix,
                            *this,
                            parameters,
                            rhs,
                            solution,
                            iterations);
    }
  } // namespace solver
} // namespace deepdraw
