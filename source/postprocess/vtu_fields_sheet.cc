// VTU fields of the sheet's shape: the displacement since t = 0 and the
// thickness strain ln(t/t0) measured at every vertex's initial (X, Y)
// (doc/theory.md §6).
#include <cmath>
#include <deepdraw/postprocess/vtu_field.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class Displacement : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          data.add_nodal_vector(simulation.sheet().dof_handler(),
                                simulation.state().total_displacement,
                                "displacement");
        }
      };


      class ThicknessStrain : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          Vector<double> &strain
            = data.add_nodal_field(simulation, "thickness_strain");
          const std::vector<double> &thickness
            = simulation.thickness().vertex_thickness();
          for (const auto &cell :
               simulation.sheet().scalar_dof_handler().active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
              strain[cell->vertex_dof_index(v, 0)]
                = std::log(thickness[cell->vertex_index(v)]
                           / simulation.blank().thickness);
        }
      };
    } // namespace

    DEEPDRAW_REGISTER_VTU_FIELD(Displacement,
                                "displacement",
                                "displacement: the total displacement since "
                                "t = 0 (mm), nodal.")
    DEEPDRAW_REGISTER_VTU_FIELD(ThicknessStrain,
                                "thickness strain",
                                "thickness_strain: ln(t/t0) from the measured "
                                "thickness, nodal.")
  } // namespace postprocess
} // namespace deepdraw
