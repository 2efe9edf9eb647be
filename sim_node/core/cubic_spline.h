#pragma once
// The natural cubic spline through samples (t_i, y_i), i = 0..n-1, t strictly increasing, n >= 2
// (e.g. de Boor, "A Practical Guide to Splines", ch. IV; Press et al., "Numerical Recipes",
// 3rd ed., §3.3). On [t_i, t_{i+1}], with h = t_{i+1} - t_i, A = (t_{i+1} - t) / h, B = 1 - A
// and M_i = y''(t_i):
//   y   = A y_i + B y_{i+1} + ((A^3 - A) M_i + (B^3 - B) M_{i+1}) h^2 / 6
//   y'  = (y_{i+1} - y_i) / h - (3 A^2 - 1) h M_i / 6 + (3 B^2 - 1) h M_{i+1} / 6
//   y'' = A M_i + B M_{i+1}
// so y, y' and y'' are continuous (C2) when the M solve, for i = 1..n-2,
//   h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
//       = 6 ((y_{i+1} - y_i) / h_i - (y_i - y_{i-1}) / h_{i-1}),
// with the natural end conditions M_0 = M_{n-1} = 0. The system is tridiagonal and strictly
// diagonally dominant: the Thomas algorithm solves it in O(n) without pivoting, once, when the
// spline is built. Two samples give the straight line. Evaluation: a binary search for the
// segment and the three formulas above, O(log n), no allocation.
//
// Accuracy for smooth data (samples of f at spacing h, away from the ends): y within
// O(h^4 f''''), y' within O(h^3 f''''), y'' within O(h^2 f''''). At the ends the natural
// condition y'' = 0 is imposed whatever f'' is there; its error decays by a factor of about
// 2 - sqrt(3) = 0.27 per knot inward.

#include <vector>

namespace towsim::core {

class CubicSpline {
 public:
  struct Value {
    double y = 0.0;    // y(t)
    double dy = 0.0;   // dy/dt
    double d2y = 0.0;  // d2y/dt2
  };

  CubicSpline() = default;
  // t strictly increasing, t.size() == y.size() >= 2 (the caller checks; see
  // scene/time_history_file.h)
  CubicSpline(std::vector<double> t, std::vector<double> y);

  // y, y', y'' at t, for t_0 <= t <= t_{n-1}; t outside is clamped to the nearest knot
  Value Evaluate(double t) const;

  const std::vector<double>& knots() const { return t_; }
  const std::vector<double>& values() const { return y_; }
  const std::vector<double>& second_derivatives() const { return m_; }  // M_i

 private:
  std::vector<double> t_;
  std::vector<double> y_;
  std::vector<double> m_;
};

}  // namespace towsim::core
