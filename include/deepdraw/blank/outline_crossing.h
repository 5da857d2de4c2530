// The first pair of crossing edges of a closed polygon (the blank outline,
// blank_outline.h), found by a sweep over the edges sorted by their
// smallest x (D169): an edge is compared only with the earlier edges whose
// x-range reaches its own, and only where their y-ranges overlap too. That
// is O(n log n) for outlines whose edges do not pile up over one x; the
// comparisons are capped at max_crossing_comparisons per corner, beyond
// which the search gives up (the caller then reports the outline's other
// fault). A star-shaped outline (every edge turning the same way about the
// origin, once round) cannot cross itself and needs no search at all.
#ifndef deepdraw_blank_outline_crossing_h
#define deepdraw_blank_outline_crossing_h

#include <cstddef>
#include <deal.II/base/point.h>
#include <optional>
#include <utility>
#include <vector>

namespace deepdraw
{
  namespace blank
  {
    constexpr std::size_t max_crossing_comparisons = 64;

    // The edge from corner k goes to corner (k + 1) % n. Returns (i, j),
    // i < j, of two edges that are not neighbours and share a point (the
    // lowest i, then the lowest j, as far as the search went); none if
    // there is no such pair or the search gave up.
    std::optional<std::pair<std::size_t, std::size_t>>
    first_crossing(const std::vector<dealii::Point<2>> &corners);
  } // namespace blank
} // namespace deepdraw

#endif
