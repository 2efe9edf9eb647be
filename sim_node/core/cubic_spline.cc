#include "core/cubic_spline.h"

#include <algorithm>
#include <utility>

namespace towsim::core {

CubicSpline::CubicSpline(std::vector<double> t, std::vector<double> y)
    : t_(std::move(t)), y_(std::move(y)), m_(t_.size(), 0.0) {
  const size_t n = t_.size();
  if (n < 3) return;  // a straight line: M = 0
  // Thomas algorithm on rows i = 1..n-2: sub h_{i-1}, diag 2 (h_{i-1} + h_i), super h_i.
  // Forward sweep: c'_i = super_i / (diag_i - sub_i c'_{i-1}), d'_i likewise; M_0 = 0 drops.
  std::vector<double> c(n, 0.0), d(n, 0.0);
  for (size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t_[i] - t_[i - 1];
    const double h1 = t_[i + 1] - t_[i];
    const double rhs = 6.0 * ((y_[i + 1] - y_[i]) / h1 - (y_[i] - y_[i - 1]) / h0);
    const double denom = 2.0 * (h0 + h1) - h0 * c[i - 1];
    c[i] = h1 / denom;
    d[i] = (rhs - h0 * d[i - 1]) / denom;
  }
  // back substitution: M_i = d'_i - c'_i M_{i+1}, M_{n-1} = 0
  for (size_t i = n - 2; i >= 1; --i) m_[i] = d[i] - c[i] * m_[i + 1];
}

CubicSpline::Value CubicSpline::Evaluate(double t) const {
  Value v;
  const size_t n = t_.size();
  if (n == 0) return v;
  if (n == 1) {
    v.y = y_[0];
    return v;
  }
  t = std::clamp(t, t_.front(), t_.back());
  // segment i: t_i <= t <= t_{i+1}
  size_t i = static_cast<size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  i = std::min(i == 0 ? 0 : i - 1, n - 2);
  const double h = t_[i + 1] - t_[i];
  const double a = (t_[i + 1] - t) / h;
  const double b = 1.0 - a;
  const double mi = m_[i], mj = m_[i + 1];
  v.y = a * y_[i] + b * y_[i + 1] + ((a * a * a - a) * mi + (b * b * b - b) * mj) * (h * h) / 6.0;
  v.dy = (y_[i + 1] - y_[i]) / h - (3.0 * a * a - 1.0) * h * mi / 6.0 +
         (3.0 * b * b - 1.0) * h * mj / 6.0;
  v.d2y = a * mi + b * mj;
  return v;
}

}  // namespace towsim::core
