// The parameters of a forming model (doc/architecture.md, "Where each
// parameter subsection is parsed"): each subsection's component declares
// and parses its own; this gathers those the problem owns, parses them in
// order and checks what needs several of them at once (D11, D50, D53).
// The contact coupling and the post-processors, which keep state, parse
// theirs themselves.
#ifndef deepdraw_problem_model_parameters_h
#define deepdraw_problem_model_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/adaptivity/adaptivity_parameters.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/fe/element_technology.h>
#include <deepdraw/geometry/square_cup_tools.h>
#include <deepdraw/io/output_parameters.h>
#include <deepdraw/material/material_parameters.h>
#include <deepdraw/process/prescribed_displacements.h>
#include <deepdraw/process/process_parameters.h>
#include <deepdraw/process/stage.h>
#include <deepdraw/solver/increment_control.h>
#include <deepdraw/solver/linear_solver.h>
#include <deepdraw/solver/newton_parameters.h>
#include <deepdraw/state/checkpoint.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace problem
  {
    using namespace dealii;

    struct ModelParameters
    {
      // Every subsection of the program, the contact coupling's and the
      // post-processors' included.
      static void
      declare_parameters(ParameterHandler &prm);

      // Parses the subsections of the members, then the stages; relative
      // file names are taken from input_directory. Throws InputError.
      void
      parse_parameters(ParameterHandler  &prm,
                       const std::string &input_directory);

      // The checks across subsections, for the contact coupling set up from
      // the same prm (D50, D53): every expression at its stage's check
      // loads, the number of increments, the memory. Throws InputError.
      void
      check(const contact::ContactCoupling &contact) const;

      blank::BlankGeometry               geometry;
      process::ProcessParameters         process;
      material::MaterialParameters       material;
      fe::ElementParameters              element;
      process::PrescribedDisplacements   boundary_conditions;
      solver::IncrementControlParameters load_stepping;
      solver::NewtonParameters           newton;
      solver::LinearSolverParameters     linear_solver;
      io::OutputParameters               output;
      geometry::SquareCupToolParameters  square_cup_tools;
      state::CheckpointParameters        checkpoint;
      adaptivity::AdaptivityParameters   adaptivity;
      // The stages of the process (process::parse_stages).
      std::vector<process::Stage> stages;
      // All parameters, flattened (a checkpoint refuses another model), and
      // their defaults (for a checkpoint older than a parameter).
      std::string listing;
      std::string default_listing;
    };
  } // namespace problem
} // namespace deepdraw

#endif
