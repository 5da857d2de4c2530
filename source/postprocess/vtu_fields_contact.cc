// VTU fields of the contact with the tools (runs with tools), at the sheet's
// surface nodes: contact_status (0 open, 1 stick, 2 slip), contact_gap
// (mm), contact_pressure and friction_stress_x/y/z (MPa: nodal forces over
// the node's share of the sheet surface).
#include <deepdraw/blank/nodal_surface_area.h>
#include <deepdraw/postprocess/vtu_field.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class ContactFields : public VtuField
      {
      public:
        void
        add(const SimulationAccess &simulation, VtuData &data) const override
        {
          const contact::ContactCoupling &contact = simulation.contact();
          if (!contact.active())
            return;
          const Triangulation<3> &mesh = simulation.sheet().triangulation();
          Vector<double>         &status
            = data.add_nodal_field(simulation, "contact_status");
          Vector<double> &gap = data.add_nodal_field(simulation, "contact_gap");
          Vector<double> &pressure
            = data.add_nodal_field(simulation, "contact_pressure");
          Vector<double> *friction[3];
          for (unsigned int d = 0; d < 3; ++d)
            friction[d] = &data.add_nodal_field(simulation,
                                                std::string("friction_stress_")
                                                  + "xyz"[d]);
          const std::vector<contact::ContactCoupling::NodalContact> nodal
            = contact.nodal_contact(mesh.n_vertices());
          const std::vector<double> area = blank::nodal_surface_area(mesh);
          for (const auto &cell :
               simulation.sheet().scalar_dof_handler().active_cell_iterators())
            for (const unsigned int v : cell->vertex_indices())
            {
              const unsigned int vertex = cell->vertex_index(v);
              const auto         dof    = cell->vertex_dof_index(v, 0);
              status[dof]               = nodal[vertex].status;
              gap[dof]                  = nodal[vertex].gap;
              if (area[vertex] > 0.)
              {
                pressure[dof] = nodal[vertex].normal_force / area[vertex];
                for (unsigned int d = 0; d < 3; ++d)
                  (*friction[d])[dof]
                    = nodal[vertex].friction_force[d] / area[vertex];
              }
            }
        }
      };
    } // namespace

    DEEPDRAW_REGISTER_VTU_FIELD(
      ContactFields,
      "contact",
      "contact_status (0 open, 1 stick, 2 slip), contact_gap (mm), "
      "contact_pressure and friction_stress_x/y/z (MPa), nodal, with tools.")
  } // namespace postprocess
} // namespace deepdraw
