// Shared by the element tests: a forming problem run from a prm text, and a
// visit of every vertex of its mesh once.
#ifndef deepdraw_tests_element_test_tools_h
#define deepdraw_tests_element_test_tools_h

#include <deal.II/base/parameter_handler.h>
#include <deepdraw/problem/forming_problem.h>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace element_test
{
  // Declares, parses prm_text, runs to the end (throws RunFailure if an
  // increment fails).
  inline std::unique_ptr<deepdraw::problem::FormingProblem>
  run_forming_problem(const std::string &prm_text)
  {
    dealii::ParameterHandler prm;
    deepdraw::problem::FormingProblem::declare_parameters(prm);
    prm.parse_input_from_string(prm_text);
    auto forming_problem
      = std::make_unique<deepdraw::problem::FormingProblem>(prm);
    forming_problem->run();
    std::cout.precision(6); // run() leaves it at 3
    return forming_problem;
  }

  // visit(cell, v, vertex index) once per vertex of the mesh.
  template <typename Visitor>
  void
  for_each_vertex(const deepdraw::problem::FormingProblem &forming_problem,
                  const Visitor                           &visit)
  {
    std::vector<bool> seen(forming_problem.get_initial_vertices().size(),
                           false);
    for (const auto &cell :
         forming_problem.get_dof_handler().active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
      {
        const unsigned int vertex = cell->vertex_index(v);
        if (seen[vertex])
          continue;
        seen[vertex] = true;
        visit(cell, v, vertex);
      }
  }
} // namespace element_test

#endif
