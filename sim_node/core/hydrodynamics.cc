#include "core/hydrodynamics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

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

DragResult CableDrag(const FluidProperties& fluid, double diameter, const Vec3& a,
                     const Vec3& v_rel, bool jacobians) {
  DragResult out;
  const double stretch = a.norm();
  const Vec3 t = a / stretch;
  const double vt_s = t.dot(v_rel);
  const Vec3 vt = vt_s * t;
  const Vec3 vn = v_rel - vt;
  const double k = fluid.density * diameter / fluid.viscosity;  // Re per unit speed
  const double mu = fluid.viscosity;

  const double vn_norm = vn.norm();
  const double vt_norm = std::abs(vt_s);
  const DragLaw ln = NormalDragLaw(k * vn_norm);
  const DragLaw lt = TangentialDragLaw(k * vt_norm);
  // per stretched length: h = h_n + h_t
  const Vec3 h = -0.5 * mu * ln.g * vn - kPi * mu * lt.g * vt;
  out.f = stretch * h;
  if (!jacobians) return out;

  const Mat3 I = Mat3::Identity();
  const Mat3 tt = t * t.transpose();
  // dh_n/dV_n = -1/2 mu (G I + Re G' nh nh^T), dh_t/dV_t = -pi mu (Nu I + Re Nu' th th^T)
  Mat3 dn = -0.5 * mu * ln.g * I;
  if (vn_norm > 0.0) {
    const Vec3 nh = vn / vn_norm;
    dn -= 0.5 * mu * ln.re_dg * nh * nh.transpose();
  }
  // V_t is parallel to t, so th th^T = t t^T
  const Mat3 dt = -kPi * mu * (lt.g * I + lt.re_dg * tt);
  // dh/dV = Dn (I - t t^T) + Dt t t^T
  out.df_dv = stretch * (dn * (I - tt) + dt * tt);
  // dV_t/dt = (t.V) I + t V^T, dV_n/dt = -dV_t/dt
  const Mat3 dvt_dt = vt_s * I + t * v_rel.transpose();
  const Mat3 dh_dt = (dt - dn) * dvt_dt;
  const Mat3 dt_da = (I - tt) / stretch;
  // f = |a| h: df/da = h t^T + |a| dh/dt dt/da
  out.df_da = h * t.transpose() + stretch * dh_dt * dt_da;
  return out;
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
