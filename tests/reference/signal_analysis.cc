#include "signal_analysis.h"

#include <cmath>
#include <cstddef>

namespace towsim::reference {

std::vector<double> ZeroCrossings(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < t.size() && i + 1 < y.size(); ++i) {
    const double y0 = y[i];
    const double y1 = y[i + 1];
    if (y0 == 0.0) {
      // count an exact zero once, where the signal actually changes side
      if (i > 0 && y[i - 1] * y1 < 0.0) out.push_back(t[i]);
      continue;
    }
    if (y0 * y1 < 0.0) out.push_back(t[i] - y0 * (t[i + 1] - t[i]) / (y1 - y0));
  }
  return out;
}

double FrequencyFromCrossings(const std::vector<double>& crossings) {
  if (crossings.size() < 2) return 0.0;
  const double span = crossings.back() - crossings.front();
  return static_cast<double>(crossings.size() - 1) / (2.0 * span);
}

double FitConvergenceOrder(const std::vector<double>& h, const std::vector<double>& error) {
  // slope = cov(x, y) / var(x) with x = log h, y = log e
  const std::size_t n = h.size();
  double mx = 0.0;
  double my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += std::log(h[i]);
    my += std::log(error[i]);
  }
  mx /= n;
  my /= n;
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = std::log(h[i]) - mx;
    sxy += dx * (std::log(error[i]) - my);
    sxx += dx * dx;
  }
  return sxy / sxx;
}

}  // namespace towsim::reference
