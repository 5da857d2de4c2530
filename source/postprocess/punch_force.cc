// Post-processor "punch force": punch_force.csv (runs with a punch), per
// converged load (and t = 0): the punch travel (the load), the punch force
// along its motion, the blank holder's force along its axis and its height
// (doc/user_guide.md §3.1; forces on the modelled part of the blank).
#include <deepdraw/io/csv_file.h>
#include <deepdraw/postprocess/interface.h>
#include <deepdraw/postprocess/punch_and_holder.h>
#include <deepdraw/postprocess/table_names.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class PunchForce : public Interface
      {
      public:
        static void
        declare_parameters(ParameterHandler &prm)
        {
          PunchAndHolder::declare_parameters(prm);
        }

        void
        parse_parameters(ParameterHandler &prm) override
        {
          tools.parse_parameters(prm);
        }

        void
        initialize(const SimulationAccess &simulation) override
        {
          tools.set_up(simulation.contact(), simulation.final_load());
        }

        void
        start(const SimulationAccess &simulation, const bool resume) override
        {
          if (tools.punch() == numbers::invalid_unsigned_int)
            return;
          file.open(simulation.output_directory() + "/"
                      + tables::punch_force_table,
                    {tables::punch_travel,
                     tables::punch_force,
                     tables::holder_force,
                     tables::holder_z},
                    resume);
        }

        void
        execute(const SimulationAccess &simulation) override
        {
          if (tools.punch() == numbers::invalid_unsigned_int)
            return;
          // Forces of the tools on the sheet, positive when the punch
          // pushes along its motion and the holder presses along its axis.
          const contact::ContactCoupling &contact      = simulation.contact();
          const std::vector<Tensor<1, 3>> forces       = contact.tool_forces();
          double                          holder_force = 0., holder_z = 0.;
          if (tools.holder() != numbers::invalid_unsigned_int)
          {
            holder_force = forces[tools.holder()]
                           * contact.tool_definitions()[tools.holder()].axis;
            holder_z = contact.tools()[tools.holder()].translation()[2];
          }
          file.add_row({simulation.state().load,
                        forces[tools.punch()] * tools.punch_direction(),
                        holder_force,
                        holder_z});
        }

      private:
        PunchAndHolder tools;
        io::CsvFile    file;
      };
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      PunchForce,
      "punch force",
      "punch_force.csv (with a punch, Process tables/Punch tool), per "
      "converged load: punch travel, punch force along its motion, blank "
      "holder force and height.")
  } // namespace postprocess
} // namespace deepdraw
