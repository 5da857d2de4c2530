// Post-processor "tools": tools.csv (runs with tools), per converged load
// (and t = 0), the force of each tool on the sheet (<tool>_Fx, _Fy, _Fz,
// N) and its translation (<tool>_ux, _uy, _uz, mm); a tool that takes no
// part in a stage has no force and stays where it is.
#include <deepdraw/io/csv_file.h>
#include <deepdraw/postprocess/interface.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class ToolForces : public Interface
      {
      public:
        void
        start(const SimulationAccess &simulation, const bool resume) override
        {
          if (!simulation.contact().active())
            return;
          std::vector<std::string> columns = {"load"};
          for (const contact::ToolDefinition &tool :
               simulation.contact().tool_definitions())
            for (const char *suffix :
                 {"_Fx", "_Fy", "_Fz", "_ux", "_uy", "_uz"})
              columns.push_back(tool.name + suffix);
          file.open(simulation.output_directory() + "/tools.csv",
                    columns,
                    resume);
        }

        void
        execute(const SimulationAccess &simulation) override
        {
          const contact::ContactCoupling &contact = simulation.contact();
          if (!contact.active())
            return;
          std::vector<double>             row    = {simulation.state().load};
          const std::vector<Tensor<1, 3>> forces = contact.tool_forces();
          for (unsigned int k = 0; k < forces.size(); ++k)
          {
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(forces[k][c]);
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(contact.tools()[k].translation()[c]);
          }
          file.add_row(row);
        }

      private:
        io::CsvFile file;
      };
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      ToolForces,
      "tools",
      "tools.csv (with tools), per converged load: the force of each tool "
      "on the sheet and its translation.")
  } // namespace postprocess
} // namespace deepdraw
