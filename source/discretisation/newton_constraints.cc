#include <deal.II/base/index_set.h>
#include <deepdraw/discretisation/newton_constraints.h>
#include <map>

namespace deepdraw
{
  namespace discretisation
  {
    namespace
    {
      void
      add_hanging_node_constraints(const AffineConstraints<double> &hanging,
                                   AffineConstraints<double>       &constraints)
      {
        for (const auto &line : hanging.get_lines())
        {
          constraints.add_line(line.index);
          constraints.add_entries(line.index, line.entries);
        }
      }
    } // namespace


    void
    NewtonConstraints::set_up(
      const SheetDiscretisation                  &sheet,
      const process::PrescribedDisplacements     &prescribed,
      const std::vector<solver::MultiplierBlock> &multiplier_blocks,
      const types::global_dof_index               n_unknowns,
      const std::vector<types::global_dof_index> &held_dofs)
    {
      // Prescribed dofs; a later entry overrides an earlier one.
      const auto &face_vertices = sheet.face_vertices();
      const auto &vertex_dofs   = sheet.vertex_dofs();
      std::map<types::global_dof_index, const process::PrescribedDisplacement *>
        owner;
      for (const process::PrescribedDisplacement &entry : prescribed.entries)
        for (const unsigned int vertex : face_vertices[entry.boundary_id])
          owner[vertex_dofs[vertex][entry.component]] = &entry;
      for (const types::global_dof_index dof : held_dofs)
        owner[dof] = nullptr;
      prescribed_dofs.assign(owner.begin(), owner.end());

      constrained_multipliers.clear();
      for (const solver::MultiplierBlock &block : multiplier_blocks)
        for (unsigned int c = 0; c < 3; ++c)
          if (owner.count(block.displacement[c]) > 0)
            constrained_multipliers.push_back(block.multiplier[c]);
      homogeneous_constraints.clear();
      homogeneous_constraints.reinit(complete_index_set(n_unknowns));
      for (const auto &[dof, entry] : prescribed_dofs)
        homogeneous_constraints.add_line(dof);
      for (const auto dof : constrained_multipliers)
        homogeneous_constraints.add_line(dof);
      add_hanging_node_constraints(sheet.hanging_node_constraints(),
                                   homogeneous_constraints);
      homogeneous_constraints.close();
    }


    void
    NewtonConstraints::set_increment(
      const SheetDiscretisation              &sheet,
      const process::PrescribedDisplacements &prescribed,
      const double                            old_load,
      const double                            new_load)
    {
      predictor_constraints.clear();
      for (const auto &[dof, entry] : prescribed_dofs)
      {
        predictor_constraints.add_line(dof);
        if (entry == nullptr)
          continue;
        const Point<3> &X = sheet.dof_initial_position(dof);
        predictor_constraints.set_inhomogeneity(
          dof,
          prescribed.value(*entry, X, new_load)
            - prescribed.value(*entry, X, old_load));
      }
      for (const auto dof : constrained_multipliers)
        predictor_constraints.add_line(dof);
      add_hanging_node_constraints(sheet.hanging_node_constraints(),
                                   predictor_constraints);
      predictor_constraints.close();
    }


    const AffineConstraints<double> &
    NewtonConstraints::homogeneous() const
    {
      return homogeneous_constraints;
    }


    const AffineConstraints<double> &
    NewtonConstraints::predictor() const
    {
      return predictor_constraints;
    }


    void
    NewtonConstraints::clear_constrained_multipliers(
      Vector<double> &unknowns) const
    {
      for (const auto dof : constrained_multipliers)
        unknowns[dof] = 0.;
    }


    std::vector<types::global_dof_index>
    NewtonConstraints::decoupled_unknowns(
      const SheetDiscretisation &sheet) const
    {
      std::vector<types::global_dof_index> decoupled;
      for (const auto &[dof, entry] : prescribed_dofs)
        decoupled.push_back(dof);
      decoupled.insert(decoupled.end(),
                       constrained_multipliers.begin(),
                       constrained_multipliers.end());
      for (const auto &line : sheet.hanging_node_constraints().get_lines())
        decoupled.push_back(line.index);
      return decoupled;
    }
  } // namespace discretisation
} // namespace deepdraw
