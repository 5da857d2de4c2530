// The fibre of a strip bent in plane strain (doc/theory.md §9.3): eps_yy =
// 0, sigma_zz = 0, loaded monotonically along eps_xx, its stress from the
// material's own return mapping (independent of the element), and the
// moment of a section, b int sigma_xx(ln(1 + kappa z)) z dz. Shared by
// tests/element/plastic_bending.cc and tests/springback/.
#ifndef deepdraw_tests_element_plane_strain_fibre_h
#define deepdraw_tests_element_plane_strain_fibre_h

#include <algorithm>
#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deepdraw/material/elasto_plasticity.h>
#include <string>
#include <utility>
#include <vector>

namespace bending_reference
{
  using namespace dealii;

  // int f(z) dz over the thickness t, z from -t/2 to t/2 (trapezoidal rule
  // on n_fibres fibres).
  template <typename Function>
  double
  through_thickness(const double       thickness,
                    const Function    &f,
                    const unsigned int n_fibres = 4000)
  {
    double sum = 0.;
    for (unsigned int i = 0; i <= n_fibres; ++i)
    {
      const double z = -thickness / 2. + thickness * i / n_fibres;
      const double w
        = (i == 0 || i == n_fibres ? 0.5 : 1.) * thickness / n_fibres;
      sum += w * f(z);
    }
    return sum;
  }

  // The element's rule through the thickness t (heights from the
  // mid-plane, weights of a unit width): `points` Gauss points a layer
  // (2: at 1/2 -+ 1/(2 sqrt 3) of it, each carrying t / (2 layers)).
  inline std::vector<std::pair<double, double>>
  layer_gauss_rule(const double       thickness,
                   const unsigned int layers,
                   const unsigned int points = 2)
  {
    std::vector<std::pair<double, double>> rule;
    const double                           layer = thickness / layers;
    const dealii::QGauss<1>                gauss(points);
    for (unsigned int l = 0; l < layers; ++l)
      for (unsigned int q = 0; q < points; ++q)
        rule.emplace_back(-thickness / 2. + layer * (l + gauss.point(q)[0]),
                          layer * gauss.weight(q));
    return rule;
  }

  class PlaneStrainFibre
  {
  public:
    // material_prm: entries of subsection Material; the path eps_xx = 0 ->
    // eps_max in n_steps steps.
    PlaneStrainFibre(const std::string &material_prm,
                     const double       eps_max,
                     const unsigned int n_steps = 20000)
        : eps_max(eps_max)
        , table(n_steps + 1, 0.)
        , coupling_table(n_steps + 1, 0.)
        , thickness_table(n_steps + 1, 0.)
    {
      ParameterHandler prm;
      prm.enter_subsection("Material");
      deepdraw::material::MaterialParameters::declare_parameters(prm);
      prm.parse_input_from_string(material_prm);
      parameters.parse_parameters(prm);
      prm.leave_subsection();
      const deepdraw::material::ElastoPlasticity material(parameters);

      deepdraw::material::MaterialPointState state, next;
      SymmetricTensor<4, 3>                  tangent;
      for (unsigned int k = 1; k <= n_steps; ++k)
      {
        SymmetricTensor<2, 3> increment;
        increment[0][0] = eps_max / n_steps;
        bool plastic    = false;
        // Newton on the thickness strain increment: sigma_zz = 0.
        for (unsigned int iteration = 0; iteration < 20; ++iteration)
        {
          material.update(state, increment, next, tangent, plastic);
          if (std::abs(next.stress[2][2]) < 1e-10)
            break;
          increment[2][2] -= next.stress[2][2] / tangent[2][2][2][2];
        }
        state              = next;
        table[k]           = state.stress[0][0];
        coupling_table[k]  = tangent[0][0][2][2] / tangent[2][2][2][2];
        thickness_table[k] = thickness_table[k - 1] + increment[2][2];
      }
      coupling_table[0] = coupling_table[1];
    }

    // sigma_xx at the logarithmic strain eps (|eps| <= eps_max), odd in
    // eps (the material is symmetric in tension and compression).
    double
    stress(const double eps) const
    {
      const unsigned int n     = table.size() - 1;
      const double       s     = std::abs(eps) / eps_max * n;
      const auto         k     = std::min<unsigned int>(s, n - 1);
      const double       value = table[k] + (s - k) * (table[k + 1] - table[k]);
      return eps < 0. ? -value : value;
    }

    // The logarithmic thickness strain eps_zz of the fibre at eps, odd in
    // eps: elastic -nu / (1 - nu) eps, towards -eps once plastic.
    double
    thickness_strain(const double eps) const
    {
      const double value = interpolate(thickness_table, eps);
      return eps < 0. ? -value : value;
    }

    // d sigma_xx / d sigma_zz at fixed eps_xx, eps_yy (the step's tangent):
    // nu / (1 - nu) while elastic, near 1 once plastic.
    double
    coupling(const double eps) const
    {
      return interpolate(coupling_table, eps);
    }

    // b int sigma_xx(ln(1 + kappa z)) z dz over the thickness t
    // (trapezoidal rule on n_fibres fibres).
    double
    moment(const double       kappa,
           const double       thickness,
           const double       width,
           const unsigned int n_fibres = 4000) const
    {
      return width
             * through_thickness(
               thickness,
               [&](const double z)
               { return stress(std::log(1. + kappa * z)) * z; },
               n_fibres);
    }

    // The same moment summed with a through-thickness rule (heights and
    // weights of a unit width, layer_gauss_rule).
    double
    moment(const double                                  kappa,
           const double                                  width,
           const std::vector<std::pair<double, double>> &rule) const
    {
      double sum = 0.;
      for (const auto &[z, weight] : rule)
        sum += weight * stress(std::log(1. + kappa * z)) * z;
      return width * sum;
    }

    deepdraw::material::MaterialParameters parameters;

  private:
    double              eps_max;
    std::vector<double> table, coupling_table, thickness_table;

    // A table at |eps|, linear between its entries.
    double
    interpolate(const std::vector<double> &values, const double eps) const
    {
      const unsigned int n = values.size() - 1;
      const double       s = std::abs(eps) / eps_max * n;
      const auto         k = std::min<unsigned int>(s, n - 1);
      return values[k] + (s - k) * (values[k + 1] - values[k]);
    }
  };
} // namespace bending_reference

#endif
