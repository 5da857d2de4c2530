// A rigid forming tool: a named set of Bézier patches in the tool's own
// frame, placed in space by a rigid motion x = R X + c, and the closest-point
// projection onto it.
//
// Orientation convention: every patch's normal x_u × x_v points towards the
// sheet (away from the tool material).
//
// Free edges: each patch edge is free (no other patch of the tool continues
// the surface there), shared, or on a symmetry plane of a partial model.
// Edges may be declared explicitly; edges declared `automatic` are shared if
// sample points along them lie on another patch of the tool (see
// doc/tool_files.md). A point whose foot is clamped onto a free edge is
// flagged in ProjectionResult::on_free_edge.
//
// Trimming: a patch of a trimmed CAD face carries the face's trimming loops
// (PatchTrimming); a foot outside them is not in contact with that face and
// is flagged like a foot on a free edge (doc/tool_files.md, CAD tools).
#ifndef deepdraw_geometry_rigid_tool_h
#define deepdraw_geometry_rigid_tool_h

#include <array>
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deepdraw/geometry/bezier_patch.h>
#include <deepdraw/geometry/projection_result.h>
#include <deepdraw/geometry/trimmed_domain.h>
#include <functional>
#include <string>
#include <vector>

namespace deepdraw::geometry
{
  enum class EdgeKind
  {
    automatic, // shared if another patch continues it, else free
    free,      // the tool ends here: clamped feet mean "not in contact"
    shared,    // another patch continues the surface
    symmetry   // lies on a symmetry plane of a partial model: not free
  };

  // "automatic", "free", "shared", "symmetry".
  std::string
  to_string(EdgeKind kind);

  class RigidTool
  {
  public:
    // Edges of a patch: 0: u = 0, 1: u = 1, 2: v = 0, 3: v = 1.
    using EdgeKinds = std::array<EdgeKind, 4>;

    explicit RigidTool(const std::string &name = "");

    const std::string &
    name() const;

    // Adds a patch given in the tool's frame and classifies the automatic
    // edges of all patches again.
    void
    add_patch(const BezierPatch &patch,
              const EdgeKinds   &edges = {{EdgeKind::automatic,
                                           EdgeKind::automatic,
                                           EdgeKind::automatic,
                                           EdgeKind::automatic}});
    // The same for a patch of a trimmed face.
    void
    add_patch(const BezierPatch   &patch,
              const EdgeKinds     &edges,
              const PatchTrimming &trimming);

    unsigned int
    n_patches() const;
    const std::vector<BezierPatch> &
    patches() const;
    const BezierPatch &
    patch(unsigned int index) const;
    // As declared.
    const EdgeKinds &
    declared_edge_kinds(unsigned int patch) const;
    // As resolved: is the edge free?
    bool
    is_free_edge(unsigned int patch, unsigned int edge) const;
    const PatchTrimming &
    trimming(unsigned int patch) const;

    // Current placement: x = rotation · X + translation. The rotation must be
    // proper orthogonal.
    void
    set_rigid_motion(const dealii::Tensor<2, 3> &rotation,
                     const dealii::Tensor<1, 3> &translation);
    const dealii::Tensor<2, 3> &
    rotation() const;
    const dealii::Tensor<1, 3> &
    translation() const;

    dealii::Point<3>
    to_global(const dealii::Point<3> &point_in_tool_frame) const;
    dealii::Point<3>
    to_tool_frame(const dealii::Point<3> &global_point) const;

    // Box of all control points at the current placement.
    const dealii::BoundingBox<3> &
    bounding_box() const;

    // Closest point of the tool to x among the patches whose control-net box
    // is within search_distance; false if no patch is that close. Patches
    // are visited nearest box first and skipped once their box is farther
    // than the best foot found; of two equally near feet, an unclamped one
    // wins over one clamped onto an edge. A foot outside its patch's
    // trimming loops loses against any foot inside (however far, within
    // search_distance), and the search goes on while the best foot is such
    // a one. Thread-safe.
    bool
    project(const dealii::Point<3> &x,
            ProjectionResult       &result,
            double                  search_distance) const;

  private:
    // Sample points per edge used to decide whether an edge is shared.
    static constexpr unsigned int n_edge_samples = 7;

    struct EdgeState
    {
      bool                             free = false;
      std::array<bool, n_edge_samples> covered{};
    };

    void
    cover_edge_samples(unsigned int patch,
                       unsigned int edge,
                       unsigned int other);
    void
    update_bounding_box();

    std::string                           tool_name;
    std::vector<BezierPatch>              patch_list;
    std::vector<EdgeKinds>                declared_kinds;
    std::vector<std::array<EdgeState, 4>> edge_states;
    std::vector<PatchTrimming>            trimmings;
    // Control-net boxes in the tool frame, as plain arrays for the culling.
    std::vector<std::array<double, 6>> local_boxes;
    double                             scale = 0.;
    dealii::Tensor<2, 3>               rotation_matrix;
    dealii::Tensor<1, 3>               translation_vector;
    bool                               is_identity_rotation = true;
    dealii::BoundingBox<3>             current_box;
  };
} // namespace deepdraw::geometry

#endif
