#include <algorithm>
#include <cmath>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deepdraw/discretisation/sheet_discretisation.h>
#include <deepdraw/fe/hanging_node_constraints.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/parallel/cell_partition.h>
#include <map>

namespace deepdraw
{
  namespace discretisation
  {
    SheetDiscretisation::SheetDiscretisation()
        : fe(FE_Q<3>(1), 3)
        , dofs(mesh)
        , fe_scalar(1)
        , scalar_dofs(mesh)
    {
    }


    void
    SheetDiscretisation::create(const blank::BlankGeometry &geometry,
                                const unsigned int points_through_thickness)
    {
      cell_quadrature
        = fe::selective_reduced_quadrature(points_through_thickness);
      geometry.create_mesh(mesh);
      initial_positions = mesh.get_vertices();
      // The mean in-plane element size of the blank (for the rectangle as
      // before, to the bit); the contact augmentation keeps it on refined
      // meshes (D82).
      element_size
        = geometry.outline == blank::BlankGeometry::Outline::rectangle
            ? std::sqrt(geometry.length / geometry.elements_along_x
                        * geometry.width / geometry.elements_along_y)
            : std::sqrt(GridTools::volume(mesh) / geometry.thickness
                        / geometry.n_plane_cells());
      distribute_dofs();
    }


    void
    SheetDiscretisation::distribute_dofs()
    {
      // Which rank evaluates which cells under mpirun (D215).
      parallel::partition_cells(mesh);
      cells_of_this_rank = parallel::OwnedCells(mesh);
      dofs.distribute_dofs(fe);
      // Hanging vertices of a refined mesh (doc/theory.md §8): their dofs
      // follow their masters, so they are neither prescribed nor contact
      // nodes (D82).
      hanging_nodes.clear();
      fe::make_q1_hanging_node_constraints(dofs, hanging_nodes);
      hanging_nodes.close();
      scalar_dofs.distribute_dofs(fe_scalar);

      dofs_of_vertex.assign(mesh.n_vertices(),
                            {{numbers::invalid_dof_index,
                              numbers::invalid_dof_index,
                              numbers::invalid_dof_index}});
      initial_dof_position.resize(dofs.n_dofs());
      component_of_dof.resize(dofs.n_dofs());
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < 3; ++c)
          {
            const auto dof = cell->vertex_dof_index(v, c);
            dofs_of_vertex[cell->vertex_index(v)][c] = dof;
            initial_dof_position[dof]
              = initial_positions[cell->vertex_index(v)];
            component_of_dof[dof] = c;
          }

      // Vertices of each face of the blank (by boundary id), sorted.
      free_face_vertices.assign(6, {});
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            for (const unsigned int v : face->vertex_indices())
              free_face_vertices[face->boundary_id()].push_back(
                face->vertex_index(v));
      for (unsigned int id = 0; id < free_face_vertices.size(); ++id)
      {
        auto &vertices = free_face_vertices[id];
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()),
                       vertices.end());
        face_dofs[id].clear();
        for (const unsigned int vertex : vertices)
          face_dofs[id].insert(face_dofs[id].end(),
                               dofs_of_vertex[vertex].begin(),
                               dofs_of_vertex[vertex].end());
        std::sort(face_dofs[id].begin(), face_dofs[id].end());
      }
      // The faces' reactions sum over all their vertices; prescribed dofs
      // and contact pairs are those of the vertices that are not hanging.
      for (auto &vertices : free_face_vertices)
        vertices.erase(std::remove_if(vertices.begin(),
                                      vertices.end(),
                                      [&](const unsigned int vertex) {
                                        return hanging_nodes.is_constrained(
                                          dofs_of_vertex[vertex][0]);
                                      }),
                       vertices.end());
      update_cell_geometry();
    }


    void
    SheetDiscretisation::add_blank_parents(
      const std::vector<fe::VertexParents> &parents,
      const unsigned int                    n_old_vertices)
    {
      if (blank_vertex_parents.empty())
        for (unsigned int v = 0; v < n_old_vertices; ++v)
          blank_vertex_parents.push_back({{v, 1.}});
      blank_vertex_parents.resize(mesh.n_vertices());
      initial_positions.resize(mesh.n_vertices());
      // The initial position of a new vertex is the Q1 interpolation of the
      // blank's, as its displacement is (doc/theory.md §8): prescribed
      // displacements and the region indicator need it. Interpolated from
      // the blank's vertices, not as x - u, so that a resume (which replays
      // the refinements) finds the same positions bit for bit.
      for (unsigned int v = n_old_vertices; v < mesh.n_vertices(); ++v)
      {
        std::map<unsigned int, double> sum;
        for (const auto &[parent, weight] : parents[v])
          for (const auto &[blank, w] : blank_vertex_parents[parent])
            sum[blank] += weight * w;
        blank_vertex_parents[v].assign(sum.begin(), sum.end());
        Point<3> X;
        for (const auto &[blank, w] : blank_vertex_parents[v])
          X += w * initial_positions[blank];
        initial_positions[v] = X;
      }
    }


    void
    SheetDiscretisation::replay_refinements(
      const std::vector<std::vector<std::array<int, 3>>> &cycles)
    {
      for (const auto &cycle : cycles)
      {
        const unsigned int n_old_vertices = mesh.n_vertices();
        for (const auto &[level, index, refinement] : cycle)
        {
          if (level < 0 || level >= int(mesh.n_levels()) || index < 0
              || index >= int(mesh.n_cells(level)))
            throw InputError("--resume: the checkpoint's refinements do not "
                             "belong to this mesh");
          const Triangulation<3>::cell_iterator cell(&mesh, level, index);
          if (!cell->is_active())
            throw InputError("--resume: the checkpoint's refinements do not "
                             "belong to this mesh");
          cell->set_refine_flag(RefinementCase<3>(refinement));
        }
        mesh.execute_coarsening_and_refinement();
        add_blank_parents(fe::vertex_parents(mesh, n_old_vertices),
                          n_old_vertices);
      }
      distribute_dofs();
    }


    void
    SheetDiscretisation::move_vertices(const Vector<double> &du)
    {
      // Updated Lagrangian: the converged configuration becomes the
      // reference of the next increment (step-18 moves the vertices too).
      std::vector<bool> moved(mesh.n_vertices(), false);
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (!moved[cell->vertex_index(v)])
          {
            moved[cell->vertex_index(v)] = true;
            for (unsigned int c = 0; c < 3; ++c)
              cell->vertex(v)[c]
                += du[dofs_of_vertex[cell->vertex_index(v)][c]];
          }
      update_cell_geometry();
    }


    void
    SheetDiscretisation::set_vertices(const std::vector<Point<3>> &positions)
    {
      for (const auto &cell : mesh.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          cell->vertex(v) = positions[cell->vertex_index(v)];
      update_cell_geometry();
    }


    void
    SheetDiscretisation::update_cell_geometry()
    {
      // Once per configuration, not per assembly (D13), and by the rank
      // that evaluates the cell only (D218).
      FEValues<3> fe_values(fe_scalar,
                            cell_quadrature,
                            fe::cell_geometry_flags());
      geometry_of_cells.resize(cells_of_this_rank.n_owned());
      for (const auto &cell : mesh.active_cell_iterators())
        if (parallel::is_owned(*cell))
        {
          fe_values.reinit(cell);
          fe::compute_cell_geometry(fe_values,
                                    geometry_of_cells[cells_of_this_rank.slot(
                                      cell->active_cell_index())]);
        }
    }


    const parallel::OwnedCells &
    SheetDiscretisation::owned_cells() const
    {
      return cells_of_this_rank;
    }


    unsigned int
    SheetDiscretisation::n_points_per_cell() const
    {
      return fe::n_weighted_points(cell_quadrature);
    }


    Triangulation<3> &
    SheetDiscretisation::triangulation()
    {
      return mesh;
    }


    const Triangulation<3> &
    SheetDiscretisation::triangulation() const
    {
      return mesh;
    }


    DoFHandler<3> &
    SheetDiscretisation::dof_handler()
    {
      return dofs;
    }


    const DoFHandler<3> &
    SheetDiscretisation::dof_handler() const
    {
      return dofs;
    }


    const DoFHandler<3> &
    SheetDiscretisation::scalar_dof_handler() const
    {
      return scalar_dofs;
    }


    types::global_dof_index
    SheetDiscretisation::n_displacement_dofs() const
    {
      return dofs.n_dofs();
    }


    const std::vector<Point<3>> &
    SheetDiscretisation::initial_vertices() const
    {
      return initial_positions;
    }


    const std::vector<std::array<types::global_dof_index, 3>> &
    SheetDiscretisation::vertex_dofs() const
    {
      return dofs_of_vertex;
    }


    const Point<3> &
    SheetDiscretisation::dof_initial_position(
      const types::global_dof_index dof) const
    {
      return initial_dof_position[dof];
    }


    unsigned int
    SheetDiscretisation::dof_component(const types::global_dof_index dof) const
    {
      return component_of_dof[dof];
    }


    const std::vector<std::vector<unsigned int>> &
    SheetDiscretisation::face_vertices() const
    {
      return free_face_vertices;
    }


    Tensor<1, 3>
    SheetDiscretisation::face_reaction(
      const unsigned int    boundary_id,
      const Vector<double> &internal_force) const
    {
      Tensor<1, 3> reaction;
      for (const auto dof : face_dofs[boundary_id])
        reaction[component_of_dof[dof]] += internal_force[dof];
      return reaction;
    }


    const AffineConstraints<double> &
    SheetDiscretisation::hanging_node_constraints() const
    {
      return hanging_nodes;
    }


    const std::vector<fe::CellGeometry> &
    SheetDiscretisation::cell_geometry() const
    {
      return geometry_of_cells;
    }


    double
    SheetDiscretisation::volume() const
    {
      // Σ JxW over the Gauss points of the current configuration: exact for
      // the trilinear geometry (volume conservation check, doc/results.md).
      double volume = 0.;
      for (const fe::CellGeometry &cell : geometry_of_cells)
        for (const double w : cell.JxW)
          volume += w;
      // Each rank has its own cells' (D218).
      parallel::sum(&volume, 1);
      return volume;
    }


    double
    SheetDiscretisation::blank_element_size() const
    {
      return element_size;
    }
  } // namespace discretisation
} // namespace deepdraw
