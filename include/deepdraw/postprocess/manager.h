// The post-processors of a run (subsection Postprocess): declares every
// registered one's parameters, makes those of `List of postprocessors` and
// calls them in the listed order (doc/architecture.md, "Post-processors").
#ifndef deepdraw_postprocess_manager_h
#define deepdraw_postprocess_manager_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deepdraw/postprocess/interface.h>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    class Manager
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      // Throws InputError naming the parameter. File names in parameters
      // are relative to input_directory (the prm file's).
      void
      parse_parameters(ParameterHandler  &prm,
                       const std::string &input_directory = ".");

      // Interface::initialize of each (after the set-up and after every
      // mesh change).
      void
      initialize(const SimulationAccess &simulation);
      // The union of their requested loads, sorted.
      std::vector<double>
      requested_loads(const SimulationAccess &simulation) const;
      void
      start(const SimulationAccess &simulation, bool resume);
      // Runs each in the listed order; output_time() is the time spent in
      // this call so far (the statistics row reports it).
      void
      execute(const SimulationAccess &simulation);
      void
      end_stage(const SimulationAccess &simulation);
      double
      output_time() const;

      // Their checkpoint data, by name.
      std::map<std::string, std::string>
      save() const;
      // Restores those listed now; one without data keeps its start.
      void
      load(const std::map<std::string, std::string> &data);

      // The names of the post-processors of this run, in order.
      const std::vector<std::string> &
      names() const;
      // The one of this run with that name; nullptr if it is not listed.
      const Interface *
      find(const std::string &name) const;
      // Their summary lines (Interface::summary), the empty ones left out.
      std::vector<std::string>
      summaries() const;

    private:
      std::vector<std::string>                names_in_order;
      std::vector<std::unique_ptr<Interface>> postprocessors;
      Timer                                   timer;
    };
  } // namespace postprocess
} // namespace deepdraw

#endif
