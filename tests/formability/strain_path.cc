// The strain path record of a point (formability::StrainPath,
// doc/theory_formability.md §6): a proportional path of small increments
// (each below the segment length) gives segments of its own ratio; a path
// that turns from uniaxial (-1/2) to equibiaxial (1) shows both as the
// least and the largest ratio, the last segment's being 1; a major strain that
// falls completes no segment; a record saved and loaded is the same. Exact in
// closed form to round-off: 1e-14 allowed (measured 5.6e-16).
#include "../test_utilities.h"

#include <deepdraw/formability/strain_path.h>
#include <sstream>

using namespace deepdraw;

int
main()
{
  const double tolerance = 1e-14;
  const double delta     = formability::StrainPath::segment_length;

  // Uniaxial, in increments of a fifth of a segment.
  formability::StrainPath path;
  deepdraw_test::check_true("no segment at the start",
                            !path.measured() && path.last_ratio() == 0.);
  double e1 = 0., e2 = 0.;
  for (unsigned int k = 1; k <= 50; ++k)
  {
    e1 += 0.2 * delta;
    e2 -= 0.1 * delta;
    path.add(e1, e2);
  }
  // 50 steps of delta/5, each a multiple of 5 steps ending a segment (the
  // sums may fall a round-off short of a multiple: at least 9).
  deepdraw_test::check_true("uniaxial: 9 or 10 segments ("
                              + std::to_string(path.segments()) + ")",
                            path.segments() >= 9 && path.segments() <= 10);
  deepdraw_test::check_close("uniaxial: last ratio",
                             path.last_ratio(),
                             -0.5,
                             tolerance);
  deepdraw_test::check_close("uniaxial: least ratio = largest ratio",
                             path.largest_ratio() - path.least_ratio(),
                             0.,
                             tolerance);

  // Then equibiaxial, in steps of 0.3 segment.
  for (unsigned int k = 1; k <= 40; ++k)
  {
    e1 += 0.3 * delta;
    e2 += 0.3 * delta;
    path.add(e1, e2);
  }
  deepdraw_test::check_close("turned: least ratio",
                             path.least_ratio(),
                             -0.5,
                             tolerance);
  deepdraw_test::check_close("turned: largest ratio",
                             path.largest_ratio(),
                             1.,
                             tolerance);
  deepdraw_test::check_close("turned: last ratio",
                             path.last_ratio(),
                             1.,
                             tolerance);

  // A falling major strain completes nothing.
  const unsigned int segments = path.segments();
  const double       last     = path.last_ratio();
  for (unsigned int k = 1; k <= 10; ++k)
    path.add(e1 - k * delta, e2 + k * delta);
  deepdraw_test::check_true("unloading: no segment",
                            path.segments() == segments
                              && path.last_ratio() == last);

  std::stringstream stream;
  path.save(stream);
  formability::StrainPath loaded;
  loaded.load(stream, "the test's stream");
  deepdraw_test::check_true("saved and loaded: the same record",
                            loaded.segments() == path.segments()
                              && loaded.last_ratio() == path.last_ratio()
                              && loaded.least_ratio() == path.least_ratio()
                              && loaded.largest_ratio()
                                   == path.largest_ratio());
  return deepdraw_test::summary();
}
