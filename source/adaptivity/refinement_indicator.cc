#include <algorithm>
#include <cmath>
#include <deepdraw/adaptivity/refinement_indicator.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <numeric>

namespace deepdraw
{
  namespace adaptivity
  {
    std::vector<double>
    plastic_strain_jump(const Triangulation<3>                        &mesh,
                        const parallel::OwnedCells                    &cells,
                        const std::vector<fe::QuadraturePointHistory> &history)
    {
      std::vector<double> own(cells.n_owned(), 0.);
      const std::size_t   n_q = own.empty() ? 0 : history.size() / own.size();
      for (std::size_t p = 0; p < history.size(); ++p)
        own[p / n_q]
          += history[p].state.equivalent_plastic_strain / double(n_q);
      const std::vector<double> average = cells.gather_on_all(own, 1);

      // Every face between two active cells is seen from the finer side
      // (whose neighbour across it is active), or from both on a conforming
      // face: the jump is entered into both cells.
      std::vector<double> jump(mesh.n_active_cells(), 0.);
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (!cell->at_boundary(f) && cell->neighbor(f)->is_active())
          {
            const unsigned int k = cell->active_cell_index();
            const unsigned int n = cell->neighbor(f)->active_cell_index();
            const double       d = std::abs(average[k] - average[n]);
            jump[k]              = std::max(jump[k], d);
            jump[n]              = std::max(jump[n], d);
          }
      return jump;
    }


    std::vector<double>
    region_indicator(const Triangulation<3>      &mesh,
                     const std::vector<Point<3>> &initial_vertices,
                     const Point<3>              &low,
                     const Point<3>              &high)
    {
      std::vector<double> inside(mesh.n_active_cells(), 0.);
      for (const auto &cell : mesh.active_cell_iterators())
      {
        Point<3> centre;
        for (const unsigned int v : cell->vertex_indices())
          centre += initial_vertices[cell->vertex_index(v)] / 8.;
        bool in_box = true;
        for (unsigned int d = 0; d < 3; ++d)
          in_box = in_box && centre[d] >= low[d] && centre[d] <= high[d];
        inside[cell->active_cell_index()] = in_box ? 1. : 0.;
      }
      return inside;
    }


    namespace
    {
      // h_K kappa of a cell's face on the sheet surface against one tool
      // (0 if no vertex of it is within distance of the tool).
      double
      face_curvature_ratio(const Triangulation<3>::face_iterator &face,
                           const geometry::RigidTool             &tool,
                           const double                           distance)
      {
        double kappa = 0.;
        for (const unsigned int v : face->vertex_indices())
        {
          geometry::ProjectionResult projection;
          if (tool.project(face->vertex(v), projection, distance)
              && !projection.on_free_edge
              && std::abs(projection.gap) <= distance)
            kappa = std::max({kappa,
                              projection.principal_curvatures[0],
                              projection.principal_curvatures[1]});
        }
        // Vertices 0-1, 2-3, 0-2, 1-3 are the edges of a quadrilateral.
        double h = 0.;
        for (const auto &[a, b] : {std::pair<unsigned int, unsigned int>{0, 1},
                                   {2, 3},
                                   {0, 2},
                                   {1, 3}})
          h = std::max(h, face->vertex(a).distance(face->vertex(b)));
        return h * kappa;
      }
    } // namespace


    std::vector<double>
    tool_curvature_indicator(const Triangulation<3>                 &mesh,
                             const std::vector<geometry::RigidTool> &tools,
                             const std::vector<unsigned int> &sheet_faces,
                             const double                     distance)
    {
      std::vector<double> ratio(mesh.n_active_cells(), 0.);
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int f : {4u, 5u})
          if (cell->at_boundary(f))
            for (unsigned int k = 0; k < tools.size(); ++k)
              if (cell->face(f)->boundary_id() == sheet_faces[k])
              {
                double &value = ratio[cell->active_cell_index()];
                value         = std::max(value,
                                 face_curvature_ratio(cell->face(f),
                                                      tools[k],
                                                      distance));
              }
      // Through the thickness: the largest value of the column, exchanged
      // across the z faces until nothing changes. Every face between two
      // active cells is seen from the finer side, whose neighbour across it
      // is active (as in plastic_strain_jump).
      for (bool changed = true; changed;)
      {
        changed = false;
        for (const auto &cell : mesh.active_cell_iterators())
          for (const unsigned int f : {4u, 5u})
            if (!cell->at_boundary(f) && cell->neighbor(f)->is_active())
            {
              double &a = ratio[cell->active_cell_index()];
              double &b = ratio[cell->neighbor(f)->active_cell_index()];
              if (a != b)
              {
                a = b   = std::max(a, b);
                changed = true;
              }
            }
      }
      return ratio;
    }


    std::vector<double>
    column_maximum(const Triangulation<3>    &mesh,
                   const std::vector<double> &indicator)
    {
      std::vector<double> result = indicator;
      for (const auto &cell : mesh.active_cell_iterators())
      {
        double &value = result[cell->active_cell_index()];
        for (const unsigned int face : {4u, 5u})
          for (auto other = cell; !other->at_boundary(face);)
          {
            const auto next = other->neighbor(face);
            if (!next->is_active() || next->level() != cell->level())
              break;
            value = std::max(value, indicator[next->active_cell_index()]);
            other = next;
          }
      }
      return result;
    }


    unsigned int
    flag_cells_for_refinement(Triangulation<3>           &mesh,
                              const std::vector<double>  &indicator,
                              const double                threshold,
                              const AdaptivityParameters &parameters)
    {
      std::vector<Triangulation<3>::active_cell_iterator> candidates;
      for (const auto &cell : mesh.active_cell_iterators())
        if (indicator[cell->active_cell_index()] > threshold
            && cell->level() < int(parameters.maximum_level))
          candidates.push_back(cell);
      // Largest first; equal values in the order of the cells.
      std::stable_sort(candidates.begin(),
                       candidates.end(),
                       [&](const auto &a, const auto &b)
                       {
                         return indicator[a->active_cell_index()]
                                > indicator[b->active_cell_index()];
                       });
      // deal.II's closure (at most one hanging node per edge, and the
      // neighbours an anisotropic refinement needs) adds flags: the cell
      // limit is checked on the closed flags, dropping the lowest-ranked
      // candidates until it holds.
      const RefinementCase<3> refinement = parameters.refinement_case();
      std::size_t             n_flagged  = candidates.size();
      while (n_flagged > 0)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          cell->clear_refine_flag();
        for (std::size_t c = 0; c < n_flagged; ++c)
          candidates[c]->set_refine_flag(refinement);
        mesh.prepare_coarsening_and_refinement();
        std::size_t n_cells = mesh.n_active_cells();
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->refine_flag_set())
            n_cells += GeometryInfo<3>::n_children(
                         RefinementCase<3>(cell->refine_flag_set()))
                       - 1;
        if (n_cells <= parameters.maximum_cells)
          break;
        n_flagged = std::min(n_flagged - 1, n_flagged * 9 / 10);
      }
      if (n_flagged == 0)
        for (const auto &cell : mesh.active_cell_iterators())
          cell->clear_refine_flag();
      return n_flagged;
    }
  } // namespace adaptivity
} // namespace deepdraw
