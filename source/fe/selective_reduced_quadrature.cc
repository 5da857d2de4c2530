#include <deal.II/base/quadrature_lib.h>
#include <deepdraw/fe/selective_reduced_quadrature.h>
#include <stdexcept>
#include <string>

namespace deepdraw
{
  namespace fe
  {
    Quadrature<3>
    selective_reduced_quadrature(const unsigned int points_through_thickness)
    {
      if (points_through_thickness < 2
          || points_through_thickness > max_points_through_thickness)
        throw std::invalid_argument(
          "selective_reduced_quadrature: 2 to 4 points through the thickness");
      const QGauss<1> in_plane(2);
      Quadrature<3>   gauss = QGauss<3>(2);
      if (points_through_thickness != 2)
        gauss = QAnisotropic<3>(in_plane,
                                in_plane,
                                QGauss<1>(points_through_thickness));
      std::vector<Point<3>> points  = gauss.get_points();
      std::vector<double>   weights = gauss.get_weights();
      points.emplace_back(0.5, 0.5, 0.5);
      weights.push_back(0.);
      return Quadrature<3>(points, weights);
    }


    Quadrature<3>
    quadrature_with_weighted_points(const unsigned int points_per_cell)
    {
      if (points_per_cell % 4 != 0 || points_per_cell < 8
          || points_per_cell > max_weighted_points)
        throw std::logic_error("no selective reduced rule has "
                               + std::to_string(points_per_cell)
                               + " points per cell");
      return selective_reduced_quadrature(
        points_through_thickness(points_per_cell));
    }
  } // namespace fe
} // namespace deepdraw
