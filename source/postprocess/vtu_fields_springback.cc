// The VTU field of springback (D150): the displacement since the release
// stage began, zero before it (and in a process without one), so that a
// series of VTU files shows the springback alone.
#include <deepdraw/postprocess/vtu_field.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class SpringbackDisplacement : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          const state::SimulationState &state = simulation.state();
          Vector<double>                springback(state.total_displacement);
          if (state.release_start_displacement.size() == springback.size())
            springback -= state.release_start_displacement;
          else
            springback = 0.;
          data.add_nodal_vector(simulation.sheet().dof_handler(),
                                springback,
                                "springback_displacement");
        }
      };
    } // namespace

    DEEPDRAW_REGISTER_VTU_FIELD(SpringbackDisplacement,
                                "springback displacement",
                                "springback_displacement: the displacement "
                                "since the release stage began (mm), nodal; "
                                "zero before it.")
  } // namespace postprocess
} // namespace deepdraw
