// deepdraw --study (doc/user_guide.md §4.2, doc/decisions.md D41-D44).
#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deepdraw/app/study.h>
#include <deepdraw/app/study_option.h>
#include <deepdraw/app/study_plot.h>
#include <deepdraw/app/study_run.h>
#include <deepdraw/app/study_table.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_lock.h>
#include <deepdraw/io/output_parameters.h>
#include <deepdraw/io/parameter_file.h>
#include <deepdraw/io/regular_file.h>
#include <deepdraw/postprocess/profile_travels.h>
#include <deepdraw/problem/forming_problem.h>
#include <deepdraw/process/process_parameters.h>
#include <deepdraw/state/stop_request.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace deepdraw
{
  namespace app
  {
    namespace
    {
      namespace fs = std::filesystem;

      const std::string one_layer_remark
        = "one layer: below the reference model's validity (at least two "
          "layers)";

      // One run: its values, its folder and what its parameters imply.
      struct StudyCase
      {
        std::vector<std::string> values;
        std::string              folder;
        // The extra lines of input.prm after the include.
        std::string   overrides;
        OptionalValue aspect_ratio;
        std::string   remark;
      };

      struct StudySetup
      {
        std::string                prm_file;
        std::vector<StudyVariable> variables;
        std::string                output_directory;
        std::vector<double>        travels;
        std::vector<std::string>   draw_in_names;
        std::vector<StudyCase>     cases;
        // FILE.prm lists the post-processor "forming limits" (D174).
        bool forming_limits = false;
        // mpirun and its options for each run (DEEPDRAW_MPI_LAUNCHER, D200).
        std::vector<std::string> launcher;
      };


      // deal.II's exception text without its source-location preamble (as
      // in main.cc).
      std::string
      deal_ii_message(const ExceptionBase &exception)
      {
        std::ostringstream text;
        exception.print_info(text);
        return Utilities::trim(text.str());
      }


      // With the checks of a plain run (io/parameter_file.h): include
      // cycles, files that are no text (D166).
      void
      read_prm(ParameterHandler &prm, const std::string &prm_file)
      {
        problem::FormingProblem::declare_parameters(prm);
        io::read_parameter_file(prm, prm_file);
      }


      // `subsection A ... set B = v ... end` for a value of a parameter.
      std::string
      prm_lines(const std::vector<std::string> &subsections,
                const std::string              &entry,
                const std::string              &value)
      {
        std::string text, indent;
        for (const std::string &subsection : subsections)
        {
          text += indent + "subsection " + subsection + "\n";
          indent += "  ";
        }
        text += indent + "set " + entry + " = " + value + "\n";
        for (unsigned int k = subsections.size(); k > 0; --k)
          text += std::string(2 * (k - 1), ' ') + "end\n";
        return text;
      }


      // Input files (tools, the outline, the Gmsh mesh, the FLC table) are
      // relative to the directory of the prm deepdraw is given; a run reads
      // input.prm in its folder, so the study names them absolutely (D42,
      // D168).
      std::string
      input_file_overrides(ParameterHandler &prm, const std::string &prm_file)
      {
        const fs::path directory = fs::absolute(prm_file).parent_path();
        std::vector<std::pair<std::vector<std::string>, std::string>> entries
          = {{{"Geometry"}, "Outline file"},
             {{"Geometry"}, "Mesh file"},
             {{"Formability"}, "Table file"}};
        for (unsigned int slot = 0; slot < contact::n_tool_slots; ++slot)
          entries.push_back(
            {{"Contact", "Tool " + std::to_string(slot + 1)}, "File"});
        std::string text;
        for (const auto &[subsections, entry] : entries)
        {
          if (!is_declared(prm, subsections, entry))
            continue;
          for (const std::string &subsection : subsections)
            prm.enter_subsection(subsection);
          const std::string file = Utilities::trim(prm.get(entry));
          for (unsigned int k = 0; k < subsections.size(); ++k)
            prm.leave_subsection();
          if (!file.empty() && fs::path(file).is_relative())
            text += prm_lines(subsections,
                              entry,
                              (directory / file).lexically_normal().string());
        }
        return text;
      }


      // The remarks of a run from its parameters: the element aspect ratio
      // and whether it has a single layer. Left empty if the values do not
      // make a valid prm (the run then fails and says why).
      void
      describe_case(ParameterHandler  &prm,
                    const std::string &prm_file,
                    StudyCase         &run,
                    double            &final_load)
      {
        blank::BlankGeometry geometry;
        geometry
          .parse_parameters(prm, fs::absolute(prm_file).parent_path().string());
        // The rectangle: the larger side of its cells; other outlines: the
        // mean in-plane size of the mesh's cells.
        double size = std::max(geometry.length / geometry.elements_along_x,
                               geometry.width / geometry.elements_along_y);
        if (geometry.outline != blank::BlankGeometry::Outline::rectangle)
        {
          Triangulation<3> mesh;
          geometry.create_mesh(mesh);
          size = std::sqrt(GridTools::volume(mesh) / geometry.thickness
                           / geometry.n_plane_cells());
        }
        run.aspect_ratio
          = size / (geometry.thickness / geometry.layers_through_thickness);
        if (geometry.layers_through_thickness == 1)
          run.remark = one_layer_remark;
        process::ProcessParameters process;
        process.parse_parameters(prm);
        final_load = process.final_load;
      }


      std::string
      folder_name(const unsigned int              run,
                  const unsigned int              n_runs,
                  const std::vector<std::string> &values)
      {
        std::ostringstream name;
        name << "run_" << std::setw(std::to_string(n_runs).size())
             << std::setfill('0') << run + 1;
        for (const std::string &value : values)
        {
          name << '_';
          for (const char c : value)
            name << (std::isalnum(static_cast<unsigned char>(c)) || c == '.'
                         || c == '-' || c == '+'
                       ? c
                       : '-');
        }
        return name.str();
      }


      StudyCase
      make_case(const StudySetup  &setup,
                const unsigned int run,
                double            &final_load)
      {
        StudyCase case_;
        for (const StudyVariable &variable : setup.variables)
        {
          case_.values.push_back(variable.values[run]);
          case_.overrides += prm_lines(variable.subsections,
                                       variable.entry,
                                       variable.values[run]);
        }
        case_.folder = setup.output_directory + "/"
                       + folder_name(run,
                                     setup.variables.front().values.size(),
                                     case_.values);
        ParameterHandler prm;
        read_prm(prm, setup.prm_file);
        try
        {
          for (const StudyVariable &variable : setup.variables)
            set_value(prm, variable, run);
          describe_case(prm, setup.prm_file, case_, final_load);
          case_.overrides += input_file_overrides(prm, setup.prm_file);
        }
        catch (const std::exception &)
        {
          // A value the prm rejects: the run reports it.
        }
        return case_;
      }


      // Names of Process tables/Draw-in points ("DX: length, 0; ...").
      std::vector<std::string>
      draw_in_names(ParameterHandler &prm)
      {
        prm.enter_subsection("Process tables");
        const std::string points = prm.get("Draw-in points");
        prm.leave_subsection();
        std::vector<std::string> names;
        std::istringstream       list(points);
        std::string              item;
        while (std::getline(list, item, ';'))
        {
          const auto colon = item.find(':');
          if (colon != std::string::npos
              && !Utilities::trim(item.substr(0, colon)).empty())
            names.push_back(Utilities::trim(item.substr(0, colon)));
        }
        return names;
      }


      // Everything checked before anything is written (D41); throws
      // InputError or a deal.II exception on bad input.
      StudySetup
      set_up(const std::string              &prm_file,
             const std::string              &output_directory,
             const std::vector<std::string> &options)
      {
        io::check_regular_file(prm_file, "parameter file");
        StudySetup setup;
        setup.prm_file = prm_file;
        setup.launcher = study_launcher();
        ParameterHandler prm;
        read_prm(prm, prm_file);
        setup.variables = parse_study_options(options, prm);

        io::OutputParameters output;
        output.parse_parameters(prm);
        setup.output_directory = output_directory.empty()
                                   ? output.output_directory
                                   : output_directory;
        setup.draw_in_names    = draw_in_names(prm);
        prm.enter_subsection("Postprocess");
        setup.forming_limits
          = prm.get("List of postprocessors").find("forming limits")
            != std::string::npos;
        prm.leave_subsection();

        process::ProcessParameters process;
        process.parse_parameters(prm);
        // The travels of the thickness profiles a run can reach (as
        // FormingProblem keeps them): up to the largest final load of the
        // runs whose values make a valid prm, else of FILE.prm.
        double largest_load = -1.;
        for (unsigned int run = 0; run < setup.variables[0].values.size();
             ++run)
        {
          double final_load = -1.;
          setup.cases.push_back(make_case(setup, run, final_load));
          largest_load = std::max(largest_load, final_load);
        }
        if (largest_load < 0.)
          largest_load = process.final_load;
        setup.travels
          = postprocess::travels_within(postprocess::parse_profile_travels(prm),
                                        largest_load);
        return setup;
      }


      std::string
      join_notes(const std::string &a, const std::string &b)
      {
        return a.empty() ? b : b.empty() ? a : a + "; " + b;
      }


      // Runs one case in its emptied folder and reads its results back.
      StudyRow
      run_case(const StudySetup  &setup,
               const unsigned int run,
               std::ostream      &console)
      {
        const StudyCase &case_ = setup.cases[run];
        fs::remove_all(case_.folder);
        fs::create_directories(case_.folder);
        const std::string input = case_.folder + "/input.prm";
        {
          std::ofstream file(input);
          file << "# Run " << run + 1 << " of " << setup.cases.size()
               << " of a study (deepdraw --study, doc/user_guide.md 4.2):\n"
               << "# the parameter file below with these values.\n"
               << "include "
               << fs::absolute(setup.prm_file).lexically_normal().string()
               << "\n"
               << case_.overrides;
          if (!file)
            throw std::runtime_error("cannot write " + input);
        }
        console << "run " << run + 1 << " of " << setup.cases.size() << ":";
        for (unsigned int v = 0; v < setup.variables.size(); ++v)
          console << (v ? "," : "") << " " << setup.variables[v].name() << " = "
                  << case_.values[v];
        console << " (" << case_.folder << ", console in deepdraw.log)"
                << std::endl;

        const StudyRunOutcome outcome
          = run_deepdraw(setup.launcher.empty()
                           ? std::string("/proc/self/exe")
                           : fs::read_symlink("/proc/self/exe").string(),
                         input,
                         case_.folder,
                         setup.launcher);
        StudyRow row;
        row.values = case_.values;
        row.failed = outcome.exit_code != 0;
        row.results
          = read_run_results(case_.folder, setup.travels, setup.draw_in_names);
        row.aspect_ratio = case_.aspect_ratio;
        row.wall_seconds = outcome.wall_seconds;
        row.note         = join_notes(outcome.failure, case_.remark);

        std::ostringstream line;
        line << std::fixed << std::setprecision(1);
        if (row.failed)
          line << "  failed after " << outcome.wall_seconds
               << " s: " << outcome.failure;
        else
        {
          const auto count = [](const OptionalValue &value)
          { return static_cast<long>(value.value_or(0.)); };
          line << "  done in " << outcome.wall_seconds
               << " s: " << count(row.results.increments) << " increments, "
               << count(row.results.newton_iterations) << " Newton iterations, "
               << count(row.results.cut_backs) << " cut-backs";
        }
        console << line.str() << std::endl;
        return row;
      }


      // The exit code of a study stopped by signal stop after n_rows rows:
      // 128 + the signal, as a shell reports a process killed by it.
      int
      study_interrupted(const int          stop,
                        const unsigned int n_rows,
                        const StudySetup  &setup,
                        const std::string &directory)
      {
        std::cerr << "deepdraw: the study was stopped by "
                  << state::signal_name(stop) << " after " << n_rows << " of "
                  << setup.cases.size() << " runs; their rows are in "
                  << directory << "/study.csv" << std::endl;
        return 128 + stop;
      }


      StudyPlotSpec
      plot_spec(const StudySetup &setup, const StudyTable &table)
      {
        StudyPlotSpec spec;
        spec.columns  = table.columns();
        spec.x_column = setup.variables.front().name();
        spec.x_label  = spec.x_column;
        spec.title    = "deepdraw --study: " + setup.prm_file;
        for (unsigned int v = 1; v < setup.variables.size(); ++v)
          spec.title
            += (v == 1 ? "; varied with " : ", ") + setup.variables[v].name();
        for (const std::string &value : setup.variables.front().values)
        {
          std::size_t used = 0;
          try
          {
            std::stod(value, &used);
          }
          catch (const std::exception &)
          {
            used = 0;
          }
          spec.x_numeric = spec.x_numeric && used == value.size();
        }
        spec.travels       = setup.travels;
        spec.draw_in_names = setup.draw_in_names;
        return spec;
      }
    } // namespace


    int
    run_study(const std::string              &prm_file,
              const std::string              &output_directory,
              const std::vector<std::string> &options)
    {
      StudySetup setup;
      try
      {
        setup = set_up(prm_file, output_directory, options);
      }
      catch (const InputError &error)
      {
        std::cerr << "deepdraw: error in the input: " << error.what()
                  << std::endl;
        return 2;
      }
      catch (const ExceptionBase &error)
      {
        std::cerr << "deepdraw: error in " << prm_file << ": "
                  << deal_ii_message(error) << std::endl;
        return 2;
      }

      const std::string          &directory = setup.output_directory;
      std::unique_ptr<StudyTable> table;
      // One study per folder, as one run per output folder (D162, D179).
      io::OutputLock lock;
      try
      {
        io::check_output_entries(directory);
        fs::create_directories(directory);
        lock.acquire(directory, "--study", false);
        std::vector<std::string> names;
        for (const StudyVariable &variable : setup.variables)
          names.push_back(variable.name());
        table = std::make_unique<StudyTable>(directory + "/study.csv",
                                             names,
                                             setup.travels,
                                             setup.draw_in_names,
                                             setup.forming_limits);
      }
      catch (const InputError &error)
      {
        std::cerr << "deepdraw: error in the input: " << error.what()
                  << std::endl;
        return 2;
      }
      catch (const std::exception &error)
      {
        std::cerr << "deepdraw: error in the input: cannot write the study "
                     "to the output directory '"
                  << directory << "': " << error.what() << std::endl;
        return 2;
      }

      std::cout << "deepdraw --study: " << setup.cases.size() << " runs of "
                << prm_file << "; results in " << directory << std::endl;
      unsigned int n_failed = 0;
      // Ctrl-C reaches the run too (the terminal's process group); kill
      // -INT of the study alone is passed on to the run (D179).
      state::install_stop_handlers(true);
      try
      {
        for (unsigned int run = 0; run < setup.cases.size(); ++run)
        {
          if (const int stop = state::requested_stop_signal())
            return study_interrupted(stop, run, setup, directory);
          StudyRow row = run_case(setup, run, std::cout);
          if (const int stop = state::requested_stop_signal())
          {
            row.interrupted = true;
            row.note = join_notes("interrupted by " + state::signal_name(stop),
                                  row.note);
            table->add_row(row);
            return study_interrupted(stop, run + 1, setup, directory);
          }
          table->add_row(row);
          n_failed += row.failed ? 1 : 0;
        }
      }
      catch (const std::exception &error)
      {
        std::cerr << "deepdraw: the study stopped: " << error.what()
                  << std::endl;
        return 3;
      }
      const std::string plot = plot_study(directory, plot_spec(setup, *table));
      std::cout << "deepdraw --study: " << setup.cases.size() << " runs, "
                << n_failed << " failed; " << directory << "/study.csv, "
                << plot << std::endl;
      return n_failed == 0 ? 0 : 3;
    }
  } // namespace app
} // namespace deepdraw
