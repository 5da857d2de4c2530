#include <algorithm>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/postprocess/manager.h>
#include <sstream>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      // Today's outputs, the statistics last: its output_s is the time of
      // those before it.
      constexpr char default_list[]
        = "visualization, reactions, tools, punch force, draw-in, thickness "
          "profiles, earing, statistics";

    } // namespace


    void
    Manager::declare_parameters(ParameterHandler &prm)
    {
      std::string documentation
        = "The results of the run, each written by a post-processor, "
          "called in this order after the initial state and every "
          "converged increment:";
      for (const auto &plugin : PostprocessorRegistry::plugins())
        documentation += " '" + plugin.name + "': " + plugin.description;
      prm.enter_subsection("Postprocess");
      prm.declare_entry("List of postprocessors",
                        default_list,
                        Patterns::Anything(),
                        documentation);
      prm.leave_subsection();
      for (const auto &plugin : PostprocessorRegistry::plugins())
        plugin.declare_parameters(prm);
    }


    void
    Manager::parse_parameters(ParameterHandler  &prm,
                              const std::string &input_directory)
    {
      prm.enter_subsection("Postprocess");
      const std::string list = prm.get("List of postprocessors");
      prm.leave_subsection();
      names_in_order.clear();
      postprocessors.clear();
      for (const std::string &name : Utilities::split_string_list(list))
      {
        if (name.empty())
          continue;
        const auto *plugin = PostprocessorRegistry::find(name);
        if (plugin == nullptr)
          throw InputError("Postprocess/List of postprocessors: unknown "
                           "post-processor '"
                           + io::one_line(name)
                           + "'; allowed: " + PostprocessorRegistry::names());
        if (std::count(names_in_order.begin(), names_in_order.end(), name))
          throw InputError("Postprocess/List of postprocessors: '" + name
                           + "' is listed twice");
        names_in_order.push_back(name);
        postprocessors.push_back(plugin->create());
        postprocessors.back()->set_input_directory(input_directory);
        postprocessors.back()->parse_parameters(prm);
      }
    }


    void
    Manager::initialize(const SimulationAccess &simulation)
    {
      for (const auto &postprocessor : postprocessors)
        postprocessor->initialize(simulation);
    }


    std::vector<double>
    Manager::requested_loads(const SimulationAccess &simulation) const
    {
      std::vector<double> loads;
      for (const auto &postprocessor : postprocessors)
      {
        const std::vector<double> requested
          = postprocessor->requested_loads(simulation);
        loads.insert(loads.end(), requested.begin(), requested.end());
      }
      std::sort(loads.begin(), loads.end());
      return loads;
    }


    void
    Manager::start(const SimulationAccess &simulation, const bool resume)
    {
      for (const auto &postprocessor : postprocessors)
        postprocessor->start(simulation, resume);
    }


    void
    Manager::execute(const SimulationAccess &simulation)
    {
      timer.restart();
      for (const auto &postprocessor : postprocessors)
        postprocessor->execute(simulation);
      timer.stop();
    }


    void
    Manager::end_stage(const SimulationAccess &simulation)
    {
      for (const auto &postprocessor : postprocessors)
        postprocessor->end_stage(simulation);
    }


    double
    Manager::output_time() const
    {
      return timer.wall_time();
    }


    std::map<std::string, std::string>
    Manager::save() const
    {
      std::map<std::string, std::string> data;
      for (unsigned int k = 0; k < postprocessors.size(); ++k)
      {
        std::ostringstream stream;
        postprocessors[k]->save(stream);
        if (!stream.str().empty())
          data[names_in_order[k]] = stream.str();
      }
      return data;
    }


    void
    Manager::load(const std::map<std::string, std::string> &data)
    {
      for (unsigned int k = 0; k < postprocessors.size(); ++k)
      {
        const auto entry = data.find(names_in_order[k]);
        if (entry == data.end())
          continue;
        std::istringstream stream(entry->second);
        postprocessors[k]->load(stream);
      }
    }


    const std::vector<std::string> &
    Manager::names() const
    {
      return names_in_order;
    }


    const Interface *
    Manager::find(const std::string &name) const
    {
      for (unsigned int k = 0; k < postprocessors.size(); ++k)
        if (names_in_order[k] == name)
          return postprocessors[k].get();
      return nullptr;
    }


    std::vector<std::string>
    Manager::summaries() const
    {
      std::vector<std::string> lines;
      for (const auto &postprocessor : postprocessors)
        if (const std::string line = postprocessor->summary(); !line.empty())
          lines.push_back(line);
      return lines;
    }
  } // namespace postprocess
} // namespace deepdraw
