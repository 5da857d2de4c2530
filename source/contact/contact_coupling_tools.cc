// ContactCoupling, part 1: the tool slots `Contact/Tool 1..4` (their
// parameters) and the tools they make (square-cup builder, tool files or
// STEP / IGES files, doc/tool_files.md);
// the pairs, their assembly and the holder equation are in
// contact_coupling.cc.
#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/geometry/cad_tool_reader.h>
#include <deepdraw/geometry/tool_file.h>
#include <deepdraw/io/function_of_load.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/regular_file.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace deepdraw
{
  namespace contact
  {
    namespace
    {
      std::string
      slot_name(const unsigned int slot)
      {
        return "Tool " + std::to_string(slot + 1);
      }

      Tensor<1, 3>
      parse_direction(const std::string &text, const std::string &parameter)
      {
        const std::vector<std::string> parts
          = Utilities::split_string_list(text, ',');
        Tensor<1, 3> direction;
        try
        {
          if (parts.size() != 3)
            throw std::invalid_argument("count");
          for (unsigned int d = 0; d < 3; ++d)
            direction[d] = Utilities::string_to_double(parts[d]);
        }
        catch (...)
        {
          throw InputError(parameter + " = '" + text
                           + "': expected three numbers 'ax, ay, az'");
        }
        // Scaled by its largest component first: the norm of (1e300, 1e300,
        // 0) overflows, and dividing by inf would give the zero vector.
        // string_to_double reads "nan" and "inf".
        double largest = 0.;
        bool   finite  = true;
        for (unsigned int d = 0; d < 3; ++d)
        {
          finite  = finite && std::isfinite(direction[d]);
          largest = std::max(largest, std::abs(direction[d]));
        }
        if (!finite)
          throw InputError(parameter + " = '" + io::one_line(text)
                           + "': expected three finite numbers");
        if (!(largest > 0.))
          throw InputError(parameter + " = '" + io::one_line(text)
                           + "': the direction must not be zero");
        direction /= largest;
        return direction / direction.norm();
      }

      // Names become CSV column names (tools.csv) and file names
      // (tool_<name>-NNNNN.vtu): no separators of either.
      void
      check_tool_name(const std::string &name, const std::string &parameter)
      {
        for (const char c : name)
          if (c == ',' || c == '"' || c == '/' || c == '\\'
              || static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
            throw InputError(parameter + " = '" + io::one_line(name)
                             + "': a tool name must not contain commas, "
                               "quotes, slashes, backslashes or control "
                               "characters (it names CSV columns and "
                               "files)");
      }

    } // namespace


    void
    ContactCoupling::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      contact::ContactParameters::declare_parameters(prm);
      prm.declare_entry("Search distance",
                        "2",
                        Patterns::Double(0., 1e4),
                        "Nodes farther than this from a tool (mm) are not "
                        "projected onto it and count as open; > 0 and, with "
                        "tools, at most the diagonal of the blank.");
      for (unsigned int slot = 0; slot < n_tool_slots; ++slot)
      {
        prm.enter_subsection(slot_name(slot));
        prm.declare_entry("Name",
                          "",
                          Patterns::Anything(),
                          "Name of the tool; an empty name leaves the slot "
                          "unused. Names must differ and must not contain "
                          "commas, quotes, slashes or backslashes (they name "
                          "the columns of tools.csv and the tool VTU files).");
        prm.declare_entry("Geometry",
                          "file",
                          Patterns::Selection("file|cad|square cup punch|"
                                              "square cup die|"
                                              "square cup blank holder"),
                          "Where the tool surface comes from: a tool file "
                          "(see doc/tool_files.md), a STEP or IGES file "
                          "(cad), or one of the square-cup tools built from "
                          "subsection Tools.");
        prm.declare_entry("File",
                          "",
                          Patterns::Anything(),
                          "Tool file (Geometry = file) or STEP / IGES file "
                          "(Geometry = cad: .step, .stp, .iges, .igs), "
                          "relative to the directory of the parameter file.");
        prm.declare_entry("Length unit",
                          "file",
                          Patterns::Selection("file|mm|cm|m|inch"),
                          "Geometry = cad: 'file' takes the length unit the "
                          "CAD file declares (converted to mm); mm, cm, m, "
                          "inch: the file's numbers are in that unit, "
                          "whatever it declares.");
        prm.declare_entry("Normals",
                          "automatic",
                          Patterns::Selection("automatic|as in file|reversed"),
                          "Geometry = cad: 'automatic' turns every connected "
                          "set of faces whose normals point away from the "
                          "sheet on average (Sheet surface top: the tool is "
                          "above the sheet, bottom: below) to face it; a "
                          "closed shell keeps its outward normals. 'as in "
                          "file': the faces' normals as written (outward "
                          "for a solid); 'reversed': all of them reversed.");
        prm.declare_entry("Sheet surface",
                          "top",
                          Patterns::Selection("top|bottom"),
                          "Surface of the sheet the tool acts on: every "
                          "node of it forms a contact pair with the tool.");
        prm.declare_entry("Control",
                          "displacement",
                          Patterns::Selection("displacement|force|spring"),
                          "'displacement': the tool follows Translation; "
                          "'force': its position along Force direction is "
                          "an unknown such that the contact forces on it "
                          "add up to Process/Blank holder force; 'spring': "
                          "Translation is its rest position, and a spring "
                          "of Spring stiffness behind it lets it yield "
                          "along Force direction: the contact forces on "
                          "it add up to Spring stiffness times its "
                          "distance from the rest position (a holder on an "
                          "elastic press or cushion, D187).");
        prm.declare_entry("Spring stiffness",
                          "0",
                          Patterns::Double(0., max_force),
                          "Control = spring: the stiffness of the spring "
                          "behind the tool (N/mm), of the model: a quarter "
                          "model takes a quarter of the whole tool's; "
                          "> 0 with Control = spring (a stiffer tool than "
                          "the bound is rigid: Control = displacement).");
        prm.declare_entry("Translation",
                          "0; 0; 0",
                          Patterns::Anything(),
                          "Displacement control: translation of the tool "
                          "from its file position as three expressions of "
                          "the load t separated by ';' (mm).");
        prm.declare_entry("Force direction",
                          "0, 0, -1",
                          Patterns::Anything(),
                          "Force control: axis along which the tool moves "
                          "and presses on the sheet.");
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }


    void
    ContactCoupling::parse_parameters(ParameterHandler  &prm,
                                      const std::string &prm_directory)
    {
      prm.enter_subsection("Contact");
      parameters.parse_parameters(prm);
      search_distance = prm.get_double("Search distance");
      if (!(search_distance > 0.))
        throw InputError("Contact/Search distance must be > 0 (mm), got "
                         + prm.get("Search distance"));
      definitions.clear();
      for (unsigned int slot = 0; slot < n_tool_slots; ++slot)
      {
        prm.enter_subsection(slot_name(slot));
        const std::string prefix = "Contact/" + slot_name(slot) + "/";
        ToolDefinition    tool;
        tool.name = Utilities::trim(prm.get("Name"));
        if (!tool.name.empty())
        {
          check_tool_name(tool.name, prefix + "Name");
          // Two tools of one name would give two sets of CSV columns and
          // VTU files of the same name.
          for (const ToolDefinition &other : definitions)
            if (other.name == tool.name)
              throw InputError(prefix + "Name = '" + io::one_line(tool.name)
                               + "': " + other.parameter_prefix
                               + "Name has this name already; tool names "
                                 "must differ");
          tool.parameter_prefix = prefix;
          tool.geometry         = prm.get("Geometry");
          tool.file             = Utilities::trim(prm.get("File"));
          tool.length_unit      = prm.get("Length unit");
          tool.normals          = prm.get("Normals");
          if (tool.geometry == "file" || tool.geometry == "cad")
          {
            if (tool.file.empty())
              throw InputError(prefix + "File: a tool file is needed when "
                               + "Geometry = " + tool.geometry);
            if (tool.file[0] != '/')
              tool.file = prm_directory + "/" + tool.file;
            // The tool file itself is read and checked when the tools
            // are made (geometry/tool_file.h), with its own messages; a
            // named pipe is refused before anything opens it (D164).
            std::error_code error;
            if (!std::filesystem::exists(tool.file, error))
              throw InputError(prefix
                               + "File: cannot open the tool "
                                 "file '"
                               + io::one_line(tool.file) + "'");
            io::check_regular_file(tool.file,
                                   tool.geometry == "cad" ? "CAD file"
                                                          : "tool file");
          }
          tool.sheet_face       = prm.get("Sheet surface") == "top" ? 5 : 4;
          tool.force_controlled = prm.get("Control") == "force";
          if (prm.get("Control") == "spring")
          {
            tool.spring_stiffness = prm.get_double("Spring stiffness");
            if (!(tool.spring_stiffness > 0.))
              throw InputError(prefix + "Spring stiffness = "
                               + prm.get("Spring stiffness")
                               + ": Control = spring needs the spring's "
                                 "stiffness; allowed are 0 < k <= 1e9 N/mm");
          }
          tool.translation_expression = prm.get("Translation");
          tool.translation
            = io::parse_function_of_load(tool.translation_expression,
                                         3,
                                         prefix + "Translation");
          tool.axis = parse_direction(prm.get("Force direction"),
                                      prefix + "Force direction");
          definitions.push_back(tool);
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
      law = std::make_unique<contact::AlartCurnierLaw>(
        parameters.friction_coefficient);
    }


    bool
    ContactCoupling::active() const
    {
      return !definitions.empty();
    }


    void
    ContactCoupling::create_tools(
      const geometry::SquareCupToolParameters &square_cup,
      const double                             sheet_thickness,
      const bool                               symmetry_plane_x,
      const bool                               symmetry_plane_y)
    {
      tool_list.clear();
      std::vector<geometry::RigidTool> square_cup_tools;
      for (const ToolDefinition &definition : definitions)
      {
        geometry::RigidTool tool;
        if (definition.geometry == "file")
          tool = geometry::read_tool_file(definition.file);
        else if (definition.geometry == "cad")
        {
          geometry::CadToolOptions options;
          options.length_unit = definition.length_unit;
          options.normals     = definition.normals == "as in file"
                                  ? geometry::CadNormals::as_in_file
                                  : (definition.normals == "reversed"
                                       ? geometry::CadNormals::reversed
                                       : geometry::CadNormals::automatic);
          // A tool on the top surface lies above the sheet.
          options.towards_sheet
            = Tensor<1, 3>({0., 0., definition.sheet_face == 5 ? -1. : 1.});
          options.symmetry_plane_x = symmetry_plane_x;
          options.symmetry_plane_y = symmetry_plane_y;
          geometry::CadToolReport report;
          tool = geometry::read_cad_tool(definition.file,
                                         definition.name,
                                         options,
                                         &report);
          std::cout << "deepdraw: tool '" << definition.name << "' from "
                    << definition.file << ": " << report.summary() << std::endl;
        }
        else
        {
          if (square_cup_tools.empty())
            square_cup_tools
              = geometry::build_square_cup_tools(square_cup, sheet_thickness);
          const unsigned int index
            = definition.geometry == "square cup punch"
                ? 0
                : (definition.geometry == "square cup die" ? 1 : 2);
          tool = square_cup_tools[index];
        }
        tool.set_rigid_motion(unit_symmetric_tensor<3>(), Tensor<1, 3>());
        tool_list.push_back(tool);
      }
    }
  } // namespace contact
} // namespace deepdraw
