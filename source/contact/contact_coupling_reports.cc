// ContactCoupling, part 6: what the contact state reports, for the output
// and the console: each node's contact for the VTU, the force on each tool,
// the stick and slip counts, the nodes that start inside a tool and the time
// spent in the contact terms.
#include <algorithm>
#include <deepdraw/contact/contact_coupling.h>
#include <limits>

namespace deepdraw
{
  namespace contact
  {
    std::vector<ContactCoupling::NodalContact>
    ContactCoupling::nodal_contact(const unsigned int n_vertices) const
    {
      std::vector<NodalContact> nodal(n_vertices);
      for (const Pair &pair : pairs)
      {
        NodalContact      &node = nodal[pair.vertex];
        const unsigned int status
          = pair.result.state == contact::ContactState::open
              ? 0
              : (pair.result.state == contact::ContactState::stick ? 1 : 2);
        node.status = std::max(node.status, status);
        node.normal_force += pair.result.normal_force;
        node.friction_force += pair.result.friction_force;
        if (pair.found)
          node.gap = std::min(node.gap, pair.result.normal_gap);
      }
      for (NodalContact &node : nodal)
        if (node.gap == std::numeric_limits<double>::max())
          node.gap = search_distance;
      return nodal;
    }


    std::vector<Tensor<1, 3>>
    ContactCoupling::tool_forces() const
    {
      std::vector<Tensor<1, 3>> forces(definitions.size());
      for (const Pair &pair : pairs)
        forces[pair.tool] += pair.result.force;
      return forces;
    }


    namespace
    {
      // The pairs (ContactCoupling's private Pair) in the given state.
      template <typename Pairs>
      unsigned int
      count_in_state(const Pairs &pairs, const contact::ContactState state)
      {
        return std::count_if(pairs.begin(),
                             pairs.end(),
                             [state](const auto &pair)
                             { return pair.result.state == state; });
      }
    } // namespace


    unsigned int
    ContactCoupling::n_stick() const
    {
      return count_in_state(pairs, contact::ContactState::stick);
    }


    unsigned int
    ContactCoupling::n_slip() const
    {
      return count_in_state(pairs, contact::ContactState::slip);
    }


    unsigned int
    ContactCoupling::n_initial_penetrations(
      const std::vector<Point<3>> &positions) const
    {
      unsigned int count = 0;
      for (const Pair &pair : pairs)
      {
        geometry::ProjectionResult projection;
        if (tool_list[pair.tool].project(positions[pair.vertex],
                                         projection,
                                         search_distance)
            && !projection.on_free_edge && projection.gap < 0.)
          ++count;
      }
      return count;
    }


    double
    ContactCoupling::contact_time() const
    {
      return total_contact_time;
    }
  } // namespace contact
} // namespace deepdraw
