#include "core/environment_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace towsim::core {
namespace {

constexpr double kPi = 3.14159265358979323846;
// a point at depth stops summing at the first component whose depth factor
// cosh k(zeta + h) / sinh kh (deep: e^{k zeta}) has fallen below this: the components are
// sorted by k, so every later one is smaller still (their sum stays below N times this of
// the surface kinematics)
constexpr double kDecayCutoff = 1e-9;

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
  long_crested_ = std::all_of(comps.begin(), comps.end(), [&](const WaveComponent& c) {
    return c.direction == comps.front().direction;
  });
  cos_b_ = std::cos(comps.front().direction);
  sin_b_ = std::sin(comps.front().direction);
  Components& s = waves_;
  const size_t n = comps.size();
  const size_t packets = (n + kPackLanes - 1) / kPackLanes;
  for (std::vector<Pack>* v : {&s.kx, &s.ky, &s.k, &s.omega, &s.phase, &s.a, &s.a_omega,
                               &s.a_omega2, &s.q, &s.inv_1mq, &s.cos_b, &s.sin_b})
    v->assign(packets, Broadcast(0.0));
  for (size_t j = 0; j < packets * kPackLanes; ++j) {
    // the padding repeats the last component with zero amplitude: it adds exactly 0
    const WaveComponent& p = comps[std::min(j, n - 1)];
    const double a = j < n ? p.amplitude : 0.0;
    const size_t i = j / kPackLanes, l = j % kPackLanes;
    const double q = std::isfinite(wave_depth_) ? std::exp(-2.0 * p.k * wave_depth_) : 0.0;
    s.kx[i][l] = p.k * std::cos(p.direction);
    s.ky[i][l] = p.k * std::sin(p.direction);
    s.k[i][l] = p.k;
    s.omega[i][l] = p.omega;
    s.phase[i][l] = p.phase;
    s.a[i][l] = a;
    s.a_omega[i][l] = a * p.omega;
    s.a_omega2[i][l] = a * p.omega * p.omega;
    s.q[i][l] = q;
    s.inv_1mq[i][l] = 1.0 / (1.0 - q);
    s.cos_b[i][l] = std::cos(p.direction);
    s.sin_b[i][l] = std::sin(p.direction);
    if (j < n) {
      s.k_scalar.push_back(p.k);
      s.log_inv_1mq.push_back(-std::log1p(-q));
    }
  }
  for (const WaveComponent& p : comps) amplitude_sum_ += p.amplitude;
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
  // eta = r sum a cos th, two components a packet
  const Components& s = waves_;
  Pack eta = Broadcast(0.0);
  for (size_t i = 0; i < s.k.size(); ++i) {
    Pack sn, c;
    SinCos(s.kx[i] * x + s.ky[i] * y + (s.phase[i] - s.omega[i] * t), &sn, &c);
    eta += s.a[i] * c;
  }
  return r * Sum(eta);
}

WaveSample EnvironmentField::Waves(const Vec3& p_W, const Vec3& d_W, double t) const {
  return SumWaves<true>(p_W, d_W, t);
}

size_t EnvironmentField::PacketsToSum(double zeta_e, bool always_wet) const {
  const Components& s = waves_;
  if (!always_wet) return s.k.size();
  // component j has decayed where C_j(zeta) <= e^{k_j zeta} / (1 - q_j) < kDecayCutoff, i.e.
  // k_j zeta + ln(1 / (1 - q_j)) < ln kDecayCutoff; both terms fall as k_j grows (zeta <= 0),
  // so the components to sum are a prefix of the sorted list
  const double log_cutoff = std::log(kDecayCutoff);
  size_t lo = 0, hi = s.k_scalar.size();
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (s.k_scalar[mid] * zeta_e + s.log_inv_1mq[mid] >= log_cutoff) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return (lo + kPackLanes - 1) / kPackLanes;
}

template <bool kDerivative>
WaveSample EnvironmentField::SumWaves(const Vec3& p_W, const Vec3& d_W, double t) const {
  return long_crested_ ? SumWaves<kDerivative, true>(p_W, d_W, t)
                       : SumWaves<kDerivative, false>(p_W, d_W, t);
}

template <bool kDerivative, bool kLongCrested>
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
  const size_t n = PacketsToSum(ze, always_wet);
  // long-crested: th = k s + phase - w t with s = x cos b + y sin b, and dth/ds = k ds along d
  const double along = x * cos_b_ + y * sin_b_;
  const double d_along = d_W.x() * cos_b_ + d_W.y() * sin_b_;
  // two components a packet; the horizontal parts are summed along the direction of travel
  // (long-crested) or resolved per component
  const Pack zero = Broadcast(0.0);
  Pack eta = zero, uh_s = zero, ah_s = zero, duh_s = zero, dah_s = zero;
  Pack ux = zero, uy = zero, uu = zero, ax = zero, ay = zero, au = zero;
  Pack dux = zero, duy = zero, duu = zero, dax = zero, day = zero, dau = zero;
  for (size_t i = 0; i < n; ++i) {
    const Pack k = s.k[i];
    // C = cosh k(zeta + h) / sinh kh, S = sinh k(zeta + h) / sinh kh (deep: e^{k zeta}):
    // E = e^{k zeta}, F = q / E, C = (E + F) / (1 - q), S = (E - F) / (1 - q)
    const Pack e = ExpNonPositive(k * ze);
    const Pack f = s.q[i] / e;
    const Pack inv = s.inv_1mq[i];
    const Pack cc = (e + f) * inv, ss = (e - f) * inv;
    const Pack th =
        (kLongCrested ? k * along : s.kx[i] * x + s.ky[i] * y) + (s.phase[i] - s.omega[i] * t);
    Pack sn, c;
    SinCos(th, &sn, &c);
    eta += s.a[i] * c;
    const Pack aw = s.a_omega[i], aw2 = s.a_omega2[i];
    // u_h = a w C cos th, u_up = a w S sin th; du/dt: th_t = -w
    const Pack uh = aw * cc * c, ah = aw2 * cc * sn;
    uu += aw * ss * sn;
    au -= aw2 * ss * c;
    if (kLongCrested) {
      uh_s += uh;
      ah_s += ah;
    } else {
      ux += uh * s.cos_b[i], uy += uh * s.sin_b[i];
      ax += ah * s.cos_b[i], ay += ah * s.sin_b[i];
    }
    if (!kDerivative) continue;
    // along d: dth/ds = kx dx + ky dy, dzeta/ds = -dz; dC/dzeta = k S, dS/dzeta = k C
    const Pack g = kLongCrested ? k * d_along : s.kx[i] * d_W.x() + s.ky[i] * d_W.y();
    const Pack dcc = k * ss * dze, dss = k * cc * dze;
    const Pack duh = aw * (dcc * c - cc * sn * g), dah = aw2 * (dcc * sn + cc * c * g);
    duu += aw * (dss * sn + ss * c * g);
    dau -= aw2 * (dss * c - ss * sn * g);
    if (kLongCrested) {
      duh_s += duh;
      dah_s += dah;
    } else {
      dux += duh * s.cos_b[i], duy += duh * s.sin_b[i];
      dax += dah * s.cos_b[i], day += dah * s.sin_b[i];
    }
  }
  // above the instantaneous surface (zeta > eta) the water is not there
  if (!always_wet && zeta > r * Sum(eta)) return out;
  // the horizontal sums resolved along (cos b, sin b)
  Vec3 u, a, du, da;
  if (kLongCrested) {
    const double uh = Sum(uh_s), ah = Sum(ah_s);
    u << uh * cos_b_, uh * sin_b_, -Sum(uu);
    a << ah * cos_b_, ah * sin_b_, -Sum(au);
    if (kDerivative) {
      const double duh = Sum(duh_s), dah = Sum(dah_s);
      du << duh * cos_b_, duh * sin_b_, -Sum(duu);
      da << dah * cos_b_, dah * sin_b_, -Sum(dau);
    }
  } else {
    u << Sum(ux), Sum(uy), -Sum(uu);
    a << Sum(ax), Sum(ay), -Sum(au);
    if (kDerivative) {
      du << Sum(dux), Sum(duy), -Sum(duu);
      da << Sum(dax), Sum(day), -Sum(dau);
    }
  }
  // NED: w = -u_up; the ramp scales the velocity, and its rate adds r' u to the acceleration
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
