#include <deepdraw/process/process_parameters.h>

namespace deepdraw
{
  namespace process
  {
    void
    ProcessParameters::declare_parameters(ParameterHandler  &prm,
                                          const unsigned int n_tool_slots)
    {
      prm.enter_subsection("Process");
      prm.declare_entry("Final load",
                        "1",
                        Patterns::Double(0., 1e6),
                        "End of the run: final value of the load parameter "
                        "t, which starts at 0 (0 to 1e6; 0 writes the initial "
                        "state only; in the "
                        "unit the prm gives t; "
                        "mm of punch travel for the square cup, where t is "
                        "the punch travel: punch Translation = 0; 0; -t); "
                        "in cases without a punch it is the end value of "
                        "the t used in their prescribed displacements and "
                        "tool translations.");
      prm.declare_entry("Blank holder force",
                        "0",
                        Patterns::Anything(),
                        "Force of every tool with Control = force on the "
                        "sheet along its Force direction, an expression of "
                        "the load t (N). For the quarter model of the "
                        "square cup it is the force on the quarter.");
      declare_stage_parameters(prm, n_tool_slots);
      prm.leave_subsection();
    }


    void
    ProcessParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Process");
      final_load         = prm.get_double("Final load");
      blank_holder_force = prm.get("Blank holder force");
      prm.leave_subsection();
    }


    std::vector<double>
    ProcessParameters::check_loads() const
    {
      std::vector<double> loads;
      for (unsigned int k = 0; k <= 10; ++k)
        loads.push_back(k == 10 ? final_load : final_load * k / 10.);
      return loads;
    }
  } // namespace process
} // namespace deepdraw
