#include <deepdraw/blank/memory_estimate.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/postprocess/manager.h>
#include <deepdraw/problem/model_parameters.h>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace problem
  {
    namespace
    {
      // A run needs at least (stage's range) / Maximum increment increments
      // (D50).
      constexpr double max_increments = 1e6;
    } // namespace


    void
    ModelParameters::declare_parameters(ParameterHandler &prm)
    {
      blank::BlankGeometry::declare_parameters(prm);
      process::ProcessParameters::declare_parameters(prm,
                                                     contact::n_tool_slots);
      prm.enter_subsection("Material");
      material::MaterialParameters::declare_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Finite element");
      fe::ElementParameters::declare_parameters(prm);
      prm.leave_subsection();
      process::PrescribedDisplacements::declare_parameters(prm);
      solver::IncrementControlParameters::declare_parameters(prm);
      solver::NewtonParameters::declare_parameters(prm);
      solver::LinearSolverParameters::declare_parameters(prm);
      io::OutputParameters::declare_parameters(prm);
      geometry::SquareCupToolParameters::declare_parameters(prm);
      contact::ContactCoupling::declare_parameters(prm);
      state::CheckpointParameters::declare_parameters(prm);
      adaptivity::AdaptivityParameters::declare_parameters(prm);
      postprocess::Manager::declare_parameters(prm);
    }


    void
    ModelParameters::parse_parameters(ParameterHandler  &prm,
                                      const std::string &input_directory)
    {
      geometry.parse_parameters(prm, input_directory);
      process.parse_parameters(prm);
      prm.enter_subsection("Material");
      material.parse_parameters(prm);
      prm.leave_subsection();
      prm.enter_subsection("Finite element");
      element.parse_parameters(prm);
      prm.leave_subsection();
      boundary_conditions.parse_parameters(prm,
                                           geometry.symmetry_plane_x,
                                           geometry.symmetry_plane_y);
      load_stepping.parse_parameters(prm);
      newton.parse_parameters(prm);
      linear_solver.parse_parameters(prm);
      output.parse_parameters(prm);
      square_cup_tools.parse_parameters(prm);
      checkpoint.parse_parameters(prm);
      adaptivity.parse_parameters(prm);
      process::StageDefaults stage_defaults;
      stage_defaults.final_load          = process.final_load;
      stage_defaults.blank_holder_force  = process.blank_holder_force;
      stage_defaults.boundary_conditions = boundary_conditions;
      stage_defaults.load_stepping       = load_stepping;
      stage_defaults.newton              = newton;
      stage_defaults.symmetry_plane_x    = geometry.symmetry_plane_x;
      stage_defaults.symmetry_plane_y    = geometry.symmetry_plane_y;
      stage_defaults.n_tool_slots        = contact::n_tool_slots;
      prm.enter_subsection("Process");
      stages = process::parse_stages(prm, stage_defaults);
      prm.leave_subsection();
      listing = state::flatten_parameters(prm);
      ParameterHandler defaults;
      declare_parameters(defaults);
      default_listing = state::flatten_parameters(defaults);
    }


    void
    ModelParameters::check(const contact::ContactCoupling &contact) const
    {
      // Every expression of t at 11 loads of its stage (D50): a boundary
      // condition, translation or force without a value there is named
      // now, not found later as "residual is not a number".
      for (const process::Stage &stage : stages)
        stage.prescribed.check_values(geometry, stage.check_loads());
      contact.check_values(
        stages,
        geometry.diagonal(),
        process::PrescribedDisplacements::max_relative_displacement
          * geometry.largest_extent());
      for (const process::Stage &stage : stages)
      {
        const double range             = stage.end_load - stage.start_load;
        const double maximum_increment = stage.load_stepping.maximum_increment;
        if (range / maximum_increment > max_increments)
        {
          std::ostringstream text;
          text << std::setprecision(6);
          if (stage.parameter_prefix.empty())
            text << "Process/Final load = " << stage.end_load;
          else
            text << stage.parameter_prefix << " (loads " << stage.start_load
                 << " to " << stage.end_load << ")";
          text << " needs more than " << max_increments
               << " increments of Load stepping/Maximum increment = "
               << maximum_increment
               << "; allowed are Final load / Maximum increment <= "
               << max_increments;
          throw InputError(text.str());
        }
      }
      // The mesh is made only if it fits into the memory (D53), with every
      // rank of this machine holding it (D209).
      blank::RanksOnMachine ranks;
      ranks.on_this_machine = parallel::ranks_on_this_machine();
      ranks.in_run          = parallel::n_ranks();
      ranks.factors_split   = linear_solver.type == "MUMPS";
      blank::check_memory(geometry,
                          contact.active() ? contact.tool_definitions().size()
                                           : 0,
                          element.points_through_thickness,
                          ranks);
    }
  } // namespace problem
} // namespace deepdraw
