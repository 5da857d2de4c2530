// ContactCoupling, part 2: the contact pairs (one per sheet surface node and
// tool), their sparsity, assembly and commit, the equation of each
// force-controlled tool and the convergence measures (doc/theory_contact.md);
// the tool slots are in contact_coupling_tools.cc, what the pairs report for
// the output in contact_coupling_reports.cc.
#include <algorithm>
#include <cmath>
#include <deal.II/base/parallel.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/full_matrix.h>
#include <deepdraw/contact/contact_coupling.h>
#include <deepdraw/io/input_error.h>
#include <deepdraw/io/printable_text.h>
#include <deepdraw/parallel/ranks.h>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

namespace deepdraw
{
  namespace contact
  {
    namespace
    {
      // A value that is not finite stops the run naming the parameter (exit
      // code 3, doc/user_guide.md §5): cutting back cannot step around an
      // expression that has no value at this load. The input check (D50)
      // has evaluated it at 11 loads already.
      void
      require_finite(const double       value,
                     const std::string &parameter,
                     const std::string &expression,
                     const double       load)
      {
        if (!std::isfinite(value))
        {
          std::ostringstream text;
          text << std::setprecision(6) << parameter << " = '"
               << io::one_line(expression) << "' is not finite at t = " << load;
          throw std::runtime_error(text.str());
        }
      }

      Tensor<1, 3>
      evaluate_translation(const ToolMotion &motion, const double load)
      {
        motion.translation->set_time(load);
        Vector<double> values(3);
        motion.translation->vector_value(Point<1>(), values);
        for (unsigned int d = 0; d < 3; ++d)
          require_finite(values[d],
                         motion.translation_parameter,
                         motion.translation_expression,
                         load);
        const Tensor<1, 3> translation({values[0], values[1], values[2]});
        return motion.relative ? motion.origin + translation : translation;
      }
    } // namespace


    Tensor<1, 3>
    ContactCoupling::spring_tool_translation(const unsigned int k,
                                             const double       load,
                                             const double       position) const
    {
      // The rest translation off the axis, the position z along it.
      const Tensor<1, 3> &a    = definitions[k].axis;
      const Tensor<1, 3>  rest = evaluate_translation(motions[k], load);
      return rest - (rest * a) * a + position * a;
    }


    double
    ContactCoupling::spring_force(const unsigned int k,
                                  const double       load,
                                  const double       position) const
    {
      // F = k (z_r - z): pressing along a while the sheet has pushed the
      // tool back from its rest position z_r = a . rest (D187).
      const double rest
        = evaluate_translation(motions[k], load) * definitions[k].axis;
      return motions[k].spring_stiffness * (rest - position);
    }


    double
    ContactCoupling::prescribed_force(const unsigned int k,
                                      const double       load) const
    {
      const ToolMotion &motion = motions[k];
      motion.force->set_time(load);
      const double force = motion.force->value(Point<1>());
      require_finite(force,
                     motion.force_parameter,
                     motion.force_expression,
                     load);
      // The input check saw a force > 0 at the check loads only (D176);
      // without one the tool has no support and the Newton stagnates.
      if (!(force > 0.))
      {
        std::ostringstream text;
        text << std::setprecision(6) << motion.force_parameter << " = '"
             << io::one_line(motion.force_expression) << "' gives " << force
             << " N at t = " << load
             << "; a force-controlled tool needs a force > 0 N";
        throw std::runtime_error(text.str());
      }
      return force;
    }


    unsigned int
    ContactCoupling::create_pairs(
      const std::vector<std::vector<unsigned int>>              &face_vertices,
      const std::vector<std::array<types::global_dof_index, 3>> &vertex_dofs,
      const types::global_dof_index                              first_index,
      const double                                               youngs_modulus,
      const double                                               element_size,
      const std::vector<unsigned int>                           &vertex_owners)
    {
      pairs.clear();
      pair_owners.clear();
      const double r = parameters.augmentation(youngs_modulus, element_size);
      force_regularisation         = r;
      types::global_dof_index next = first_index;
      for (unsigned int k = 0; k < definitions.size(); ++k)
        for (const unsigned int vertex :
             motions[k].takes_part ? face_vertices[definitions[k].sheet_face]
                                   : std::vector<unsigned int>())
        {
          Pair pair;
          pair.vertex           = vertex;
          pair.tool             = k;
          pair.u_dofs           = vertex_dofs[vertex];
          pair.first_multiplier = next;
          pair.augmentation     = r;
          next += 3;
          pairs.push_back(pair);
          if (!vertex_owners.empty())
            pair_owners.push_back(vertex_owners[vertex]);
        }
      position_dof.assign(definitions.size(), numbers::invalid_dof_index);
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (motions[k].position_is_unknown())
          position_dof[k] = next++;
      position_at_start.assign(definitions.size(), 0.);
      spring_forces.assign(definitions.size(), 0.);
      translation_at_start.assign(definitions.size(), Tensor<1, 3>());
      translation_at_end.assign(definitions.size(), Tensor<1, 3>());
      return next - first_index;
    }


    void
    ContactCoupling::add_sparsity(DynamicSparsityPattern &dsp) const
    {
      for (const Pair &pair : pairs)
      {
        std::vector<types::global_dof_index> dofs(pair.u_dofs.begin(),
                                                  pair.u_dofs.end());
        for (unsigned int c = 0; c < 3; ++c)
          dofs.push_back(pair.first_multiplier + c);
        if (position_dof[pair.tool] != numbers::invalid_dof_index)
          dofs.push_back(position_dof[pair.tool]);
        for (const auto i : dofs)
          for (const auto j : dofs)
            dsp.add(i, j);
      }
      for (const auto dof : position_dof)
        if (dof != numbers::invalid_dof_index)
          dsp.add(dof, dof);
    }


    std::vector<solver::MultiplierBlock>
    ContactCoupling::multiplier_blocks() const
    {
      std::vector<solver::MultiplierBlock> blocks;
      blocks.reserve(pairs.size());
      for (const Pair &pair : pairs)
      {
        solver::MultiplierBlock block;
        block.displacement = pair.u_dofs;
        for (unsigned int c = 0; c < 3; ++c)
          block.multiplier[c] = pair.first_multiplier + c;
        block.augmentation = pair.augmentation;
        blocks.push_back(block);
      }
      return blocks;
    }


    void
    ContactCoupling::start_increment(const double old_load,
                                     const double new_load)
    {
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (!motions[k].takes_part)
        {
          // Left where it stands.
          translation_at_start[k] = tool_list[k].translation();
          translation_at_end[k]   = translation_at_start[k];
        }
        else if (motions[k].force_controlled)
        {
          translation_at_start[k] = position_at_start[k] * definitions[k].axis;
          translation_at_end[k]   = translation_at_start[k];
        }
        else if (motions[k].spring_stiffness > 0.)
        {
          translation_at_start[k]
            = spring_tool_translation(k, old_load, position_at_start[k]);
          translation_at_end[k]
            = spring_tool_translation(k, new_load, position_at_start[k]);
          tool_list[k].set_rigid_motion(unit_symmetric_tensor<3>(),
                                        translation_at_end[k]);
        }
        else
        {
          translation_at_start[k] = evaluate_translation(motions[k], old_load);
          translation_at_end[k]   = evaluate_translation(motions[k], new_load);
          tool_list[k].set_rigid_motion(unit_symmetric_tensor<3>(),
                                        translation_at_end[k]);
        }
    }


    bool
    ContactCoupling::evaluate_pair(Pair                        &pair,
                                   const std::vector<Point<3>> &positions,
                                   const Vector<double>        &solution,
                                   const bool                   predictor) const
    {
      const bool                  was_found      = pair.found;
      const contact::ContactState previous_state = pair.result.state;
      Tensor<1, 3>                du, lambda;
      for (unsigned int c = 0; c < 3; ++c)
      {
        du[c]     = solution[pair.u_dofs[c]];
        lambda[c] = solution[pair.first_multiplier + c];
      }
      const Point<3>             x    = positions[pair.vertex] + du;
      const geometry::RigidTool &tool = tool_list[pair.tool];
      geometry::ProjectionResult projection;
      pair.found = tool.project(x, projection, search_distance)
                   && !projection.on_free_edge;
      // In the predictor the tool has moved but the sheet not yet: the
      // gaps of open pairs say nothing about the new state; closing them
      // flattened the sheet against the punch and Newton then had to open
      // them again one ring at a time.
      if (pair.found && !(predictor && pair.open_at_start))
      {
        geometry::ProjectionResult closest = projection;
        if (projection.on_edge)
        {
          // Clamped feet keep the frozen linearisation (zero tangents:
          // no curvature terms, ContactPairKinematics).
          closest.tangent_u = closest.tangent_v = Tensor<1, 3>();
          closest.x_uu = closest.x_uv = closest.x_vv = Tensor<1, 3>();
        }
        const bool force_controlled
          = position_dof[pair.tool] != numbers::invalid_dof_index;
        const contact::ContactPairKinematics kinematics(
          x,
          du,
          closest,
          translation_at_end[pair.tool] - translation_at_start[pair.tool],
          force_controlled ? definitions[pair.tool].axis : Tensor<1, 3>(),
          parameters.linearisation);
        pair.result = contact::evaluate_contact_pair(*law,
                                                     kinematics,
                                                     lambda,
                                                     pair.augmentation);
      }
      else
      {
        // Far from the tool: open, F_sup = lambda / r.
        pair.result = contact::open_contact_pair(lambda,
                                                 pair.augmentation,
                                                 search_distance);
      }
      return was_found != pair.found || previous_state != pair.result.state;
    }


    unsigned int
    ContactCoupling::assemble(const std::vector<Point<3>>     &positions,
                              const Vector<double>            &solution,
                              const AffineConstraints<double> &constraints,
                              linear_algebra::SystemMatrix    *matrix,
                              Vector<double>                  &rhs,
                              const double                     new_load,
                              const bool                       predictor)
    {
      Timer timer;
      // Force-controlled and spring-backed tools sit at their current
      // unknown position.
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (position_dof[k] != numbers::invalid_dof_index)
        {
          translation_at_end[k]
            = motions[k].force_controlled
                ? solution[position_dof[k]] * definitions[k].axis
                : spring_tool_translation(k,
                                          new_load,
                                          solution[position_dof[k]]);
          tool_list[k].set_rigid_motion(unit_symmetric_tensor<3>(),
                                        translation_at_end[k]);
        }

      // Projection and local law of every pair, independent of each other:
      // on all threads (D61). Under mpirun each rank evaluates the pairs of
      // the nodes whose rows it owns and sends them to the others, so that
      // every rank adds every pair as before (D216).
      std::vector<unsigned char> changed(pairs.size(), 0);
      const unsigned int         me = parallel::this_rank();
      const auto                 evaluate_pairs
        = [&](const std::size_t begin, const std::size_t end)
      {
        for (std::size_t p = begin; p < end; ++p)
          if (pair_owners.empty() || pair_owners[p] == me)
            changed[p]
              = evaluate_pair(pairs[p], positions, solution, predictor);
      };
      dealii::parallel::apply_to_subranges(std::size_t(0),
                                           pairs.size(),
                                           evaluate_pairs,
                                           64);
      exchange_pair_outcomes(solution);
      const unsigned int changes
        = parallel::sum(static_cast<unsigned long long>(
          std::count(changed.begin(), changed.end(), 1)));

      // Local systems [u (3), lambda (3), z (0 or 1)], residual
      // r = [-P, F_sup, a.P]; rhs = -r (doc/theory_contact.md, reference Eq.
      // 19).
      std::vector<unsigned int>            active_pairs(definitions.size(), 0);
      FullMatrix<double>                   local_matrix;
      Vector<double>                       local_rhs;
      std::vector<types::global_dof_index> dofs;
      for (const Pair &pair : pairs)
      {
        const contact::ContactPairResult &result = pair.result;
        const bool                        with_z
          = position_dof[pair.tool] != numbers::invalid_dof_index;
        const unsigned int n = with_z ? 7 : 6;
        local_matrix.reinit(n, n);
        local_rhs.reinit(n);
        dofs.assign(pair.u_dofs.begin(), pair.u_dofs.end());
        for (unsigned int c = 0; c < 3; ++c)
          dofs.push_back(pair.first_multiplier + c);
        if (with_z)
          dofs.push_back(position_dof[pair.tool]);
        if (result.state != contact::ContactState::open)
          ++active_pairs[pair.tool];

        const Tensor<1, 3> &a = definitions[pair.tool].axis;
        for (unsigned int i = 0; i < 3; ++i)
        {
          local_rhs(i)     = result.force[i];
          local_rhs(3 + i) = -result.constraint_residual[i];
          for (unsigned int j = 0; j < 3; ++j)
          {
            local_matrix(i, j)         = -result.dforce_ddisplacement[i][j];
            local_matrix(i, 3 + j)     = -result.dforce_dmultiplier[i][j];
            local_matrix(3 + i, j)     = result.dconstraint_ddisplacement[i][j];
            local_matrix(3 + i, 3 + j) = result.dconstraint_dmultiplier[i][j];
          }
          if (with_z)
          {
            local_matrix(i, 6)     = -result.dforce_dtool_position[i];
            local_matrix(3 + i, 6) = result.dconstraint_dtool_position[i];
            for (unsigned int j = 0; j < 3; ++j)
            {
              local_matrix(6, j) += a[i] * result.dforce_ddisplacement[i][j];
              local_matrix(6, 3 + j) += a[i] * result.dforce_dmultiplier[i][j];
            }
            local_matrix(6, 6) += a[i] * result.dforce_dtool_position[i];
          }
        }
        if (with_z)
          local_rhs(6) = -(a * result.force);
        if (matrix != nullptr)
          matrix->add_local(constraints, local_matrix, local_rhs, dofs, rhs);
        else
          constraints.distribute_local_to_global(local_rhs, dofs, rhs);
      }

      // Holder equation: sum a.P - F(t) = 0. While no pair of the tool is
      // in contact its row is empty; then the Newton step moves the tool by
      // F / r along its axis towards the sheet instead (only the iterates
      // change, not the converged solution). A spring-backed tool's F is
      // k (z_r - z), linear in its position z (D187): its row is never
      // empty.
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (position_dof[k] == numbers::invalid_dof_index)
          continue;
        else if (motions[k].force_controlled)
        {
          rhs[position_dof[k]] += prescribed_force(k, new_load);
          if (active_pairs[k] == 0 && matrix != nullptr)
            matrix->add(position_dof[k], position_dof[k], force_regularisation);
        }
        else
        {
          spring_forces[k]
            = spring_force(k, new_load, solution[position_dof[k]]);
          rhs[position_dof[k]] += spring_forces[k];
          if (matrix != nullptr)
            matrix->add(position_dof[k],
                        position_dof[k],
                        motions[k].spring_stiffness);
        }
      // The search, the local law and the pairs' terms in the system: the
      // terms were untimed until D212, which hid D211's quadratic cost.
      total_contact_time += timer.wall_time();
      return changes;
    }


    void
    ContactCoupling::add_open_multipliers(
      std::vector<types::global_dof_index> &unknowns) const
    {
      // Open: P = 0 whatever lambda and du are, so dP/d(du, lambda, z) = 0
      // and F_sup = lambda / r (doc/theory.md §7, D60).
      for (const Pair &pair : pairs)
        if (pair.result.state == contact::ContactState::open)
          for (unsigned int c = 0; c < 3; ++c)
            unknowns.push_back(pair.first_multiplier + c);
    }


    double
    ContactCoupling::residual_norm(const Vector<double> &rhs) const
    {
      double sum = 0.;
      for (const Pair &pair : pairs)
        for (unsigned int c = 0; c < 3; ++c)
          sum
            += std::pow(pair.augmentation * rhs[pair.first_multiplier + c], 2);
      for (const auto dof : position_dof)
        if (dof != numbers::invalid_dof_index)
          sum += rhs[dof] * rhs[dof];
      return std::sqrt(sum);
    }


    double
    ContactCoupling::tool_force_error(const Vector<double> &rhs,
                                      const double          load,
                                      const double zero_force_scale) const
    {
      double error = 0.;
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (position_dof[k] != numbers::invalid_dof_index)
        {
          // A spring's force is that of the last assembly, the iterate
          // rhs belongs to.
          const double force
            = std::abs(motions[k].force_controlled ? prescribed_force(k, load)
                                                   : spring_forces[k]);
          error = std::max(error,
                           std::abs(rhs[position_dof[k]])
                             / (force > 0. ? force : zero_force_scale));
        }
      return error;
    }


    void
    ContactCoupling::commit(const Vector<double> &solution)
    {
      for (unsigned int k = 0; k < definitions.size(); ++k)
        if (position_dof[k] != numbers::invalid_dof_index)
          position_at_start[k] = solution[position_dof[k]];
      for (Pair &pair : pairs)
        pair.open_at_start
          = !pair.found || pair.result.state == contact::ContactState::open;
    }


    ContactHistory
    ContactCoupling::committed_history() const
    {
      ContactHistory history;
      history.tool_position = position_at_start;
      for (unsigned int k = 0; k < motions.size(); ++k)
        for (unsigned int d = 0; d < 3; ++d)
        {
          history.tool_origin.push_back(motions[k].origin[d]);
          history.tool_translation.push_back(tool_list[k].translation()[d]);
        }
      history.pair_open.reserve(pairs.size());
      history.pair_status.reserve(pairs.size());
      for (const Pair &pair : pairs)
      {
        history.pair_open.push_back(pair.open_at_start ? 1 : 0);
        history.pair_status.push_back(
          pair.found ? 1 + static_cast<unsigned char>(pair.result.state) : 0);
      }
      return history;
    }


    void
    ContactCoupling::restore(const ContactHistory &history)
    {
      if (history.pair_open.size() != pairs.size()
          || history.pair_status.size() != pairs.size()
          || history.tool_position.size() != position_at_start.size()
          || history.tool_origin.size() != 3 * motions.size())
        throw InputError("--resume: the contact state has "
                         + std::to_string(history.pair_open.size())
                         + " pairs and "
                         + std::to_string(history.tool_position.size())
                         + " tools, the model " + std::to_string(pairs.size())
                         + " and " + std::to_string(position_at_start.size()));
      position_at_start = history.tool_position;
      // A checkpoint of the time before stages leaves the tools where the
      // next increment puts them.
      for (unsigned int k = 0; k < motions.size(); ++k)
      {
        Tensor<1, 3> translation;
        for (unsigned int d = 0; d < 3; ++d)
        {
          motions[k].origin[d] = history.tool_origin[3 * k + d];
          if (history.tool_translation.size() == 3 * motions.size())
            translation[d] = history.tool_translation[3 * k + d];
        }
        tool_list[k].set_rigid_motion(unit_symmetric_tensor<3>(), translation);
      }
      for (std::size_t p = 0; p < pairs.size(); ++p)
      {
        pairs[p].open_at_start = history.pair_open[p] != 0;
        pairs[p].found         = history.pair_status[p] != 0;
        if (pairs[p].found)
          pairs[p].result.state
            = static_cast<contact::ContactState>(history.pair_status[p] - 1);
      }
    }


    const std::vector<geometry::RigidTool> &
    ContactCoupling::tools() const
    {
      return tool_list;
    }


    const std::vector<ToolDefinition> &
    ContactCoupling::tool_definitions() const
    {
      return definitions;
    }


    Tensor<1, 3>
    ContactCoupling::prescribed_translation(const unsigned int k,
                                            const double       load) const
    {
      return evaluate_translation(motions[k], load);
    }


    Tensor<1, 3>
    ContactCoupling::declared_translation(const unsigned int k,
                                          const double       load) const
    {
      ToolMotion declared;
      declared.translation            = definitions[k].translation;
      declared.translation_expression = definitions[k].translation_expression;
      declared.translation_parameter
        = definitions[k].parameter_prefix + "Translation";
      return evaluate_translation(declared, load);
    }


    std::vector<types::global_dof_index>
    ContactCoupling::tool_position_unknowns() const
    {
      std::vector<types::global_dof_index> unknowns;
      for (const auto dof : position_dof)
        if (dof != numbers::invalid_dof_index)
          unknowns.push_back(dof);
      return unknowns;
    }
  } // namespace contact
} // namespace deepdraw
