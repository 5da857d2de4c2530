// The supports of a released sheet (doc/user_guide.md §2.6, D151): points
// at which the nearest sheet node is held in given directions while the
// forces that formed the sheet are released, so that the sheet cannot move
// as a rigid body. Read from a stage's `Release supports`, e.g. the "3-2-1"
// support
//   point(0, 0, 0): ux uy uz; point(50, 0, 0): uy uz; point(0, 30, 0): uz
// The node of a point is the sheet node nearest to it at the start of the
// stage (current coordinates), held where it stands.
#ifndef deepdraw_process_release_supports_h
#define deepdraw_process_release_supports_h

#include <array>
#include <deal.II/base/point.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace process
  {
    using namespace dealii;

    struct ReleaseSupport
    {
      Point<3> point;
      // Which of ux, uy, uz are held.
      std::array<bool, 3> components = {{false, false, false}};
      // The item as written, for messages.
      std::string item;
    };

    // Reads 'point(X, Y, Z): COMPONENTS; ...' (COMPONENTS: one or more of
    // ux, uy, uz separated by spaces); an empty text gives none. Throws
    // InputError naming `parameter`, the item and what is allowed.
    std::vector<ReleaseSupport>
    parse_release_supports(const std::string &text,
                           const std::string &parameter);

    // "ux uz" for the held components of a support.
    std::string
    component_names(const std::array<bool, 3> &components);
  } // namespace process
} // namespace deepdraw

#endif
