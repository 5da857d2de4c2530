#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/solver/increment_control.h>
#include <deepdraw/solver/stage_overrides.h>

namespace deepdraw
{
  namespace solver
  {
    namespace
    {
      // The entries of subsection Load stepping, with what each sets: one
      // table serves the declaration, the parsing and a stage's overrides.
      struct Entry
      {
        const char *name;
        const char *default_value;
        double      low, high;
        bool        integer;
        const char *description;
      };

      const Entry entries[] = {
        {"Initial increment",
         "0.1",
         0.,
         1e6,
         false,
         "First increment of the load parameter (0 < value <= 1e6)."},
        {"Minimum increment",
         "1e-6",
         0.,
         1e6,
         false,
         "The run stops with an error if a cut-back would make the "
         "increment smaller than this (0 to Initial increment)."},
        {"Maximum increment",
         "0.1",
         0.,
         1e6,
         false,
         "Upper bound of the increment after regrowth (0 < value <= 1e6)."},
        {"Cut-back factor",
         "0.5",
         0.01,
         0.99,
         false,
         "Factor applied to the increment after a failed attempt."},
        {"Growth factor",
         "1.5",
         1.,
         10.,
         false,
         "Factor applied to the increment after an easy increment (see Easy "
         "increment iterations; 1 to 10)."},
        {"Easy increment iterations",
         "4",
         1,
         1000,
         true,
         "An increment that converged in at most this many Newton iterations "
         "counts as easy."},
        {"Maximum cut-backs",
         "12",
         0,
         100,
         true,
         "Cut-backs allowed for one increment before the run stops (0 to "
         "100)."}};

      // An entry without its default: its range and description.
      OverridableEntry
      overridable(const Entry &entry)
      {
        return {entry.name,
                entry.low,
                entry.high,
                entry.integer,
                entry.description};
      }


      void
      set_value(IncrementControlParameters &parameters,
                const std::string          &name,
                const std::string          &value)
      {
        const double number = Utilities::string_to_double(value);
        if (name == "Initial increment")
          parameters.initial_increment = number;
        else if (name == "Minimum increment")
          parameters.minimum_increment = number;
        else if (name == "Maximum increment")
          parameters.maximum_increment = number;
        else if (name == "Cut-back factor")
          parameters.cut_back_factor = number;
        else if (name == "Growth factor")
          parameters.growth_factor = number;
        else if (name == "Easy increment iterations")
          parameters.easy_iterations = Utilities::string_to_int(value);
        else
          parameters.maximum_cut_backs = Utilities::string_to_int(value);
      }
    } // namespace


    void
    IncrementControlParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      for (const Entry &entry : entries)
        prm.declare_entry(entry.name,
                          entry.default_value,
                          *range_pattern(overridable(entry)),
                          entry.description);
      prm.leave_subsection();
    }


    void
    IncrementControlParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Load stepping");
      for (const Entry &entry : entries)
        set_value(*this, entry.name, prm.get(entry.name));
      prm.leave_subsection();
      check("Load stepping/");
    }


    namespace
    {
      // The entries as a stage's overrides: every one of them.
      std::vector<OverridableEntry>
      overridable_entries()
      {
        std::vector<OverridableEntry> list;
        for (const Entry &entry : entries)
          list.push_back(overridable(entry));
        return list;
      }
    } // namespace


    void
    IncrementControlParameters::declare_overrides(ParameterHandler &prm)
    {
      solver::declare_overrides(prm, "Load stepping", overridable_entries());
    }


    void
    IncrementControlParameters::parse_overrides(ParameterHandler  &prm,
                                                const std::string &prefix)
    {
      solver::parse_overrides(prm,
                              "Load stepping",
                              overridable_entries(),
                              prefix,
                              [this](const std::string &name,
                                     const std::string &value)
                              { set_value(*this, name, value); });
      check(prefix + "Load stepping/");
    }


    std::string
    IncrementControlParameters::first_override(ParameterHandler &prm)
    {
      return solver::first_override(prm,
                                    "Load stepping",
                                    overridable_entries());
    }


    void
    IncrementControlParameters::check(const std::string &prefix) const
    {
      if (!(initial_increment > 0.))
        throw InputError(prefix + "Initial increment must be > 0");
      if (!(maximum_increment > 0.))
        throw InputError(prefix + "Maximum increment must be > 0");
      if (minimum_increment > initial_increment)
        throw InputError(prefix + "Minimum increment must not exceed " + prefix
                         + "Initial increment");
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
