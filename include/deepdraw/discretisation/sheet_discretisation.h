// The finite-element discretisation of the sheet (doc/architecture.md): its
// mesh in the current configuration x_t (updated Lagrangian), the initial
// position of every vertex, the Q1 displacement dofs and a scalar Q1 dof
// handler for nodal output fields, the hanging-node constraints of a
// refined mesh, the vertices and dofs of each face of the blank, and the
// geometry of every cell on x_t.
#ifndef deepdraw_discretisation_sheet_discretisation_h
#define deepdraw_discretisation_sheet_discretisation_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <deepdraw/blank/blank_geometry.h>
#include <deepdraw/fe/cell_geometry.h>
#include <deepdraw/fe/vertex_parents.h>
#include <deepdraw/parallel/owned_cells.h>
#include <vector>

namespace deepdraw
{
  namespace discretisation
  {
    using namespace dealii;

    class SheetDiscretisation
    {
    public:
      SheetDiscretisation();

      // The blank's mesh (blank::BlankGeometry::create_mesh) and its dofs;
      // the cells integrated with points_through_thickness Gauss points
      // through the thickness (fe::selective_reduced_quadrature).
      void
      create(const blank::BlankGeometry &geometry,
             unsigned int                points_through_thickness);
      // The dofs of the current mesh (after create() or a refinement): the
      // hanging-node constraints, the dofs of every vertex, the faces, and
      // the cell geometry.
      void
      distribute_dofs();
      // After a refinement that added the vertices from n_old_vertices on:
      // their parents among the blank's vertices and their initial
      // positions, interpolated from those (parents: fe::vertex_parents).
      void
      add_blank_parents(const std::vector<fe::VertexParents> &parents,
                        unsigned int                          n_old_vertices);
      // A resume of an adaptive run: the refinement cycles of a checkpoint
      // on the blank's mesh (D84), then distribute_dofs(). Throws
      // InputError if a cycle does not belong to this mesh.
      void
      replay_refinements(
        const std::vector<std::vector<std::array<int, 3>>> &cycles);

      // Moves every vertex by the displacement block of du (updated
      // Lagrangian), or to the given positions, and recomputes the cell
      // geometry.
      void
      move_vertices(const Vector<double> &du);
      void
      set_vertices(const std::vector<Point<3>> &positions);

      Triangulation<3> &
      triangulation();
      const Triangulation<3> &
      triangulation() const;
      DoFHandler<3> &
      dof_handler();
      const DoFHandler<3> &
      dof_handler() const;
      // Scalar Q1 dofs on the same mesh (nodal output fields).
      const DoFHandler<3> &
      scalar_dof_handler() const;
      types::global_dof_index
      n_displacement_dofs() const;

      // Initial position X of every vertex.
      const std::vector<Point<3>> &
      initial_vertices() const;
      // The displacement dofs of every vertex.
      const std::vector<std::array<types::global_dof_index, 3>> &
      vertex_dofs() const;
      // Initial position of a dof's vertex, and its component.
      const Point<3> &
      dof_initial_position(types::global_dof_index dof) const;
      unsigned int
      dof_component(types::global_dof_index dof) const;
      // The vertices of each face of the blank (by boundary id) that are
      // not hanging: prescribed displacements and contact pairs live there.
      const std::vector<std::vector<unsigned int>> &
      face_vertices() const;
      // Sum of the internal forces over the dofs of a face, hanging
      // vertices included (a reaction).
      Tensor<1, 3>
      face_reaction(unsigned int          boundary_id,
                    const Vector<double> &internal_force) const;

      // Hanging vertices of a refined mesh (closed; empty on the blank's
      // mesh).
      const AffineConstraints<double> &
      hanging_node_constraints() const;
      // Geometry on x_t (gradients, weights) of the cells this rank
      // evaluates, by their slot in owned_cells() (every cell with one
      // rank, D218); recomputed whenever the vertices move.
      const std::vector<fe::CellGeometry> &
      cell_geometry() const;
      // The cells this rank evaluates (all with one rank), where the state
      // keeps their records (D215, D217); set by distribute_dofs().
      const parallel::OwnedCells &
      owned_cells() const;
      // The weighted points of the cells' quadrature: a cell's points in
      // the state.
      unsigned int
      n_points_per_cell() const;
      // Volume of the sheet on x_t (mm³); a sum over the ranks, which must
      // all call it.
      double
      volume() const;
      // Mean in-plane element size of the blank's mesh (contact
      // augmentation, D34, D82).
      double
      blank_element_size() const;

    private:
      void
      update_cell_geometry();

      Triangulation<3>                                    mesh;
      std::vector<Point<3>>                               initial_positions;
      FESystem<3>                                         fe;
      DoFHandler<3>                                       dofs;
      FE_Q<3>                                             fe_scalar;
      DoFHandler<3>                                       scalar_dofs;
      std::vector<std::array<types::global_dof_index, 3>> dofs_of_vertex;
      std::vector<Point<3>>                               initial_dof_position;
      std::vector<unsigned int>                           component_of_dof;
      std::array<std::vector<types::global_dof_index>, 6> face_dofs;
      std::vector<std::vector<unsigned int>>              free_face_vertices;
      AffineConstraints<double>                           hanging_nodes;
      parallel::OwnedCells                                cells_of_this_rank;
      std::vector<fe::CellGeometry>                       geometry_of_cells;
      Quadrature<3>                                       cell_quadrature;
      double                                              element_size = 1.;
      // After adaptive refinement: for every vertex, the blank's vertices
      // it is interpolated from (empty before the first refinement).
      std::vector<fe::VertexParents> blank_vertex_parents;
    };
  } // namespace discretisation
} // namespace deepdraw

#endif
