#include <array>
#include <cmath>
#include <deepdraw/problem/viscous_stabilization.h>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      // Volume of a hexahedron from its corners in deal.II's lexicographic
      // order: six tetrahedra around the diagonal 0-7 (exact for the flat
      // blank's parallelepipeds, a weight otherwise).
      double
      hexahedron_volume(const std::array<Point<3>, 8> &x)
      {
        static constexpr unsigned int tetrahedra[6][2]
          = {{1, 3}, {3, 2}, {2, 6}, {6, 4}, {4, 5}, {5, 1}};
        double volume = 0.;
        for (const auto &[a, b] : tetrahedra)
        {
          const Tensor<1, 3> e1 = x[a] - x[0], e2 = x[b] - x[0],
                             e3 = x[7] - x[0];
          volume += std::abs(scalar_product(e1, cross_product_3d(e2, e3)));
        }
        return volume / 6.;
      }
    } // namespace


    void
    ViscousStabilization::update_weights(
      const discretisation::SheetDiscretisation &discretisation)
    {
      const auto &dofs    = discretisation.vertex_dofs();
      const auto &initial = discretisation.initial_vertices();
      volume_of_dof.assign(discretisation.n_displacement_dofs(), 0.);
      for (const auto &cell :
           discretisation.triangulation().active_cell_iterators())
      {
        std::array<Point<3>, 8> corners;
        for (unsigned int v = 0; v < 8; ++v)
          corners[v] = initial[cell->vertex_index(v)];
        const double share = hexahedron_volume(corners) / 8.;
        for (unsigned int v = 0; v < 8; ++v)
          for (const types::global_dof_index dof : dofs[cell->vertex_index(v)])
            volume_of_dof[dof] += share;
      }
    }


    void
    ViscousStabilization::add(
      const discretisation::SheetDiscretisation &discretisation,
      const Vector<double>                      &du,
      const double                               coefficient,
      const double                               dt,
      const AffineConstraints<double>           &constraints,
      linear_algebra::SystemMatrix              *matrix,
      Vector<double>                            &rhs)
    {
      if (volume_of_dof.size() != discretisation.n_displacement_dofs())
        update_weights(discretisation);
      for (types::global_dof_index i = 0; i < volume_of_dof.size(); ++i)
      {
        if (constraints.is_constrained(i))
          continue;
        // f_i = c V_i du_i / dt (theory.md Eq. 5.7.1), rhs = -r.
        const double damping = coefficient * volume_of_dof[i] / dt;
        rhs[i] -= damping * du[i];
        if (matrix != nullptr)
          matrix->add(i, i, damping);
      }
    }
  } // namespace problem
} // namespace deepdraw
