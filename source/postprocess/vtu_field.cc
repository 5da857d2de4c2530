#include <deepdraw/postprocess/vtu_field.h>

namespace deepdraw
{
  namespace postprocess
  {
    Vector<double> &
    VtuData::add_nodal_field(const SimulationAccess &simulation,
                             const std::string      &name)
    {
      const DoFHandler<3> &dofs = simulation.sheet().scalar_dof_handler();
      data.push_back({&dofs, Vector<double>(dofs.n_dofs()), name, false});
      return data.back().values;
    }


    void
    VtuData::add_nodal_vector(const DoFHandler<3>  &dof_handler,
                              const Vector<double> &values,
                              const std::string    &name)
    {
      data.push_back({&dof_handler, values, name, true});
    }


    Vector<double> &
    VtuData::add_cell_field(const SimulationAccess &simulation,
                            const std::string      &name)
    {
      data.push_back(
        {nullptr,
         Vector<double>(simulation.sheet().triangulation().n_active_cells()),
         name,
         false});
      return data.back().values;
    }


    const std::list<VtuData::Field> &
    VtuData::fields() const
    {
      return data;
    }


    void
    VtuField::check(const SimulationAccess &) const
    {
    }
  } // namespace postprocess
} // namespace deepdraw
