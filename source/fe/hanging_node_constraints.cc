#include <deal.II/fe/fe.h>
#include <deepdraw/fe/hanging_node_constraints.h>
#include <stdexcept>

namespace deepdraw
{
  namespace fe
  {
    namespace
    {
      // Constrains every component of vertex `hanging` of `object` to the
      // given vertices of `parent` with equal weights.
      template <typename Child, typename Parent>
      void
      constrain_vertex(const Child               &child,
                       const unsigned int         hanging,
                       const Parent              &parent,
                       const unsigned int         n_masters,
                       const unsigned int         n_components,
                       AffineConstraints<double> &constraints)
      {
        for (unsigned int c = 0; c < n_components; ++c)
        {
          const types::global_dof_index dof
            = child->vertex_dof_index(hanging, c);
          if (constraints.is_constrained(dof))
            continue;
          constraints.add_line(dof);
          for (unsigned int m = 0; m < n_masters; ++m)
            constraints.add_entry(dof,
                                  parent->vertex_dof_index(m, c),
                                  1. / n_masters);
        }
      }

      // The midpoint of a refined edge, and recursively those of its
      // refined children.
      template <typename Line>
      void
      constrain_line(const Line                &line,
                     const unsigned int         n_components,
                     AffineConstraints<double> &constraints)
      {
        if (!line->has_children())
          return;
        constrain_vertex(line->child(0), 1, line, 2, n_components, constraints);
        for (unsigned int child = 0; child < 2; ++child)
          constrain_line(line->child(child), n_components, constraints);
      }

      // The centre of an isotropically refined face (its edges are handled
      // as lines), and recursively the faces of its children.
      template <typename Face>
      void
      constrain_face(const Face                &face,
                     const unsigned int         n_components,
                     AffineConstraints<double> &constraints)
      {
        if (!face->has_children())
          return;
        if (face->refinement_case() == RefinementCase<2>::isotropic_refinement)
          // Child 0 spans from face vertex 0 to the centre (its vertex 3).
          constrain_vertex(face->child(0),
                           3,
                           face,
                           4,
                           n_components,
                           constraints);
        for (unsigned int child = 0; child < face->n_children(); ++child)
        {
          for (unsigned int l = 0; l < 4; ++l)
            constrain_line(face->child(child)->line(l),
                           n_components,
                           constraints);
          constrain_face(face->child(child), n_components, constraints);
        }
      }
    } // namespace


    void
    make_q1_hanging_node_constraints(const DoFHandler<3>       &dof_handler,
                                     AffineConstraints<double> &constraints)
    {
      const FiniteElement<3> &fe = dof_handler.get_fe();
      if (fe.dofs_per_vertex * GeometryInfo<3>::vertices_per_cell
          != fe.n_dofs_per_cell())
        throw std::logic_error("make_q1_hanging_node_constraints: the "
                               "element must have vertex dofs only (Q1)");
      const unsigned int n_components = fe.dofs_per_vertex;
      for (const auto &cell : dof_handler.active_cell_iterators())
      {
        for (const unsigned int l : cell->line_indices())
          constrain_line(cell->line(l), n_components, constraints);
        for (const unsigned int f : cell->face_indices())
          constrain_face(cell->face(f), n_components, constraints);
      }
    }
  } // namespace fe
} // namespace deepdraw
