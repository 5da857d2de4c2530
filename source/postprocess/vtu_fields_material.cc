// VTU fields of the material state, per cell (the average of its 8 Gauss
// points): the Cauchy stress and the back-stress (MPa, in x, y, z), the
// rolling direction, the equivalent stress (of the yield criterion, MPa)
// and the equivalent plastic strain.
#include <deepdraw/fe/quadrature_point_update.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/postprocess/vtu_field.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      const char *const axes[] = {"x", "y", "z"};
      // The components of a symmetric tensor, as xx, yy, zz, xy, yz, xz.
      const unsigned int pairs[6][2]
        = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};

      // The cell averages of value(point) over the quadrature points, for
      // the cells of this rank, which holds their state and writes them
      // (D201, D217).
      template <typename Value>
      void
      add_cell_average(const SimulationAccess &simulation,
                       VtuData                &data,
                       const std::string      &name,
                       const Value            &value)
      {
        Vector<double> &field = data.add_cell_field(simulation, name);
        const std::vector<fe::QuadraturePointHistory> &history
          = simulation.state().history;
        const unsigned int n_q = simulation.sheet().n_points_per_cell();
        const parallel::OwnedCells &cells = simulation.sheet().owned_cells();
        for (unsigned int cell = 0; cell < field.size(); ++cell)
        {
          const unsigned int slot = cells.slot(cell);
          if (slot != numbers::invalid_unsigned_int)
            for (unsigned int q = 0; q < n_q; ++q)
              field[cell] += value(history[slot * n_q + q]) / n_q;
        }
      }

      // A symmetric tensor of each point as six cell fields
      // prefix_xx ... prefix_xz.
      template <typename TensorOfPoint>
      void
      add_tensor(const SimulationAccess &simulation,
                 VtuData                &data,
                 const std::string      &prefix,
                 const TensorOfPoint    &tensor)
      {
        for (const auto &pair : pairs)
          add_cell_average(simulation,
                           data,
                           prefix + axes[pair[0]] + axes[pair[1]],
                           [&](const fe::QuadraturePointHistory &point)
                           { return tensor(point)[pair[0]][pair[1]]; });
      }


      class Stress : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          add_tensor(simulation,
                     data,
                     "stress_",
                     [](const fe::QuadraturePointHistory &point)
                     { return fe::cauchy_stress(point); });
        }
      };


      class BackStress : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          // Rotated from the material axes into x, y, z.
          add_tensor(simulation,
                     data,
                     "back_stress_",
                     [](const fe::QuadraturePointHistory &point)
                     {
                       const Tensor<2, 3> &R = point.material_axes;
                       return Tensor<2, 3>(
                         R * Tensor<2, 3>(point.state.back_stress)
                         * transpose(R));
                     });
        }
      };


      class RollingDirection : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          for (unsigned int d = 0; d < 3; ++d)
            add_cell_average(simulation,
                             data,
                             std::string("rolling_direction_") + axes[d],
                             [d](const fe::QuadraturePointHistory &point)
                             { return point.material_axes[d][0]; });
        }
      };


      class EquivalentStress : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          const material::ElastoPlasticity &material = simulation.material();
          add_cell_average(simulation,
                           data,
                           "equivalent_stress",
                           [&](const fe::QuadraturePointHistory &point)
                           {
                             return material.equivalent_stress(
                               point.state.stress - point.state.back_stress);
                           });
        }
      };


      class EquivalentPlasticStrain : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          add_cell_average(simulation,
                           data,
                           "equivalent_plastic_strain",
                           [](const fe::QuadraturePointHistory &point)
                           { return point.state.equivalent_plastic_strain; });
        }
      };
    } // namespace

    DEEPDRAW_REGISTER_VTU_FIELD(Stress,
                                "stress",
                                "stress_xx ... stress_xz: the Cauchy stress "
                                "(MPa), per cell.")
    DEEPDRAW_REGISTER_VTU_FIELD(BackStress,
                                "back stress",
                                "back_stress_xx ... back_stress_xz: the "
                                "back-stress (MPa), per cell.")
    DEEPDRAW_REGISTER_VTU_FIELD(RollingDirection,
                                "rolling direction",
                                "rolling_direction_x/y/z: the material's "
                                "rolling direction, per cell.")
    DEEPDRAW_REGISTER_VTU_FIELD(EquivalentStress,
                                "equivalent stress",
                                "equivalent_stress: of the yield criterion, "
                                "of sigma - X (MPa), per cell.")
    DEEPDRAW_REGISTER_VTU_FIELD(EquivalentPlasticStrain,
                                "equivalent plastic strain",
                                "equivalent_plastic_strain, per cell.")
  } // namespace postprocess
} // namespace deepdraw
