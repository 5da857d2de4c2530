// A stage of the forming process (doc/user_guide.md §2.6, D101): a range of
// the load parameter t with its own kind, the tools that take part and how
// each moves or is loaded, the boundary conditions and the load stepping.
// The stages run one after the other; t runs on through them, so every
// expression of t keeps its meaning. They are declared in the slots
// `subsection Process / subsection Stage 1 … 4`; a prm without named stages
// is one forming stage from 0 to Process/Final load.
#ifndef deepdraw_process_stage_h
#define deepdraw_process_stage_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/process/prescribed_displacements.h>
#include <deepdraw/process/release_supports.h>
#include <deepdraw/solver/increment_control.h>
#include <deepdraw/solver/newton_parameters.h>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace process
  {
    using namespace dealii;

    constexpr unsigned int n_stage_slots = 4;

    // How one tool slot moves in a stage, where the stage changes it;
    // empty strings keep what subsection Contact/Tool N declares.
    struct ToolStageSettings
    {
      // "", "displacement" or "force".
      std::string control;
      // Displacement control: three expressions of t separated by ';', the
      // translation from where the tool stands at the start of the stage
      // (so 0 there).
      std::string translation;
    };

    struct Stage
    {
      enum class Kind
      {
        forming,
        // Springback (D150): the tools leave and the forces that held the
        // sheet are released, or the tools move away.
        release
      };
      enum class ReleaseMethod
      {
        // The nodal forces on the sheet at the end of the stage before
        // (contact, friction, the reactions of the faces it held) become
        // loads, ramped to zero over the stage's load range.
        force,
        // The tools move away along the stage's translations, contact
        // active, until every pair is open.
        tool_retraction
      };

      std::string name;
      Kind        kind       = Kind::forming;
      double      start_load = 0.;
      double      end_load   = 1.;
      // Every tool takes part, or those named.
      bool                     all_tools = true;
      std::vector<std::string> tools;
      // Force of the force-controlled tools, an expression of t (N), and
      // the parameter it comes from (for messages).
      std::string blank_holder_force           = "0";
      std::string blank_holder_force_parameter = "Process/Blank holder force";
      PrescribedDisplacements prescribed;
      // A release stage: how, and the points that stop the sheet's
      // rigid-body modes (with the symmetry planes and the prescribed
      // faces).
      ReleaseMethod               release_method = ReleaseMethod::force;
      std::vector<ReleaseSupport> supports;
      // Its final_load is end_load.
      solver::IncrementControlParameters load_stepping;
      // Subsection Newton with the stage's overrides (D208).
      solver::NewtonParameters newton;
      // Viscous stabilization c(t) (D208), 0 at end_load; null: none.
      // Evaluated with set_time(t), as every expression of t.
      std::shared_ptr<FunctionParser<1>> viscous_stabilization;
      // c(t) at load t (0 without a stabilization).
      double
      viscous_coefficient(double load) const;
      // One per tool slot.
      std::vector<ToolStageSettings> tool_settings;
      // "Process/Stage N/" for messages; empty for the stage of a prm
      // without stages (its parameters are the top-level ones).
      std::string parameter_prefix;

      // The loads at which its expressions are checked when the input is
      // read (D50): 11 loads from start_load to end_load.
      std::vector<double>
      check_loads() const;
      // A release stage whose forces are released as loads.
      bool
      releases_forces() const;
    };

    std::string
    to_string(Stage::Kind kind);

    // Declares subsection Stage 1 … Stage n_stage_slots in the current
    // subsection (Process); n_tool_slots tool subsections in each.
    void
    declare_stage_parameters(ParameterHandler &prm, unsigned int n_tool_slots);

    // What a stage takes from the rest of the prm where it sets nothing.
    struct StageDefaults
    {
      // Process/Final load: where the last stage ends.
      double                             final_load = 1.;
      std::string                        blank_holder_force;
      PrescribedDisplacements            boundary_conditions;
      solver::IncrementControlParameters load_stepping;
      solver::NewtonParameters           newton;
      // Of subsection Geometry (the symmetry planes add prescribed
      // displacements).
      bool         symmetry_plane_x = true;
      bool         symmetry_plane_y = true;
      unsigned int n_tool_slots     = 0;
    };

    // Reads the stages from the current subsection (Process). Without a
    // named stage: one forming stage from 0 to the final load of the
    // defaults. Throws InputError naming the parameter.
    std::vector<Stage>
    parse_stages(ParameterHandler &prm, const StageDefaults &defaults);
  } // namespace process
} // namespace deepdraw

#endif
