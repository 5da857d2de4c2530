// Element residual and exact tangent of the updated-Lagrangian hexahedron
// with selective reduced integration (DESIGN §1.1, §1.3):
//   r_i = sum_q w_q Gbar_i(q) : P_q,   K_ij = sum_q w_q Gbar_i : dP/dH :
//   Gbar_j,
// with Gbar_i = e_c (x) g_a + 1/3 (gbar_a[c] - g_a[c]) I the gradient of
// the shape function i = (node a, component c) whose trace is replaced by a
// constant one, gbar_a = (1/V) int g_a dV (reference Eqs. 17-18 in the mean
// dilatation form; full integration: no correction). Gradients are with
// respect to x_t and computed once per increment.
#include <atomic>
#include <deal.II/base/timer.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/fe/fe_values.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <deepdraw/problem/forming_problem.h>

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
        // The constant volumetric gradient is the volume average
        // (1/V) int grad N_a dV (mean dilatation), not the gradient at the
        // centre: the two agree on parallelepipeds, but only the average
        // passes the patch test on warped hexahedra (the SRI term of an
        // interior node's residual is tr P / 3 sum_cells
        // (V gbar_a - int grad N_a), zero only if gbar_a is the average;
        // tests/element/patch_test.cc). 2x2x2 Gauss integrates grad N_a
        // exactly on a trilinear cell.
        double volume = 0.;
        geometry.mean_gradient.fill(Tensor<1, 3>());
        for (unsigned int q = 0; q < fe::n_weighted_points; ++q)
        {
          geometry.JxW[q] = fe_values.JxW(q);
          volume += geometry.JxW[q];
          for (unsigned int a = 0; a < 8; ++a)
          {
            geometry.gradient[q * 8 + a] = fe_values.shape_grad(a, q);
            geometry.mean_gradient[a]
              += geometry.JxW[q] * geometry.gradient[q * 8 + a];
          }
        }
        for (unsigned int a = 0; a < 8; ++a)
          geometry.mean_gradient[a] /= volume;
      }
    }


    namespace
    {
      struct AssemblyScratch
      {
      };

      struct AssemblyCopy
      {
        FullMatrix<double> matrix   = FullMatrix<double>(24, 24);
        Vector<double>     residual = Vector<double>(24);
        std::vector<types::global_dof_index> dofs
          = std::vector<types::global_dof_index>(24);
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

      auto worker
        = [&](const typename DoFHandler<3>::active_cell_iterator &cell,
              AssemblyScratch &,
              AssemblyCopy &copy)
      {
        copy.active = false;
        cell->get_dof_indices(copy.dofs);
        const unsigned int  index    = cell->active_cell_index();
        const CellGeometry &geometry = cell_geometry[index];

        // Nodal displacement increments u[a][c].
        Tensor<1, 3> u[8];
        for (unsigned int i = 0; i < 24; ++i)
          u[local_node[i]][local_component[i]] = du[copy.dofs[i]];

        // Cell-average trace of H: the volumetric part used at every point.
        double mean_divergence = 0.;
        for (unsigned int a = 0; a < 8; ++a)
          mean_divergence += u[a] * geometry.mean_gradient[a];

        copy.matrix   = 0.;
        copy.residual = 0.;
        // Counted per cell: one atomic update instead of one per point.
        unsigned int cell_plastic_points = 0;
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
            const double correction = (mean_divergence - trace(H)) / 3.;
            for (unsigned int d = 0; d < 3; ++d)
              H[d][d] += correction;
          }

          const unsigned int point   = index * fe::n_weighted_points + q;
          bool               plastic = false;
          const PointStatus  status
            = update_quadrature_point(*material,
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
          cell_plastic_points += plastic;

          const double w = geometry.JxW[q];
          // beta_i: trace correction of Gbar_i; Gbar_i : T =
          //   T[c] . g_a + beta_i tr T.
          double beta[24];
          for (unsigned int i = 0; i < 24; ++i)
          {
            const unsigned int a = local_node[i], c = local_component[i];
            beta[i] = sri ? (geometry.mean_gradient[a][c] - g[a][c]) / 3. : 0.;
          }
          const double trace_P = trace(P);
          for (unsigned int i = 0; i < 24; ++i)
          {
            const unsigned int a = local_node[i], c = local_component[i];
            copy.residual(i) += w * (P[c] * g[a] + beta[i] * trace_P);
          }
          if (!assemble_matrix)
            continue;

          // K_ij += w Gbar_i : A : Gbar_j in two sparse steps (Gbar_j has
          // 3 + 3 non-zeros): T_j = w A : Gbar_j, stored as
          // T[c][m][j] = (T_j)_cm so that the update of a row i = (a, c),
          //   K_ij += sum_m g_a[m] T[c][m][j] + beta_i tr T_j,
          // runs contiguously over j.
          double A_trace[3][3]; // sum_n A[c][m][n][n]
          for (unsigned int c = 0; c < 3; ++c)
            for (unsigned int m = 0; m < 3; ++m)
              A_trace[c][m] = A[c][m][0][0] + A[c][m][1][1] + A[c][m][2][2];
          double T[3][3][24], trace_T[24];
          for (unsigned int j = 0; j < 24; ++j)
          {
            const unsigned int  b = local_node[j], d = local_component[j];
            const Tensor<1, 3> &g_b = g[b];
            for (unsigned int c = 0; c < 3; ++c)
              for (unsigned int m = 0; m < 3; ++m)
              {
                const Tensor<1, 3> &A_cmd = A[c][m][d];
                T[c][m][j]                = w
                             * (A_cmd[0] * g_b[0] + A_cmd[1] * g_b[1]
                                + A_cmd[2] * g_b[2] + beta[j] * A_trace[c][m]);
              }
            trace_T[j] = T[0][0][j] + T[1][1][j] + T[2][2][j];
          }
          for (unsigned int i = 0; i < 24; ++i)
          {
            const unsigned int a = local_node[i], c = local_component[i];
            const double       g0 = g[a][0], g1 = g[a][1], g2 = g[a][2];
            const double       beta_i = beta[i];
            double            *K_i    = &copy.matrix(i, 0);
            for (unsigned int j = 0; j < 24; ++j)
              K_i[j] += g0 * T[c][0][j] + g1 * T[c][1][j] + g2 * T[c][2][j]
                        + beta_i * trace_T[j];
          }
        }
        plastic_points += cell_plastic_points;
        copy.active = true;
      };

      auto copier = [&](const AssemblyCopy &copy)
      {
        if (!copy.active)
          return;
        for (unsigned int i = 0; i < 24; ++i)
          internal_force[copy.dofs[i]] += copy.residual(i);
        Vector<double> rhs(copy.residual);
        rhs *= -1.;
        if (assemble_matrix)
          constraints.distribute_local_to_global(copy.matrix,
                                                 rhs,
                                                 copy.dofs,
                                                 system_matrix,
                                                 system_rhs);
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

      // Contact forces and their constraints, after the elements so that
      // the assembly time excludes the contact search.
      if (contact.active())
        contact_changes
          += contact.assemble(triangulation.get_vertices(),
                              du,
                              constraints,
                              assemble_matrix ? &system_matrix : nullptr,
                              system_rhs,
                              target_load,
                              &constraints == &predictor_constraints);

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


    bool
    FormingProblem::evaluate_residual(const Vector<double> &du,
                                      Vector<double>       &residual,
                                      FullMatrix<double>   *tangent)
    {
      AffineConstraints<double> none;
      none.close();
      const IncrementOutcome status = assemble(du, none, tangent != nullptr);
      // Without constraints rhs = -r for all equations, contact included.
      residual = system_rhs;
      residual *= -1.;
      if (tangent != nullptr)
      {
        tangent->reinit(system_matrix.m(), system_matrix.n());
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
