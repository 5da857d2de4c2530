// Helpers for the contact tests that run a whole FormingProblem: build it
// from parameter text or from a .prm file in tests/contact/data, run it,
// and pick the sheet vertices of a face with their contact results.
#ifndef deepdraw_tests_contact_forming_test_tools_h
#define deepdraw_tests_contact_forming_test_tools_h

#include "test_utilities.h"

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/problem/forming_problem.h>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace forming_test
{
  using namespace dealii;

  // tests/contact/data of the source tree: tool files and parameter files
  // are read from there, wherever ctest runs the program.
  inline std::string
  data_directory()
  {
    return (std::filesystem::path(__FILE__).parent_path() / "data").string();
  }

  // Output goes to the working directory (the build tree), never into the
  // sources; no VTU, the tests read the results through the API.
  inline void
  redirect_output(ParameterHandler &prm, const std::string &output_directory)
  {
    prm.enter_subsection("Output");
    prm.set("Output directory", output_directory);
    prm.set("Write VTU", false);
    prm.leave_subsection();
  }

  // Parses text (tool files relative to data_directory()) and runs it.
  inline std::unique_ptr<deepdraw::problem::FormingProblem>
  run_from_text(const std::string &text, const std::string &output_directory)
  {
    ParameterHandler prm;
    deepdraw::problem::FormingProblem::declare_parameters(prm);
    prm.parse_input_from_string(text);
    redirect_output(prm, output_directory);
    auto problem
      = std::make_unique<deepdraw::problem::FormingProblem>(prm,
                                                            data_directory());
    problem->run();
    std::cout.precision(8);
    return problem;
  }

  // Runs data_directory()/name (the same file the benchmark script runs).
  inline std::unique_ptr<deepdraw::problem::FormingProblem>
  run_from_file(const std::string &name, const std::string &output_directory)
  {
    ParameterHandler prm;
    deepdraw::problem::FormingProblem::declare_parameters(prm);
    prm.parse_input(data_directory() + "/" + name);
    redirect_output(prm, output_directory);
    auto problem
      = std::make_unique<deepdraw::problem::FormingProblem>(prm,
                                                            data_directory());
    problem->run();
    std::cout.precision(8);
    return problem;
  }

  // Vertices whose initial coordinate `component` equals `value`.
  inline std::vector<unsigned int>
  vertices_on_plane(const deepdraw::problem::FormingProblem &problem,
                    const unsigned int                       component,
                    const double                             value)
  {
    std::vector<unsigned int> result;
    const auto               &X = problem.access().sheet().initial_vertices();
    for (unsigned int v = 0; v < X.size(); ++v)
      if (std::abs(X[v][component] - value) < 1e-10)
        result.push_back(v);
    return result;
  }

  // Total displacement of vertex v.
  inline Tensor<1, 3>
  vertex_displacement(const deepdraw::problem::FormingProblem &problem,
                      const unsigned int                       vertex)
  {
    const auto &u = problem.access().state().total_displacement;
    for (const auto &cell :
         problem.access().sheet().dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex_index(v) == vertex)
        {
          Tensor<1, 3> result;
          for (unsigned int c = 0; c < 3; ++c)
            result[c] = u[cell->vertex_dof_index(v, c)];
          return result;
        }
    return Tensor<1, 3>();
  }

  // visit(cell, v, vertex index) once per vertex of the mesh.
  template <typename Visitor>
  void
  for_each_vertex(const deepdraw::problem::FormingProblem &problem,
                  const Visitor                           &visit)
  {
    std::vector<bool> seen(problem.access().sheet().initial_vertices().size(),
                           false);
    for (const auto &cell :
         problem.access().sheet().dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
      {
        const unsigned int vertex = cell->vertex_index(v);
        if (seen[vertex])
          continue;
        seen[vertex] = true;
        visit(cell, v, vertex);
      }
  }
} // namespace forming_test

#endif
