// The vertices of the mesh before a refinement from which each vertex of
// the refined mesh is interpolated (doc/theory.md §8.2): an old vertex is
// its own parent, a new one is the midpoint of a refined edge (1/2, 1/2)
// or the centre of an isotropically refined face (1/4 each) or cell (1/8
// each), resolved recursively down to old vertices. The contact state of new
// surface nodes and the initial position of every new vertex are
// interpolated from these parents.
#ifndef deepdraw_fe_vertex_parents_h
#define deepdraw_fe_vertex_parents_h

#include <deal.II/grid/tria.h>
#include <utility>
#include <vector>

namespace deepdraw
{
  namespace fe
  {
    using namespace dealii;

    // (old vertex, weight) pairs, the weights summing to 1.
    using VertexParents = std::vector<std::pair<unsigned int, double>>;

    // For every vertex of the refined mesh, its parents among the vertices
    // 0 ... n_old_vertices - 1 (the refinement numbers new vertices after
    // the old ones).
    std::vector<VertexParents>
    vertex_parents(const Triangulation<3> &mesh, unsigned int n_old_vertices);
  } // namespace fe
} // namespace deepdraw

#endif
