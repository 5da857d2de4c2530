// The stages of a process as the prm declares them (process::parse_stages,
// D101): without a named stage, one forming stage from 0 to Process/Final
// load with the top-level boundary conditions and load stepping; with
// stages, the ranges follow one another, every stage starts from the
// top-level values and keeps only what it overrides.
#include "../test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deepdraw/problem/model_parameters.h>

using namespace dealii;
using namespace deepdraw;
using deepdraw_test::check_close;
using deepdraw_test::check_true;

namespace
{
  const std::string common = R"(
subsection Boundary conditions
  set Prescribed displacements = zmin: uz = 0; xmax: ux = 2*t
end
subsection Load stepping
  set Initial increment = 0.1
  set Maximum increment = 0.2
end
subsection Process
  set Final load = 3
  set Blank holder force = 100
)";

  std::vector<process::Stage>
  stages_of(const std::string &text)
  {
    ParameterHandler prm;
    problem::ModelParameters::declare_parameters(prm);
    prm.parse_input_from_string(common + text + "end\n");
    problem::ModelParameters parameters;
    parameters.parse_parameters(prm, ".");
    return parameters.stages;
  }
} // namespace


int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const std::vector<process::Stage> one = stages_of("");
  check_true("a prm without stages has one stage", one.size() == 1);
  check_true("it is the forming stage of the top-level parameters",
             one[0].name == "forming" && one[0].all_tools
               && one[0].parameter_prefix.empty()
               && one[0].blank_holder_force == "100");
  check_close("it begins at 0", one[0].start_load, 0., 0.);
  check_close("it ends at Process/Final load", one[0].end_load, 3., 0.);
  check_close("its load stepping ends there too",
              one[0].load_stepping.final_load,
              3.,
              0.);
  // Symmetry planes x, y (the default) and the two entries of the list.
  check_true("its boundary conditions are the top-level ones",
             one[0].prescribed.entries.size() == 4
               && one[0].prescribed.entries[3].item == "xmax: ux = 2*t");

  const std::vector<process::Stage> three = stages_of(R"(
  subsection Stage 1
    set Name       = draw
    set Final load = 1
  end
  subsection Stage 2
    set Name                     = release
    set Final load               = 2.5
    set Tools                    = die, punch
    set Blank holder force       = 0
    set Prescribed displacements = none
    subsection Load stepping
      set Maximum increment = 0.05
    end
    subsection Tool 1
      set Translation = 0; 0; t - 1
    end
  end
  subsection Stage 3
    set Name  = redraw
    set Tools = none
  end
)");
  check_true("three stages", three.size() == 3);
  const double ends[]   = {1., 2.5, 3.};
  const double starts[] = {0., 1., 2.5};
  for (unsigned int s = 0; s < 3; ++s)
  {
    check_close(three[s].name + " begins where the last one ended",
                three[s].start_load,
                starts[s],
                0.);
    check_close(three[s].name
                  + " ends at its Final load (the last at "
                    "Process/Final load)",
                three[s].load_stepping.final_load,
                ends[s],
                0.);
  }
  check_true("stage 1 keeps the top-level values",
             three[0].all_tools && three[0].blank_holder_force == "100"
               && three[0].prescribed.entries.size() == 4
               && three[0].load_stepping.maximum_increment == 0.2);
  check_true("stage 2 names its tools",
             !three[1].all_tools
               && three[1].tools == std::vector<std::string>({"die", "punch"}));
  check_true("stage 2's force and parameter",
             three[1].blank_holder_force == "0"
               && three[1].blank_holder_force_parameter
                    == "Process/Stage 2/Blank holder force");
  check_true("stage 2: 'none' leaves the symmetry planes only",
             three[1].prescribed.entries.size() == 2
               && three[1].prescribed.parameter
                    == "Process/Stage 2/Prescribed displacements");
  check_true("stage 2 overrides one entry of Load stepping",
             three[1].load_stepping.maximum_increment == 0.05
               && three[1].load_stepping.initial_increment == 0.1);
  check_true("stage 2's own translation of tool 1",
             three[1].tool_settings[0].translation == "0; 0; t - 1"
               && three[1].tool_settings[1].translation.empty());
  check_true("stage 3: no tool takes part",
             !three[2].all_tools && three[2].tools.empty());
  return deepdraw_test::summary();
}
