// Micro-benchmark of ElastoPlasticity::update (NUMISHEET'93 aluminium with
// Hill'48, with and without Prager, and Yld2004-18p with the AA2090-T3
// coefficients, a = 8): microseconds per elastic and per plastic update.
// Increments cycle through a table so the compiler cannot hoist the work.
#include "../tests/material/material_test_tools.h"

#include <chrono>
#include <cstdio>
#include <deepdraw/material/elasto_plasticity.h>
#include <vector>

using namespace deepdraw::material;

namespace
{
  double
  time_updates(const ElastoPlasticity                           &material,
               const MaterialPointState                         &old_state,
               const std::vector<dealii::SymmetricTensor<2, 3>> &increments,
               const unsigned int                                n,
               const bool                                        expect_plastic)
  {
    MaterialPointState            new_state;
    dealii::SymmetricTensor<4, 3> tangent;
    bool                          plastic;
    double                        sink  = 0.;
    unsigned int                  wrong = 0;
    const auto                    start = std::chrono::steady_clock::now();
    for (unsigned int i = 0; i < n; ++i)
    {
      material.update(old_state,
                      increments[i % increments.size()],
                      new_state,
                      tangent,
                      plastic);
      sink += new_state.stress[0][0] + tangent[0][0][1][1];
      wrong += (plastic != expect_plastic);
    }
    const double seconds
      = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
    if (wrong != 0 || sink == 0.)
      std::printf("  warning: %u steps with unexpected plastic flag\n", wrong);
    return 1e6 * seconds / n;
  }
} // namespace

int
main()
{
  // The AA2090-T3 set of the material tests (one place for its numbers).
  const MaterialParameters yld2004 = material_test::aa2090_t3_parameters();
  MaterialParameters       hill_prager;
  hill_prager.prager_modulus = 2000.;
  for (const auto &[name, parameters] :
       {std::make_pair("Hill'48", MaterialParameters()),
        std::make_pair("Hill'48, Prager k = 2000 MPa", hill_prager),
        std::make_pair("Yld2004-18p AA2090-T3", yld2004)})
  {
    const ElastoPlasticity material(parameters);

    // A state on the yield surface after 2 % plastic straining.
    MaterialPointState            virgin, loaded;
    dealii::SymmetricTensor<4, 3> tangent;
    bool                          plastic;
    dealii::SymmetricTensor<2, 3> pre;
    pre[0][0] = 0.02;
    pre[1][1] = -0.008;
    pre[2][2] = -0.012;
    pre[0][1] = 0.004;
    material.update(virgin, pre, loaded, tangent, plastic);

    std::vector<dealii::SymmetricTensor<2, 3>> plastic_increments,
      elastic_increments;
    for (unsigned int i = 0; i < 64; ++i)
    {
      const double                  a = 1. + 0.01 * i;
      dealii::SymmetricTensor<2, 3> d;
      d[0][0] = 1e-3 * a;
      d[1][1] = -0.4e-3;
      d[2][2] = -0.5e-3 * a;
      d[0][1] = 0.2e-3 * (i % 5);
      d[1][2] = 0.1e-3 * (i % 3);
      plastic_increments.push_back(d);
      elastic_increments.push_back(-0.5 * d); // unloading
    }
    const unsigned int n = 2000000;
    time_updates(material, loaded, plastic_increments, n / 10, true); // warm-up
    const double t_plastic
      = time_updates(material, loaded, plastic_increments, n, true);
    const double t_elastic
      = time_updates(material, loaded, elastic_increments, n, false);
    std::printf("%s: plastic update %.3f us, elastic update %.3f us\n",
                name,
                t_plastic,
                t_elastic);
  }
  return 0;
}
