// Post-processor "reactions": reactions.csv, per converged load (and
// t = 0), the force (N) applied to the blank through every face that
// carries a prescribed displacement in some stage, symmetry planes
// included: the sum of the internal nodal forces of the face's nodes
// (doc/user_guide.md §3).
#include <deepdraw/io/csv_file.h>
#include <deepdraw/postprocess/interface.h>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      class Reactions : public Interface
      {
      public:
        void
        start(const SimulationAccess &simulation, const bool resume) override
        {
          std::vector<std::string> columns = {"load"};
          for (const unsigned int face : simulation.reaction_faces())
            for (const char *component : {"_Fx", "_Fy", "_Fz"})
              columns.push_back(blank::face_names[face] + component);
          file.open(simulation.output_directory() + "/reactions.csv",
                    columns,
                    resume);
        }

        void
        execute(const SimulationAccess &simulation) override
        {
          std::vector<double> row = {simulation.state().load};
          for (const unsigned int face : simulation.reaction_faces())
          {
            const Tensor<1, 3> reaction = simulation.face_reaction(face);
            for (unsigned int c = 0; c < 3; ++c)
              row.push_back(reaction[c]);
          }
          file.add_row(row);
        }

      private:
        io::CsvFile file;
      };
    } // namespace

    DEEPDRAW_REGISTER_POSTPROCESSOR(
      Reactions,
      "reactions",
      "reactions.csv, per converged load: the force on the blank through "
      "every face with a prescribed displacement (xmin_Fx, ...).")
  } // namespace postprocess
} // namespace deepdraw
