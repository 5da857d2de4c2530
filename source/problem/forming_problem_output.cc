// Results of FormingProblem: geometric thickness, VTU/PVD, CSV tables.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <deal.II/numerics/data_out.h>
#include <deepdraw/blank/nodal_surface_area.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/geometry/tool_vtu.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/output_file.h>
#include <deepdraw/problem/forming_problem.h>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::compute_thickness()
    {
      // Thickness measured as a real distance (doc/theory.md §6): at every
      // vertex's initial (X, Y), (x_top - x_bottom) . n with n the mean
      // sheet normal there (blank::SheetThickness).
      const auto &vertices = triangulation.get_vertices();
      sheet_thickness->update(vertices);
      vertex_thickness.assign(vertices.size(), geometry.thickness);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
        {
          const unsigned int vertex = cell->vertex_index(v);
          vertex_thickness[vertex]
            = sheet_thickness->thickness(vertex_locations[vertex], vertices);
        }
    }


    void
    FormingProblem::set_up_thickness_profiles()
    {
      // Rays from the origin along x, y and the diagonal x = y, from where
      // they enter the sheet to the outline, sampled where they cross a
      // face edge (doc/user_guide.md §3.1).
      thickness_profiles.clear();
      const std::pair<const char *, Tensor<1, 2>> rays[]
        = {{"OX", Tensor<1, 2>({1., 0.})},
           {"OY", Tensor<1, 2>({0., 1.})},
           {"OD", Tensor<1, 2>({std::sqrt(0.5), std::sqrt(0.5)})}};
      for (const auto &[name, direction] : rays)
      {
        ThicknessProfile profile{name, {}};
        for (const double s : sheet_thickness->ray_crossings(direction))
          if (const auto location
              = sheet_thickness->locate(Point<2>(s * direction)))
            profile.points.emplace_back(s, *location);
        thickness_profiles.push_back(profile);
      }
      // The rim: the outline, not the symmetry planes.
      std::vector<types::boundary_id> rim_ids = {1, 3};
      if (!geometry.symmetry_plane_x)
        rim_ids.push_back(0);
      if (!geometry.symmetry_plane_y)
        rim_ids.push_back(2);
      earing.set_up(triangulation,
                    initial_vertices,
                    rim_ids,
                    material_parameters.rolling_direction_angle);
    }


    double
    FormingProblem::sheet_volume() const
    {
      // Σ JxW over the Gauss points of the current configuration: exact for
      // the trilinear geometry (volume conservation check, doc/results.md).
      double volume = 0.;
      for (const fe::CellGeometry &cell : cell_geometry)
        for (const double w : cell.JxW)
          volume += w;
      return volume;
    }


    std::vector<Tensor<2, 3>>
    FormingProblem::cell_average_cauchy_stress() const
    {
      std::vector<Tensor<2, 3>> stress(triangulation.n_active_cells());
      for (unsigned int cell = 0; cell < stress.size(); ++cell)
        for (unsigned int q = 0; q < fe::n_weighted_points; ++q)
          stress[cell]
            += cauchy_stress(state.history[cell * fe::n_weighted_points + q])
               / double(fe::n_weighted_points);
      return stress;
    }


    void
    FormingProblem::open_output_files(const bool resume)
    {
      // A failure here is an input error (exit code 2, D11), after which
      // nothing may be left behind: a directory made here is removed again.
      const std::string &directory = output_parameters.output_directory;
      const bool         existed   = std::filesystem::exists(directory);
      std::filesystem::create_directories(directory);
      try
      {
        open_output_tables(resume);
      }
      catch (...)
      {
        statistics_file.close_silently();
        newton_file.close_silently();
        reactions_file.close_silently();
        tools_file.close_silently();
        adaptivity_file.close_silently();
        if (!existed)
        {
          std::error_code ignored;
          std::filesystem::remove_all(directory, ignored);
        }
        throw;
      }
    }


    void
    FormingProblem::open_output_tables(const bool resume)
    {
      const std::string &directory = output_parameters.output_directory;
      pvd = std::make_unique<io::PvdRecord>(directory + "/solution.pvd",
                                            resumed_pvd_steps);
      statistics_file.open(directory + "/statistics.csv",
                           {"increment",
                            "load",
                            "load_increment",
                            "newton_iterations",
                            "cut_backs",
                            "force_residual",
                            "contact_residual",
                            "plastic_points",
                            "contact_changes",
                            "stick_pairs",
                            "slip_pairs",
                            "assembly_s",
                            "contact_search_s",
                            "linear_solve_s",
                            "output_s",
                            "wall_s",
                            "sheet_volume_mm3",
                            "factorized_unknowns",
                            "symbolic_analyses"},
                           resume);
      newton_file.open(directory + "/newton.csv",
                       {"increment",
                        "load",
                        "iteration",
                        "force_residual",
                        "contact_residual",
                        "correction",
                        "contact_changes"},
                       resume);
      std::vector<std::string> columns = {"load"};
      for (const unsigned int face : reaction_faces)
        for (const char *component : {"_Fx", "_Fy", "_Fz"})
          columns.push_back(blank::face_names[face] + component);
      reactions_file.open(directory + "/reactions.csv", columns, resume);
      if (contact.active())
      {
        // Force of each tool on the sheet (N) and its translation (mm).
        std::vector<std::string> tool_columns = {"load"};
        for (const contact::ToolDefinition &tool : contact.tool_definitions())
          for (const char *suffix : {"_Fx", "_Fy", "_Fz", "_ux", "_uy", "_uz"})
            tool_columns.push_back(tool.name + suffix);
        tools_file.open(directory + "/tools.csv", tool_columns, resume);

        process_tables.open(directory, resume);
        if (!profile_travels.empty())
        {
          std::vector<std::string> labels;
          for (const double travel : profile_travels)
            labels.push_back(io::OutputParameters::travel_label(travel));
          postprocess::EaringProfile::write_plot_script(directory, labels);
        }
      }
      if (adaptivity_parameters.enabled)
        adaptivity_file.open(directory + "/adaptivity.csv",
                             {"cycle",
                              "increment",
                              "load",
                              "cells_before",
                              "cells_after",
                              "hanging_vertices",
                              "displacement_unknowns",
                              "contact_unknowns",
                              "initial_force_residual",
                              "initial_contact_residual",
                              "reequilibration_iterations",
                              "force_residual",
                              "wall_s"},
                             resume);
      if (!resume)
        write_increment_tables(0.);
    }


    void
    FormingProblem::write_increment_tables(const double load)
    {
      std::vector<double> row = {load};
      for (const unsigned int face : reaction_faces)
      {
        const Tensor<1, 3> reaction = face_reaction(face);
        for (unsigned int c = 0; c < 3; ++c)
          row.push_back(reaction[c]);
      }
      reactions_file.add_row(row);

      if (contact.active())
      {
        std::vector<double>             tool_row = {load};
        const std::vector<Tensor<1, 3>> forces   = contact.tool_forces();
        for (unsigned int k = 0; k < forces.size(); ++k)
        {
          for (unsigned int c = 0; c < 3; ++c)
            tool_row.push_back(forces[k][c]);
          for (unsigned int c = 0; c < 3; ++c)
            tool_row.push_back(contact.tools()[k].translation()[c]);
        }
        tools_file.add_row(tool_row);
        process_tables.write(load, contact, triangulation.get_vertices());
        for (const double travel : profile_travels)
          if (std::abs(travel - load) < 1e-9 * std::max(1., travel))
            write_thickness_profiles(travel);
      }
    }


    void
    FormingProblem::write_thickness_profiles(const double travel)
    {
      const std::string  label     = io::OutputParameters::travel_label(travel);
      const std::string &directory = output_parameters.output_directory;
      const auto        &vertices  = triangulation.get_vertices();
      for (const ThicknessProfile &profile : thickness_profiles)
      {
        std::vector<std::vector<double>> rows;
        for (const auto &[s0, location] : profile.points)
          rows.push_back(
            {s0,
             std::log(sheet_thickness->thickness(location, vertices)
                      / geometry.thickness)});
        io::write_csv_file_atomically(directory + "/thickness_" + profile.name
                                        + "_" + label + "mm.csv",
                                      {"s0_mm", "thickness_strain"},
                                      rows);
      }
      earing.write(directory, label, vertices, process_tables.punch_motion());
    }


    void
    FormingProblem::write_vtu(const double load)
    {
      if (!output_parameters.write_vtu)
        return;

      const unsigned int n_cells = triangulation.n_active_cells();
      const unsigned int n_q     = fe::n_weighted_points;
      const char        *axes[]  = {"x", "y", "z"};

      // Cell averages of the quadrature-point fields.
      std::vector<Vector<double>> stress(6, Vector<double>(n_cells));
      std::vector<Vector<double>> back_stress(6, Vector<double>(n_cells));
      std::vector<Vector<double>> rolling_direction(3, Vector<double>(n_cells));
      Vector<double>     equivalent_stress(n_cells), plastic_strain(n_cells);
      const unsigned int pairs[6][2]
        = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
      for (unsigned int cell = 0; cell < n_cells; ++cell)
        for (unsigned int q = 0; q < n_q; ++q)
        {
          const QuadraturePointHistory &point = state.history[cell * n_q + q];
          const Tensor<2, 3>            sigma = cauchy_stress(point);
          const Tensor<2, 3>           &R     = point.material_axes;
          const Tensor<2, 3>            X
            = R * Tensor<2, 3>(point.state.back_stress) * transpose(R);
          for (unsigned int p = 0; p < 6; ++p)
          {
            stress[p][cell] += sigma[pairs[p][0]][pairs[p][1]] / n_q;
            back_stress[p][cell] += X[pairs[p][0]][pairs[p][1]] / n_q;
          }
          for (unsigned int d = 0; d < 3; ++d)
            rolling_direction[d][cell] += R[d][0] / n_q;
          equivalent_stress[cell]
            += material->equivalent_stress(point.state.stress
                                           - point.state.back_stress)
               / n_q;
          plastic_strain[cell] += point.state.equivalent_plastic_strain / n_q;
        }

      // Thickness strain ln(t/t0) at every vertex, measured at its initial
      // (X, Y).
      Vector<double> thickness_strain(scalar_dof_handler.n_dofs());
      for (const auto &cell : scalar_dof_handler.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          thickness_strain[cell->vertex_dof_index(v, 0)] = std::log(
            vertex_thickness[cell->vertex_index(v)] / geometry.thickness);

      DataOut<3> data_out;
      data_out.attach_triangulation(triangulation);
      std::vector<std::string> names(3, "displacement");
      std::vector<DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          3,
          DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(dof_handler,
                               state.total_displacement,
                               names,
                               interpretation);
      data_out.add_data_vector(scalar_dof_handler,
                               thickness_strain,
                               "thickness_strain");

      // Contact fields at the surface nodes: status (0 open, 1 stick,
      // 2 slip), normal gap, contact pressure and friction stress (nodal
      // forces over the node's share of the sheet surface).
      Vector<double> contact_status(scalar_dof_handler.n_dofs()),
        contact_gap(scalar_dof_handler.n_dofs()),
        contact_pressure(scalar_dof_handler.n_dofs());
      std::vector<Vector<double>> friction_stress(
        3,
        Vector<double>(scalar_dof_handler.n_dofs()));
      if (contact.active())
      {
        const std::vector<contact::ContactCoupling::NodalContact> nodal
          = contact.nodal_contact(triangulation.n_vertices());
        const std::vector<double> area
          = blank::nodal_surface_area(triangulation);
        for (const auto &cell : scalar_dof_handler.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int vertex = cell->vertex_index(v);
            const auto         dof    = cell->vertex_dof_index(v, 0);
            contact_status[dof]       = nodal[vertex].status;
            contact_gap[dof]          = nodal[vertex].gap;
            if (area[vertex] > 0.)
            {
              contact_pressure[dof] = nodal[vertex].normal_force / area[vertex];
              for (unsigned int d = 0; d < 3; ++d)
                friction_stress[d][dof]
                  = nodal[vertex].friction_force[d] / area[vertex];
            }
          }
        data_out.add_data_vector(scalar_dof_handler,
                                 contact_status,
                                 "contact_status");
        data_out.add_data_vector(scalar_dof_handler,
                                 contact_gap,
                                 "contact_gap");
        data_out.add_data_vector(scalar_dof_handler,
                                 contact_pressure,
                                 "contact_pressure");
        for (unsigned int d = 0; d < 3; ++d)
          data_out.add_data_vector(scalar_dof_handler,
                                   friction_stress[d],
                                   std::string("friction_stress_") + axes[d]);
      }
      for (unsigned int p = 0; p < 6; ++p)
      {
        const std::string suffix
          = std::string(axes[pairs[p][0]]) + axes[pairs[p][1]];
        data_out.add_data_vector(stress[p],
                                 "stress_" + suffix,
                                 DataOut<3>::type_cell_data);
        data_out.add_data_vector(back_stress[p],
                                 "back_stress_" + suffix,
                                 DataOut<3>::type_cell_data);
      }
      for (unsigned int d = 0; d < 3; ++d)
        data_out.add_data_vector(rolling_direction[d],
                                 std::string("rolling_direction_") + axes[d],
                                 DataOut<3>::type_cell_data);
      data_out.add_data_vector(equivalent_stress,
                               "equivalent_stress",
                               DataOut<3>::type_cell_data);
      data_out.add_data_vector(plastic_strain,
                               "equivalent_plastic_strain",
                               DataOut<3>::type_cell_data);
      std::ostringstream name;
      name << "solution-" << std::setw(5) << std::setfill('0') << output_step
           << ".vtu";
      const std::string path
        = output_parameters.output_directory + "/" + name.str();

      // No NaN or inf reaches a file (doc/user_guide.md §3, D51): every
      // field and the vertices are checked before anything is written.
      const auto check
        = [&](const Vector<double> &values, const std::string &field)
      {
        io::check_finite_for_output(values.begin(),
                                    values.end(),
                                    "the field " + field + " of " + path
                                      + " (load " + std::to_string(load) + ")");
      };
      check(state.total_displacement, "displacement");
      check(thickness_strain, "thickness_strain");
      if (contact.active())
      {
        check(contact_status, "contact_status");
        check(contact_gap, "contact_gap");
        check(contact_pressure, "contact_pressure");
        for (unsigned int d = 0; d < 3; ++d)
          check(friction_stress[d], std::string("friction_stress_") + axes[d]);
      }
      for (unsigned int p = 0; p < 6; ++p)
      {
        const std::string suffix
          = std::string(axes[pairs[p][0]]) + axes[pairs[p][1]];
        check(stress[p], "stress_" + suffix);
        check(back_stress[p], "back_stress_" + suffix);
      }
      for (unsigned int d = 0; d < 3; ++d)
        check(rolling_direction[d],
              std::string("rolling_direction_") + axes[d]);
      check(equivalent_stress, "equivalent_stress");
      check(plastic_strain, "equivalent_plastic_strain");
      for (const Point<3> &vertex : triangulation.get_vertices())
        io::check_finite_for_output(&vertex[0],
                                    &vertex[0] + 3,
                                    "the vertices of " + path);

      data_out.build_patches();
      // Written in memory first: deal.II's writer reports a failed stream
      // only as an exception with a stack trace, and a file written in
      // place could be left half written.
      std::ostringstream vtu;
      // zlib's default level: files 0.4 % larger than deal.II's default
      // best_compression, written in half the time (D98).
      DataOutBase::VtkFlags flags;
      flags.compression_level = DataOutBase::VtkFlags::default_compression;
      data_out.set_flags(flags);
      data_out.write_vtu(vtu);
      io::write_file_atomically(path, vtu.str());
      std::vector<std::string> parts = {name.str()};
      for (unsigned int k = 0; k < contact.tools().size(); ++k)
      {
        const geometry::RigidTool &tool = contact.tools()[k];
        // The slot's name, unique among the tools (the name inside a tool
        // file may be shared by two slots).
        std::string tool_name = contact.tool_definitions()[k].name;
        std::replace(tool_name.begin(), tool_name.end(), ' ', '_');
        std::ostringstream tool_file;
        tool_file << "tool_" << tool_name << "-" << std::setw(5)
                  << std::setfill('0') << output_step << ".vtu";
        const std::string tool_path
          = output_parameters.output_directory + "/" + tool_file.str();
        geometry::write_vtu(tool, tool_path, 8);
        parts.push_back(tool_file.str());
      }
      pvd->add_step(load, parts);
      ++output_step;
    }
  } // namespace problem
} // namespace deepdraw
