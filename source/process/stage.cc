#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/function_of_load.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/process/stage.h>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace process
  {
    namespace
    {
      std::string
      slot_name(const unsigned int slot)
      {
        return "Stage " + std::to_string(slot + 1);
      }

      std::string
      number(const double value)
      {
        std::ostringstream text;
        text << std::setprecision(10) << value;
        return text.str();
      }

      // Release method and Release supports (D150, D151): only in a release
      // stage; a force release removes every tool, so it takes no tool
      // settings.
      void
      parse_release(ParameterHandler &prm, Stage &stage)
      {
        const std::string &prefix  = stage.parameter_prefix;
        const std::string  method  = prm.get("Release method");
        const std::string  support = prm.get("Release supports");
        if (stage.kind != Stage::Kind::release)
        {
          if (method != "force" || !Utilities::trim(support).empty())
            throw InputError(
              prefix
              + (method != "force" ? "Release method" : "Release supports")
              + " is set, but the stage is not a release "
                "(Kind = release)");
          return;
        }
        stage.release_method = method == "tool retraction"
                                 ? Stage::ReleaseMethod::tool_retraction
                                 : Stage::ReleaseMethod::force;
        stage.supports
          = parse_release_supports(support, prefix + "Release supports");
        if (stage.release_method == Stage::ReleaseMethod::tool_retraction)
          return;
        const std::string tools = Utilities::trim(prm.get("Tools"));
        if (tools != "all" && tools != "none")
          throw InputError(prefix + "Tools = '" + io::one_line(tools)
                           + "': a force release removes every tool; allowed "
                             "are 'all' or 'none' (or Release method = tool "
                             "retraction)");
        stage.all_tools = false;
        stage.tools.clear();
        for (unsigned int k = 0; k < stage.tool_settings.size(); ++k)
          if (!stage.tool_settings[k].control.empty()
              || !stage.tool_settings[k].translation.empty())
            throw InputError(prefix + "Tool " + std::to_string(k + 1) + "/"
                             + (stage.tool_settings[k].control.empty()
                                  ? "Translation"
                                  : "Control")
                             + " is set, but a force release removes every "
                               "tool (Release method = tool retraction moves "
                               "them)");
      }


      // Viscous stabilization (D208): an expression of t, >= 0 over the
      // stage and 0 at its end, so that the stage ends in equilibrium
      // without the viscous forces.
      std::shared_ptr<FunctionParser<1>>
      parse_viscous_stabilization(ParameterHandler &prm, const Stage &stage)
      {
        const std::string text
          = Utilities::trim(prm.get("Viscous stabilization"));
        if (text.empty())
          return nullptr;
        const std::string parameter
          = stage.parameter_prefix + "Viscous stabilization";
        const auto coefficient = io::parse_function_of_load(text, 1, parameter);
        const std::string start
          = parameter + " = '" + io::one_line(text) + "' gives ";
        for (const double t : stage.check_loads())
        {
          coefficient->set_time(t);
          const double value = coefficient->value(Point<1>());
          if (!std::isfinite(value) || value < 0.)
            throw InputError(start + number(value) + " at t = " + number(t)
                             + ": allowed are values >= 0");
        }
        coefficient->set_time(stage.end_load);
        const double last = coefficient->value(Point<1>());
        if (last != 0.)
          throw InputError(start + number(last) + " at the stage's end, t = "
                           + number(stage.end_load)
                           + ": it must be 0 there, so that the stage ends "
                             "in equilibrium without viscous forces");
        return coefficient;
      }


      // The entries of one named stage slot (the current subsection).
      Stage
      parse_stage(ParameterHandler    &prm,
                  const std::string   &prefix,
                  const double         start_load,
                  const double         end_load,
                  const StageDefaults &defaults)
      {
        Stage stage;
        stage.parameter_prefix = prefix;
        stage.name             = Utilities::trim(prm.get("Name"));
        stage.kind       = prm.get("Kind") == "release" ? Stage::Kind::release
                                                        : Stage::Kind::forming;
        stage.start_load = start_load;
        stage.end_load   = end_load;
        const std::string tools = Utilities::trim(prm.get("Tools"));
        stage.all_tools         = tools == "all";
        if (tools != "all" && tools != "none")
          for (const std::string &name : Utilities::split_string_list(tools))
            if (!name.empty())
              stage.tools.push_back(name);
        const std::string force
          = Utilities::trim(prm.get("Blank holder force"));
        stage.blank_holder_force
          = force.empty() ? defaults.blank_holder_force : force;
        if (!force.empty())
          stage.blank_holder_force_parameter = prefix + "Blank holder force";
        const std::string conditions
          = Utilities::trim(prm.get("Prescribed displacements"));
        if (conditions.empty())
          stage.prescribed = defaults.boundary_conditions;
        else
          stage.prescribed.parse(conditions == "none" ? std::string()
                                                      : conditions,
                                 defaults.symmetry_plane_x,
                                 defaults.symmetry_plane_y,
                                 prefix + "Prescribed displacements");
        stage.load_stepping = defaults.load_stepping;
        stage.load_stepping.parse_overrides(prm, prefix);
        stage.load_stepping.final_load = end_load;
        stage.newton                   = defaults.newton;
        stage.newton.parse_overrides(prm, prefix);
        for (unsigned int slot = 0; slot < defaults.n_tool_slots; ++slot)
        {
          prm.enter_subsection("Tool " + std::to_string(slot + 1));
          stage.tool_settings.push_back(
            {Utilities::trim(prm.get("Control")),
             Utilities::trim(prm.get("Translation"))});
          prm.leave_subsection();
        }
        parse_release(prm, stage);
        stage.viscous_stabilization = parse_viscous_stabilization(prm, stage);
        return stage;
      }
    } // namespace


    std::vector<double>
    Stage::check_loads() const
    {
      std::vector<double> loads;
      for (unsigned int k = 0; k <= 10; ++k)
        loads.push_back(
          k == 10 ? end_load : start_load + (end_load - start_load) * k / 10.);
      return loads;
    }


    std::string
    to_string(const Stage::Kind kind)
    {
      switch (kind)
      {
        case Stage::Kind::forming:
          return "forming";
        case Stage::Kind::release:
          return "release";
      }
      return "forming";
    }


    double
    Stage::viscous_coefficient(const double load) const
    {
      if (viscous_stabilization == nullptr)
        return 0.;
      viscous_stabilization->set_time(load);
      return viscous_stabilization->value(Point<1>());
    }


    bool
    Stage::releases_forces() const
    {
      return kind == Kind::release && release_method == ReleaseMethod::force;
    }


    void
    declare_stage_parameters(ParameterHandler  &prm,
                             const unsigned int n_tool_slots)
    {
      for (unsigned int slot = 0; slot < n_stage_slots; ++slot)
      {
        prm.enter_subsection(slot_name(slot));
        prm.declare_entry("Name",
                          "",
                          Patterns::Anything(),
                          "Name of the stage; an empty name leaves the slot "
                          "unused. Stages run in the order of their slots, "
                          "from Stage 1 on, without gaps; a prm without "
                          "named stages is one forming stage from 0 to "
                          "Process/Final load.");
        prm.declare_entry("Kind",
                          "forming",
                          Patterns::Selection("forming|release"),
                          "What the stage does: 'forming', the tools move "
                          "and press as given and the sheet follows; "
                          "'release', the sheet springs back (Release "
                          "method), held only by the symmetry planes, the "
                          "stage's Prescribed displacements and its Release "
                          "supports, which must stop every rigid-body mode.");
        prm.declare_entry("Release method",
                          "force",
                          Patterns::Selection("force|tool retraction"),
                          "A release stage: 'force', every tool leaves and "
                          "the forces on the sheet at the end of the stage "
                          "before (contact, friction, the reactions of the "
                          "faces this stage no longer holds) become nodal "
                          "loads, ramped linearly to zero over the stage's "
                          "load range; 'tool retraction', the tools move "
                          "away along the stage's Tool N/Translation with "
                          "contact active, and every pair must be open at "
                          "the stage's end.");
        prm.declare_entry("Release supports",
                          "",
                          Patterns::Anything(),
                          "A release stage: points whose nearest sheet node "
                          "(at the stage's start, current coordinates) is "
                          "held where it stands in the given directions, "
                          "'point(X, Y, Z): COMPONENTS; ...' with COMPONENTS "
                          "one or more of ux, uy, uz, e.g. the 3-2-1 support "
                          "'point(0, 0, 0): ux uy uz; point(50, 0, 0): uy "
                          "uz; point(0, 30, 0): uz' (mm). With the symmetry "
                          "planes and the Prescribed displacements they must "
                          "stop the 3 translations and 3 rotations of the "
                          "sheet.");
        prm.declare_entry(
          "Viscous stabilization",
          "",
          Patterns::Anything(),
          "Empty: none. Otherwise c(t), an expression of t (>= 0, and 0 at "
          "the stage's end): every free displacement dof carries the force "
          "c V du/dt against its motion, with V its node's share of the "
          "sheet's initial volume (mm^3), du its displacement in the "
          "increment (mm) and dt the increment of t; c in N per mm^4 per "
          "unit of t. For a tool retraction, where the sheet hangs on a few "
          "sliding contacts; the states before the stage's end carry these "
          "forces, the last one does not (doc/theory.md §5.7, D208).");
        prm.declare_entry("Final load",
                          "",
                          Patterns::Anything(),
                          "The load t at which the stage ends; it begins "
                          "where the stage before it ended (the first at "
                          "0). The last stage ends at Process/Final load "
                          "and leaves this empty.");
        prm.declare_entry("Tools",
                          "all",
                          Patterns::Anything(),
                          "The tools that take part in the stage: 'all', "
                          "'none' or a comma-separated list of their names "
                          "(Contact/Tool N/Name). A tool left out has no "
                          "contact with the sheet in this stage: its "
                          "contact forces are removed at the start of the "
                          "stage.");
        prm.declare_entry("Blank holder force",
                          "",
                          Patterns::Anything(),
                          "Force of the force-controlled tools in this "
                          "stage, an expression of t (N); empty: "
                          "Process/Blank holder force.");
        prm.declare_entry("Prescribed displacements",
                          "",
                          Patterns::Anything(),
                          "The boundary conditions of this stage, in the "
                          "form of Boundary conditions/Prescribed "
                          "displacements; empty: that list; 'none': none "
                          "beside the symmetry planes. A dof prescribed "
                          "from this stage on moves by the change of its "
                          "expression from where it is at the stage's "
                          "start.");
        solver::IncrementControlParameters::declare_overrides(prm);
        solver::NewtonParameters::declare_overrides(prm);
        for (unsigned int tool = 0; tool < n_tool_slots; ++tool)
        {
          prm.enter_subsection("Tool " + std::to_string(tool + 1));
          prm.declare_entry("Control",
                            "",
                            Patterns::Selection("|displacement|force"),
                            "How the tool of Contact/Tool "
                              + std::to_string(tool + 1)
                              + " is driven in this stage; empty: as "
                                "declared there.");
          prm.declare_entry("Translation",
                            "",
                            Patterns::Anything(),
                            "Displacement control in this stage: the "
                            "translation of the tool from where it stands "
                            "at the start of the stage, three expressions "
                            "of t separated by ';' (mm), 0 at the stage's "
                            "start; empty: the translation declared in "
                            "Contact/Tool "
                              + std::to_string(tool + 1)
                              + " (from the tool's file position).");
          prm.leave_subsection();
        }
        prm.leave_subsection();
      }
    }


    namespace
    {
      // An unnamed slot must keep every entry at its default: a setting
      // there would silently not apply.
      void
      check_unused_slot(ParameterHandler  &prm,
                        const std::string &prefix,
                        const unsigned int n_tool_slots)
      {
        std::vector<std::pair<std::string, std::string>> entries
          = {{"Kind", "forming"},
             {"Final load", ""},
             {"Tools", "all"},
             {"Blank holder force", ""},
             {"Prescribed displacements", ""},
             {"Release method", "force"},
             {"Release supports", ""},
             {"Viscous stabilization", ""}};
        const auto check = [&](const std::string &path)
        {
          for (const auto &[name, default_value] : entries)
            if (Utilities::trim(prm.get(name)) != default_value)
              throw InputError(prefix + path + name
                               + " is set, but the stage has no Name (an "
                                 "unnamed slot is unused)");
        };
        check("");
        entries = {{"Control", ""}, {"Translation", ""}};
        for (unsigned int tool = 0; tool < n_tool_slots; ++tool)
        {
          prm.enter_subsection("Tool " + std::to_string(tool + 1));
          check("Tool " + std::to_string(tool + 1) + "/");
          prm.leave_subsection();
        }
        const std::string load_stepping
          = solver::IncrementControlParameters::first_override(prm);
        const std::string newton
          = solver::NewtonParameters::first_override(prm);
        if (!load_stepping.empty() || !newton.empty())
          throw InputError(prefix
                           + (load_stepping.empty()
                                ? "Newton/" + newton
                                : "Load stepping/" + load_stepping)
                           + " is set, but the stage has no Name (an "
                             "unnamed slot is unused)");
      }


      // Where a named stage ends: its Final load, the last one at
      // Process/Final load.
      double
      stage_end(ParameterHandler  &prm,
                const std::string &prefix,
                const bool         last,
                const double       final_load,
                const double       start)
      {
        const std::string text = Utilities::trim(prm.get("Final load"));
        if (last && !text.empty())
          throw InputError(prefix + "Final load = '" + io::one_line(text)
                           + "': the last stage ends at Process/Final load; "
                             "leave it empty");
        double end = final_load;
        if (!last)
        {
          try
          {
            end = Utilities::string_to_double(text);
          }
          catch (...)
          {
            throw InputError(prefix + "Final load = '" + io::one_line(text)
                             + "': a stage before the last needs the load "
                               "at which it ends, a number");
          }
        }
        if (!(end > start) || !(end <= 1e6))
          throw InputError(
            (last ? std::string("Process/Final load = ")
                  : prefix + "Final load = ")
            + number(end) + ": " + prefix.substr(8, prefix.size() - 9)
            + (start > 0. ? " begins where the stage before "
                            "it ends, at load "
                          : " begins at load ")
            + number(start) + ", and must end after that (at most at 1e6)");
        return end;
      }
    } // namespace


    std::vector<Stage>
    parse_stages(ParameterHandler &prm, const StageDefaults &defaults)
    {
      std::vector<unsigned int> named;
      for (unsigned int slot = 0; slot < n_stage_slots; ++slot)
      {
        const std::string prefix = "Process/" + slot_name(slot) + "/";
        prm.enter_subsection(slot_name(slot));
        if (!Utilities::trim(prm.get("Name")).empty())
          named.push_back(slot);
        else
          check_unused_slot(prm, prefix, defaults.n_tool_slots);
        prm.leave_subsection();
        if (!named.empty() && named.back() != named.size() - 1)
          throw InputError(prefix
                           + "Name: stages run from Stage 1 on "
                             "without gaps, but "
                           + slot_name(named.size() - 1) + " has no name");
      }

      std::vector<Stage> stages;
      if (named.empty())
      {
        // The process of a prm without stages: the top-level parameters.
        Stage stage;
        stage.name                     = "forming";
        stage.end_load                 = defaults.final_load;
        stage.blank_holder_force       = defaults.blank_holder_force;
        stage.prescribed               = defaults.boundary_conditions;
        stage.load_stepping            = defaults.load_stepping;
        stage.load_stepping.final_load = defaults.final_load;
        stage.newton                   = defaults.newton;
        stage.tool_settings.resize(defaults.n_tool_slots);
        stages.push_back(std::move(stage));
        return stages;
      }

      double start = 0.;
      for (const unsigned int slot : named)
      {
        const std::string prefix = "Process/" + slot_name(slot) + "/";
        prm.enter_subsection(slot_name(slot));
        const double end   = stage_end(prm,
                                     prefix,
                                     slot == named.back(),
                                     defaults.final_load,
                                     start);
        Stage        stage = parse_stage(prm, prefix, start, end, defaults);
        prm.leave_subsection();
        if (stage.kind == Stage::Kind::release && stages.empty())
          throw InputError(prefix
                           + "Kind = release: the first stage has nothing "
                             "to release; a release follows a forming "
                             "stage");
        for (const Stage &other : stages)
          if (other.name == stage.name)
            throw InputError(prefix + "Name = '" + io::one_line(stage.name)
                             + "': another stage has this name");
        stages.push_back(std::move(stage));
        start = end;
      }
      return stages;
    }
  } // namespace process
} // namespace deepdraw
