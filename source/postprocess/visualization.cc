// Post-processor "visualization": the VTU files of the sheet (the fields of
// Output/VTU fields, vtu_field.h) and of every tool that takes part (its
// patches at their current position), and solution.pvd, the ParaView
// collection with the load as time (doc/user_guide.md §3). Written at t = 0,
// at every load the increments land on (the multiples of Output interval,
// the travels of the other results, the end of each stage), or every
// increment with an interval of 0.
#include <algorithm>
#include <cmath>
#include <deal.II/numerics/data_out.h>
#include <deepdraw/geometry/tool_vtu.h>
#include <deepdraw/io/binary_stream.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/output_error.h>
#include <deepdraw/io/output_file.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/io/pvd_record.h>
#include <deepdraw/io/writing_rank.h>
#include <deepdraw/parallel/cell_partition.h>
#include <deepdraw/parallel/ranks.h>
#include <deepdraw/postprocess/interface.h>
#include <deepdraw/postprocess/vtu_field.h>
#include <iomanip>
#include <memory>
#include <sstream>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      // At most this many VTU outputs in a run (D50).
      constexpr double max_outputs = 1e5;

      constexpr char default_fields[]
        = "displacement, thickness strain, contact, stress, back stress, "
          "rolling direction, equivalent stress, equivalent plastic strain";

      std::string
      numbered(const std::string &stem,
               const unsigned int step,
               const std::string &extension = ".vtu")
      {
        std::ostringstream name;
        name << stem << "-" << std::setw(5) << std::setfill('0') << step
             << extension;
        return name.str();
      }


      class Visualization : public Interface
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm);

        void
        parse_parameters(ParameterHandler &prm) override;

        void
        initialize(const SimulationAccess &simulation) override;

        std::vector<double>
        requested_loads(const SimulationAccess &simulation) const override;

        void
        start(const SimulationAccess &simulation, bool resume) override;

        void
        execute(const SimulationAccess &simulation) override;

        void
        save(std::ostream &stream) const override
        {
          io::write_value(stream, output_step);
          io::write_entries(stream, pvd_steps);
        }

        void
        load(std::istream &stream) override
        {
          io::read_value(stream, output_step, "the visualization's state");
          pvd_steps = io::read_entries(stream, "the visualization's state");
        }

      private:
        // Writes solution-NNNNN.vtu and the tools' files of this step.
        void
        write(const SimulationAccess &simulation);
        // The VTU file of the sheet (its name relative to the directory).
        std::string
        write_sheet(const SimulationAccess &simulation) const;

        double                                 interval  = 0.;
        bool                                   write_vtu = true;
        std::vector<std::unique_ptr<VtuField>> fields;
        unsigned int                           output_step = 0;
        std::vector<io::PvdRecord::Entry>      pvd_steps;
        std::unique_ptr<io::PvdRecord>         pvd;
      };


      void
      Visualization::declare_parameters(ParameterHandler &prm)
      {
        std::string documentation
          = "The fields of the sheet's VTU files, a comma-separated list "
            "of:";
        for (const auto &plugin : VtuFieldRegistry::plugins())
          documentation += " '" + plugin.name + "': " + plugin.description;
        prm.enter_subsection("Output");
        prm.declare_entry("Output interval",
                          "0",
                          Patterns::Double(0., 1e6),
                          "Load-parameter interval between VTU outputs "
                          "(increments land on these loads); 0 writes every "
                          "converged increment. At most 100000 outputs "
                          "(Final load / Output interval).");
        prm.declare_entry("Write VTU",
                          "true",
                          Patterns::Bool(),
                          "Write the VTU/PVD files for ParaView (the CSV "
                          "tables are always written).");
        prm.declare_entry("VTU fields",
                          default_fields,
                          Patterns::Anything(),
                          documentation);
        prm.leave_subsection();
        for (const auto &plugin : VtuFieldRegistry::plugins())
          plugin.declare_parameters(prm);
      }


      void
      Visualization::parse_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Output");
        interval               = prm.get_double("Output interval");
        write_vtu              = prm.get_bool("Write VTU");
        const std::string list = prm.get("VTU fields");
        prm.leave_subsection();
        std::vector<std::string> names;
        for (const std::string &name : Utilities::split_string_list(list))
        {
          if (name.empty())
            continue;
          const auto *plugin = VtuFieldRegistry::find(name);
          if (plugin == nullptr)
            throw InputError("Output/VTU fields: unknown field '"
                             + io::one_line(name)
                             + "'; allowed: " + VtuFieldRegistry::names());
          if (std::count(names.begin(), names.end(), name))
            throw InputError("Output/VTU fields: '" + name
                             + "' is listed twice");
          names.push_back(name);
          fields.push_back(plugin->create());
        }
      }


      void
      Visualization::initialize(const SimulationAccess &simulation)
      {
        const double final_load = simulation.final_load();
        if (interval > 0. && final_load / interval > max_outputs)
        {
          std::ostringstream text;
          text << std::setprecision(6)
               << "Output/Output interval = " << interval << " would write "
               << final_load / interval
               << " VTU files up to Process/Final load = " << final_load
               << "; allowed are Final load / Output interval <= "
               << max_outputs << " (0 writes one per increment)";
          throw InputError(text.str());
        }
        if (write_vtu)
          for (const auto &field : fields)
            field->check(simulation);
      }


      std::vector<double>
      Visualization::requested_loads(const SimulationAccess &simulation) const
      {
        // Summed up as before (D50), so that the landings keep their bits.
        std::vector<double> loads;
        if (interval > 0.)
          for (double load = interval; load < simulation.final_load();
               load += interval)
            loads.push_back(load);
        return loads;
      }


      void
      Visualization::start(const SimulationAccess &simulation, bool)
      {
        pvd = std::make_unique<io::PvdRecord>(simulation.output_directory()
                                                + "/solution.pvd",
                                              pvd_steps);
      }


      void
      Visualization::execute(const SimulationAccess &simulation)
      {
        // Also where the other results are taken (the thickness profiles'
        // travels) and at the end of each stage.
        if (write_vtu
            && (simulation.state().increment_number == 0 || interval <= 0.
                || simulation.landed()))
          write(simulation);
      }


      void
      Visualization::write(const SimulationAccess &simulation)
      {
        std::vector<std::string>        parts   = {write_sheet(simulation)};
        const contact::ContactCoupling &contact = simulation.contact();
        for (unsigned int k = 0; k < contact.tools().size(); ++k)
        {
          if (!contact.takes_part(k))
            continue;
          // The slot's name, unique among the tools (the name inside a
          // tool file may be shared by two slots).
          std::string name = contact.tool_definitions()[k].name;
          std::replace(name.begin(), name.end(), ' ', '_');
          const std::string file = numbered("tool_" + name, output_step);
          geometry::write_vtu(contact.tools()[k],
                              simulation.output_directory() + "/" + file,
                              8);
          parts.push_back(file);
        }
        pvd->add_step(simulation.state().load, parts);
        pvd_steps = pvd->steps();
        ++output_step;
      }


      std::string
      Visualization::write_sheet(const SimulationAccess &simulation) const
      {
        VtuData data;
        for (const auto &field : fields)
          field->add(simulation, data);
        const std::string name = numbered("solution", output_step);
        const std::string path = simulation.output_directory() + "/" + name;

        // No NaN or inf reaches a file (doc/user_guide.md §3, D51): every
        // field and the vertices are checked before anything is written.
        DataOut<3> data_out;
        data_out.attach_triangulation(simulation.sheet().triangulation());
        // Under mpirun each rank writes the cells whose elements it
        // evaluates, and rank 0 a .pvtu record of the pieces (D201, D215).
        const unsigned int ranks = parallel::n_ranks();
        if (ranks > 1)
          data_out.set_cell_selection(
            [](const typename Triangulation<3>::cell_iterator &cell)
            { return cell->is_active() && parallel::is_owned(*cell); });
        for (const VtuData::Field &field : data.fields())
        {
          io::check_finite_for_output(
            field.values.begin(),
            field.values.end(),
            "the field " + field.name + " of " + path + " (load "
              + std::to_string(simulation.state().load) + ")");
          if (field.vector)
            data_out.add_data_vector(
              *field.dof_handler,
              field.values,
              std::vector<std::string>(3, field.name),
              std::vector<
                DataComponentInterpretation::DataComponentInterpretation>(
                3,
                DataComponentInterpretation::component_is_part_of_vector));
          else if (field.dof_handler != nullptr)
            data_out.add_data_vector(*field.dof_handler,
                                     field.values,
                                     field.name);
          else
            data_out.add_data_vector(field.values,
                                     field.name,
                                     DataOut<3>::type_cell_data);
        }
        for (const Point<3> &vertex :
             simulation.sheet().triangulation().get_vertices())
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
        if (ranks == 1)
        {
          io::write_file_atomically(path, vtu.str());
          return name;
        }
        std::vector<std::string> pieces;
        for (unsigned int rank = 0; rank < ranks; ++rank)
          pieces.push_back(
            numbered("solution", output_step, "." + std::to_string(rank))
            + ".vtu");
        io::write_own_file_atomically(simulation.output_directory() + "/"
                                        + pieces[parallel::this_rank()],
                                      vtu.str());
        // The record names only pieces that are on disk.
        parallel::barrier();
        std::ostringstream record;
        data_out.write_pvtu_record(record, pieces);
        const std::string record_name
          = numbered("solution", output_step, ".pvtu");
        io::write_file_atomically(simulation.output_directory() + "/"
                                    + record_name,
                                  record.str());
        return record_name;
      }
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      Visualization,
      "visualization",
      "solution.pvd and solution-NNNNN.vtu for ParaView (Output/Output "
      "interval, Write VTU, VTU fields), with every tool that takes part.")
  } // namespace postprocess
} // namespace deepdraw
