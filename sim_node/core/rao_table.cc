#include "core/rao_table.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/constants.h"

namespace towsim::core {
namespace {

constexpr double kTwoPi = 2.0 * kPi;

// the two neighbouring entries along one axis and the weight w of the second:
// value = (1 - w) v[lo] + w v[hi]
struct AxisWeights {
  size_t lo = 0;
  size_t hi = 0;
  double w = 0.0;
};

// x within [v.front(), v.back()] (v strictly increasing): the bracketing pair
AxisWeights Bracket(const std::vector<double>& v, double x) {
  AxisWeights a;
  if (v.size() < 2 || !(x > v.front())) return a;  // lo = hi = 0 (also for a NaN x)
  if (x >= v.back()) {
    a.lo = a.hi = v.size() - 1;
    return a;
  }
  // v[lo] <= x < v[lo + 1]
  a.lo = static_cast<size_t>(std::upper_bound(v.begin(), v.end(), x) - v.begin()) - 1;
  a.hi = a.lo + 1;
  a.w = (x - v[a.lo]) / (v[a.hi] - v[a.lo]);
  return a;
}

// periods: clamped to the table's range (constant extrapolation)
AxisWeights PeriodWeights(const RaoTable& t, double period) { return Bracket(t.periods, period); }

// directions: beta' = d0 + (beta - d0 mod 2 pi) in [d0, d0 + 2 pi), then inside the span,
// across the wrap-around (periodic) or held at the nearer end of the gap (see the header)
AxisWeights DirectionWeights(const RaoTable& t, double direction) {
  const std::vector<double>& d = t.directions;
  AxisWeights a;
  if (d.size() < 2) return a;
  const double d0 = d.front(), d1 = d.back();
  double r = std::fmod(direction - d0, kTwoPi);
  if (r < 0.0) r += kTwoPi;
  if (r >= kTwoPi) r = 0.0;  // -tiny + 2 pi rounds to 2 pi: that is d0
  const double b = d0 + r;
  if (b <= d1) return Bracket(d, b);
  const size_t last = d.size() - 1;
  const double end = d0 + kTwoPi;  // the first direction once more around
  if (t.periodic_directions) {
    a.lo = last;
    a.hi = 0;
    a.w = (b - d1) / (end - d1);
    return a;
  }
  a.lo = a.hi = (b - d1 <= end - b) ? last : 0;
  return a;
}

// H = |H| e^{-i phi} of one table entry
std::complex<double> Entry(const RaoTable& t, int dof, size_t i, size_t j) {
  const size_t k = i * t.directions.size() + j;
  return std::polar(t.amplitude[dof][k], -t.phase[dof][k]);
}

std::complex<double> Interpolate(const RaoTable& t, int dof, const AxisWeights& p,
                                 const AxisWeights& d) {
  if (t.amplitude[dof].empty()) return {0.0, 0.0};
  // H = (1-wp)(1-wd) H00 + (1-wp) wd H01 + wp (1-wd) H10 + wp wd H11
  const std::complex<double> row_lo =
      (1.0 - d.w) * Entry(t, dof, p.lo, d.lo) + d.w * Entry(t, dof, p.lo, d.hi);
  const std::complex<double> row_hi =
      (1.0 - d.w) * Entry(t, dof, p.hi, d.lo) + d.w * Entry(t, dof, p.hi, d.hi);
  return (1.0 - p.w) * row_lo + p.w * row_hi;
}

}  // namespace

std::complex<double> RaoAt(const RaoTable& table, VesselDof dof, double period, double direction) {
  return Interpolate(table, static_cast<int>(dof), PeriodWeights(table, period),
                     DirectionWeights(table, direction));
}

std::array<std::complex<double>, kVesselDofs> RaosAt(const RaoTable& table, double period,
                                                     double direction) {
  const AxisWeights p = PeriodWeights(table, period);
  const AxisWeights d = DirectionWeights(table, direction);
  std::array<std::complex<double>, kVesselDofs> h;
  for (int j = 0; j < kVesselDofs; ++j) h[j] = Interpolate(table, j, p, d);
  return h;
}

}  // namespace towsim::core
