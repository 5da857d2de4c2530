// The earing profile of a drawn cup (doc/user_guide.md §3.1, D75): the cup
// height at every rim position against its angle from the rolling
// direction, written as earing_<travel>mm.csv, and the gnuplot script
// earing.gp that plots all of them.
#ifndef deepdraw_postprocess_earing_profile_h
#define deepdraw_postprocess_earing_profile_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <string>
#include <utility>
#include <vector>

namespace deepdraw
{
  namespace postprocess
  {
    using namespace dealii;

    class EaringProfile
    {
    public:
      // The rim: the vertices on the faces of rim_ids (the outline, not the
      // symmetry planes), grouped by their initial in-plane position (one
      // group per rim column); angles measured from the rolling direction,
      // rolling_direction_angle degrees from x.
      void
      set_up(const Triangulation<3>                &triangulation,
             const std::vector<Point<3>>           &initial_vertices,
             const std::vector<types::boundary_id> &rim_ids,
             double                                 rolling_direction_angle);

      // (angle_deg, height_mm) of every rim column, sorted by angle: the
      // height is the largest h = -d . x over the column's vertices minus
      // the smallest h over all vertices of the sheet (the outside of the
      // cup bottom), d the unit punch direction.
      std::vector<std::pair<double, double>>
      heights(const std::vector<Point<3>> &vertices,
              const Tensor<1, 3>          &punch_direction) const;

      // earing_<label>mm.csv in directory.
      void
      write(const std::string           &directory,
            const std::string           &label,
            const std::vector<Point<3>> &vertices,
            const Tensor<1, 3>          &punch_direction) const;

      // directory/earing.gp: 'gnuplot earing.gp' there plots every
      // earing_<label>mm.csv of labels into earing.png.
      static void
      write_plot_script(const std::string              &directory,
                        const std::vector<std::string> &labels);

    private:
      struct RimColumn
      {
        double                    angle_deg;
        std::vector<unsigned int> vertices;
      };
      std::vector<RimColumn> rim;
    };
  } // namespace postprocess
} // namespace deepdraw

#endif
