#include "grounded_catenary.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "damped_newton.h"

namespace towsim::reference {
namespace {

double Compliance(double ea) { return std::isinf(ea) ? 0.0 : 1.0 / ea; }

// r(H, V_F) = [span(H, V_F) - span, height(H, V_F) - height] of the grounded equations
Eigen::Vector2d Residual(const GroundedCatenaryProblem& p, double h, double v) {
  const double c = Compliance(p.ea);
  const double w = p.weight;
  const double lb = p.length - v / w;
  const double x = lb + (h / w) * std::asinh(v / h) + h * p.length * c;
  const double y = (h / w) * (std::hypot(1.0, v / h) - 1.0) + 0.5 * v * v * c / w;
  return {x - p.span, y - p.height};
}

}  // namespace

GroundedCatenarySolution SolveGroundedCatenary(const GroundedCatenaryProblem& p) {
  if (!(p.length > 0.0 && p.span > 0.0 && p.height > 0.0 && p.weight > 0.0 && p.ea > 0.0)) {
    throw std::runtime_error("grounded catenary: length, span, height, weight, EA must be > 0");
  }
  GroundedCatenarySolution sol;
  const double w = p.weight;
  // the free elastic catenary from the anchor decides: V_A is the upward force of the anchor
  // on the line; V_A > 0 means the free line would leave the anchor downward, into the bed, so
  // part of it rests on the bed; V_A <= 0: it rises from the anchor and never touches it
  {
    const CatenarySolution free = SolveElasticCatenary({p.length, p.span, p.height, w, p.ea});
    if (free.vertical_force_a <= 0.0) {
      sol.suspended = true;
      sol.horizontal_tension = free.horizontal_tension;
      sol.vertical_force = free.vertical_force_b;
      sol.fairlead_tension = free.tension_b;
      sol.anchor_tension = free.tension_a;
      return sol;
    }
  }
  // initial guess (Jonkman 2007 §2.1): lambda0 = sqrt(3 ((L^2 - h^2) / x^2 - 1)),
  // H0 = |w x / (2 lambda0)|, V0 = w / 2 (h / tanh(lambda0) + L), V held below w L
  const double ratio = (p.length * p.length - p.height * p.height) / (p.span * p.span) - 1.0;
  const double lambda0 = ratio > 0.0 ? std::sqrt(3.0 * ratio) : 0.2;
  double h = std::abs(w * p.span / (2.0 * lambda0));
  double v = std::min(0.5 * w * (p.height / std::tanh(lambda0) + p.length), 0.99 * w * p.length);
  // damped Newton: stay in H > 0, 0 < V_F <= w L
  const double scale = std::hypot(p.span, p.height);
  Eigen::Vector2d x(h, v), r;
  DampedNewton2(
      [&](const Eigen::Vector2d& y) { return Residual(p, y(0), y(1)); },
      [](const Eigen::Vector2d& y) { return Eigen::Vector2d(1e-6 * y(0), 1e-6 * y(1)); },
      [&](const Eigen::Vector2d& y) { return y(0) > 0.0 && y(1) > 0.0 && y(1) <= w * p.length; },
      1e-13 * scale, 200, 40, &x, &r);
  h = x(0);
  v = x(1);
  if (!(r.norm() <= 1e-10 * scale)) {
    throw std::runtime_error("grounded catenary: Newton did not converge, residual " +
                             std::to_string(r.norm()) + " m");
  }
  sol.horizontal_tension = h;
  sol.vertical_force = v;
  sol.fairlead_tension = std::hypot(h, v);
  sol.anchor_tension = h;
  sol.grounded_length = p.length - v / w;
  sol.touchdown = sol.grounded_length * (1.0 + h * Compliance(p.ea));
  return sol;
}

GroundedCatenaryPoint GroundedCatenaryShape(const GroundedCatenaryProblem& p,
                                            const GroundedCatenarySolution& sol, double s) {
  const double c = Compliance(p.ea);
  const double w = p.weight, h = sol.horizontal_tension;
  GroundedCatenaryPoint pt;
  if (sol.suspended) {
    const CatenaryPoint q = CatenaryShape({p.length, p.span, p.height, w, p.ea}, h,
                                          w * p.length - sol.vertical_force, s);
    pt.x = q.x;
    pt.y = q.y;
    pt.tension = q.tension;
    return pt;
  }
  if (s <= sol.grounded_length) {
    // on the bed: straight, tension H, stretched by H / EA
    pt.x = s * (1.0 + h * c);
    pt.tension = h;
    return pt;
  }
  // suspended from the touchdown point, where the vertical tension is zero:
  //   x = x_td + (H/w) asinh(w s'/H) + H s'/EA,  y = (H/w)(sqrt(1 + (w s'/H)^2) - 1) + w s'^2/(2EA)
  const double sp = s - sol.grounded_length;
  pt.x = sol.touchdown + (h / w) * std::asinh(w * sp / h) + h * sp * c;
  pt.y = (h / w) * (std::hypot(1.0, w * sp / h) - 1.0) + 0.5 * w * sp * sp * c;
  pt.tension = std::hypot(h, w * sp);
  return pt;
}

}  // namespace towsim::reference
