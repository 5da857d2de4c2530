// Load stepping with cut-back and regrowth (doc/theory.md §5): proposes the
// next increment of the load parameter, lands exactly on requested loads
// (output points, the end), halves after a divergence and grows after easy
// increments.
#ifndef deepdraw_solver_increment_control_h
#define deepdraw_solver_increment_control_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace solver
  {
    using namespace dealii;

    struct IncrementControlParameters
    {
      // End of the run; not read from subsection Load stepping but set by
      // the owner (Process/Final load).
      double       final_load        = 1.;
      double       initial_increment = 0.1;
      double       minimum_increment = 1e-6;
      double       maximum_increment = 0.1;
      double       cut_back_factor   = 0.5;
      double       growth_factor     = 1.5;
      unsigned int easy_iterations   = 4;
      unsigned int maximum_cut_backs = 12;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      // A stage's subsection Load stepping (process::Stage): the same
      // entries, empty by default; parse_overrides() replaces the values
      // that are not empty, checked as parse_parameters() checks them.
      // prefix names the stage in messages ("Process/Stage 2/").
      static void
      declare_overrides(ParameterHandler &prm);
      void
      parse_overrides(ParameterHandler &prm, const std::string &prefix);
      // The name of the first override that is not empty, or "".
      static std::string
      first_override(ParameterHandler &prm);

    private:
      // Throws InputError (prefix + the parameter) for inconsistent values.
      void
      check(const std::string &prefix) const;
    };

    class IncrementControl
    {
    public:
      IncrementControl(const IncrementControlParameters &parameters,
                       const std::vector<double>        &landing_loads);

      bool
      finished() const;
      double
      current_load() const;
      // Size of the next attempt, clipped to land on the next landing load.
      double
      next_increment() const;
      // After a converged increment of the size next_increment() returned.
      void
      accept(unsigned int newton_iterations);
      // After a failed attempt; returns false if the increment would fall
      // below the minimum or the cut-backs of one increment are exhausted.
      bool
      cut_back();
      unsigned int
      cut_backs_of_current_increment() const;

      // What a restart needs (between increments): the load reached and
      // the size of the next attempt before it is clipped to a landing.
      struct State
      {
        double load      = 0.;
        double increment = 0.;
      };
      State
      state() const;
      void
      restore(const State &state);

    private:
      IncrementControlParameters parameters;
      std::vector<double>        landing_loads;
      double                     load;
      double                     increment;
      unsigned int               cut_backs = 0;
    };
  } // namespace solver
} // namespace deepdraw

#endif
