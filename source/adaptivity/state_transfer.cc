#include <deal.II/numerics/solution_transfer.h>
#include <deepdraw/adaptivity/history_interpolation.h>
#include <deepdraw/adaptivity/state_transfer.h>
#include <deepdraw/adaptivity/vertex_placement.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/fe/vertex_parents.h>
#include <map>
#include <stdexcept>

namespace deepdraw
{
  namespace adaptivity
  {
    namespace
    {
      using CellKey = std::pair<int, int>; // level, index

      template <typename Iterator>
      CellKey
      key_of(const Iterator &cell)
      {
        return {cell->level(), cell->index()};
      }

      // Where a cell's records start among those this rank holds
      // (numbers::invalid_unsigned_int where another rank holds them), and
      // the rank that holds them.
      struct HeldRecords
      {
        unsigned int position;
        unsigned int holder;
      };

      // The records of each active cell, by cell (not by active index,
      // which refinement renumbers).
      std::map<CellKey, HeldRecords>
      records_before(const Triangulation<3>     &triangulation,
                     const parallel::OwnedCells *held)
      {
        std::map<CellKey, HeldRecords> records;
        for (const auto &cell : triangulation.active_cell_iterators())
        {
          if (cell->coarsen_flag_set())
            throw std::logic_error("refine_and_transfer: coarsening is not "
                                   "supported");
          const unsigned int index = cell->active_cell_index();
          records[key_of(cell)]
            = held == nullptr
                ? HeldRecords{index, parallel::this_rank()}
                : HeldRecords{held->slot(index), held->owner(index)};
        }
        return records;
      }

      // The displacement block (first n entries) of a Newton solution.
      Vector<double>
      displacement_block(const Vector<double> &solution, const std::size_t n)
      {
        Vector<double> block(n);
        for (std::size_t i = 0; i < std::min<std::size_t>(n, solution.size());
             ++i)
          block[i] = solution[i];
        return block;
      }

      // Index of the Gauss point of the reference cell nearest to xi.
      unsigned int
      nearest_point(const Quadrature<3> &quadrature, const Point<3> &xi)
      {
        unsigned int nearest = 0;
        for (unsigned int q = 1; q < fe::n_weighted_points(quadrature); ++q)
          if (xi.distance_square(quadrature.point(q))
              < xi.distance_square(quadrature.point(nearest)))
            nearest = q;
        return nearest;
      }


      // The records of the refined mesh's cells whose own records, or
      // their parent's, this rank holds, in the cells' order; each new
      // cell's place among them (or numbers::invalid_unsigned_int) and the
      // rank that holds it.
      void
      transfer_records(const Triangulation<3>               &triangulation,
                       const std::map<CellKey, HeldRecords> &before,
                       const unsigned int                    n_points,
                       const bool                            has_enhanced,
                       const TransferOptions                &options,
                       state::SimulationState               &state,
                       std::vector<unsigned int>            &position_of_cell,
                       std::vector<unsigned int>            &holder_of_cell)
      {
        const unsigned int n_cells = triangulation.n_active_cells();
        position_of_cell.assign(n_cells, numbers::invalid_unsigned_int);
        holder_of_cell.assign(n_cells, 0);
        // A new cell's records come from itself where it was active, else
        // from its parent.
        std::vector<const HeldRecords *> source(n_cells);
        std::vector<bool>                is_child(n_cells, false);
        unsigned int                     n_held = 0;
        for (const auto &cell : triangulation.active_cell_iterators())
        {
          const unsigned int index = cell->active_cell_index();
          auto               found = before.find(key_of(cell));
          if (found == before.end())
          {
            found           = before.find(key_of(cell->parent()));
            is_child[index] = true;
            if (found == before.end())
              throw std::logic_error("refine_and_transfer: a new cell whose "
                                     "parent was not active");
          }
          source[index]         = &found->second;
          holder_of_cell[index] = found->second.holder;
          if (found->second.position != numbers::invalid_unsigned_int)
            position_of_cell[index] = n_held++;
        }

        const Quadrature<3> quadrature
          = fe::quadrature_with_weighted_points(n_points);
        std::vector<fe::QuadraturePointHistory> history(std::size_t(n_held)
                                                        * n_points);
        std::vector<fe::EnhancedParameters> enhanced(has_enhanced ? n_held : 0);
        for (const auto &cell : triangulation.active_cell_iterators())
        {
          const unsigned int index = cell->active_cell_index();
          const std::size_t  to    = position_of_cell[index];
          if (to == numbers::invalid_unsigned_int)
            continue;
          const std::size_t                 from = source[index]->position;
          const fe::QuadraturePointHistory *points
            = &state.history[from * n_points];
          if (!is_child[index])
          {
            std::copy_n(points, n_points, history.begin() + to * n_points);
            if (has_enhanced)
              enhanced[to] = state.enhanced_parameters[from];
            continue;
          }
          // The child's points in the parent's unit cell: exact, and
          // independent of where the new vertices were placed. Children's
          // enhanced parameters start from zero.
          const auto         parent = cell->parent();
          const unsigned int child  = parent->child_iterator_to_index(cell);
          for (unsigned int q = 0; q < n_points; ++q)
          {
            const Point<3> xi = GeometryInfo<3>::child_to_cell_coordinates(
              quadrature.point(q),
              child,
              parent->refinement_case());
            history[to * n_points + q]
              = options.history == HistoryTransfer::interpolated
                  ? interpolate_history(points,
                                        quadrature,
                                        xi,
                                        *options.material)
                  : points[nearest_point(quadrature, xi)];
          }
        }
        state.history             = std::move(history);
        state.enhanced_parameters = std::move(enhanced);
      }
    } // namespace


    std::vector<unsigned int>
    refine_and_transfer(Triangulation<3>       &triangulation,
                        DoFHandler<3>          &dof_handler,
                        state::SimulationState &state,
                        const TransferOptions  &options)
    {
      if (options.history == HistoryTransfer::interpolated
          && options.material == nullptr)
        throw std::invalid_argument("refine_and_transfer: the interpolated "
                                    "history needs the material");
      // The rule follows from the state's points per cell (D202).
      const parallel::OwnedCells *held = options.held_cells;
      const unsigned int          n_held
        = held ? held->n_owned() : triangulation.n_active_cells();
      const unsigned int n_points
        = held ? options.points_per_cell
               : state.history.size() / triangulation.n_active_cells();
      const bool has_enhanced = held ? options.enhanced_parameters
                                     : !state.enhanced_parameters.empty();
      if ((held && held->n_cells() != triangulation.n_active_cells())
          || state.history.size() != std::size_t(n_held) * n_points
          || (has_enhanced && state.enhanced_parameters.size() != n_held)
          || state.total_displacement.size() != dof_handler.n_dofs())
        throw std::logic_error("refine_and_transfer: the state does not "
                               "belong to this mesh");
      const std::map<CellKey, HeldRecords> before
        = records_before(triangulation, held);
      const std::size_t n_dofs = dof_handler.n_dofs();

      // For the smooth placement (D87): the mesh lines before refinement
      // and the old vertices' initial positions x - u, in which those lines
      // are straight.
      const bool smooth = options.vertex_placement == VertexPlacement::smooth;
      const unsigned int n_old_vertices = triangulation.n_vertices();
      std::vector<std::vector<unsigned int>> lines;
      std::vector<Point<3>>                  reference;
      std::vector<fe::VertexParents>         freed_parents;
      std::vector<bool>                      hung;
      if (smooth)
      {
        lines         = line_neighbours(triangulation);
        freed_parents = hanging_edge_parents(triangulation);
        hung          = hanging_vertices(triangulation);
        reference     = triangulation.get_vertices();
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int c = 0; c < 3; ++c)
              reference[cell->vertex_index(v)][c]
                = cell->vertex(v)[c]
                  - state.total_displacement[cell->vertex_dof_index(v, c)];
      }

      std::vector<Vector<double>> fields
        = {state.total_displacement,
           displacement_block(state.converged_solution, n_dofs),
           displacement_block(state.previous_converged_solution, n_dofs)};
      SolutionTransfer<3, Vector<double>> solution_transfer(dof_handler);
      solution_transfer.prepare_for_pure_refinement();
      triangulation.execute_coarsening_and_refinement();
      dof_handler.distribute_dofs(dof_handler.get_fe());
      for (Vector<double> &field : fields)
      {
        Vector<double> refined(dof_handler.n_dofs());
        solution_transfer.refine_interpolate(field, refined);
        field = std::move(refined);
      }
      state.total_displacement          = fields[0];
      state.converged_solution          = fields[1];
      state.previous_converged_solution = fields[2];

      std::vector<Point<3>> q1_vertices;
      std::vector<bool>     moved;
      if (smooth)
      {
        // New vertices, and old ones that hung on a coarse edge and do not
        // any more, onto the smooth curves through the old ones; the total
        // displacement moves with them (D87). Hanging vertices stay on
        // their coarse edge or face, and so does every vertex of a cell
        // with a hanging vertex: moving it alone would bend or squash that
        // cell by the sagitta (measured: a column of the square cup whose
        // bottom layer was refined and top layer not came out 1.4 % thicker
        // at once).
        q1_vertices               = triangulation.get_vertices();
        std::vector<bool> hanging = hanging_vertices(triangulation);
        {
          std::vector<bool> beside = hanging;
          for (const auto &cell : triangulation.active_cell_iterators())
          {
            bool any = false;
            for (const unsigned int v : cell->vertex_indices())
              any = any || hanging[cell->vertex_index(v)];
            if (any)
              for (const unsigned int v : cell->vertex_indices())
                beside[cell->vertex_index(v)] = true;
          }
          hanging = std::move(beside);
        }
        std::vector<fe::VertexParents> parents
          = fe::vertex_parents(triangulation, n_old_vertices);
        moved.assign(triangulation.n_vertices(), false);
        std::vector<bool> hung_all = hung;
        hung_all.resize(triangulation.n_vertices(), false);
        for (unsigned int v = 0; v < triangulation.n_vertices(); ++v)
          if (!hanging[v])
          {
            if (v < n_old_vertices && freed_parents[v].size() == 2)
              parents[v] = freed_parents[v];
            moved[v] = parents[v].size() >= 2;
          }
        const std::vector<Point<3>> positions
          = smooth_vertex_positions(q1_vertices,
                                    reference,
                                    lines,
                                    parents,
                                    moved,
                                    hung_all);
        std::vector<bool> done(triangulation.n_vertices(), false);
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int index = cell->vertex_index(v);
            if (!moved[index] || done[index])
              continue;
            done[index]               = true;
            const Tensor<1, 3> offset = positions[index] - cell->vertex(v);
            for (unsigned int c = 0; c < 3; ++c)
              state.total_displacement[cell->vertex_dof_index(v, c)]
                += offset[c];
            cell->vertex(v) = positions[index];
          }
      }

      std::vector<unsigned int> position_of_cell, holder_of_cell;
      transfer_records(triangulation,
                       before,
                       n_points,
                       has_enhanced,
                       options,
                       state,
                       position_of_cell,
                       holder_of_cell);
      // The points of every cell with a moved vertex turn with it from the
      // Q1 to the smooth placement (D87): the stress stays the same in the
      // material frame. (Cells whose vertices did not move keep their axes
      // bit for bit.)
      if (smooth)
      {
        const Quadrature<3> quadrature
          = fe::quadrature_with_weighted_points(n_points);
        for (const auto &cell : triangulation.active_cell_iterators())
        {
          // Only the cells whose records this rank holds.
          const std::size_t position
            = position_of_cell[cell->active_cell_index()];
          if (position == numbers::invalid_unsigned_int)
            continue;
          std::array<Point<3>, 8> q1_corners, corners;
          bool                    any_moved = false;
          for (const unsigned int v : cell->vertex_indices())
          {
            q1_corners[v] = q1_vertices[cell->vertex_index(v)];
            corners[v]    = cell->vertex(v);
            any_moved     = any_moved || corners[v] != q1_corners[v];
          }
          if (!any_moved)
            continue;
          for (unsigned int q = 0; q < n_points; ++q)
          {
            auto &axes = state.history[position * n_points + q].material_axes;
            axes = placement_rotation(q1_corners, corners, quadrature.point(q))
                   * axes;
          }
        }
      }
      state.vertices = triangulation.get_vertices();
      return holder_of_cell;
    }
  } // namespace adaptivity
} // namespace deepdraw
