// ContactCoupling, part 4: the contact state carried over a mesh change
// (adaptive refinement, doc/theory.md §8.2, D83).
#include <deepdraw/contact/contact_coupling.h>
#include <map>

namespace deepdraw
{
  namespace contact
  {
    ContactCoupling::Snapshot
    ContactCoupling::snapshot(const Vector<double> &converged,
                              const Vector<double> &previous) const
    {
      Snapshot result;
      for (const Pair &pair : pairs)
      {
        PairSnapshot entry{pair.vertex,
                           pair.tool,
                           {},
                           pair.open_at_start,
                           pair.found,
                           pair.result.state};
        for (unsigned int c = 0; c < 3; ++c)
        {
          entry.multiplier[0][c] = converged[pair.first_multiplier + c];
          entry.multiplier[1][c] = previous[pair.first_multiplier + c];
        }
        result.pairs.push_back(entry);
      }
      for (unsigned int k = 0; k < position_dof.size(); ++k)
      {
        const types::global_dof_index dof = position_dof[k];
        // Without a position unknown: where the tool stands along its axis
        // (a tool that turns to force control starts there).
        const double z = tool_list[k].translation() * definitions[k].axis;
        result.tool_position.push_back(
          dof == numbers::invalid_dof_index
            ? std::array<double, 2>{{z, z}}
            : std::array<double, 2>{{converged[dof], previous[dof]}});
        result.translation.push_back(tool_list[k].translation());
      }
      return result;
    }


    void
    ContactCoupling::transfer(const Snapshot                       &old,
                              const std::vector<fe::VertexParents> &parents,
                              const std::vector<double>            &old_area,
                              const std::vector<double>            &new_area,
                              Vector<double>                       &converged,
                              Vector<double>                       &previous)
    {
      if (parents.empty())
      {
        carry_over(old, converged, previous);
        return;
      }
      std::map<std::pair<unsigned int, unsigned int>, const PairSnapshot *>
        old_pair;
      for (const PairSnapshot &entry : old.pairs)
        old_pair[{entry.vertex, entry.tool}] = &entry;

      for (Pair &pair : pairs)
      {
        std::array<Tensor<1, 3>, 2> multiplier;
        bool                        all_closed = true, any_slip = false;
        bool                        any_found = false, any_parent = false;
        double                      weights = 0.;
        for (const auto &[vertex, weight] : parents[pair.vertex])
        {
          const auto found = old_pair.find({vertex, pair.tool});
          // A parent without a pair (a hanging node of the old mesh)
          // leaves its weight to the others.
          if (found == old_pair.end() || !(old_area[vertex] > 0.))
            continue;
          const PairSnapshot &entry = *found->second;
          any_parent                = true;
          weights += weight;
          for (unsigned int s = 0; s < 2; ++s)
            multiplier[s] += weight / old_area[vertex] * entry.multiplier[s];
          const bool closed = !entry.open_at_start
                              && entry.state != contact::ContactState::open;
          all_closed = all_closed && closed;
          any_slip   = any_slip || entry.state == contact::ContactState::slip;
          any_found  = any_found || entry.found;
        }
        if (!any_parent)
          all_closed = false;
        for (unsigned int c = 0; c < 3; ++c)
        {
          const double scale
            = weights > 0. ? new_area[pair.vertex] / weights : 0.;
          converged[pair.first_multiplier + c] = scale * multiplier[0][c];
          previous[pair.first_multiplier + c]  = scale * multiplier[1][c];
        }
        pair.open_at_start = !all_closed;
        pair.found         = any_found;
        pair.result        = contact::ContactPairResult();
        pair.result.state  = !all_closed ? contact::ContactState::open
                             : any_slip  ? contact::ContactState::slip
                                         : contact::ContactState::stick;
      }
      for (unsigned int k = 0; k < position_dof.size(); ++k)
        if (position_dof[k] != numbers::invalid_dof_index)
        {
          converged[position_dof[k]] = old.tool_position[k][0];
          previous[position_dof[k]]  = old.tool_position[k][1];
          // create_pairs() reset it; the committed z is the converged one.
          position_at_start[k] = old.tool_position[k][0];
        }
    }


    void
    ContactCoupling::carry_over(const Snapshot &old,
                                Vector<double> &converged,
                                Vector<double> &previous)
    {
      // The same mesh (a new stage): each pair takes the state and the
      // multipliers of the old pair of its node and tool, if there was one;
      // a new pair starts open with no force.
      std::map<std::pair<unsigned int, unsigned int>, const PairSnapshot *>
        old_pair;
      for (const PairSnapshot &entry : old.pairs)
        old_pair[{entry.vertex, entry.tool}] = &entry;
      for (Pair &pair : pairs)
      {
        const auto found = old_pair.find({pair.vertex, pair.tool});
        pair.result      = contact::ContactPairResult();
        if (found == old_pair.end())
        {
          pair.open_at_start = true;
          pair.found         = false;
          pair.result.state  = contact::ContactState::open;
          continue;
        }
        const PairSnapshot &entry = *found->second;
        for (unsigned int c = 0; c < 3; ++c)
        {
          converged[pair.first_multiplier + c] = entry.multiplier[0][c];
          previous[pair.first_multiplier + c]  = entry.multiplier[1][c];
        }
        pair.open_at_start = entry.open_at_start;
        pair.found         = entry.found;
        pair.result.state  = entry.state;
      }
      for (unsigned int k = 0; k < position_dof.size(); ++k)
        if (position_dof[k] != numbers::invalid_dof_index)
        {
          converged[position_dof[k]] = old.tool_position[k][0];
          previous[position_dof[k]]  = old.tool_position[k][1];
          position_at_start[k]       = old.tool_position[k][0];
        }
    }
  } // namespace contact
} // namespace deepdraw
