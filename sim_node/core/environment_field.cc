#include "core/environment_field.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>

namespace towsim::core {
namespace {

constexpr double kPi = 3.14159265358979323846;
// a point at depth stops summing at the first component whose depth factor
// cosh k(zeta + h) / sinh kh (deep: e^{k zeta}) has fallen below this: the components are
// sorted by k, so every later one is smaller still (their sum stays below N times this of
// the surface kinematics)
constexpr double kDecayCutoff = 1e-9;

// round to the nearest integer (|x| < 2^51) by the 1.5 * 2^52 shift, without a library call
inline double RoundToInt(double x) {
  constexpr double kShift = 6755399441055744.0;  // 1.5 * 2^52
  return (x + kShift) - kShift;  // IEEE addition, not re-associated (no -ffast-math here)
}

// sin and cos of x (|x| < 1e9: wave phases) to about 1e-15 absolute, without the library's
// range reduction and special cases: x is reduced to r in [-pi, pi], the Taylor series of sin
// and cos to degree 17 and 18 give them at h = r / 2 (truncation (pi/2)^19 / 19! = 4e-15),
// and the double-angle formulas return to r
inline void SinCos(double x, double* s, double* c) {
  constexpr double kInv2Pi = 0.15915494309189535;
  constexpr double k2PiHi = 6.283185307179586, k2PiLo = 2.4492935982947064e-16;
  const double n = RoundToInt(x * kInv2Pi);
  const double r = (x - n * k2PiHi) - n * k2PiLo;
  const double h = 0.5 * r, h2 = h * h;
  // Horner in h^2 with the Taylor coefficients 1 / (2j (2j + 1)) and 1 / ((2j - 1) 2j)
  double ps = 1.0, pc = 1.0;
  constexpr double kS[8] = {1.0 / 272, 1.0 / 210, 1.0 / 156, 1.0 / 110,
                            1.0 / 72,  1.0 / 42,  1.0 / 20,  1.0 / 6};
  constexpr double kC[9] = {1.0 / 306, 1.0 / 240, 1.0 / 182, 1.0 / 132, 1.0 / 90,
                            1.0 / 56,  1.0 / 30,  1.0 / 12,  1.0 / 2};
  for (double k : kS) ps = 1.0 - h2 * k * ps;
  for (double k : kC) pc = 1.0 - h2 * k * pc;
  const double sh = h * ps, ch = pc;
  *s = 2.0 * sh * ch;
  *c = (ch - sh) * (ch + sh);
}

// e^y for y <= 0 (depth factors) to about 1e-15 relative: y = n ln 2 + r, |r| <= ln 2 / 2,
// Taylor to degree 12 (truncation 0.347^13 / 13! = 2e-16), 2^n from its exponent bits;
// below -700 (1e-304) it returns 0
inline double ExpNonPositive(double y) {
  if (y < -700.0) return 0.0;
  constexpr double kInvLn2 = 1.4426950408889634;
  constexpr double kLn2Hi = 0.6931471803691238, kLn2Lo = 1.9082149292705877e-10;
  const double n = RoundToInt(y * kInvLn2);
  const double r = (y - n * kLn2Hi) - n * kLn2Lo;
  constexpr double kInv[12] = {1.0 / 12, 1.0 / 11, 1.0 / 10, 1.0 / 9, 1.0 / 8, 1.0 / 7,
                               1.0 / 6,  1.0 / 5,  1.0 / 4,  1.0 / 3, 1.0 / 2, 1.0};
  double p = 1.0;
  for (double k : kInv) p = 1.0 + r * k * p;
  // 2^n: the biased exponent n + 1023 in bits 52-62
  const std::uint64_t bits = static_cast<std::uint64_t>(static_cast<std::int64_t>(n) + 1023) << 52;
  double two_n;
  std::memcpy(&two_n, &bits, sizeof two_n);
  return p * two_n;
}

}  // namespace

EnvironmentField::EnvironmentField(const Environment& env) : env_(env) {
  const CurrentField& c = env_.current;
  const WaveField& w = env_.waves;
  has_waves_ = !w.empty();
  has_seabed_ = env_.seabed.present();
  steady_uniform_current_ = c.IsUniform() && c.IsSteady();
  uniform_ = !has_waves_ && steady_uniform_current_;
  if (steady_uniform_current_) uniform_current_ = c.Velocity(0.0, 0.0);
  if (!has_waves_) return;
  wave_depth_ = w.depth();
  ramp_ = w.ramp();
  std::vector<WaveComponent> comps = w.components();
  std::stable_sort(comps.begin(), comps.end(),
                   [](const WaveComponent& a, const WaveComponent& b) { return a.k < b.k; });
  Components& s = waves_;
  for (const WaveComponent& p : comps) {
    s.kx.push_back(p.k * std::cos(p.direction));
    s.ky.push_back(p.k * std::sin(p.direction));
    s.k.push_back(p.k);
    s.omega.push_back(p.omega);
    s.phase.push_back(p.phase);
    s.a.push_back(p.amplitude);
    s.a_omega.push_back(p.amplitude * p.omega);
    s.a_omega2.push_back(p.amplitude * p.omega * p.omega);
    s.q.push_back(std::isfinite(wave_depth_) ? std::exp(-2.0 * p.k * wave_depth_) : 0.0);
    s.inv_1mq.push_back(1.0 / (1.0 - s.q.back()));
    s.cos_b.push_back(std::cos(p.direction));
    s.sin_b.push_back(std::sin(p.direction));
  }
  amplitude_sum_ = std::accumulate(s.a.begin(), s.a.end(), 0.0);
}

double EnvironmentField::Ramp(double t, double* rate) const {
  // r(t) = (1 - cos(pi t / T)) / 2 on [0, T), 1 after, 0 before 0 (wave_field.h)
  *rate = 0.0;
  if (ramp_ <= 0.0) return t < 0.0 ? 0.0 : 1.0;
  if (t <= 0.0) return 0.0;
  if (t >= ramp_) return 1.0;
  const double w = kPi / ramp_;
  *rate = 0.5 * w * std::sin(w * t);
  return 0.5 * (1.0 - std::cos(w * t));
}

FlowSample EnvironmentField::Current(const Vec3& p_W, double t, Vec3* shear) const {
  FlowSample f;
  if (steady_uniform_current_) {
    f.velocity = uniform_current_;
    if (shear) shear->setZero();
    return f;
  }
  const CurrentField& c = env_.current;
  f.velocity = c.Velocity(p_W.z(), t);
  f.acceleration = c.Acceleration(p_W.z(), t);
  if (shear) *shear = c.Shear(p_W.z(), t);
  return f;
}

double EnvironmentField::Elevation(double x, double y, double t) const {
  if (!has_waves_) return 0.0;
  double rate;
  const double r = Ramp(t, &rate);
  if (r == 0.0) return 0.0;
  const Components& s = waves_;
  double eta = 0.0;
  for (size_t i = 0; i < s.k.size(); ++i)
    eta += s.a[i] * std::cos(s.kx[i] * x + s.ky[i] * y - s.omega[i] * t + s.phase[i]);
  return r * eta;
}

WaveSample EnvironmentField::Waves(const Vec3& p_W, const Vec3& d_W, double t) const {
  return SumWaves<true>(p_W, d_W, t);
}

template <bool kDerivative>
WaveSample EnvironmentField::SumWaves(const Vec3& p_W, const Vec3& d_W, double t) const {
  WaveSample out;
  if (!has_waves_) return out;
  double r_rate;
  const double r = Ramp(t, &r_rate);
  if (r == 0.0 && r_rate == 0.0) return out;
  const Components& s = waves_;
  const double x = p_W.x(), y = p_W.y(), zeta = -p_W.z();  // zeta: height above the mean level
  // crest rule: between the mean and the instantaneous surface, the kinematics at zeta = 0;
  // below the seabed those at zeta = -h (wave_field.h); the clamped coordinate does not move
  double ze = zeta, dze = -d_W.z();
  if (ze > 0.0) ze = 0.0, dze = 0.0;
  if (ze < -wave_depth_) ze = -wave_depth_, dze = 0.0;
  // a point below every possible trough is always wet: its elevation is not needed, and it
  // may stop at the first decayed component
  const bool always_wet = zeta < -r * amplitude_sum_;
  double eta = 0.0;
  double ux = 0.0, uy = 0.0, uu = 0.0, ax = 0.0, ay = 0.0, au = 0.0;  // u_h, u_up, ...
  double dux = 0.0, duy = 0.0, duu = 0.0, dax = 0.0, day = 0.0, dau = 0.0;
  const size_t n = s.k.size();
  for (size_t i = 0; i < n; ++i) {
    const double k = s.k[i];
    // C = cosh k(zeta + h) / sinh kh, S = sinh k(zeta + h) / sinh kh (deep: e^{k zeta})
    const double e = ExpNonPositive(k * ze);
    const double q = s.q[i];
    const double inv = s.inv_1mq[i];
    if (always_wet && e * inv < kDecayCutoff) break;
    const double f = q / e;
    const double cc = (e + f) * inv, ss = (e - f) * inv;
    const double th = s.kx[i] * x + s.ky[i] * y - s.omega[i] * t + s.phase[i];
    double c, sn;
    SinCos(th, &sn, &c);
    eta += s.a[i] * c;
    // direction of travel (cos b, sin b) = (kx, ky) / k
    const double cb = s.cos_b[i], sb = s.sin_b[i];
    const double aw = s.a_omega[i], aw2 = s.a_omega2[i];
    // u_h = a w C cos th, u_up = a w S sin th; du/dt: th_t = -w
    const double uh = aw * cc * c, up = aw * ss * sn;
    const double ah = aw2 * cc * sn, ap = -aw2 * ss * c;
    ux += uh * cb, uy += uh * sb, uu += up;
    ax += ah * cb, ay += ah * sb, au += ap;
    if (!kDerivative) continue;
    // along d: dth/ds = kx dx + ky dy, dzeta/ds = -dz; dC/dzeta = k S, dS/dzeta = k C
    const double g = s.kx[i] * d_W.x() + s.ky[i] * d_W.y();
    const double dcc = k * ss * dze, dss = k * cc * dze;
    const double duh = aw * (dcc * c - cc * sn * g), dup = aw * (dss * sn + ss * c * g);
    const double dah = aw2 * (dcc * sn + cc * c * g), dap = -aw2 * (dss * c - ss * sn * g);
    dux += duh * cb, duy += duh * sb, duu += dup;
    dax += dah * cb, day += dah * sb, dau += dap;
  }
  // above the instantaneous surface (zeta > eta) the water is not there
  if (!always_wet && zeta > r * eta) return out;
  // NED: w = -u_up; the ramp scales the velocity, and its rate adds r' u to the acceleration
  const Vec3 u(ux, uy, -uu), a(ax, ay, -au), du(dux, duy, -duu), da(dax, day, -dau);
  out.velocity = r * u;
  out.acceleration = r * a + r_rate * u;
  if (kDerivative) {
    out.d_velocity = r * du;
    out.d_acceleration = r * da + r_rate * du;
  }
  return out;
}

template WaveSample EnvironmentField::SumWaves<true>(const Vec3&, const Vec3&, double) const;
template WaveSample EnvironmentField::SumWaves<false>(const Vec3&, const Vec3&, double) const;

FlowSample EnvironmentField::Flow(const Vec3& p_W, double t) const {
  FlowSample f = Current(p_W, t);
  if (has_waves_) {
    const WaveSample w = SumWaves<false>(p_W, Vec3::Zero(), t);
    f.velocity += w.velocity;
    f.acceleration += w.acceleration;
  }
  return f;
}

}  // namespace towsim::core
