#include <algorithm>
#include <deal.II/base/utilities.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/problem/blank_geometry.h>
#include <deepdraw/problem/prescribed_displacements.h>

namespace deepdraw
{
  namespace problem
  {
    void
    PrescribedDisplacements::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry(
        "Prescribed displacements",
        "",
        Patterns::Anything(),
        "Semicolon-separated list of 'FACE: COMPONENT = EXPRESSION', FACE one "
        "of xmin, xmax, ymin, ymax, zmin, zmax (the faces of the blank), "
        "COMPONENT one of ux, uy, uz, EXPRESSION a function of the initial "
        "coordinates x, y, z (mm) and the load parameter t, in mm, e.g. "
        "'xmin: ux = 0; xmax: ux = 10*(exp(0.5*t)-1)'. Symmetry planes add "
        "'xmin: ux = 0' and 'ymin: uy = 0'. Later entries win where two "
        "constrain the same node and component.");
      prm.leave_subsection();
    }


    void
    PrescribedDisplacements::parse_parameters(ParameterHandler &prm,
                                              const bool symmetry_plane_x,
                                              const bool symmetry_plane_y)
    {
      prm.enter_subsection("Boundary conditions");
      const std::string text = prm.get("Prescribed displacements");
      prm.leave_subsection();

      const std::string parameter
        = "Boundary conditions/Prescribed displacements";
      std::vector<std::string> items;
      if (symmetry_plane_x)
        items.emplace_back("xmin: ux = 0");
      if (symmetry_plane_y)
        items.emplace_back("ymin: uy = 0");
      for (const std::string &item : Utilities::split_string_list(text, ';'))
        if (!item.empty())
          items.push_back(item);

      const std::vector<std::string> components = {"ux", "uy", "uz"};
      for (const std::string &item : items)
      {
        const auto colon = item.find(':');
        const auto equal = item.find('=');
        if (colon == std::string::npos || equal == std::string::npos
            || equal < colon)
          throw InputError(parameter + ": cannot read '" + item
                           + "'; expected 'FACE: COMPONENT = EXPRESSION'");
        const std::string face = Utilities::trim(item.substr(0, colon));
        const std::string component
          = Utilities::trim(item.substr(colon + 1, equal - colon - 1));
        const std::string expression = Utilities::trim(item.substr(equal + 1));

        const auto face_it
          = std::find(face_names.begin(), face_names.end(), face);
        if (face_it == face_names.end())
          throw InputError(parameter + ": unknown face '" + face + "' in '"
                           + item
                           + "'; allowed: xmin, xmax, ymin, ymax, zmin, zmax");
        const auto component_it
          = std::find(components.begin(), components.end(), component);
        if (component_it == components.end())
          throw InputError(parameter + ": unknown component '" + component
                           + "' in '" + item + "'; allowed: ux, uy, uz");
        if (expression.empty())
          throw InputError(parameter + ": empty expression in '" + item + "'");

        PrescribedDisplacement entry;
        entry.boundary_id = face_it - face_names.begin();
        entry.component   = component_it - components.begin();
        entry.expression  = expression;
        entry.function    = std::make_shared<FunctionParser<3>>(1);
        try
        {
          entry.function->initialize("x,y,z,t",
                                     expression,
                                     std::map<std::string, double>(),
                                     /*time_dependent=*/true);
          // muparser reports some errors only on evaluation.
          entry.function->set_time(0.);
          entry.function->value(Point<3>());
        }
        catch (...)
        {
          throw InputError(parameter + ": cannot evaluate the expression '"
                           + expression + "' in '" + item
                           + "' (variables: x, y, z, t)");
        }
        entries.push_back(entry);
      }
    }


    double
    PrescribedDisplacements::value(const PrescribedDisplacement &entry,
                                   const Point<3>               &X,
                                   const double                  load) const
    {
      // FunctionParser keeps its time as state: not thread safe, called
      // serially by the problem.
      entry.function->set_time(load);
      return entry.function->value(X);
    }
  } // namespace problem
} // namespace deepdraw
