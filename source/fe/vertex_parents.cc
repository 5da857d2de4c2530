#include <deepdraw/fe/vertex_parents.h>
#include <map>

namespace deepdraw
{
  namespace fe
  {
    namespace
    {
      // Expands the direct parents of vertex v into old vertices.
      const VertexParents &
      resolve(const unsigned int                v,
              const unsigned int                n_old_vertices,
              const std::vector<VertexParents> &direct,
              std::vector<VertexParents>       &resolved,
              std::vector<bool>                &done)
      {
        if (done[v])
          return resolved[v];
        done[v] = true;
        if (v < n_old_vertices)
        {
          resolved[v] = {{v, 1.}};
          return resolved[v];
        }
        std::map<unsigned int, double> sum;
        for (const auto &[parent, weight] : direct[v])
          for (const auto &[old, w] :
               resolve(parent, n_old_vertices, direct, resolved, done))
            sum[old] += weight * w;
        resolved[v].assign(sum.begin(), sum.end());
        return resolved[v];
      }
    } // namespace


    std::vector<VertexParents>
    vertex_parents(const Triangulation<3> &mesh,
                   const unsigned int      n_old_vertices)
    {
      // Direct parents: the ends of each refined edge, the corners of each
      // isotropically refined face (its child 0 spans from corner 0 to the
      // centre, child vertex 3, as in make_q1_hanging_node_constraints).
      // Every line and face of the mesh is a line or face of some cell, on
      // some level (a refined face's children are faces of the children).
      std::vector<VertexParents> direct(mesh.n_vertices());
      for (const auto &cell : mesh.cell_iterators())
      {
        for (const unsigned int l : cell->line_indices())
        {
          const auto line = cell->line(l);
          if (line->has_children())
            direct[line->child(0)->vertex_index(1)]
              = {{line->vertex_index(0), 0.5}, {line->vertex_index(1), 0.5}};
        }
        // The centre of an isotropically refined cell (child 0 spans from
        // vertex 0 to it, its vertex 7).
        if (cell->has_children()
            && cell->refinement_case()
                 == RefinementCase<3>::isotropic_refinement)
        {
          VertexParents &parents = direct[cell->child(0)->vertex_index(7)];
          parents.clear();
          for (const unsigned int v : cell->vertex_indices())
            parents.emplace_back(cell->vertex_index(v), 0.125);
        }
        for (const unsigned int f : cell->face_indices())
        {
          const auto face = cell->face(f);
          if (face->has_children()
              && face->refinement_case()
                   == RefinementCase<2>::isotropic_refinement)
          {
            VertexParents &parents = direct[face->child(0)->vertex_index(3)];
            parents.clear();
            for (unsigned int v = 0; v < 4; ++v)
              parents.emplace_back(face->vertex_index(v), 0.25);
          }
        }
      }

      std::vector<VertexParents> resolved(mesh.n_vertices());
      std::vector<bool>          done(mesh.n_vertices(), false);
      for (unsigned int v = 0; v < mesh.n_vertices(); ++v)
        resolve(v, n_old_vertices, direct, resolved, done);
      return resolved;
    }
  } // namespace fe
} // namespace deepdraw
