#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deepdraw/geometry/rigid_tool.h>
#include <limits>
#include <utility>

namespace deepdraw::geometry
{
  namespace
  {
    // Patch parameters of sample m of n along edge `edge` (endpoints left
    // out: a corner shared with a neighbour says nothing about the edge).
    std::pair<double, double>
    edge_sample(const unsigned int edge,
                const unsigned int m,
                const unsigned int n)
    {
      const double t = (m + 1.) / (n + 1.);
      switch (edge)
      {
        case 0:
          return {0., t};
        case 1:
          return {1., t};
        case 2:
          return {t, 0.};
        default:
          return {t, 1.};
      }
    }

    std::array<double, 6>
    box_array(const dealii::BoundingBox<3> &box)
    {
      const auto &corners = box.get_boundary_points();
      return {{corners.first[0],
               corners.first[1],
               corners.first[2],
               corners.second[0],
               corners.second[1],
               corners.second[2]}};
    }

    dealii::Tensor<2, 3>
    identity_matrix()
    {
      dealii::Tensor<2, 3> identity;
      for (unsigned int d = 0; d < 3; ++d)
        identity[d][d] = 1.;
      return identity;
    }

    inline double
    box_distance_square(const std::array<double, 6> &box,
                        const dealii::Point<3>      &x)
    {
      double d2 = 0.;
      for (unsigned int d = 0; d < 3; ++d)
      {
        const double below = box[d] - x[d];
        const double above = x[d] - box[d + 3];
        if (below > 0.)
          d2 += below * below;
        else if (above > 0.)
          d2 += above * above;
      }
      return d2;
    }
  } // namespace


  std::string
  to_string(const EdgeKind kind)
  {
    switch (kind)
    {
      case EdgeKind::automatic:
        return "automatic";
      case EdgeKind::free:
        return "free";
      case EdgeKind::shared:
        return "shared";
      case EdgeKind::symmetry:
        return "symmetry";
    }
    return "";
  }


  RigidTool::RigidTool(const std::string &name)
      : tool_name(name)
      , rotation_matrix(identity_matrix())
  {
  }


  const std::string &
  RigidTool::name() const
  {
    return tool_name;
  }


  void
  RigidTool::cover_edge_samples(const unsigned int patch,
                                const unsigned int edge,
                                const unsigned int other)
  {
    const BezierPatch &this_patch  = patch_list[patch];
    const BezierPatch &other_patch = patch_list[other];
    // Far above the projection's accuracy (1e-13 of the patch size), far
    // below any real gap between patches.
    const double tolerance
      = 1e-9
        * std::max({1., this_patch.length_scale(), other_patch.length_scale()});
    EdgeState &state = edge_states[patch][edge];
    for (unsigned int m = 0; m < n_edge_samples; ++m)
      if (!state.covered[m])
      {
        const auto [u, v]        = edge_sample(edge, m, n_edge_samples);
        const dealii::Point<3> x = this_patch.value(u, v);
        if (box_distance_square(local_boxes[other], x) > tolerance * tolerance)
          continue;
        if (other_patch.closest_point(x).distance <= tolerance)
          state.covered[m] = true;
      }
  }


  void
  RigidTool::add_patch(const BezierPatch &patch, const EdgeKinds &edges)
  {
    add_patch(patch, edges, PatchTrimming());
  }


  void
  RigidTool::add_patch(const BezierPatch   &patch,
                       const EdgeKinds     &edges,
                       const PatchTrimming &trimming)
  {
    const unsigned int k = patch_list.size();
    patch_list.push_back(patch);
    trimmings.push_back(trimming);
    local_boxes.push_back(box_array(patch.bounding_box()));
    scale = std::max(scale, patch.length_scale());
    declared_kinds.push_back(edges);
    edge_states.emplace_back();
    for (unsigned int e = 0; e < 4; ++e)
    {
      EdgeState &state = edge_states[k][e];
      if (edges[e] != EdgeKind::automatic)
        continue;
      // A collapsed edge (e.g. at the pole of a sphere) is not a boundary.
      const auto [u0, v0] = edge_sample(e, 0, n_edge_samples);
      const auto [u1, v1] = edge_sample(e, n_edge_samples - 1, n_edge_samples);
      if (patch.value(u0, v0).distance(patch.value(u1, v1))
          <= 1e-12 * patch.length_scale())
        state.covered.fill(true);
      for (unsigned int other = 0; other < k; ++other)
        cover_edge_samples(k, e, other);
    }
    for (unsigned int other = 0; other < k; ++other)
      for (unsigned int e = 0; e < 4; ++e)
        if (declared_kinds[other][e] == EdgeKind::automatic)
          cover_edge_samples(other, e, k);

    for (unsigned int j = 0; j <= k; ++j)
      for (unsigned int e = 0; e < 4; ++e)
      {
        EdgeState     &state    = edge_states[j][e];
        const EdgeKind declared = declared_kinds[j][e];
        // A declared edge of an earlier patch is settled (the new patch
        // can only cover automatic ones): skipping it keeps adding n
        // patches with declared edges (CAD tools) at O(n) each.
        if (j < k && declared != EdgeKind::automatic)
          continue;
        state.free
          = (declared == EdgeKind::free)
            || (declared == EdgeKind::automatic
                && !std::all_of(state.covered.begin(),
                                state.covered.end(),
                                [](const bool covered) { return covered; }));
      }
    // The box grows by the new control points (min and max are exact, so
    // this is the box update_bounding_box() would compute).
    if (k == 0)
      update_bounding_box();
    else
    {
      std::pair<dealii::Point<3>, dealii::Point<3>> corners
        = current_box.get_boundary_points();
      for (const dealii::Point<3> &point : patch.control_points())
      {
        const dealii::Point<3> x = to_global(point);
        for (unsigned int d = 0; d < 3; ++d)
        {
          corners.first[d]  = std::min(corners.first[d], x[d]);
          corners.second[d] = std::max(corners.second[d], x[d]);
        }
      }
      current_box = dealii::BoundingBox<3>(corners);
    }
  }


  unsigned int
  RigidTool::n_patches() const
  {
    return patch_list.size();
  }


  const std::vector<BezierPatch> &
  RigidTool::patches() const
  {
    return patch_list;
  }


  const BezierPatch &
  RigidTool::patch(const unsigned int index) const
  {
    AssertIndexRange(index, patch_list.size());
    return patch_list[index];
  }


  const RigidTool::EdgeKinds &
  RigidTool::declared_edge_kinds(const unsigned int patch) const
  {
    AssertIndexRange(patch, patch_list.size());
    return declared_kinds[patch];
  }


  bool
  RigidTool::is_free_edge(const unsigned int patch,
                          const unsigned int edge) const
  {
    AssertIndexRange(patch, patch_list.size());
    AssertIndexRange(edge, 4);
    return edge_states[patch][edge].free;
  }


  const PatchTrimming &
  RigidTool::trimming(const unsigned int patch) const
  {
    AssertIndexRange(patch, patch_list.size());
    return trimmings[patch];
  }


  void
  RigidTool::set_rigid_motion(const dealii::Tensor<2, 3> &rotation,
                              const dealii::Tensor<1, 3> &translation)
  {
    const double orthogonality_error
      = (dealii::transpose(rotation) * rotation - identity_matrix()).norm();
    AssertThrow(orthogonality_error < 1e-10
                  && dealii::determinant(rotation) > 0.,
                dealii::ExcMessage("The rotation of tool '" + tool_name
                                   + "' is not a proper rotation"));
    rotation_matrix      = rotation;
    translation_vector   = translation;
    is_identity_rotation = (rotation - identity_matrix()).norm() == 0.;
    update_bounding_box();
  }


  const dealii::Tensor<2, 3> &
  RigidTool::rotation() const
  {
    return rotation_matrix;
  }


  const dealii::Tensor<1, 3> &
  RigidTool::translation() const
  {
    return translation_vector;
  }


  dealii::Point<3>
  RigidTool::to_global(const dealii::Point<3> &point_in_tool_frame) const
  {
    if (is_identity_rotation)
      return point_in_tool_frame + translation_vector;
    return dealii::Point<3>(rotation_matrix * point_in_tool_frame
                            + translation_vector);
  }


  dealii::Point<3>
  RigidTool::to_tool_frame(const dealii::Point<3> &global_point) const
  {
    const dealii::Tensor<1, 3> shifted
      = global_point - dealii::Point<3>(translation_vector);
    if (is_identity_rotation)
      return dealii::Point<3>(shifted);
    return dealii::Point<3>(dealii::transpose(rotation_matrix) * shifted);
  }


  void
  RigidTool::update_bounding_box()
  {
    if (patch_list.empty())
      return;
    const dealii::Point<3> first = to_global(patch_list[0].control_points()[0]);
    std::pair<dealii::Point<3>, dealii::Point<3>> corners(first, first);
    for (const BezierPatch &patch : patch_list)
      for (const dealii::Point<3> &point : patch.control_points())
      {
        const dealii::Point<3> x = to_global(point);
        for (unsigned int d = 0; d < 3; ++d)
        {
          corners.first[d]  = std::min(corners.first[d], x[d]);
          corners.second[d] = std::max(corners.second[d], x[d]);
        }
      }
    current_box = dealii::BoundingBox<3>(corners);
  }


  const dealii::BoundingBox<3> &
  RigidTool::bounding_box() const
  {
    return current_box;
  }


  bool
  RigidTool::project(const dealii::Point<3> &x,
                     ProjectionResult       &result,
                     const double            search_distance) const
  {
    const dealii::Point<3> x_local = to_tool_frame(x);

    // Candidates: patches whose box is within the search distance, nearest
    // box first. A stack buffer avoids allocations for ordinary tools.
    constexpr unsigned int stack_capacity = 64;
    std::array<std::pair<double, unsigned int>, stack_capacity> stack_buffer;
    std::vector<std::pair<double, unsigned int>>                heap_buffer;
    std::pair<double, unsigned int> *candidates = stack_buffer.data();
    if (patch_list.size() > stack_capacity)
    {
      heap_buffer.resize(patch_list.size());
      candidates = heap_buffer.data();
    }
    const double search_square = search_distance * search_distance;
    unsigned int n_candidates  = 0;
    for (unsigned int k = 0; k < patch_list.size(); ++k)
    {
      const double d2 = box_distance_square(local_boxes[k], x_local);
      if (d2 <= search_square)
        candidates[n_candidates++] = {d2, k};
    }
    std::sort(candidates, candidates + n_candidates);

    // Distances that differ by less than this are equal (the two feet of a
    // point above a shared edge); a clamp smaller than edge_tolerance is
    // round-off (e.g. a node on a symmetry plane).
    const double tie_tolerance  = 1e-12 * scale;
    const double edge_tolerance = 1e-10 * scale;

    PatchProjection best;
    unsigned int    best_patch   = 0;
    bool            found        = false;
    bool            best_on_edge = false;
    // A foot outside its trimming loops is no closest point of the trimmed
    // face (that lies on the loops, farther away): farther patches may
    // still hold the closest point, so the search goes on.
    bool best_outside = false;
    for (unsigned int c = 0; c < n_candidates; ++c)
    {
      if (found && !best_outside)
      {
        const double reach = best.distance + tie_tolerance;
        if (candidates[c].first > reach * reach)
          break;
      }
      const unsigned int    k          = candidates[c].second;
      const PatchProjection projection = patch_list[k].closest_point(x_local);
      const bool on_edge = *std::max_element(projection.beyond_edge.begin(),
                                             projection.beyond_edge.end())
                           > edge_tolerance;
      const bool outside = trimmings[k].trimmed()
                           && !trimmings[k].contains(projection.u,
                                                     projection.v,
                                                     projection.point.x_u,
                                                     projection.point.x_v);
      if (!found || (best_outside && !outside)
          || (outside == best_outside
              && (projection.distance < best.distance - tie_tolerance
                  || (projection.distance <= best.distance + tie_tolerance
                      && best_on_edge && !on_edge))))
      {
        best         = projection;
        best_patch   = k;
        best_on_edge = on_edge;
        best_outside = outside;
        found        = true;
      }
    }
    if (!found || best.distance > search_distance)
      return false;

    const SurfacePoint        &s         = best.point;
    const dealii::Tensor<1, 3> n         = unit_normal(s);
    const SurfaceCurvature     curvature = compute_curvature(s);

    result.gap                     = (x_local - s.position) * n;
    result.distance                = best.distance;
    result.foot_in_tool_frame      = s.position;
    result.metric                  = curvature.metric;
    result.second_fundamental_form = curvature.second_fundamental_form;
    result.principal_curvatures    = curvature.principal_curvatures;
    result.u                       = best.u;
    result.v                       = best.v;
    result.patch                   = best_patch;
    result.on_edge                 = best_on_edge;
    result.outside_trimming        = best_outside;
    result.on_free_edge            = best_outside;
    for (unsigned int e = 0; e < 4; ++e)
      if (best.beyond_edge[e] > edge_tolerance
          && edge_states[best_patch][e].free)
        result.on_free_edge = true;

    result.foot = to_global(s.position);
    if (is_identity_rotation)
    {
      result.normal    = n;
      result.tangent_u = s.x_u;
      result.tangent_v = s.x_v;
      result.x_uu      = s.x_uu;
      result.x_uv      = s.x_uv;
      result.x_vv      = s.x_vv;
      result.curvature = curvature.normal_gradient;
    }
    else
    {
      const dealii::Tensor<2, 3> &R = rotation_matrix;
      result.normal                 = R * n;
      result.tangent_u              = R * s.x_u;
      result.tangent_v              = R * s.x_v;
      result.x_uu                   = R * s.x_uu;
      result.x_uv                   = R * s.x_uv;
      result.x_vv                   = R * s.x_vv;
      result.curvature = R * curvature.normal_gradient * dealii::transpose(R);
    }
    return true;
  }
} // namespace deepdraw::geometry
