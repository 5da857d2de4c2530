// ContactCoupling, part 5: how each tool takes part in each stage of the
// process (process::Stage, D101): which tools act, how each is driven, and
// the checks of their expressions over the stage's loads.
#include <algorithm>
#include <cmath>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/io/function_of_load.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace contact
  {
    namespace
    {
      std::string
      tool_slot(const unsigned int k)
      {
        return "Tool " + std::to_string(k + 1) + "/";
      }

      // The force of a force-controlled tool at the stage's check loads:
      // finite and at most max_force, then positive (D176): a force of 0
      // leaves the tool without support, a negative one pulls it off the
      // sheet, and both end in a stagnating Newton iteration.
      void
      check_force(const ToolMotion     &motion,
                  const std::string    &tool_name,
                  const process::Stage &stage)
      {
        const std::vector<double> loads = stage.check_loads();
        for (const bool finite_pass : {true, false})
          for (const double load : loads)
          {
            motion.force->set_time(load);
            const double       force = motion.force->value(Point<1>());
            std::ostringstream text;
            text << std::setprecision(6) << motion.force_parameter << " = '"
                 << io::one_line(motion.force_expression) << "' gives " << force
                 << " N at t = " << load;
            if (finite_pass && !(std::abs(force) <= ContactCoupling::max_force))
            {
              text << "; allowed are finite forces up to "
                   << ContactCoupling::max_force << " N";
              throw InputError(text.str());
            }
            if (!finite_pass && !(force > 0.))
              throw InputError(
                text.str() + " for the force-controlled tool '"
                + io::one_line(tool_name)
                + "'; allowed are forces > 0 N, pressing the tool onto "
                  "the sheet along its Force direction");
          }
      }
    } // namespace


    void
    ContactCoupling::parse_stages(const std::vector<process::Stage> &stages)
    {
      stage_motions.clear();
      for (const process::Stage &stage : stages)
      {
        const std::string &prefix = stage.parameter_prefix;
        // Checked even without a force-controlled tool: a bad expression
        // is an input error wherever it is.
        const std::string &force_parameter = stage.blank_holder_force_parameter;
        const auto force = io::parse_function_of_load(stage.blank_holder_force,
                                                      1,
                                                      force_parameter);
        for (const std::string &name : stage.tools)
          if (std::none_of(definitions.begin(),
                           definitions.end(),
                           [&](const ToolDefinition &tool)
                           { return tool.name == name; }))
            throw InputError(prefix + "Tools: no tool is named '"
                             + io::one_line(name) + "' (Contact/Tool N/Name)");
        std::vector<ToolMotion> tool_motions;
        for (unsigned int k = 0; k < definitions.size(); ++k)
        {
          const ToolDefinition             &tool     = definitions[k];
          const process::ToolStageSettings &settings = stage.tool_settings[k];
          ToolMotion                        motion;
          motion.takes_part
            = stage.all_tools
              || std::count(stage.tools.begin(), stage.tools.end(), tool.name);
          motion.force_controlled = settings.control.empty()
                                      ? tool.force_controlled
                                      : settings.control == "force";
          // A stage that names a control makes the tool rigid or
          // force-controlled; else the spring stays (D187).
          motion.spring_stiffness
            = settings.control.empty() ? tool.spring_stiffness : 0.;
          motion.force            = force;
          motion.force_expression = stage.blank_holder_force;
          motion.force_parameter  = force_parameter;
          if (!settings.translation.empty())
          {
            const std::string parameter = prefix + tool_slot(k) + "Translation";
            if (motion.force_controlled)
              throw InputError(parameter
                               + ": the tool is force-controlled "
                                 "in this stage; a translation is "
                                 "for displacement control");
            motion.translation
              = io::parse_function_of_load(settings.translation, 3, parameter);
            motion.translation_expression = settings.translation;
            motion.translation_parameter  = parameter;
            motion.relative               = true;
          }
          else
          {
            if (!motion.force_controlled && tool.force_controlled)
              throw InputError(prefix + tool_slot(k)
                               + "Translation: the tool turns to "
                                 "displacement control in this stage and "
                                 "needs its translation here");
            motion.translation            = tool.translation;
            motion.translation_expression = tool.translation_expression;
            motion.translation_parameter
              = tool.parameter_prefix + "Translation";
          }
          tool_motions.push_back(motion);
        }
        stage_motions.push_back(tool_motions);
      }
      motions = stage_motions.front();
    }


    void
    ContactCoupling::check_values(const std::vector<process::Stage> &stages,
                                  const double blank_diagonal,
                                  const double length_bound) const
    {
      if (!active())
        return;
      if (!(search_distance <= blank_diagonal))
      {
        std::ostringstream text;
        text << std::setprecision(6)
             << "Contact/Search distance = " << search_distance
             << " mm is larger than the blank: allowed is 0 < Search "
                "distance <= "
             << blank_diagonal << " mm (the diagonal of the blank)";
        throw InputError(text.str());
      }
      for (unsigned int s = 0; s < stages.size(); ++s)
        for (unsigned int k = 0; k < definitions.size(); ++k)
        {
          const ToolMotion &motion = stage_motions[s][k];
          if (!motion.takes_part)
            continue;
          for (const double load : stages[s].check_loads())
          {
            std::ostringstream text;
            text << std::setprecision(6);
            if (motion.force_controlled)
            {
              check_force(motion, definitions[k].name, stages[s]);
              break;
            }
            Vector<double> u(3);
            motion.translation->set_time(load);
            motion.translation->vector_value(Point<1>(), u);
            for (unsigned int d = 0; d < 3; ++d)
            {
              // A stage's own translation starts where the tool stands.
              const bool jump = motion.relative && load == stages[s].start_load
                                && std::abs(u[d]) > 1e-9 * length_bound;
              if (!(std::abs(u[d]) <= length_bound) || jump)
              {
                text << motion.translation_parameter << " = '"
                     << io::one_line(motion.translation_expression)
                     << "' gives u"
                     << "xyz"[d] << " = " << u[d] << " mm at t = " << load
                     << (jump ? "; a stage's translation is measured from "
                                "where the tool stands at the start of the "
                                "stage and must be 0 there"
                              : "; allowed are finite translations up to "
                                  + std::to_string(length_bound) + " mm");
                throw InputError(text.str());
              }
            }
          }
        }
    }


    void
    ContactCoupling::begin_stage(const unsigned int s)
    {
      const std::vector<ToolMotion> previous = motions;
      motions                                = stage_motions[s];
      for (unsigned int k = 0; k < motions.size(); ++k)
        if (motions[k].relative)
          motions[k].origin = tool_list[k].translation();
      // A tool that turns to force control starts at its position along
      // its axis (transfer() carries it into the unknowns): it must stand
      // on that axis.
      for (unsigned int k = 0; k < motions.size(); ++k)
        if (motions[k].force_controlled && !previous[k].force_controlled)
        {
          const Tensor<1, 3> &translation = tool_list[k].translation();
          const Tensor<1, 3>  off_axis
            = translation
              - (translation * definitions[k].axis) * definitions[k].axis;
          if (off_axis.norm() > 1e-9 * (1. + translation.norm()))
            throw std::runtime_error(
              "tool '" + definitions[k].name
              + "' turns to force control at the start of stage "
              + std::to_string(s + 1)
              + " but stands off its Force direction; its translation must "
                "lie along that axis");
        }
    }


    bool
    ContactCoupling::takes_part(const unsigned int k) const
    {
      return motions[k].takes_part;
    }
  } // namespace contact
} // namespace deepdraw
