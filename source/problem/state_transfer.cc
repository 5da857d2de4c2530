#include <deal.II/fe/mapping_q1.h>
#include <deal.II/numerics/solution_transfer.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/problem/state_transfer.h>
#include <map>
#include <stdexcept>

namespace deepdraw
{
  namespace problem
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
        for (unsigned int q = 1; q < fe::n_weighted_points; ++q)
          if (xi.distance_square(quadrature.point(q))
              < xi.distance_square(quadrature.point(nearest)))
            nearest = q;
        return nearest;
      }
    } // namespace


    void
    refine_and_transfer(Triangulation<3> &triangulation,
                        DoFHandler<3>    &dof_handler,
                        SimulationState  &state)
    {
      const unsigned int n_points = fe::n_weighted_points;
      const std::size_t  n_dofs   = dof_handler.n_dofs();
      if (state.history.size() != triangulation.n_active_cells() * n_points
          || state.total_displacement.size() != n_dofs)
        throw std::logic_error("refine_and_transfer: the state does not "
                               "belong to this mesh");
      const bool has_enhanced = !state.enhanced_parameters.empty();

      // Where each active cell's data start, by cell (not by active index,
      // which refinement renumbers).
      std::map<CellKey, unsigned int> old_index;
      for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (cell->coarsen_flag_set())
          throw std::logic_error("refine_and_transfer: coarsening is not "
                                 "supported");
        old_index[key_of(cell)] = cell->active_cell_index();
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

      const Quadrature<3> quadrature = fe::selective_reduced_quadrature();
      const MappingQ1<3>  mapping;
      std::vector<fe::QuadraturePointHistory> history(
        triangulation.n_active_cells() * n_points);
      std::vector<fe::EnhancedParameters> enhanced(
        has_enhanced ? triangulation.n_active_cells() : 0);
      for (const auto &cell : triangulation.active_cell_iterators())
      {
        const unsigned int new_cell = cell->active_cell_index();
        const auto         same     = old_index.find(key_of(cell));
        if (same != old_index.end())
        {
          std::copy_n(state.history.begin() + same->second * n_points,
                      n_points,
                      history.begin() + new_cell * n_points);
          if (has_enhanced)
            enhanced[new_cell] = state.enhanced_parameters[same->second];
          continue;
        }
        const auto parent = cell->parent();
        const auto origin = old_index.find(key_of(parent));
        if (origin == old_index.end())
          throw std::logic_error("refine_and_transfer: a new cell whose "
                                 "parent was not active");
        for (unsigned int q = 0; q < n_points; ++q)
        {
          const Point<3> x
            = mapping.transform_unit_to_real_cell(cell, quadrature.point(q));
          const Point<3> xi = mapping.transform_real_to_unit_cell(parent, x);
          history[new_cell * n_points + q]
            = state.history[origin->second * n_points
                            + nearest_point(quadrature, xi)];
        }
      }
      state.history             = std::move(history);
      state.enhanced_parameters = std::move(enhanced);
      state.vertices            = triangulation.get_vertices();
    }
  } // namespace problem
} // namespace deepdraw
