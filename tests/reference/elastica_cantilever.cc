#include "elastica_cantilever.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace towsim::reference {

namespace {

// state y = [theta, theta', x, z] over sigma in [0, 1]
using Y = std::array<double, 4>;

Y Rhs(double alpha, const Y& y) {
  return {y[1], -alpha * std::cos(y[0]), std::cos(y[0]), std::sin(y[0])};
}

Y Integrate(double alpha, double kappa0, int steps) {
  Y y = {0.0, kappa0, 0.0, 0.0};
  const double h = 1.0 / steps;
  for (int i = 0; i < steps; ++i) {
    // classical RK4
    const Y k1 = Rhs(alpha, y);
    Y t;
    for (int j = 0; j < 4; ++j) t[j] = y[j] + 0.5 * h * k1[j];
    const Y k2 = Rhs(alpha, t);
    for (int j = 0; j < 4; ++j) t[j] = y[j] + 0.5 * h * k2[j];
    const Y k3 = Rhs(alpha, t);
    for (int j = 0; j < 4; ++j) t[j] = y[j] + h * k3[j];
    const Y k4 = Rhs(alpha, t);
    for (int j = 0; j < 4; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
  }
  return y;
}

}  // namespace

ElasticaTip SolveCantileverElastica(double alpha, int steps) {
  if (alpha < 0.0 || steps < 1) throw std::runtime_error("elastica: alpha >= 0, steps >= 1");
  // the root curvature theta'(0) = alpha x_tip lies in [0, alpha]; theta'(1) is the residual.
  // bracket the physical (first-mode) root: theta'(1) is < 0 for kappa0 = 0 when alpha > 0,
  // and the theta(s) of the physical branch stays within [0, pi/2]
  double lo = 0.0;
  double hi = alpha;
  auto residual = [&](double k0) { return Integrate(alpha, k0, steps)[1]; };
  double r_lo = residual(lo);
  double r_hi = residual(hi);
  if (alpha > 0.0 && !(r_lo <= 0.0 && r_hi >= 0.0)) {
    throw std::runtime_error("elastica: root not bracketed for alpha = " + std::to_string(alpha));
  }
  // bisection to near machine precision, then secant polish
  double k0 = 0.5 * (lo + hi);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * (1.0 + alpha); ++it) {
    k0 = 0.5 * (lo + hi);
    const double r = residual(k0);
    if (r < 0.0) {
      lo = k0;
      r_lo = r;
    } else {
      hi = k0;
      r_hi = r;
    }
  }
  k0 = (r_hi - r_lo) != 0.0 ? lo - r_lo * (hi - lo) / (r_hi - r_lo) : lo;
  const Y y = Integrate(alpha, k0, steps);
  ElasticaTip tip;
  tip.deflection = y[3];
  tip.shortening = 1.0 - y[2];
  tip.tip_angle = y[0];
  tip.root_curvature = k0;
  return tip;
}

}  // namespace towsim::reference
