#include <algorithm>
#include <cmath>
#include <deepdraw/io/input_error.h>
#include <deepdraw/solver/increment_control.h>

namespace deepdraw
{
  namespace solver
  {
    void
    IncrementControlParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      prm.declare_entry("Initial increment",
                        "0.1",
                        Patterns::Double(0., 1e6),
                        "First increment of the load parameter (0 < value "
                        "<= 1e6).");
      prm.declare_entry("Minimum increment",
                        "1e-6",
                        Patterns::Double(0., 1e6),
                        "The run stops with an error if a cut-back would "
                        "make the increment smaller than this (0 to Initial "
                        "increment).");
      prm.declare_entry("Maximum increment",
                        "0.1",
                        Patterns::Double(0., 1e6),
                        "Upper bound of the increment after regrowth (0 < "
                        "value <= 1e6).");
      prm.declare_entry("Cut-back factor",
                        "0.5",
                        Patterns::Double(0.01, 0.99),
                        "Factor applied to the increment after a failed "
                        "attempt.");
      prm.declare_entry("Growth factor",
                        "1.5",
                        Patterns::Double(1., 10.),
                        "Factor applied to the increment after an easy "
                        "increment (see Easy increment iterations; 1 to "
                        "10).");
      prm.declare_entry("Easy increment iterations",
                        "4",
                        Patterns::Integer(1, 1000),
                        "An increment that converged in at most this many "
                        "Newton iterations counts as easy.");
      prm.declare_entry("Maximum cut-backs",
                        "12",
                        Patterns::Integer(0, 100),
                        "Cut-backs allowed for one increment before the run "
                        "stops (0 to 100).");
      prm.leave_subsection();
    }


    void
    IncrementControlParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      initial_increment = prm.get_double("Initial increment");
      minimum_increment = prm.get_double("Minimum increment");
      maximum_increment = prm.get_double("Maximum increment");
      cut_back_factor   = prm.get_double("Cut-back factor");
      growth_factor     = prm.get_double("Growth factor");
      easy_iterations   = prm.get_integer("Easy increment iterations");
      maximum_cut_backs = prm.get_integer("Maximum cut-backs");
      prm.leave_subsection();

      if (!(initial_increment > 0.))
        throw InputError("Load stepping/Initial increment must be > 0");
      if (!(maximum_increment > 0.))
        throw InputError("Load stepping/Maximum increment must be > 0");
      if (minimum_increment > initial_increment)
        throw InputError("Load stepping/Minimum increment must not exceed "
                         "Load stepping/Initial increment");
    }


    IncrementControl::IncrementControl(
      const IncrementControlParameters &parameters,
      const std::vector<double>        &landing)
        : parameters(parameters)
        , landing_loads(landing)
        , load(0.)
        , increment(std::min(parameters.initial_increment,
                             parameters.maximum_increment))
    {
      landing_loads.push_back(parameters.final_load);
      std::sort(landing_loads.begin(), landing_loads.end());
      // Loads requested twice (a VTU interval and a thickness-profile
      // travel, up to summation round-off) are one landing.
      landing_loads.erase(std::unique(landing_loads.begin(),
                                      landing_loads.end(),
                                      [](const double a, const double b) {
                                        return std::abs(a - b)
                                               < 1e-9 * std::max(1., b);
                                      }),
                          landing_loads.end());
    }


    bool
    IncrementControl::finished() const
    {
      return load >= parameters.final_load * (1. - 1e-12);
    }


    double
    IncrementControl::current_load() const
    {
      return load;
    }


    double
    IncrementControl::next_increment() const
    {
      // Land exactly on the next requested load; avoid a sliver step just
      // before it by stretching up to 1 % .
      for (const double target : landing_loads)
        if (target > load * (1. + 1e-12) + 1e-14)
        {
          if (load + increment * 1.01 >= target)
            return target - load;
          break;
        }
      return increment;
    }


    void
    IncrementControl::accept(const unsigned int newton_iterations)
    {
      const double step = next_increment();
      load += step;
      if (std::abs(load - parameters.final_load)
          < 1e-12 * std::max(1., parameters.final_load))
        load = parameters.final_load;
      cut_backs = 0;
      if (newton_iterations <= parameters.easy_iterations)
        increment = std::min(increment * parameters.growth_factor,
                             parameters.maximum_increment);
    }


    bool
    IncrementControl::cut_back()
    {
      ++cut_backs;
      increment = next_increment() * parameters.cut_back_factor;
      return increment >= parameters.minimum_increment
             && cut_backs <= parameters.maximum_cut_backs;
    }


    unsigned int
    IncrementControl::cut_backs_of_current_increment() const
    {
      return cut_backs;
    }


    IncrementControl::State
    IncrementControl::state() const
    {
      return {load, increment};
    }


    void
    IncrementControl::restore(const State &state)
    {
      load      = state.load;
      increment = state.increment;
      cut_backs = 0;
    }
  } // namespace solver
} // namespace deepdraw
