#include "core/hydrodynamics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/cable_drag.h"
#include "core/constants.h"

namespace towsim::core {
namespace {
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
constexpr double kReMax = 1.0e5;    // upper end of Eq. 18's range
constexpr double kReMin = 1.0e-12;  // guard: below, the Re -> 0 limit of G is used

// x^(1/3) for a normal x > 0, to the last bit or two, several times cheaper than std::cbrt
// (which goes through frexp / ldexp): a first guess from the exponent bits (dividing the
// biased exponent by 3; relative error < 4 %), then Halley's iteration
// y <- y (y^3 + 2x) / (2 y^3 + x), cubically convergent: 4e-2 -> 1e-5 -> 1e-15 -> rounding.
double CubeRoot(double x) {
  if (!(x > 1e-300 && x < 1e300)) return std::cbrt(x);  // subnormal, huge, inf, nan
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits = bits / 3 + 0x2A9F7893782DA1CEull;  // (bits - bias) / 3 + bias, with a tuned offset
  double y;
  std::memcpy(&y, &bits, sizeof y);
  for (int k = 0; k < 3; ++k) {
    const double y3 = y * y * y;
    y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
  }
  return y;
}
}  // namespace

double NormalDragCoefficient(double re) {
  re = std::max(re, kReMin);
  return NormalDragLaw(re).g / re;
}

double NusseltNumber(double re) { return TangentialDragLaw(re).g; }

DragLaw NormalDragLaw(double re) {
  if (re < kReMin) re = kReMin;
  if (re <= 1.0) {
    // C = 8 pi / (Re S) (1 - 0.87 S^-2), S = -0.07721 + ln(8 / Re)
    // G = 8 pi (1/S - 0.87/S^3), Re G' = 8 pi (1/S^2 - 2.61/S^4)  (dS/dRe = -1/Re)
    const double s = -0.07721 + std::log(8.0 / re);
    const double s2 = s * s;
    return {8.0 * kPi * (1.0 / s - 0.87 / (s2 * s)), 8.0 * kPi * (1.0 / s2 - 2.61 / (s2 * s2))};
  }
  if (re < 30.0) {
    // C = 1.45 + 8.55 Re^-0.9
    const double p = std::pow(re, 0.1);
    return {1.45 * re + 8.55 * p, 1.45 * re + 0.855 * p};
  }
  if (re <= kReMax) {
    // C = 1.1 + 4 Re^-0.5
    const double s = std::sqrt(re);
    return {1.1 * re + 4.0 * s, 1.1 * re + 2.0 * s};
  }
  const double c_max = 1.1 + 4.0 / std::sqrt(kReMax);
  return {c_max * re, c_max * re};
}

DragLaw TangentialDragLaw(double re) {
  if (re <= 0.0) return {0.0, 0.0};
  const double s = std::sqrt(re), c = CubeRoot(re), t = c * c;  // Re^1/2, Re^2/3
  return {0.55 * s + 0.084 * t, 0.275 * s + 0.056 * t};
}

// Choo & Casarella's instantiation here, the constant coefficients' in constant_drag.cc (one
// each per file: the default law compiles to the code it had before line types)
template DragResult CableDragOf<false>(const FluidProperties&, const CableDragLaw&, double,
                                       const Vec3&, const Vec3&, bool);

DragResult CableDrag(const FluidProperties& fluid, const CableDragLaw& law, double diameter,
                     const Vec3& a, const Vec3& v_rel, bool jacobians) {
  if (law.kind == CableDragLaw::kConstant)
    return CableDragOf<true>(fluid, law, diameter, a, v_rel, jacobians);
  return CableDragOf<false>(fluid, law, diameter, a, v_rel, jacobians);
}

Mat3 NormalProjector(const Vec3& a) {
  const Vec3 t = a.normalized();
  return Mat3::Identity() - t * t.transpose();
}

Mat3 AddedMassTangentDerivative(double m_a, const Vec3& a, const Vec3& acc) {
  // f = -m_a (acc - t (t.acc)); df/dt = m_a ((t.acc) I + t acc^T); dt/da = (I - t t^T)/|a|
  const double n = a.norm();
  const Vec3 t = a / n;
  const Mat3 I = Mat3::Identity();
  return m_a * (t.dot(acc) * I + t * acc.transpose()) * (I - t * t.transpose()) / n;
}

}  // namespace towsim::core
