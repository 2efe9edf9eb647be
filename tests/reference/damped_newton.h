#pragma once
// Damped Newton's method for two unknowns, shared by the catenary references: the Jacobian
// from central differences, the step halved until the residual's norm falls (accepted anyway
// after the last halving) while the iterate stays admissible.

#include <Eigen/Dense>

namespace towsim::reference {

// Iterates x <- x + lambda dx, J dx = -r(x), until |r| <= tolerance or max_iterations.
//   residual(x) -> Eigen::Vector2d; fd_steps(x) -> Eigen::Vector2d of difference steps;
//   admissible(x) -> bool (a candidate that is not is halved again).
// Returns the iterations used; *x and *r hold the last iterate and its residual.
template <typename Residual, typename Steps, typename Admissible>
int DampedNewton2(const Residual& residual, const Steps& fd_steps, const Admissible& admissible,
                  double tolerance, int max_iterations, int max_halvings, Eigen::Vector2d* x,
                  Eigen::Vector2d* r) {
  *r = residual(*x);
  int it = 0;
  for (; it < max_iterations && r->norm() > tolerance; ++it) {
    // J = [dr/dx_0, dr/dx_1] by central differences
    const Eigen::Vector2d d = fd_steps(*x);
    Eigen::Matrix2d jac;
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d e = Eigen::Vector2d::Zero();
      e(j) = d(j);
      jac.col(j) = (residual(*x + e) - residual(*x - e)) / (2.0 * d(j));
    }
    const Eigen::Vector2d step = -jac.partialPivLu().solve(*r);
    double lambda = 1.0;
    for (int k = 0; k < max_halvings; ++k, lambda *= 0.5) {
      const Eigen::Vector2d x_new = *x + lambda * step;
      if (!admissible(x_new)) continue;
      const Eigen::Vector2d r_new = residual(x_new);
      if (r_new.norm() < r->norm() || k == max_halvings - 1) {
        *x = x_new;
        *r = r_new;
        break;
      }
    }
  }
  return it;
}

}  // namespace towsim::reference
