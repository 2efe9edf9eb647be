#include "core/wave_field.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/constants.h"

namespace towsim::core {
namespace {

// 2 k h above which tanh(k h) = 1 and exp(-2 k h) = 0 to double precision
constexpr double kDeepWaterTwoKh = 80.0;

// the spectrum without its scale A: w^-5 exp(-5/4 (w_p/w)^4) gamma^r(w)
double SpectrumShape(const WaveSpectrum& s, double omega) {
  if (omega <= 0.0) return 0.0;
  const double wp = 2.0 * kPi / s.tp;
  const double x = wp / omega;
  const double x4 = (x * x) * (x * x);
  double shape = std::exp(-1.25 * x4) / std::pow(omega, 5.0);
  if (s.kind == WaveSpectrumKind::kJonswap && s.gamma != 1.0) {
    // r = exp(-(w - w_p)^2 / (2 sigma^2 w_p^2)), sigma = 0.07 (w <= w_p) or 0.09
    const double sigma = omega <= wp ? 0.07 : 0.09;
    const double d = (omega - wp) / (sigma * wp);
    shape *= std::pow(s.gamma, std::exp(-0.5 * d * d));
  }
  return shape;
}

// The cumulative energy of the shape on a grid uniform in u = ln w from w_p/5 to 50 w_p
// (trapezoid rule in u of S(w) w; 20000 intervals, relative error ~1e-9 for gamma <= 20),
// plus the analytic tail beyond: int_W^inf w^-5 dw = W^-4 / 4 (there gamma^r = 1 and the
// exponential is 1 - 2e-7). Below w_p/5 the shape is below exp(-780): zero.
struct CumulativeSpectrum {
  std::vector<double> omega;
  std::vector<double> energy;  // int_0^omega shape
  double total = 0.0;          // int_0^inf shape

  explicit CumulativeSpectrum(const WaveSpectrum& s) {
    constexpr int kIntervals = 20000;
    const double wp = 2.0 * kPi / s.tp;
    const double u0 = std::log(0.2 * wp), u1 = std::log(50.0 * wp);
    const double du = (u1 - u0) / kIntervals;
    omega.resize(kIntervals + 1);
    energy.resize(kIntervals + 1);
    double prev = 0.0;
    for (int j = 0; j <= kIntervals; ++j) {
      const double w = std::exp(u0 + j * du);
      const double g = SpectrumShape(s, w) * w;
      omega[j] = w;
      energy[j] = j == 0 ? 0.0 : energy[j - 1] + 0.5 * du * (prev + g);
      prev = g;
    }
    const double w_end = omega.back();
    total = energy.back() + 0.25 / ((w_end * w_end) * (w_end * w_end));
  }

  // w at which the cumulative energy reaches e (0 <= e <= energy.back()), linear in the table
  double Inverse(double e) const {
    const auto it = std::lower_bound(energy.begin(), energy.end(), e);
    if (it == energy.begin()) return omega.front();
    if (it == energy.end()) return omega.back();
    const size_t j = static_cast<size_t>(it - energy.begin());
    const double f = (e - energy[j - 1]) / (energy[j] - energy[j - 1]);
    return omega[j - 1] + f * (omega[j] - omega[j - 1]);
  }
};

}  // namespace

double WaveNumber(double omega, double depth, double gravity) {
  if (omega <= 0.0) return 0.0;
  // deep water: w^2 = g k
  const double k0 = omega * omega / gravity;
  if (!std::isfinite(depth) || 2.0 * k0 * depth > kDeepWaterTwoKh) return k0;
  // Eckart (1952): k ~ k0 / sqrt(tanh(k0 h)); exact in both limits, within 5 % between
  double k = k0 / std::sqrt(std::tanh(k0 * depth));
  // Newton on f(k) = g k tanh(k h) - w^2, f' = g tanh(k h) + g k h sech^2(k h)
  for (int it = 0; it < 50; ++it) {
    const double th = std::tanh(k * depth);
    const double f = gravity * k * th - omega * omega;
    const double fp = gravity * (th + k * depth * (1.0 - th * th));
    const double dk = f / fp;
    k -= dk;
    if (std::abs(dk) <= 1e-15 * k) break;
  }
  return k;
}

double UniformUnit(std::uint64_t draw) {
  // the top 53 bits as a fraction: (x >> 11) 2^-53 in [0, 1)
  return static_cast<double>(draw >> 11) * (1.0 / 9007199254740992.0);
}

double SpectralDensity(const WaveSpectrum& spectrum, double omega) {
  // S = A shape, A = (Hs^2 / 16) / int shape
  const CumulativeSpectrum cumulative(spectrum);
  const double m0 = spectrum.hs * spectrum.hs / 16.0;
  return m0 / cumulative.total * SpectrumShape(spectrum, omega);
}

WaveField::WaveField(double depth, double gravity, double density)
    : depth_(depth), gravity_(gravity), density_(density) {}

WaveField WaveField::Regular(double height, double period, double direction, double phase,
                             double depth, double gravity, double density) {
  WaveField w(depth, gravity, density);
  w.AddComponent(0.5 * height, 2.0 * kPi / period, direction, phase);
  return w;
}

WaveField WaveField::Irregular(const WaveSpectrum& spectrum, double depth, double gravity,
                               double density) {
  WaveField w(depth, gravity, density);
  const CumulativeSpectrum cumulative(spectrum);
  const int n = spectrum.components;
  // equal-energy bins over the band [e_lo, e_hi] of the cumulative energy
  const double e_lo = kSpectrumTailFraction * cumulative.total;
  const double e_hi = (1.0 - kSpectrumTailFraction) * cumulative.total;
  const double de = (e_hi - e_lo) / n;
  // a = sqrt(2 m0 / N): the components share the whole m0 = Hs^2 / 16
  const double a = std::sqrt(2.0 * (spectrum.hs * spectrum.hs / 16.0) / n);
  std::mt19937_64 rng(spectrum.seed);
  double w_lo = cumulative.Inverse(e_lo);
  for (int i = 0; i < n; ++i) {
    const double w_hi = cumulative.Inverse(e_lo + (i + 1) * de);
    // frequency uniform in the bin, then phase uniform in [0, 2 pi): two draws per component
    const double omega = w_lo + UniformUnit(rng()) * (w_hi - w_lo);
    const double phase = 2.0 * kPi * UniformUnit(rng());
    w.AddComponent(a, omega, spectrum.direction, phase);
    w_lo = w_hi;
  }
  return w;
}

void WaveField::AddComponent(double amplitude, double omega, double direction, double phase) {
  WaveComponent c;
  c.amplitude = amplitude;
  c.omega = omega;
  c.k = WaveNumber(omega, depth_, gravity_);
  c.direction = direction;
  c.phase = phase;
  components_.push_back(c);

  Term t;
  t.k = c.k;
  t.cos_b = std::cos(direction);
  t.sin_b = std::sin(direction);
  t.kx = c.k * t.cos_b;
  t.ky = c.k * t.sin_b;
  t.omega = omega;
  t.phase = phase;
  t.a = amplitude;
  t.a_omega = amplitude * omega;
  t.a_omega2 = amplitude * omega * omega;
  t.rho_g_a = density_ * gravity_ * amplitude;
  // q = exp(-2 k h): 0 in deep water (and where it underflows)
  t.q = std::isfinite(depth_) && 2.0 * c.k * depth_ <= kDeepWaterTwoKh
            ? std::exp(-2.0 * c.k * depth_)
            : 0.0;
  t.inv_1mq = 1.0 / (1.0 - t.q);
  t.inv_1pq = 1.0 / (1.0 + t.q);
  terms_.push_back(t);
}

double WaveField::Ramp(double t) const {
  // r = (1 - cos(pi t / T_r)) / 2 on [0, T_r)
  if (ramp_ <= 0.0) return 1.0;
  if (t <= 0.0) return 0.0;
  if (t >= ramp_) return 1.0;
  return 0.5 * (1.0 - std::cos(kPi * t / ramp_));
}

double WaveField::RampRate(double t) const {
  // dr/dt = pi / (2 T_r) sin(pi t / T_r) on (0, T_r)
  if (ramp_ <= 0.0 || t <= 0.0 || t >= ramp_) return 0.0;
  return 0.5 * kPi / ramp_ * std::sin(kPi * t / ramp_);
}

double WaveField::RampAcceleration(double t) const {
  // d2r/dt2 = pi^2 / (2 T_r^2) cos(pi t / T_r) on (0, T_r)
  if (ramp_ <= 0.0 || t <= 0.0 || t >= ramp_) return 0.0;
  return 0.5 * kPi * kPi / (ramp_ * ramp_) * std::cos(kPi * t / ramp_);
}

double WaveField::Elevation(double x, double y, double t) const {
  // eta = r(t) sum a cos th
  if (terms_.empty()) return 0.0;
  double eta = 0.0;
  for (const Term& c : terms_) eta += c.a * std::cos(c.kx * x + c.ky * y - c.omega * t + c.phase);
  return Ramp(t) * eta;
}

void WaveField::ElevationGrid(double x0, double dx, int nx, double y0, double dy, int ny, double t,
                              std::vector<double>* work, double* out) const {
  const size_t n = static_cast<size_t>(nx) * static_cast<size_t>(ny);
  std::fill(out, out + n, 0.0);
  if (terms_.empty()) return;
  work->resize(2 * static_cast<size_t>(nx + ny));
  double* cos_a = work->data();
  double* sin_a = cos_a + nx;
  double* cos_b = sin_a + nx;
  double* sin_b = cos_b + ny;
  for (const Term& c : terms_) {
    // a cos(A_i + B_j), A_i = kx x_i - w t + f, B_j = ky y_j
    for (int i = 0; i < nx; ++i) {
      const double th = c.kx * (x0 + i * dx) - c.omega * t + c.phase;
      cos_a[i] = c.a * std::cos(th);
      sin_a[i] = c.a * std::sin(th);
    }
    for (int j = 0; j < ny; ++j) {
      cos_b[j] = std::cos(c.ky * (y0 + j * dy));
      sin_b[j] = std::sin(c.ky * (y0 + j * dy));
    }
    for (int i = 0; i < nx; ++i) {
      double* row = out + static_cast<size_t>(i) * static_cast<size_t>(ny);
      for (int j = 0; j < ny; ++j) row[j] += cos_a[i] * cos_b[j] - sin_a[i] * sin_b[j];
    }
  }
  const double r = Ramp(t);
  for (size_t k = 0; k < n; ++k) out[k] *= r;
}

WaveKinematics WaveField::Kinematics(const Vec3& p_W, double t) const {
  WaveKinematics out;
  if (terms_.empty()) {
    out.wet = p_W.z() >= 0.0;  // calm: the surface is z = 0
    return out;
  }
  // zeta: height above the mean surface, held in [-h, 0] (see the header)
  const double zeta = std::clamp(-p_W.z(), std::isfinite(depth_) ? -depth_ : -1e300, 0.0);
  // clamped (a crest, below the seabed): the kinematics do not vary with z there
  const double vertical = zeta == -p_W.z() ? 1.0 : 0.0;
  double eta = 0.0, ux = 0.0, uy = 0.0, uup = 0.0, ax = 0.0, ay = 0.0, aup = 0.0, p = 0.0;
  Eigen::Matrix3d grad = Eigen::Matrix3d::Zero();
  for (const Term& c : terms_) {
    const double th = c.kx * p_W.x() + c.ky * p_W.y() - c.omega * t + c.phase;
    const double cs = std::cos(th), sn = std::sin(th);
    // E = exp(k zeta), F = q / E: C = (E + F)/(1 - q), S = (E - F)/(1 - q), K = (E + F)/(1 + q)
    const double e = std::exp(c.k * zeta);
    double ch = e, sh = e, kk = e;
    if (c.q != 0.0) {
      const double f = c.q / e;
      ch = (e + f) * c.inv_1mq;
      sh = (e - f) * c.inv_1mq;
      kk = (e + f) * c.inv_1pq;
    }
    eta += c.a * cs;
    // u_h = a w C cos th [cos b, sin b], u_up = a w S sin th
    const double uh = c.a_omega * ch * cs;
    ux += uh * c.cos_b;
    uy += uh * c.sin_b;
    uup += c.a_omega * sh * sn;
    // d/dt: a_h = a w^2 C sin th [cos b, sin b], a_up = -a w^2 S cos th
    const double ah = c.a_omega2 * ch * sn;
    ax += ah * c.cos_b;
    ay += ah * c.sin_b;
    aup -= c.a_omega2 * sh * cs;
    // p_d = rho g a K cos th
    p += c.rho_g_a * kk * cs;
    // G = [-P e e^T, -Q e; -Q e^T, P], P = a w k C sin th, Q = a w k S cos th (NED, the
    // header); d/dz = -d/dzeta
    const Eigen::Vector3d e_h(c.cos_b, c.sin_b, 0.0);
    const double gp = c.a_omega * c.k * ch * sn, gq = c.a_omega * c.k * sh * cs;
    grad.topLeftCorner<2, 2>() -= gp * e_h.head<2>() * e_h.head<2>().transpose();
    grad.block<2, 1>(0, 2) -= vertical * gq * e_h.head<2>();
    grad.block<1, 2>(2, 0) -= gq * e_h.head<2>().transpose();
    grad(2, 2) += vertical * gp;
  }
  const double r = Ramp(t);
  out.elevation = r * eta;
  // dry above the instantaneous surface z < -eta
  out.wet = p_W.z() >= -out.elevation;
  if (!out.wet) return out;
  // NED: w = -u_up; a = r du/dt + r' u
  const Vec3 u(ux, uy, -uup);
  out.velocity = r * u;
  out.acceleration = r * Vec3(ax, ay, -aup) + RampRate(t) * u;
  out.velocity_gradient = r * grad;
  // Du/Dt = du/dt + G u
  out.material_acceleration = out.acceleration + out.velocity_gradient * out.velocity;
  out.dynamic_pressure = r * p;
  return out;
}

}  // namespace towsim::core
