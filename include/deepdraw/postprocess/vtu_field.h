// A field of the VTU files (post-processor "visualization", Output/VTU
// fields): it computes its values from the simulation and hands them to
// VtuData, which checks them and writes them with the mesh. Each field (or
// group of fields) registers itself with DEEPDRAW_REGISTER_VTU_FIELD in its
// own file.
#ifndef deepdraw_postprocess_vtu_field_h
#define deepdraw_postprocess_vtu_field_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/postprocess/plugin_registry.h>
#include <deepdraw/postprocess/simulation_access.h>
#include <list>
#include <string>

namespace deepdraw
{
  namespace postprocess
  {
    // The values of the fields of one VTU file.
    class VtuData
    {
    public:
      // A nodal scalar on the sheet's scalar Q1 dofs (sized, zero).
      Vector<double> &
      add_nodal_field(const SimulationAccess &simulation,
                      const std::string      &name);
      // A nodal vector on the displacement dofs.
      void
      add_nodal_vector(const DoFHandler<3>  &dof_handler,
                       const Vector<double> &values,
                       const std::string    &name);
      // A value per active cell (sized, zero).
      Vector<double> &
      add_cell_field(const SimulationAccess &simulation,
                     const std::string      &name);

      struct Field
      {
        const DoFHandler<3> *dof_handler = nullptr; // nullptr: cell data
        Vector<double>       values;
        std::string          name;
        bool                 vector = false;
      };
      const std::list<Field> &
      fields() const;

    private:
      // A list: add_*_field hand out references that must stay valid.
      std::list<Field> data;
    };

    class VtuField
    {
    public:
      virtual ~VtuField() = default;

      // Its parameters, if any (the derived class hides this one).
      static void
      declare_parameters(ParameterHandler &)
      {
      }

      // Before anything is written (the post-processor "visualization"'s
      // initialize): InputError if the field cannot be computed in this
      // run, naming the parameter. By default nothing.
      virtual void
      check(const SimulationAccess &simulation) const;

      // Adds its field(s), computed on the state of the last converged
      // increment.
      virtual void
      add(const SimulationAccess &simulation, VtuData &data) const = 0;
    };

    using VtuFieldRegistry = PluginRegistry<VtuField>;
  } // namespace postprocess
} // namespace deepdraw

// In the field's .cc file, after the class: registers it under `name`, the
// name in Output/VTU fields.
#define DEEPDRAW_REGISTER_VTU_FIELD(classname, name, description) \
  DEEPDRAW_REGISTER_PLUGIN(::deepdraw::postprocess::VtuField,     \
                           classname,                             \
                           name,                                  \
                           description)

#endif
