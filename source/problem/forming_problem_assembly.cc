// Element residual and exact tangent of the updated-Lagrangian hexahedron
// with selective reduced integration (DESIGN §1.1, §1.3):
//   r_i = sum_q w_q Gbar_i(q) : P_q,   K_ij = sum_q w_q Gbar_i : dP/dH : Gbar_j,
// with Gbar_i = e_c (x) g_a + 1/3 (g_a^centre[c] - g_a[c]) I the gradient of
// the shape function i = (node a, component c) whose trace is replaced by the
// trace at the cell centre (reference Eqs. 17-18; full integration: no
// correction). Gradients are with respect to x_t and computed once per
// increment.
#include <deal.II/base/timer.h>
#include <deal.II/base/work_stream.h>

#include <deal.II/fe/fe_values.h>

#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/problem/forming_problem.h>

#include <atomic>

namespace deepdraw
{
  namespace problem
  {
    void
    FormingProblem::update_cell_geometry()
    {
      const Quadrature<3> quadrature = fe::selective_reduced_quadrature();
      FEValues<3>         fe_values(fe_scalar,
                            quadrature,
                            update_gradients | update_JxW_values);
      cell_geometry.resize(triangulation.n_active_cells());
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          fe_values.reinit(cell);
          CellGeometry &geometry = cell_geometry[cell->active_cell_index()];
          for (unsigned int q = 0; q < fe::n_weighted_points; ++q)
            {
              geometry.JxW[q] = fe_values.JxW(q);
              for (unsigned int a = 0; a < 8; ++a)
                geometry.gradient[q * 8 + a] = fe_values.shape_grad(a, q);
            }
          for (unsigned int a = 0; a < 8; ++a)
            geometry.centre_gradient[a] =
              fe_values.shape_grad(a, fe::centre_point);
        }
    }



    namespace
    {
      struct AssemblyScratch
      {};

      struct AssemblyCopy
      {
        FullMatrix<double> matrix = FullMatrix<double>(24, 24);
        Vector<double>     residual = Vector<double>(24);
        std::vector<types::global_dof_index> dofs =
          std::vector<types::global_dof_index>(24);
        bool active = false;
      };
    } // namespace



    FormingProblem::IncrementOutcome
    FormingProblem::assemble(const Vector<double>            &du,
                             const AffineConstraints<double> &constraints,
                             const bool                       assemble_matrix)
    {
      Timer timer;
      if (assemble_matrix)
        system_matrix = 0.;
      system_rhs     = 0.;
      internal_force = 0.;
      std::atomic<int>          worst_status{0};
      std::atomic<unsigned int> plastic_points{0};
      const bool                sri = selective_reduced_integration;

      auto worker = [&](const typename DoFHandler<3>::active_cell_iterator &cell,
                        AssemblyScratch &,
                        AssemblyCopy &copy) {
        copy.active = false;
        cell->get_dof_indices(copy.dofs);
        const unsigned int  index    = cell->active_cell_index();
        const CellGeometry &geometry = cell_geometry[index];

        // Nodal displacement increments u[a][c].
        Tensor<1, 3> u[8];
        for (unsigned int i = 0; i < 24; ++i)
          u[local_node[i]][local_component[i]] = du[copy.dofs[i]];

        // Trace of H at the centre: the volumetric part used at every point.
        double centre_divergence = 0.;
        for (unsigned int a = 0; a < 8; ++a)
          centre_divergence += u[a] * geometry.centre_gradient[a];

        copy.matrix   = 0.;
        copy.residual = 0.;
        Tensor<4, 3> A;
        Tensor<2, 3> P;
        for (unsigned int q = 0; q < fe::n_weighted_points; ++q)
          {
            const Tensor<1, 3> *g = &geometry.gradient[q * 8];
            Tensor<2, 3>        H;
            for (unsigned int a = 0; a < 8; ++a)
              H += outer_product(u[a], g[a]);
            if (sri)
              {
                const double correction = (centre_divergence - trace(H)) / 3.;
                for (unsigned int d = 0; d < 3; ++d)
                  H[d][d] += correction;
              }

            const unsigned int point = index * fe::n_weighted_points + q;
            bool               plastic = false;
            const PointStatus  status  = update_quadrature_point(
              *material,
              history[point],
              H,
              trial_history[point],
              P,
              assemble_matrix ? &A : nullptr,
              plastic);
            if (status != PointStatus::ok)
              {
                // Atomic maximum: a return-mapping failure (2) is reported
                // over an inverted element (1).
                const int code = status == PointStatus::inverted ? 1 : 2;
                int       seen = worst_status.load();
                while (seen < code
                       && !worst_status.compare_exchange_weak(seen, code))
                  {
                  }
                return;
              }
            if (plastic)
              ++plastic_points;

            const double w = geometry.JxW[q];
            // beta_i: trace correction of Gbar_i; Gbar_i : T =
            //   T[c] . g_a + beta_i tr T.
            double beta[24];
            for (unsigned int i = 0; i < 24; ++i)
              {
                const unsigned int a = local_node[i], c = local_component[i];
                beta[i] =
                  sri ? (geometry.centre_gradient[a][c] - g[a][c]) / 3. : 0.;
              }
            const double trace_P = trace(P);
            for (unsigned int i = 0; i < 24; ++i)
              {
                const unsigned int a = local_node[i], c = local_component[i];
                copy.residual(i) += w * (P[c] * g[a] + beta[i] * trace_P);
              }
            if (!assemble_matrix)
              continue;

            // A_trace[i][j] = sum_m A[i][j][m][m]
            Tensor<2, 3> A_trace;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                A_trace[i][j] = A[i][j][0][0] + A[i][j][1][1] + A[i][j][2][2];
            for (unsigned int j = 0; j < 24; ++j)
              {
                const unsigned int b = local_node[j], d = local_component[j];
                // T = A : Gbar_j
                Tensor<2, 3> T;
                for (unsigned int k = 0; k < 3; ++k)
                  for (unsigned int l = 0; l < 3; ++l)
                    T[k][l] = A[k][l][d] * g[b] + beta[j] * A_trace[k][l];
                const double trace_T = trace(T);
                for (unsigned int i = 0; i < 24; ++i)
                  {
                    const unsigned int a = local_node[i], c = local_component[i];
                    copy.matrix(i, j) +=
                      w * (T[c] * g[a] + beta[i] * trace_T);
                  }
              }
          }
        copy.active = true;
      };

      auto copier = [&](const AssemblyCopy &copy) {
        if (!copy.active)
          return;
        for (unsigned int i = 0; i < 24; ++i)
          internal_force[copy.dofs[i]] += copy.residual(i);
        Vector<double> rhs(copy.residual);
        rhs *= -1.;
        if (assemble_matrix)
          constraints.distribute_local_to_global(
            copy.matrix, rhs, copy.dofs, system_matrix, system_rhs);
        else
          constraints.distribute_local_to_global(rhs, copy.dofs, system_rhs);
      };

      WorkStream::run(dof_handler.begin_active(),
                      dof_handler.end(),
                      worker,
                      copier,
                      AssemblyScratch(),
                      AssemblyCopy());
      n_plastic_points = plastic_points;
      assembly_time += timer.wall_time();
      total_assembly_seconds += timer.wall_time();

      // Contact forces and their constraints, after the elements so that
      // the assembly time excludes the contact search.
      if (contact.active())
        contact_changes +=
          contact.assemble(triangulation.get_vertices(),
                           du,
                           constraints,
                           assemble_matrix ? &system_matrix : nullptr,
                           system_rhs,
                           target_load);

      if (worst_status == 1)
        return IncrementOutcome::inverted_element;
      if (worst_status == 2)
        return IncrementOutcome::return_mapping_failed;
      return IncrementOutcome::converged;
    }



    bool
    FormingProblem::assemble_system(const Vector<double> &du)
    {
      AffineConstraints<double> none;
      none.close();
      return assemble(du, none, true) == IncrementOutcome::converged;
    }



    double
    FormingProblem::total_assembly_time() const
    {
      return total_assembly_seconds;
    }



    bool
    FormingProblem::evaluate_residual(const Vector<double> &du,
                                      Vector<double>       &residual,
                                      FullMatrix<double>   *tangent)
    {
      AffineConstraints<double> none;
      none.close();
      const IncrementOutcome status = assemble(du, none, tangent != nullptr);
      residual                      = internal_force;
      if (tangent != nullptr)
        {
          tangent->reinit(dof_handler.n_dofs(), dof_handler.n_dofs());
          for (unsigned int i = 0; i < system_matrix.m(); ++i)
            for (auto entry = system_matrix.begin(i);
                 entry != system_matrix.end(i);
                 ++entry)
              (*tangent)(i, entry->column()) = entry->value();
        }
      return status == IncrementOutcome::converged;
    }
  } // namespace problem
} // namespace deepdraw
