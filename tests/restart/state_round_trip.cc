// state::SimulationState, the committed state of a run (doc/architecture.md):
// after three plastic bending increments with incompatible modes (non-zero
// stresses, back stresses, plastic strains, rotated material axes, enhanced
// parameters and a moved mesh), write() and read() reproduce every field
// bit for bit; a stream cut short, or one that is not a state, is rejected.
// With 2 Gauss points through the thickness (9 enhanced parameters a cell,
// format 5) and with 4 (15, the through-thickness modes' among them
// non-zero: format 6, D202). A history of more points than are packed at a
// time, and a checkpoint written to a full disk (D221).
#include "contact/forming_test_tools.h"
#include "test_utilities.h"

#include <deal.II/base/mpi.h>
#include <deepdraw/problem/forming_problem.h>
#include <deepdraw/state/checkpoint.h>
#include <fstream>
#include <sstream>

using namespace dealii;
using namespace deepdraw;

namespace
{
  const char *prm_text = R"(
subsection Geometry
  set Length = 6
  set Width = 1
  set Thickness = 0.81
  set Elements along x = 4
  set Elements along y = 1
  set Layers through thickness = 2
  set Symmetry planes =
  set Mesh distortion = 0.2
end
subsection Material
  set Prager modulus = 1000
end
subsection Boundary conditions
  set Prescribed displacements = xmin: ux = 0; xmin: uy = 0; xmin: uz = 0; xmax: ux = 0.1*t*(z - 0.405); xmax: uz = 0.2*t
end
subsection Process
  set Final load = 0.3
end
subsection Load stepping
  set Initial increment = 0.1
  set Maximum increment = 0.1
end
subsection Output
  set Output directory = state-test-output
  set Write VTU = false
end
)";

  bool
  same(const Vector<double> &a, const Vector<double> &b)
  {
    if (a.size() != b.size())
      return false;
    for (unsigned int i = 0; i < a.size(); ++i)
      if (!(a[i] == b[i]))
        return false;
    return true;
  }

  void
  round_trip(const unsigned int points)
  {
    const std::string name            = std::to_string(points) + " points: ";
    const auto        forming_problem = forming_test::run_from_text(
      std::string(prm_text)
        + "subsection Finite element\n  set Points through the thickness = "
        + std::to_string(points) + "\nend\n",
      "state-test-output");
    // This model has no tools: the contact history is given values here so
    // that its serialisation is checked too (the contact runs are checked end
    // to end by kill_and_resume_test.py).
    state::SimulationState state = forming_problem->access().state();
    state.contact.pair_open      = {1, 0, 1};
    state.contact.pair_status    = {0, 2, 3};
    state.contact.tool_position  = {0.5, -1.25};
    // And the refinement cycles of an adaptive run (D84).
    state.refinements = {{{0, 3, 7}, {1, 12, 4}}, {}, {{2, 5, 3}}};

    // The state is not trivial (else the comparison proves little).
    double largest_plastic_strain = 0., largest_enhanced = 0., axes_turn = 0.;
    for (const auto &point : state.history)
    {
      largest_plastic_strain = std::max(largest_plastic_strain,
                                        point.state.equivalent_plastic_strain);
      axes_turn = std::max(axes_turn, std::abs(point.material_axes[0][2]));
    }
    double largest_thickness_mode = 0.;
    for (const auto &cell : state.enhanced_parameters)
      for (unsigned int k = 0; k < cell.values.size(); ++k)
        (k < 9 ? largest_enhanced : largest_thickness_mode)
          = std::max(k < 9 ? largest_enhanced : largest_thickness_mode,
                     std::abs(cell.values[k]));
    deepdraw_test::check_true(name + "through-thickness modes "
                                + (points > 2 ? "non-zero" : "unused"),
                              (largest_thickness_mode > 0.) == (points > 2));
    deepdraw_test::check_true(name + "plastic points (epbar "
                                + std::to_string(largest_plastic_strain) + ")",
                              largest_plastic_strain > 1e-3);
    deepdraw_test::check_true(name + "enhanced parameters are not zero",
                              largest_enhanced > 0.);
    deepdraw_test::check_true(name + "material axes turned", axes_turn > 1e-4);
    deepdraw_test::check_true(name + "three increments, load 0.3",
                              state.increment_number == 3
                                && std::abs(state.load - 0.3) < 1e-12);
    deepdraw_test::check_true(name + "next increment 0.1 (Maximum increment)",
                              std::abs(state.next_increment - 0.1) < 1e-15);

    std::stringstream stream;
    state.write(stream);
    const std::string image = stream.str();
    deepdraw_test::check_true(
      name + "format " + (points > 2 ? "6" : "5"),
      image.rfind(points > 2 ? "deepdraw-state-6" : "deepdraw-state-5", 0)
        == 0);
    state::SimulationState copy;
    std::istringstream     input(image);
    copy.read(input);

    bool vertices_same = copy.vertices.size() == state.vertices.size();
    for (unsigned int v = 0; vertices_same && v < state.vertices.size(); ++v)
      vertices_same = copy.vertices[v] == state.vertices[v];
    bool history_same = copy.history.size() == state.history.size();
    for (unsigned int q = 0; history_same && q < state.history.size(); ++q)
      history_same
        = copy.history[q].state.stress == state.history[q].state.stress
          && copy.history[q].state.back_stress
               == state.history[q].state.back_stress
          && copy.history[q].state.equivalent_plastic_strain
               == state.history[q].state.equivalent_plastic_strain
          && copy.history[q].material_axes == state.history[q].material_axes;
    bool enhanced_same
      = copy.enhanced_parameters.size() == state.enhanced_parameters.size();
    for (unsigned int c = 0;
         enhanced_same && c < state.enhanced_parameters.size();
         ++c)
      enhanced_same = copy.enhanced_parameters[c].values
                        == state.enhanced_parameters[c].values
                      && copy.enhanced_parameters[c].sensitivity
                           == state.enhanced_parameters[c].sensitivity
                      && copy.enhanced_parameters[c].evaluated_at
                           == state.enhanced_parameters[c].evaluated_at
                      && copy.enhanced_parameters[c].correction
                           == state.enhanced_parameters[c].correction;
    deepdraw_test::check_true(name + "load, step, increment",
                              copy.load == state.load
                                && copy.last_load_increment
                                     == state.last_load_increment
                                && copy.increment_number
                                     == state.increment_number
                                && copy.next_increment == state.next_increment);
    deepdraw_test::check_true(name + "contact history",
                              copy.contact.pair_open == state.contact.pair_open
                                && copy.contact.pair_status
                                     == state.contact.pair_status
                                && copy.contact.tool_position
                                     == state.contact.tool_position);
    deepdraw_test::check_true(name + "refinement cycles",
                              copy.refinements == state.refinements);
    deepdraw_test::check_true(name + "vertices", vertices_same);
    deepdraw_test::check_true(
      "total displacement, Newton unknowns",
      same(copy.total_displacement, state.total_displacement)
        && same(copy.converged_solution, state.converged_solution)
        && same(copy.previous_converged_solution,
                state.previous_converged_solution));
    deepdraw_test::check_true(name + "quadrature-point history", history_same);
    deepdraw_test::check_true(name + "enhanced parameters", enhanced_same);

    // Cut short anywhere: rejected.
    bool truncated_rejected = true;
    for (const std::size_t length :
         {std::size_t(0), std::size_t(10), image.size() / 2, image.size() - 1})
    {
      std::istringstream     cut(image.substr(0, length));
      state::SimulationState target;
      try
      {
        target.read(cut);
        truncated_rejected = false;
      }
      catch (const std::runtime_error &)
      {
      }
    }
    deepdraw_test::check_true(name + "a stream cut short is rejected",
                              truncated_rejected);
    std::istringstream     foreign("this is not a state, only text......");
    state::SimulationState target;
    bool                   foreign_rejected = false;
    try
    {
      target.read(foreign);
    }
    catch (const std::runtime_error &)
    {
      foreign_rejected = true;
    }
    deepdraw_test::check_true(name + "a foreign stream is rejected",
                              foreign_rejected);
  }

  // More points than the writer packs at a time (4 096, D221), the last
  // block part full: every point read back bit for bit, its values naming
  // it. The checkpoint's image written to a full disk (/dev/full) fails.
  void
  many_points()
  {
    state::SimulationState saved;
    saved.next_increment = 0.1;
    saved.history.resize(2 * 4096 + 5);
    for (std::size_t q = 0; q < saved.history.size(); ++q)
    {
      fe::QuadraturePointHistory &point     = saved.history[q];
      point.state.equivalent_plastic_strain = 1e-6 * double(q);
      point.state.stress[0][1]              = double(q);
      point.material_axes[2][0]             = -double(q);
    }
    std::stringstream stream(std::ios::in | std::ios::out | std::ios::binary);
    saved.write(stream);
    state::SimulationState read;
    read.read(stream);
    bool same = read.history.size() == saved.history.size();
    for (std::size_t q = 0; same && q < saved.history.size(); ++q)
      same = read.history[q].state.equivalent_plastic_strain
               == saved.history[q].state.equivalent_plastic_strain
             && read.history[q].state.stress == saved.history[q].state.stress
             && read.history[q].material_axes == saved.history[q].material_axes;
    deepdraw_test::check_true("8 197 points, three blocks: read back bit for "
                              "bit",
                              same);

    state::Checkpoint checkpoint;
    checkpoint.state = saved;
    std::ofstream full("/dev/full", std::ios::binary);
    bool          failed = false;
    try
    {
      state::write_checkpoint_image(full, checkpoint);
      full.flush();
      failed = !full;
    }
    catch (const std::runtime_error &)
    {
      failed = true;
    }
    deepdraw_test::check_true("a checkpoint written to a full disk fails",
                              failed);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  round_trip(2);
  round_trip(4);
  many_points();
  return deepdraw_test::summary();
}
