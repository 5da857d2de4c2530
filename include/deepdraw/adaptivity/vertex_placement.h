// Where the vertices added by a refinement go in the current configuration
// (doc/theory.md §8, doc/decisions.md D87). deal.II puts a new vertex at
// the Q1 interpolation of its parents (the midpoint of the straight coarse
// edge, the bilinear centre of a face, the trilinear centre of a cell).
// On a sheet already bent over a tool radius R that point lies on the
// chord, off the curved surface by the sagitta L^2 / (8 R) for an edge of
// length L. smooth_vertex_positions puts it instead on a smooth curve
// through the old vertices along each mesh line: the cubic through the
// edge's two ends and the next old vertex beyond each end (for equal
// spacing the 4-point rule x = 9/16 (x_a + x_b) - 1/16 (x_a' + x_b')),
// the quadratic through three where the line ends (a free edge, a
// symmetry plane, a coarser neighbour), the chord if neither neighbour
// exists. A face or cell centre adds the corrections of its edges.
#ifndef deepdraw_adaptivity_vertex_placement_h
#define deepdraw_adaptivity_vertex_placement_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/fe/vertex_parents.h>
#include <vector>

namespace deepdraw
{
  namespace adaptivity
  {
    using namespace dealii;

    // Per vertex, the other ends of the lines that meet at it, on every
    // level (a refined line included): the mesh lines of the mesh before
    // a refinement.
    std::vector<std::vector<unsigned int>>
    line_neighbours(const Triangulation<3> &mesh);

    // Vertices that lie inside an edge or face of an active cell (hanging
    // vertices: their position is the Q1 interpolation of the coarse
    // cell's, D82, and must stay so for the mesh to stay conforming).
    std::vector<bool>
    hanging_vertices(const Triangulation<3> &mesh);

    // Per vertex, the ends of the refined line of an active cell whose
    // midpoint it is (weights 1/2), else empty: the parents of the hanging
    // edge midpoints, which a later refinement of the coarse cell frees.
    std::vector<fe::VertexParents>
    hanging_edge_parents(const Triangulation<3> &mesh);

    // Positions of all vertices of a refined mesh with those flagged in
    // `place` put on the smooth curves through their parents (D87): the new
    // vertices that do not hang, and old vertices that hung on a coarse
    // edge and no longer do (their parents: the edge's ends). current: the
    // refined mesh's vertices (new ones at the Q1 positions); reference:
    // the old vertices' positions in a configuration in which the mesh
    // lines are straight or nearly so (the blank's), which gives the
    // parameter along each line and selects the continuation of a line at
    // a vertex (the neighbour most nearly opposite, within 25 degrees,
    // spaced at 1/2..2 times the edge); neighbours: active_line_neighbours
    // of the mesh before refinement; parents: old vertices with weights
    // (fe::vertex_parents for the new ones). A coordinate that all parents
    // share bit for bit (a symmetry plane) is kept exactly.
    std::vector<Point<3>>
    smooth_vertex_positions(
      const std::vector<Point<3>>                  &current,
      const std::vector<Point<3>>                  &reference,
      const std::vector<std::vector<unsigned int>> &neighbours,
      const std::vector<fe::VertexParents>         &parents,
      const std::vector<bool>                      &place,
      const std::vector<bool>                      &excluded);

    // The rotation of a cell at xi (its unit cell) from the corners `from`
    // to the corners `to` (deal.II's vertex order): the orthogonal factor of
    // F = (dx_to / dxi) (dx_from / dxi)^-1. Moving the new vertices of a
    // bent coarse cell onto the arc turns each child by about a quarter of
    // the parent's bending angle; the child's material axes, and with them
    // the stress and back stress, turn with it (D87). The stretch of F is
    // not applied: the new placement defines the configuration, it does
    // not strain it.
    Tensor<2, 3>
    placement_rotation(const std::array<Point<3>, 8> &from,
                       const std::array<Point<3>, 8> &to,
                       const Point<3>                &xi);
  } // namespace adaptivity
} // namespace deepdraw

#endif
