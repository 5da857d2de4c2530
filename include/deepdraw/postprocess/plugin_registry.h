// The registry of a kind of plug-in (post-processors, VTU fields): each
// registers itself from its own file through a static initialiser (the
// macros of interface.h and vtu_field.h), the manager makes those the prm
// lists. The library is linked whole (CMakeLists.txt), so that no
// registration is left out.
#ifndef deepdraw_postprocess_plugin_registry_h
#define deepdraw_postprocess_plugin_registry_h

#include <algorithm>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    template <typename Base>
    struct Plugin
    {
      std::string                                     name;
      std::string                                     description;
      std::function<void(dealii::ParameterHandler &)> declare_parameters;
      std::function<std::unique_ptr<Base>()>          create;
    };

    template <typename Base>
    class PluginRegistry
    {
    public:
      // Adds a plug-in; returns true (for the static initialisation).
      static bool
      add(const Plugin<Base> &plugin)
      {
        std::vector<Plugin<Base>> &list = plugins();
        if (find(plugin.name) != nullptr)
          throw std::logic_error("two plug-ins are named '" + plugin.name
                                 + "'");
        list.push_back(plugin);
        return true;
      }

      // In the order of registration.
      static std::vector<Plugin<Base>> &
      plugins()
      {
        static std::vector<Plugin<Base>> list;
        return list;
      }

      // nullptr if none has that name.
      static const Plugin<Base> *
      find(const std::string &name)
      {
        const std::vector<Plugin<Base>> &list  = plugins();
        const auto                       found = std::find_if(list.begin(),
                                        list.end(),
                                        [&](const Plugin<Base> &plugin)
                                        { return plugin.name == name; });
        return found == list.end() ? nullptr : &*found;
      }

      // "a, b, c", for messages.
      static std::string
      names()
      {
        std::string text;
        for (const Plugin<Base> &plugin : plugins())
          text += (text.empty() ? "" : ", ") + plugin.name;
        return text;
      }
    };
  } // namespace postprocess
} // namespace deepdraw

// Registers `classname` (with a static declare_parameters) as a plug-in of
// kind `base` under `name`; in the plug-in's .cc file, after the class.
#define DEEPDRAW_PLUGIN_JOIN_(a, b) a##b
#define DEEPDRAW_PLUGIN_JOIN(a, b) DEEPDRAW_PLUGIN_JOIN_(a, b)
#define DEEPDRAW_REGISTER_PLUGIN(base, classname, name, description) \
  namespace                                                          \
  {                                                                  \
    const bool DEEPDRAW_PLUGIN_JOIN(registered_, __LINE__)           \
      = ::deepdraw::postprocess::PluginRegistry<base>::add(          \
        {name,                                                       \
         description,                                                \
         &classname::declare_parameters,                             \
         []() -> std::unique_ptr<base>                               \
         { return std::make_unique<classname>(); }});                \
  }

#endif
