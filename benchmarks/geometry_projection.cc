// Closest-point projections per second onto the square-cup punch and die,
// single thread: 10^6 random points within a few mm of the tools (a random
// patch, a random parameter point, an offset along the normal in [-0.5, 3]
// mm and a tangential jitter of up to 1 mm), search distance 5 mm.
#include <chrono>
#include <deepdraw/geometry/square_cup_tools.h>
#include <iostream>
#include <random>

using namespace deepdraw::geometry;

int
main(int argc, char **argv)
{
  const unsigned int n_points = (argc > 1) ? std::stoul(argv[1]) : 1000000;
  const auto tools = build_square_cup_tools(SquareCupToolParameters(), 0.81);

  std::mt19937                           rng(2024);
  std::uniform_real_distribution<double> uniform(0., 1.);
  std::vector<dealii::Point<3>>          points(n_points);
  std::vector<unsigned int>              tool_of_point(n_points);
  for (unsigned int k = 0; k < n_points; ++k)
  {
    const unsigned int t    = (uniform(rng) < 0.5) ? 0 : 1;
    const RigidTool   &tool = tools[t];
    const BezierPatch &patch
      = tool.patch(std::min<unsigned int>(tool.n_patches() * uniform(rng),
                                          tool.n_patches() - 1));
    const SurfacePoint   s = patch.derivatives(uniform(rng), uniform(rng));
    const double         h = -0.5 + 3.5 * uniform(rng);
    dealii::Tensor<1, 3> jitter;
    for (unsigned int d = 0; d < 3; ++d)
      jitter[d] = 2 * uniform(rng) - 1;
    const dealii::Tensor<1, 3> n = unit_normal(s);
    jitter -= (jitter * n) * n;
    points[k]        = s.position + h * n + (1. / std::sqrt(3.)) * jitter;
    tool_of_point[k] = t;
  }

  ProjectionResult result;
  double           checksum = 0.;
  unsigned int     n_found = 0, n_free = 0;
  const auto       start = std::chrono::steady_clock::now();
  for (unsigned int k = 0; k < n_points; ++k)
    if (tools[tool_of_point[k]].project(points[k], result, 5.))
    {
      checksum += result.gap;
      ++n_found;
      n_free += result.on_free_edge;
    }
  const double seconds
    = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();

  std::cout << "projections: " << n_points << " (found " << n_found
            << ", on a free edge " << n_free << ", gap checksum " << checksum
            << ")\n"
            << "time: " << seconds << " s\n"
            << "points/s: " << n_points / seconds << std::endl;
  return 0;
}
