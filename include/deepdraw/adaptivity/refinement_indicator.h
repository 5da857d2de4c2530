// Which cells adaptive refinement refines (doc/theory.md §8.1, D81): the
// indicator of subsection Adaptivity per active cell, and the refine flags
// it sets within the maximum level and the maximum number of cells.
#ifndef deepdraw_adaptivity_refinement_indicator_h
#define deepdraw_adaptivity_refinement_indicator_h

#include <deal.II/grid/tria.h>
#include <deepdraw/adaptivity/adaptivity_parameters.h>
#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/geometry/rigid_tool.h>
#include <deepdraw/parallel/owned_cells.h>
#include <vector>

namespace deepdraw
{
  namespace adaptivity
  {
    using namespace dealii;

    // Per active cell: the largest jump |ε̄ᵖ_K − ε̄ᵖ_N| of the cell-average
    // equivalent plastic strain to a face neighbour N (history has
    // fe::n_weighted_points per cell for the cells of this rank, in their
    // order, D217; the ranks' averages are gathered, so every rank must
    // call it).
    std::vector<double>
    plastic_strain_jump(const Triangulation<3>                        &mesh,
                        const parallel::OwnedCells                    &cells,
                        const std::vector<fe::QuadraturePointHistory> &history);

    // Per active cell: 1 if its centre in the initial configuration
    // (initial_vertices) lies in the box [low, high], else 0.
    std::vector<double>
    region_indicator(const Triangulation<3>      &mesh,
                     const std::vector<Point<3>> &initial_vertices,
                     const Point<3>              &low,
                     const Point<3>              &high);

    // Per active cell: h_K kappa, its in-plane size h_K (longest edge of its
    // face on the sheet surface, current configuration) times the largest
    // convex principal curvature kappa of a tool at the foot points of that
    // face's vertices, over the tools acting on that surface (sheet_faces:
    // the boundary id, 4 bottom or 5 top, of each tool) and the vertices
    // closer to the tool than `distance`; 0 where no tool is that close or
    // the tool is flat there. Carried to every cell of the column through
    // the thickness (faces 4 and 5 of the blank's cells are its bottom and
    // top), so that the whole column is refined. The mesh is in the current
    // configuration and the tools at their current placement.
    std::vector<double>
    tool_curvature_indicator(const Triangulation<3>                 &mesh,
                             const std::vector<geometry::RigidTool> &tools,
                             const std::vector<unsigned int> &sheet_faces,
                             double                           distance);

    // Per active cell: the largest indicator over its through-thickness
    // column (the active neighbours of the same level across the z faces,
    // 4 and 5, of the blank's structured cells), so that `in_plane`
    // refinement refines whole columns, without hanging vertices in the
    // mid layers of a band (D89; the smooth vertex placement, D87, moves
    // no vertex of a cell with a hanging vertex).
    std::vector<double>
    column_maximum(const Triangulation<3>    &mesh,
                   const std::vector<double> &indicator);

    // Sets the refine flag (parameters.refinement_case()) of the cells whose
    // indicator exceeds threshold and whose level is below the maximum,
    // largest indicator first, as long as the refined mesh, with the cells
    // deal.II's closure of the flags adds, keeps at most
    // parameters.maximum_cells active cells. Returns the number of
    // candidates flagged (the closure's flags are set too).
    unsigned int
    flag_cells_for_refinement(Triangulation<3>           &mesh,
                              const std::vector<double>  &indicator,
                              double                      threshold,
                              const AdaptivityParameters &parameters);
  } // namespace adaptivity
} // namespace deepdraw

#endif
