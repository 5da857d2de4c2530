// Post-processor "statistics": statistics.csv, one row per converged
// increment (doc/user_guide.md §3): the load, the Newton iterations and
// cut-backs, the last residuals, the plastic points, the contact states,
// the split of the wall time, the sheet's volume and the linear solver.
#include <deepdraw/io/csv_file.h>
#include <deepdraw/postprocess/interface.h>
#include <deepdraw/postprocess/table_names.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class Statistics : public Interface
      {
      public:
        void
        start(const SimulationAccess &simulation, const bool resume) override
        {
          file.open(simulation.output_directory() + "/" + tables::statistics,
                    {"increment",
                     "load",
                     "load_increment",
                     tables::newton_iterations,
                     tables::cut_backs,
                     "force_residual",
                     "contact_residual",
                     "plastic_points",
                     "contact_changes",
                     "stick_pairs",
                     "slip_pairs",
                     "assembly_s",
                     // The whole contact coupling since D212 (search, law
                     // and terms); the name is kept for existing tables.
                     "contact_search_s",
                     "linear_solve_s",
                     "output_s",
                     tables::wall_time,
                     "sheet_volume_mm3",
                     "factorized_unknowns",
                     "symbolic_analyses"},
                    resume);
        }

        void
        execute(const SimulationAccess &simulation) override
        {
          const state::SimulationState &state = simulation.state();
          if (state.increment_number == 0)
            return;
          const IncrementReport &report = simulation.increment_report();
          const contact::ContactCoupling &contact = simulation.contact();
          file.add_row({double(state.increment_number),
                        state.load,
                        report.load_increment,
                        double(report.iterations),
                        double(report.cut_backs),
                        report.force_residual,
                        report.contact_residual,
                        double(report.plastic_points),
                        double(report.contact_changes),
                        double(contact.n_stick()),
                        double(contact.n_slip()),
                        report.assembly_time,
                        report.contact_time,
                        report.solve_time,
                        simulation.output_time(),
                        simulation.increment_wall_time(),
                        simulation.sheet().volume(),
                        report.factorized_unknowns,
                        double(report.symbolic_analyses)});
        }

      private:
        io::CsvFile file;
      };
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      Statistics,
      "statistics",
      "statistics.csv, a row per converged increment: load, Newton iterations, "
      "cut-backs, residuals, plastic points, contact states, the time of "
      "assembly, contact (search, law and terms), linear solve and output (of "
      "the post-processors listed before it) and the whole increment, the "
      "sheet's volume and the linear solver's sizes.")
  } // namespace postprocess
} // namespace deepdraw
