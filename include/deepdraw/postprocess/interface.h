// A post-processor: one result of a run, as a component that declares and
// parses its own parameters and reads the simulation through
// SimulationAccess (doc/architecture.md, "Post-processors"; the model is
// ASPECT's postprocess/interface.h). The ones to run are listed in
// subsection Postprocess, `List of postprocessors`; each registers itself
// with DEEPDRAW_REGISTER_POSTPROCESSOR in its own file.
#ifndef deepdraw_postprocess_interface_h
#define deepdraw_postprocess_interface_h

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/postprocess/plugin_registry.h>
#include <deepdraw/postprocess/simulation_access.h>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    class Interface
    {
    public:
      virtual ~Interface() = default;

      // Declares its parameters; the registration calls the derived
      // class's, and this one (none) where it has none.
      static void
      declare_parameters(ParameterHandler &)
      {
      }

      // Its parameters. Throws InputError naming the parameter.
      virtual void
      parse_parameters(ParameterHandler &prm);

      // After the model is set up, before anything is written: the set-up
      // that needs the mesh or the tools (InputError if the parameters do
      // not fit them), and again after every mesh change.
      virtual void
      initialize(const SimulationAccess &simulation);

      // Loads the load stepping must land on exactly for this result.
      virtual std::vector<double>
      requested_loads(const SimulationAccess &simulation) const;

      // Opens its files in the output directory (resume: appends to them).
      virtual void
      start(const SimulationAccess &simulation, bool resume);

      // The initial state (not on a resume) and every converged increment.
      virtual void
      execute(const SimulationAccess &simulation)
        = 0;

      // After the last increment of a stage.
      virtual void
      end_stage(const SimulationAccess &simulation);

      // What a checkpoint keeps of it, and its restoration (the same
      // bytes).
      virtual void
      save(std::ostream &stream) const;
      virtual void
      load(std::istream &stream);

      // A line for the end of the run (ConsoleReport::finished, also with
      // --quiet), or nothing (the default).
      virtual std::string
      summary() const;

      // The directory of the prm file, set by the Manager before
      // parse_parameters: file names in parameters are relative to it.
      void
      set_input_directory(const std::string &directory);

    protected:
      const std::string &
      input_directory() const;

    private:
      std::string prm_directory = ".";
    };

    using PostprocessorRegistry = PluginRegistry<Interface>;
  } // namespace postprocess
} // namespace deepdraw

// In the post-processor's .cc file, after the class: registers class
// `classname` under `name` (the name in List of postprocessors) with its
// description.
#define DEEPDRAW_REGISTER_POSTPROCESSOR(classname, name, description) \
  DEEPDRAW_REGISTER_PLUGIN(::deepdraw::postprocess::Interface,        \
                           classname,                                 \
                           name,                                      \
                           description)

#endif
