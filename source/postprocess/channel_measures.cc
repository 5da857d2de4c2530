#include <cmath>
#include <deal.II/base/tensor.h>
#include <deepdraw/postprocess/channel_measures.h>
#include <limits>
#include <stdexcept>

namespace deepdraw
{
  namespace postprocess
  {
    namespace
    {
      // The unit direction of the total-least-squares line through the
      // points (the principal axis of their scatter), oriented from the
      // first point towards the last.
      Tensor<1, 2>
      line_direction(const std::vector<Point<2>> &points)
      {
        Point<2> centre;
        for (const Point<2> &p : points)
          centre += p / double(points.size());
        double sxx = 0., sxz = 0., szz = 0.;
        for (const Point<2> &p : points)
        {
          const Tensor<1, 2> d = p - centre;
          sxx += d[0] * d[0];
          sxz += d[0] * d[1];
          szz += d[1] * d[1];
        }
        const double angle = 0.5 * std::atan2(2. * sxz, sxx - szz);
        Tensor<1, 2> direction({std::cos(angle), std::sin(angle)});
        if (direction * (points.back() - points.front()) < 0.)
          direction *= -1.;
        return direction;
      }

      // 180 degrees minus the angle between two directions of travel.
      double
      inside_angle(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        const double between
          = std::atan2(a[0] * b[1] - a[1] * b[0], a * b) * 180. / M_PI;
        return 180. - std::abs(between);
      }

      // Kasa's fit: x^2 + z^2 + D x + E z + F = 0 in least squares, about
      // the centroid (for conditioning); the radius sqrt(D^2/4 + E^2/4 - F).
      double
      circle_radius(const std::vector<Point<2>> &points)
      {
        Point<2> centre;
        for (const Point<2> &p : points)
          centre += p / double(points.size());
        double m[3][4] = {};
        for (const Point<2> &p : points)
        {
          const double x = p[0] - centre[0], z = p[1] - centre[1];
          const double row[4] = {x, z, 1., -(x * x + z * z)};
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = 0; j < 4; ++j)
              m[i][j] += row[i] * row[j];
        }
        // Gaussian elimination with partial pivoting on the 3 x 3 normal
        // equations.
        for (unsigned int k = 0; k < 3; ++k)
        {
          unsigned int pivot = k;
          for (unsigned int i = k + 1; i < 3; ++i)
            if (std::abs(m[i][k]) > std::abs(m[pivot][k]))
              pivot = i;
          for (unsigned int j = 0; j < 4; ++j)
            std::swap(m[k][j], m[pivot][j]);
          if (std::abs(m[k][k]) < 1e-300)
            return std::numeric_limits<double>::infinity();
          for (unsigned int i = k + 1; i < 3; ++i)
          {
            const double factor = m[i][k] / m[k][k];
            for (unsigned int j = k; j < 4; ++j)
              m[i][j] -= factor * m[k][j];
          }
        }
        double solution[3];
        for (int i = 2; i >= 0; --i)
        {
          double sum = m[i][3];
          for (unsigned int j = i + 1; j < 3; ++j)
            sum -= m[i][j] * solution[j];
          solution[i] = sum / m[i][i];
        }
        const double squared
          = 0.25 * (solution[0] * solution[0] + solution[1] * solution[1])
            - solution[2];
        // A straight wall: the circle through collinear points is at
        // infinity (the fit degenerates).
        return squared > 0. && std::isfinite(squared)
                 ? std::sqrt(squared)
                 : std::numeric_limits<double>::infinity();
      }
    } // namespace


    ChannelMeasures
    channel_measures(const std::vector<Point<2>> &bottom,
                     const std::vector<Point<2>> &wall,
                     const std::vector<Point<2>> &flange)
    {
      if (bottom.size() < 2 || wall.size() < 3 || flange.size() < 2)
        throw std::invalid_argument(
          "a channel's bottom and flange need 2 points, its wall 3");
      const Tensor<1, 2> d_bottom = line_direction(bottom);
      const Tensor<1, 2> d_wall   = line_direction(wall);
      const Tensor<1, 2> d_flange = line_direction(flange);
      ChannelMeasures    measures;
      measures.theta1 = inside_angle(d_bottom, d_wall);
      measures.theta2 = inside_angle(d_wall, d_flange);
      measures.rho    = circle_radius(wall);
      return measures;
    }
  } // namespace postprocess
} // namespace deepdraw
