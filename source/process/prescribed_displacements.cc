#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/io/expression_error.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/process/prescribed_displacements.h>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace deepdraw
{
  namespace process
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
      parse(text,
            symmetry_plane_x,
            symmetry_plane_y,
            "Boundary conditions/Prescribed displacements");
    }


    void
    PrescribedDisplacements::parse(const std::string &text,
                                   const bool         symmetry_plane_x,
                                   const bool         symmetry_plane_y,
                                   const std::string &parameter_name)
    {
      parameter = parameter_name;
      entries.clear();
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
          = std::find(blank::face_names.begin(), blank::face_names.end(), face);
        if (face_it == blank::face_names.end())
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
        entry.boundary_id = face_it - blank::face_names.begin();
        entry.component   = component_it - components.begin();
        entry.expression  = expression;
        entry.item        = item;
        entry.function    = std::make_shared<FunctionParser<3>>(1);
        // muparser reports some errors only on evaluation; its own lines
        // on std::cerr become the reason of our message.
        const std::string error = io::expression_error(
          [&]()
          {
            entry.function->initialize("x,y,z,t",
                                       expression,
                                       std::map<std::string, double>(),
                                       /*time_dependent=*/true);
            entry.function->set_time(0.);
            entry.function->value(Point<3>());
          });
        if (!error.empty())
          throw InputError(parameter + ": cannot evaluate the expression '"
                           + io::one_line(expression) + "' in '"
                           + io::one_line(item)
                           + "' (variables: x, y, z, t): " + error);
        entries.push_back(entry);
      }
    }


    namespace
    {
      std::string
      describe_point(const Point<3> &X, const double load)
      {
        std::ostringstream text;
        text << std::setprecision(6) << "t = " << load << " (x = " << X[0]
             << ", y = " << X[1] << ", z = " << X[2] << ")";
        return text.str();
      }

      // The coordinates 0, h, 2h, ..., extent of n elements, every stride-th
      // one and always the last.
      std::vector<double>
      grid_coordinates(const double       extent,
                       const unsigned int n,
                       const unsigned int stride)
      {
        std::vector<double> coordinates;
        for (unsigned int i = 0; i <= n; i += stride)
          coordinates.push_back(extent * i / n);
        if (n % stride != 0)
          coordinates.push_back(extent);
        return coordinates;
      }
    } // namespace


    void
    PrescribedDisplacements::check_values(
      const blank::BlankGeometry &geometry,
      const std::vector<double>  &loads) const
    {
      // Every expression at the nodes of its face and at every check load
      // (D50): finite, and at most max_relative_displacement blank sizes.
      // Large faces are sampled with a stride so that this stays below
      // about 2e5 evaluations per entry.
      const double bound
        = max_relative_displacement * geometry.largest_extent();
      const unsigned int n[3] = {geometry.elements_along_x,
                                 geometry.elements_along_y,
                                 geometry.layers_through_thickness};
      const double       extent[3]
        = {geometry.length, geometry.width, geometry.thickness};
      for (const PrescribedDisplacement &entry : entries)
      {
        const unsigned int normal = entry.boundary_id / 2;
        const unsigned int a = (normal + 1) % 3, b = (normal + 2) % 3;
        const double       n_points = double(n[a] + 1) * (n[b] + 1);
        const unsigned int stride   = static_cast<unsigned int>(
          std::ceil(std::sqrt(n_points * loads.size() / 2e5)));
        const std::vector<double> along_a
          = grid_coordinates(extent[a], n[a], std::max(1u, stride));
        const std::vector<double> along_b
          = grid_coordinates(extent[b], n[b], std::max(1u, stride));
        Point<3> X;
        X[normal] = entry.boundary_id % 2 == 0 ? 0. : extent[normal];
        for (const double load : loads)
          for (const double xa : along_a)
            for (const double xb : along_b)
            {
              X[a] = xa;
              X[b] = xb;
              // Evaluated directly: value() reports a run-time failure.
              entry.function->set_time(load);
              const double value = entry.function->value(X);
              if (!(std::abs(value) <= bound))
              {
                std::ostringstream text;
                text << std::setprecision(6) << parameter << ": '"
                     << io::one_line(entry.item) << "' gives " << value
                     << " at " << describe_point(X, load)
                     << "; allowed are finite displacements up to " << bound
                     << " mm (" << max_relative_displacement
                     << " times the largest extent of the blank)";
                throw InputError(text.str());
              }
            }
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
      const double value = entry.function->value(X);
      // A value that is not finite stops the run naming the entry (exit
      // code 3, doc/user_guide.md §5): cutting the increment back cannot
      // step around a boundary condition that has no value at this load.
      if (!std::isfinite(value))
        throw std::runtime_error(parameter + ": '" + io::one_line(entry.item)
                                 + "' is not finite at "
                                 + describe_point(X, load));
      return value;
    }
  } // namespace process
} // namespace deepdraw
