// Which rigid-body modes of a sheet a set of held displacement components
// leaves free (doc/theory.md §9.2, D151). A rigid motion u(X) = t + w x X
// (3 translations t, 3 small rotations w) moves a held component c at point
// X by e_c . t + (X x e_c) . w; the modes the held components stop are the
// row space of these rows, the free ones its null space in R^6.
#ifndef deepdraw_process_rigid_body_modes_h
#define deepdraw_process_rigid_body_modes_h

#include <array>
#include <deal.II/base/point.h>
#include <string>
#include <vector>

namespace deepdraw
{
  namespace process
  {
    using namespace dealii;

    class RigidBodyModes
    {
    public:
      // A component held at a point.
      void
      hold(const Point<3> &point, unsigned int component);

      // The free modes, each named by its largest part ("translation along
      // z", "rotation about x"); rotations are about the centroid of the
      // held points, measured with their extent so that both kinds weigh
      // alike. Empty if the held components stop all six.
      std::vector<std::string>
      free_modes() const;

    private:
      std::vector<std::pair<Point<3>, unsigned int>> held;
    };
  } // namespace process
} // namespace deepdraw

#endif
