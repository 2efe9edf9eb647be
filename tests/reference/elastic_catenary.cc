#include "elastic_catenary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "damped_newton.h"

namespace towsim::reference {

namespace {

// stretch term 1/EA, zero for an inextensible cable
double Compliance(double ea) { return std::isinf(ea) ? 0.0 : 1.0 / ea; }

// residual of Irvine's equations r(H, V) = [x(L) - span, y(L) - height]
Eigen::Vector2d Residual(const CatenaryProblem& p, double h, double v) {
  const CatenaryPoint end = CatenaryShape(p, h, v, p.length);
  return {end.x - p.span, end.y - p.height};
}

}  // namespace

double InextensibleCatenaryParameter(double length, double span, double height) {
  const double chord2 = length * length - height * height;
  if (chord2 <= span * span) {
    throw std::runtime_error("catenary: L = " + std::to_string(length) +
                             " does not exceed the chord; no inextensible catenary");
  }
  // solve sinh(u) / u = sqrt(L^2 - h^2) / span =: k for u = span / (2a) > 0
  const double k = std::sqrt(chord2) / span;
  double u = std::sqrt(6.0 * (k - 1.0));  // sinh(u)/u ~ 1 + u^2/6
  if (k > 3.0) u = std::log(2.0 * k * std::log(2.0 * k) + 1.0);
  for (int it = 0; it < 100; ++it) {
    // f(u) = sinh(u) - k u, f' = cosh(u) - k
    const double f = std::sinh(u) - k * u;
    const double df = std::cosh(u) - k;
    double du = -f / df;
    if (u + du <= 0.0) du = -0.5 * u;
    u += du;
    if (std::abs(du) < 1e-15 * u) break;
  }
  return span / (2.0 * u);
}

CatenaryPoint CatenaryShape(const CatenaryProblem& p, double h, double v, double s) {
  const double c = Compliance(p.ea);
  const double w = p.weight;
  const double vs = v - w * s;  // upward component of the tension at s
  CatenaryPoint pt;
  pt.x = h * s * c + (h / w) * (std::asinh(v / h) - std::asinh(vs / h));
  pt.y =
      (0.5 * w * s * s - v * s) * c + (h / w) * (std::hypot(1.0, vs / h) - std::hypot(1.0, v / h));
  pt.tension = std::hypot(h, vs);
  return pt;
}

CatenarySolution SolveElasticCatenary(const CatenaryProblem& p) {
  if (!(p.length > 0.0 && p.span > 0.0 && p.weight > 0.0 && p.ea > 0.0)) {
    throw std::runtime_error("catenary: length, span, weight and EA must be > 0");
  }
  const double w_total = p.weight * p.length;
  // initial guess: inextensible catenary when it exists, else a taut straight cable
  double h = 0.0;
  double v = 0.0;
  const double chord = std::hypot(p.span, p.height);
  if (p.length > chord * (1.0 + 1e-9)) {
    const double a = InextensibleCatenaryParameter(p.length, p.span, p.height);
    h = p.weight * a;
    // tanh((alpha + beta) / 2) = height / L, alpha - beta = span / a, V = H sinh(alpha)
    const double alpha = std::atanh(p.height / p.length) + p.span / (2.0 * a);
    v = h * std::sinh(alpha);
  } else {
    if (std::isinf(p.ea)) throw std::runtime_error("catenary: inextensible cable too short");
    const double t = p.ea * (chord / p.length - 1.0) + w_total;
    h = t * p.span / chord;
    v = t * p.height / chord + 0.5 * w_total;
  }

  // Newton on (H, V) with a central-difference Jacobian and step halving
  CatenarySolution sol;
  const double scale = chord;
  Eigen::Vector2d x(h, v), r;
  const int it = DampedNewton2(
      [&](const Eigen::Vector2d& y) { return Residual(p, y(0), y(1)); },
      [](const Eigen::Vector2d& y) {
        return Eigen::Vector2d(1e-6 * y(0), 1e-6 * std::max(std::abs(y(1)), y(0)));
      },
      [](const Eigen::Vector2d& y) { return y(0) > 0.0; }, 1e-13 * scale, 100, 30, &x, &r);
  h = x(0);
  v = x(1);
  if (!(r.norm() <= 1e-10 * scale)) {
    throw std::runtime_error("catenary: Newton did not converge, residual " +
                             std::to_string(r.norm()) + " m");
  }
  sol.iterations = it;
  sol.horizontal_tension = h;
  sol.vertical_force_a = v;
  sol.vertical_force_b = w_total - v;
  sol.tension_a = std::hypot(h, v);
  sol.tension_b = std::hypot(h, w_total - v);

  // mid-span sag: find s with x(s) = span / 2 (x is increasing in s), by Newton on s
  // with dx/ds = (1 + T/EA) H / T
  double s = 0.5 * p.length;
  for (int k = 0; k < 100; ++k) {
    const CatenaryPoint pt = CatenaryShape(p, h, v, s);
    const double dxds = (1.0 + pt.tension * Compliance(p.ea)) * h / pt.tension;
    const double ds = -(pt.x - 0.5 * p.span) / dxds;
    s += ds;
    if (std::abs(ds) < 1e-14 * p.length) break;
  }
  sol.sag_mid_span = 0.5 * p.height - CatenaryShape(p, h, v, s).y;
  return sol;
}

}  // namespace towsim::reference
