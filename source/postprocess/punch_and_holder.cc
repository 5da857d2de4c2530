#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/postprocess/punch_and_holder.h>

namespace deepdraw
{
  namespace postprocess
  {
    void
    PunchAndHolder::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Process tables");
      prm.declare_entry("Punch tool",
                        "punch",
                        Patterns::Anything(),
                        "Name of the tool (Contact/Tool N/Name) whose force "
                        "along its motion is punch_force_N in "
                        "punch_force.csv. The default 'punch' is used if a "
                        "tool has that name (no punch_force.csv otherwise); "
                        "any other name must exist.");
      prm.declare_entry("Blank holder tool",
                        "",
                        Patterns::Anything(),
                        "Name of the force-controlled or spring-backed "
                        "tool whose force and position are holder_force_N "
                        "and holder_z_mm in punch_force.csv; empty: the "
                        "first such tool.");
      prm.leave_subsection();
    }


    void
    PunchAndHolder::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Process tables");
      punch_name  = Utilities::trim(prm.get("Punch tool"));
      holder_name = Utilities::trim(prm.get("Blank holder tool"));
      prm.leave_subsection();
    }


    void
    PunchAndHolder::set_up(const contact::ContactCoupling &contact,
                           const double                    final_load)
    {
      punch_tool  = numbers::invalid_unsigned_int;
      holder_tool = numbers::invalid_unsigned_int;
      const std::vector<contact::ToolDefinition> &tools
        = contact.tool_definitions();
      for (unsigned int k = 0; k < tools.size(); ++k)
      {
        if (punch_tool == numbers::invalid_unsigned_int
            && tools[k].name == punch_name)
          punch_tool = k;
        if (holder_tool == numbers::invalid_unsigned_int
            && (tools[k].force_controlled || tools[k].spring_stiffness > 0.)
            && (holder_name.empty() || tools[k].name == holder_name))
          holder_tool = k;
      }
      if (punch_tool == numbers::invalid_unsigned_int && punch_name != "punch"
          && !punch_name.empty())
        throw InputError("Process tables/Punch tool: no tool is named '"
                         + punch_name + "'");
      if (holder_tool == numbers::invalid_unsigned_int && !holder_name.empty())
        throw InputError("Process tables/Blank holder tool: no "
                         "force-controlled or spring-backed tool is named '"
                         + holder_name + "'");
      direction = Tensor<1, 3>({0., 0., -1.});
      if (punch_tool == numbers::invalid_unsigned_int)
        return;
      // Over the whole run as the tool declares its motion.
      const contact::ToolDefinition &punch = tools[punch_tool];
      const Tensor<1, 3>             motion
        = punch.force_controlled
            ? punch.axis
            : contact.declared_translation(punch_tool, final_load)
                - contact.declared_translation(punch_tool, 0.);
      if (motion.norm() > 0.)
        direction = motion / motion.norm();
    }


    unsigned int
    PunchAndHolder::punch() const
    {
      return punch_tool;
    }


    unsigned int
    PunchAndHolder::holder() const
    {
      return holder_tool;
    }


    const Tensor<1, 3> &
    PunchAndHolder::punch_direction() const
    {
      return direction;
    }
  } // namespace postprocess
} // namespace deepdraw
