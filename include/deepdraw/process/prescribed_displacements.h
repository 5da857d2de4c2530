// Prescribed displacements on faces of the blank as functions of the initial
// position (x, y, z) and of the load parameter t, read from
//   subsection Boundary conditions
//     set Prescribed displacements = xmin: ux = 0; xmax: ux = 10*(exp(0.5*t)-1)
// Faces: xmin, xmax, ymin, ymax, zmin, zmax; components: ux, uy, uz.
// The symmetry planes of the Geometry subsection add xmin: ux = 0 and
// ymin: uy = 0. Where two entries constrain the same node and component the
// later entry wins.
#ifndef deepdraw_process_prescribed_displacements_h
#define deepdraw_process_prescribed_displacements_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deepdraw/blank/blank_geometry.h>
#include <memory>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace process
  {
    using namespace dealii;

    struct PrescribedDisplacement
    {
      unsigned int boundary_id;
      unsigned int component;
      std::string  expression;
      // The whole item 'FACE: COMPONENT = EXPRESSION', for messages.
      std::string                        item;
      std::shared_ptr<FunctionParser<3>> function; // of (x, y, z) and t
    };

    class PrescribedDisplacements
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      // Throws InputError naming the entry if it cannot be understood.
      void
      parse_parameters(ParameterHandler &prm,
                       bool              symmetry_plane_x,
                       bool              symmetry_plane_y);
      // The same from the text of a list; parameter_name names it in
      // messages (a stage's list: "Process/Stage 2/Prescribed
      // displacements").
      void
      parse(const std::string &text,
            bool               symmetry_plane_x,
            bool               symmetry_plane_y,
            const std::string &parameter_name);

      // Largest |u| allowed at the check loads, in blank sizes (D50).
      static constexpr double max_relative_displacement = 100.;

      // Evaluates every entry at the nodes of its face at each of loads
      // (ProcessParameters::check_loads): throws InputError naming the
      // entry, the load and the point where a value is not finite or
      // larger than max_relative_displacement x the largest blank extent.
      void
      check_values(const blank::BlankGeometry &geometry,
                   const std::vector<double>  &loads) const;

      // Displacement component at initial position X and load t; throws
      // std::runtime_error naming the entry if it is not finite (a run-time
      // failure, exit code 3).
      double
      value(const PrescribedDisplacement &entry,
            const Point<3>               &X,
            double                        load) const;

      std::vector<PrescribedDisplacement> entries;
      // The parameter the entries were read from, for messages.
      std::string parameter = "Boundary conditions/Prescribed displacements";
    };
  } // namespace process
} // namespace deepdraw

#endif
