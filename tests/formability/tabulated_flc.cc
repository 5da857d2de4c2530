// A tabulated FLC is exact at its nodes, linear between them and constant
// beyond its ends (D131); the margin changes sign where a point crosses
// the curve; the zones of classify() in their order of precedence; a table
// file with a header and comments reads the same as the prm table. All
// expectations are hand values (binary fractions); measured errors 1e-17
// and less (round-off): 1e-16 allowed (1e-14 for the margin in %).
#include "../test_utilities.h"

#include <deepdraw/formability/fld_zone.h>
#include <deepdraw/formability/tabulated_flc.h>
#include <fstream>

using namespace deepdraw;
using namespace formability;

int
main()
{
  const std::vector<FlcPoint> points
    = parse_flc_table("-0.25, 0.5; 0, 0.25;  0.25 , 0.375;",
                      "Formability/Table");
  const TabulatedFlc curve(points, "Formability/Table", "test");
  for (const FlcPoint &p : points)
    deepdraw_test::check_close("at a node",
                               curve.limit_major_strain(p.minor_strain),
                               p.major_strain,
                               0.);
  deepdraw_test::check_close("a quarter between the first two nodes",
                             curve.limit_major_strain(-0.1875),
                             0.4375,
                             1e-16);
  deepdraw_test::check_close("halfway between the last two nodes",
                             curve.limit_major_strain(0.125),
                             0.3125,
                             1e-16);
  deepdraw_test::check_close("left of the table: the first value",
                             curve.limit_major_strain(-0.6),
                             0.5,
                             0.);
  deepdraw_test::check_close("right of the table: the last value",
                             curve.limit_major_strain(1.),
                             0.375,
                             0.);

  // A point moved up across the curve at eps2 = 0.125 (limit 0.3125).
  const FlcMargin below = curve.margin(0.3, 0.125);
  const FlcMargin above = curve.margin(0.325, 0.125);
  deepdraw_test::check_close("margin below, strain",
                             below.strain,
                             0.0125,
                             1e-16);
  deepdraw_test::check_close("margin below, %", below.percent, 4., 1e-14);
  deepdraw_test::check_close("margin above, strain",
                             above.strain,
                             -0.0125,
                             1e-16);
  deepdraw_test::check_true("the margin changes sign across the curve",
                            below.strain > 0. && above.strain < 0.);

  FldZoneParameters zones; // band 10 %, thinning -0.25, 0.02, 0.02
  const auto        zone = [&](double e1, double e2, double e3)
  { return classify(&curve, zones, e1, e2, e3); };
  deepdraw_test::check_true("split above the curve",
                            zone(0.325, 0.125, -0.45) == FldZone::split);
  deepdraw_test::check_true("split on the curve",
                            zone(0.3125, 0.125, -0.44) == FldZone::split);
  deepdraw_test::check_true("marginal within 10 %",
                            zone(0.3, 0.125, -0.1) == FldZone::marginal);
  deepdraw_test::check_true("marginal before thinning",
                            zone(0.3, 0.125, -0.3) == FldZone::marginal);
  deepdraw_test::check_true("thinning below the band",
                            zone(0.2, 0.1, -0.3) == FldZone::thinning);
  deepdraw_test::check_true("safe", zone(0.2, 0.05, -0.25) == FldZone::safe);
  deepdraw_test::check_true("wrinkling tendency: eps2 <= -0.02, thicker",
                            zone(0.05, -0.1, 0.05)
                              == FldZone::wrinkling_tendency);
  deepdraw_test::check_true("no wrinkling tendency where the sheet thins",
                            zone(0.15, -0.1, -0.05) == FldZone::safe);
  deepdraw_test::check_true("insufficient stretch",
                            zone(0.01, -0.005, -0.005)
                              == FldZone::insufficient_stretch);
  deepdraw_test::check_true("no curve: neither split nor marginal",
                            classify(nullptr, zones, 0.9, 0.1, -0.2)
                              == FldZone::safe);
  deepdraw_test::check_true("zone names",
                            zone_name(FldZone::insufficient_stretch)
                                == "insufficient stretch"
                              && zone_name(FldZone::split) == "split");

  {
    std::ofstream file("formability_table.csv");
    file << "eps2,eps1\n# a lab's curve\n-0.25,0.5\n\n0, 0.25 # "
            "FLC0\n0.25;0.375\n";
  }
  const std::vector<FlcPoint> read
    = read_flc_table_file("formability_table.csv");
  bool same = read.size() == points.size();
  for (unsigned int k = 0; same && k < read.size(); ++k)
    same = read[k].minor_strain == points[k].minor_strain
           && read[k].major_strain == points[k].major_strain;
  deepdraw_test::check_true("the file reads as the prm table", same);
  return deepdraw_test::summary();
}
