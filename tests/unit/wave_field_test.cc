#include "core/wave_field.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "signal_analysis.h"

namespace towsim::core {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kG = 9.81;
constexpr double kInf = std::numeric_limits<double>::infinity();

// k h by bisection on x tanh x = w^2 h / g (an algorithm independent of WaveNumber's Newton)
double BisectWaveNumber(double omega, double h) {
  const double y = omega * omega * h / kG;
  double lo = 0.0, hi = std::max(y, std::sqrt(y)) + 1.0;  // x tanh x >= y at hi
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid * std::tanh(mid) < y ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) / h;
}

TEST(WaveNumber, SolvesTheDispersionRelationFromShallowToDeep) {
  constexpr double kResidualTol = 1e-12;  // relative residual of w^2 = g k tanh(k h)
  constexpr double kBisectionTol = 1e-12;
  for (double h : {0.5, 5.0, 30.0, 60.0, 400.0, 5000.0}) {
    for (double period : {0.5, 2.0, 6.0, 8.0, 15.0, 30.0, 120.0}) {
      const double w = 2.0 * kPi / period;
      const double k = WaveNumber(w, h, kG);
      EXPECT_LT(std::abs(kG * k * std::tanh(k * h) - w * w), kResidualTol * w * w)
          << "h = " << h << ", T = " << period;
      const double kb = BisectWaveNumber(w, h);
      EXPECT_NEAR(k, kb, kBisectionTol * kb) << "h = " << h << ", T = " << period;
    }
  }
}

TEST(WaveNumber, DeepWaterLimitIsOmegaSquaredOverG) {
  for (double period : {1.0, 8.0, 20.0}) {
    const double w = 2.0 * kPi / period;
    EXPECT_DOUBLE_EQ(WaveNumber(w, kInf, kG), w * w / kG);
    // kh = 20 and more: tanh(kh) = 1 - 8e-18
    const double h = 20.0 * kG / (w * w);
    EXPECT_NEAR(WaveNumber(w, h, kG), w * w / kG, 1e-15 * w * w / kG);
  }
  EXPECT_EQ(WaveNumber(0.0, 30.0, kG), 0.0);
}

// kh -> 0: k -> w / sqrt(g h); with y = w^2 h / g, kh = sqrt(y) (1 + y/6 + O(y^2))
TEST(WaveNumber, ShallowWaterLimitIsOmegaOverSqrtGh) {
  const double h = 10.0;
  for (double period : {200.0, 600.0, 2000.0}) {
    const double w = 2.0 * kPi / period;
    const double k = WaveNumber(w, h, kG);
    const double y = w * w * h / kG;
    const double k_shallow = w / std::sqrt(kG * h);
    EXPECT_NEAR(k, k_shallow, 0.2 * y * k_shallow) << period;  // first correction y/6
    // to second order the series; its next term is O(y^2)
    EXPECT_NEAR(k, k_shallow * (1.0 + y / 6.0), 2.0 * y * y * k_shallow) << period;
  }
}

// Independent velocity potential of linear theory (zeta = -z up), written with cosh directly:
//   phi = sum (a g / w) cosh k(zeta + h) / cosh kh  sin th  (deep water: exp(k zeta))
struct Potential {
  const WaveField& waves;
  double operator()(const Vec3& p, double t) const {
    double phi = 0.0;
    const double zeta = -p.z();
    for (const WaveComponent& c : waves.components()) {
      const double th = c.k * (p.x() * std::cos(c.direction) + p.y() * std::sin(c.direction)) -
                        c.omega * t + c.phase;
      const double h = waves.depth();
      const double f =
          std::isinf(h) ? std::exp(c.k * zeta) : std::cosh(c.k * (zeta + h)) / std::cosh(c.k * h);
      phi += c.amplitude * kG / c.omega * f * std::sin(th);
    }
    return phi;
  }
};

// three components in several directions over finite and infinite depth
std::vector<WaveField> TestSeas() {
  std::vector<WaveField> seas;
  for (double h : {25.0, kInf}) {
    WaveField w(h, kG, 1025.0);
    w.AddComponent(0.4, 2.0 * kPi / 9.0, 0.3, 0.2);
    w.AddComponent(0.25, 2.0 * kPi / 5.5, -1.2, 2.5);
    w.AddComponent(0.1, 2.0 * kPi / 3.0, 2.0, -1.0);
    seas.push_back(w);
  }
  return seas;
}

// velocity = grad phi (NED: w = d phi / dz_NED), acceleration = du/dt, p_d = -rho dphi/dt,
// by central differences of the independent potential and of the field itself
TEST(WaveField, AiryKinematicsAreDerivativesOfThePotential) {
  constexpr double kD = 1e-4;         // [m], [s]: (k kD)^2 ~ 1e-9, round-off eps phi / kD ~ 1e-11
  constexpr double kVelTol = 1e-7;    // [m/s], velocities ~ 0.5 m/s
  constexpr double kAccelTol = 1e-7;  // [m/s^2]
  constexpr double kPressTol = 1e-3;  // [Pa], pressures ~ 4e3 Pa
  for (const WaveField& w : TestSeas()) {
    const Potential phi{w};
    for (const Vec3& p : {Vec3(3.0, -7.0, 1.5), Vec3(-40.0, 12.0, 6.0), Vec3(100.0, 50.0, 20.0)}) {
      for (double t : {0.0, 3.7, 61.0}) {
        const WaveKinematics k = w.Kinematics(p, t);
        ASSERT_TRUE(k.wet);
        Vec3 grad;
        for (int i = 0; i < 3; ++i) {
          Vec3 e = Vec3::Zero();
          e(i) = kD;
          grad(i) = (phi(p + e, t) - phi(p - e, t)) / (2.0 * kD);
        }
        EXPECT_LT((k.velocity - grad).norm(), kVelTol) << p.transpose() << " t " << t;
        const Vec3 du_dt =
            (w.Kinematics(p, t + kD).velocity - w.Kinematics(p, t - kD).velocity) / (2.0 * kD);
        EXPECT_LT((k.acceleration - du_dt).norm(), kAccelTol) << p.transpose() << " t " << t;
        const double dphi_dt = (phi(p, t + kD) - phi(p, t - kD)) / (2.0 * kD);
        EXPECT_NEAR(k.dynamic_pressure, -1025.0 * dphi_dt, kPressTol);
        EXPECT_DOUBLE_EQ(k.elevation, w.Elevation(p.x(), p.y(), t));
      }
    }
  }
}

// div u = 0 (Laplace's equation for phi) from differences of the field's velocity; the
// linearised surface conditions: kinematic d eta/dt = u_up(0), dynamic p_d(0) = rho g eta
TEST(WaveField, IncompressibleAndSatisfiesTheSurfaceConditions) {
  constexpr double kD = 1e-4;
  constexpr double kDivTol = 1e-7;       // [1/s]; the velocity gradients are ~ 0.3 1/s
  constexpr double kSurfaceTol = 1e-7;   // [m/s]
  constexpr double kPressureTol = 1e-9;  // relative, the same sum evaluated twice
  for (const WaveField& w : TestSeas()) {
    for (const Vec3& p : {Vec3(3.0, -7.0, 1.5), Vec3(-40.0, 12.0, 9.0)}) {
      const double t = 12.3;
      double div = 0.0;
      for (int i = 0; i < 3; ++i) {
        Vec3 e = Vec3::Zero();
        e(i) = kD;
        div +=
            (w.Kinematics(p + e, t).velocity(i) - w.Kinematics(p - e, t).velocity(i)) / (2.0 * kD);
      }
      EXPECT_LT(std::abs(div), kDivTol);
    }
    // on the mean surface z = 0 (under a crest, eta > 0, so it is wet: z >= -eta)
    for (double t = 0.0; t < 20.0; t += 0.73) {
      const double x = 5.0, y = 2.0;
      if (w.Elevation(x, y, t) < 0.0) continue;
      const WaveKinematics k = w.Kinematics(Vec3(x, y, 0.0), t);
      ASSERT_TRUE(k.wet);
      const double deta_dt = (w.Elevation(x, y, t + kD) - w.Elevation(x, y, t - kD)) / (2.0 * kD);
      EXPECT_NEAR(-k.velocity.z(), deta_dt, kSurfaceTol) << t;
      EXPECT_NEAR(k.dynamic_pressure, 1025.0 * kG * k.elevation, kPressureTol * 1025.0 * kG * 0.75)
          << t;
    }
  }
}

// the velocity gradient G_ij = du_i/dx_j against central differences of the velocity, and the
// material acceleration Du/Dt = du/dt + G u against the rate of change of the velocity seen by
// a point that moves with the local water velocity, (u(p + u dt, t + dt) - u(p - u dt,
// t - dt)) / (2 dt)
TEST(WaveField, VelocityGradientAndMaterialAcceleration) {
  constexpr double kD = 1e-4;          // [m], [s]: truncation (k kD)^2 ~ 1e-9
  constexpr double kGradTol = 1e-8;    // [1/s], gradients ~ 0.1 1/s
  constexpr double kAccelTol = 1e-7;   // [m/s^2]
  for (const WaveField& w : TestSeas()) {
    for (const Vec3& p : {Vec3(3.0, -7.0, 1.5), Vec3(-40.0, 12.0, 6.0), Vec3(100.0, 50.0, 20.0)}) {
      for (double t : {0.0, 3.7, 61.0}) {
        const WaveKinematics k = w.Kinematics(p, t);
        ASSERT_TRUE(k.wet);
        Eigen::Matrix3d g;
        for (int j = 0; j < 3; ++j) {
          Vec3 e = Vec3::Zero();
          e(j) = kD;
          g.col(j) = (w.Kinematics(p + e, t).velocity - w.Kinematics(p - e, t).velocity) / (2 * kD);
        }
        EXPECT_LT((k.velocity_gradient - g).norm(), kGradTol) << p.transpose() << " t " << t;
        // irrotational and incompressible
        EXPECT_LT((k.velocity_gradient - k.velocity_gradient.transpose()).norm(), 1e-14);
        EXPECT_LT(std::abs(k.velocity_gradient.trace()), 1e-14);
        const Vec3 du = k.velocity * kD;
        const Vec3 dudt_material =
            (w.Kinematics(p + du, t + kD).velocity - w.Kinematics(p - du, t - kD).velocity) /
            (2.0 * kD);
        EXPECT_LT((k.material_acceleration - dudt_material).norm(), kAccelTol)
            << p.transpose() << " t " << t;
      }
    }
  }
  // one deep-water component: (u . grad) u = grad |u|^2 / 2 = a^2 w^2 k e^{2 k zeta} upward,
  // the same at every phase (the mean force a body at a displaced position feels without it)
  const WaveField one = WaveField::Regular(2.0, 8.0, 0.0, 0.0, kInf, kG, 1025.0);
  const double omega = 2.0 * kPi / 8.0, k = omega * omega / kG;
  const double expected = omega * omega * k * std::exp(-2.0 * k * 10.0);
  for (double t : {0.0, 1.0, 2.5, 5.0}) {
    const WaveKinematics kin = one.Kinematics(Vec3(3.0, 0.0, 10.0), t);
    const Vec3 convective = kin.material_acceleration - kin.acceleration;
    EXPECT_NEAR(convective.z(), -expected, 1e-14) << t;
    EXPECT_NEAR(convective.x(), 0.0, 1e-14) << t;
  }
}

TEST(WaveField, DryAboveTheSurfaceAndBoundedInTheCrest) {
  const WaveField w = WaveField::Regular(2.0, 8.0, 0.0, 0.0, kInf, kG, 1025.0);
  // t = 0, x = 0: a crest, eta = 1 m; the surface is at z = -1
  EXPECT_NEAR(w.Elevation(0.0, 0.0, 0.0), 1.0, 1e-15);
  const WaveKinematics above = w.Kinematics(Vec3(0.0, 0.0, -1.2), 0.0);
  EXPECT_FALSE(above.wet);
  EXPECT_EQ(above.velocity, Vec3::Zero());
  EXPECT_EQ(above.acceleration, Vec3::Zero());
  EXPECT_EQ(above.dynamic_pressure, 0.0);
  EXPECT_NEAR(above.elevation, 1.0, 1e-15);
  // in the crest above z = 0: the kinematics of z = 0 (constant extension)
  const WaveKinematics crest = w.Kinematics(Vec3(0.0, 0.0, -0.8), 0.0);
  const WaveKinematics mean = w.Kinematics(Vec3(0.0, 0.0, 0.0), 0.0);
  EXPECT_TRUE(crest.wet);
  EXPECT_EQ(crest.velocity, mean.velocity);
  // the crest particle moves forward at a w: 1 m * 2 pi / 8 s
  EXPECT_NEAR(mean.velocity.x(), 2.0 * kPi / 8.0, 1e-14);
  // deep-water decay exp(k z_up): at z = 10 m
  const double k = WaveNumber(2.0 * kPi / 8.0, kInf, kG);
  EXPECT_NEAR(w.Kinematics(Vec3(0.0, 0.0, 10.0), 0.0).velocity.x(),
              2.0 * kPi / 8.0 * std::exp(-k * 10.0), 1e-14);
  // calm water: nothing, and dry above z = 0
  const WaveField calm;
  EXPECT_TRUE(calm.empty());
  EXPECT_EQ(calm.Elevation(1.0, 2.0, 3.0), 0.0);
  EXPECT_TRUE(calm.Kinematics(Vec3(0.0, 0.0, 1.0), 0.0).wet);
  EXPECT_FALSE(calm.Kinematics(Vec3(0.0, 0.0, -1.0), 0.0).wet);
}

// below the seabed depth the field holds its bottom values; at the bottom w = 0
TEST(WaveField, NoFlowThroughTheBottom) {
  const WaveField w = WaveField::Regular(1.0, 7.0, 0.4, 0.0, 20.0, kG, 1025.0);
  for (double t : {0.0, 1.1, 2.9}) {
    const WaveKinematics bottom = w.Kinematics(Vec3(3.0, 1.0, 20.0), t);
    EXPECT_NEAR(bottom.velocity.z(), 0.0, 1e-15);
    EXPECT_NEAR(bottom.acceleration.z(), 0.0, 1e-15);
    EXPECT_EQ(w.Kinematics(Vec3(3.0, 1.0, 25.0), t).velocity, bottom.velocity);
  }
}

// r(t) = (1 - cos(pi t / T)) / 2: zero at t = 0, half at T/2, full after T; the acceleration
// stays the time derivative of the velocity through the ramp
TEST(WaveField, CosineRampStartsFromCalm) {
  WaveField w = WaveField::Regular(2.0, 8.0, 0.0, 0.0, kInf, kG, 1025.0);
  w.set_ramp(20.0);
  EXPECT_EQ(w.Elevation(0.0, 0.0, 0.0), 0.0);
  EXPECT_NEAR(w.Elevation(0.0, 0.0, 10.0), 0.5 * std::cos(-2.0 * kPi / 8.0 * 10.0), 1e-14);
  EXPECT_NEAR(w.Elevation(0.0, 0.0, 24.0), std::cos(-2.0 * kPi / 8.0 * 24.0), 1e-14);
  constexpr double kD = 1e-4;
  const Vec3 p(2.0, 1.0, 3.0);
  for (double t : {1.0, 7.0, 13.0, 19.0}) {
    const Vec3 du_dt =
        (w.Kinematics(p, t + kD).velocity - w.Kinematics(p, t - kD).velocity) / (2.0 * kD);
    EXPECT_LT((w.Kinematics(p, t).acceleration - du_dt).norm(), 1e-7) << t;
  }
}

}  // namespace
}  // namespace towsim::core

// ---- irregular seas: the record against its target spectrum ----

namespace towsim::core {
namespace {

// Pierson-Moskowitz in Hs and Tp, normalised in closed form (DNV-RP-C205 Eq. 3.5.5):
//   S(w) = 5/16 Hs^2 w_p^4 w^-5 exp(-5/4 (w_p / w)^4), int S = Hs^2 / 16
double PiersonMoskowitz(double hs, double tp, double w) {
  const double wp = 2.0 * kPi / tp;
  return 5.0 / 16.0 * hs * hs * std::pow(wp, 4) * std::pow(w, -5) *
         std::exp(-1.25 * std::pow(wp / w, 4));
}

// ElevationGrid is Elevation at every node of the grid: an irregular sea of 100 components,
// in the ramp, on a grid that does not start at the origin. cos(A + B) by the addition theorem
// rounds differently from cos of the summed phase: a few ulps of a phase of O(100) rad on each
// of 100 amplitudes summing to ~4 m, well inside kGridTol
TEST(WaveField, ElevationGridIsElevationAtTheNodes) {
  constexpr double kGridTol = 1e-11;  // [m]
  WaveSpectrum s;
  s.hs = 2.0;
  s.tp = 8.0;
  s.components = 100;
  s.seed = 7;
  WaveField w = WaveField::Irregular(s, 60.0, kG, 1025.0);
  w.set_ramp(20.0);
  constexpr int kNx = 7, kNy = 5;
  const double x0 = -130.0, dx = 10.0, y0 = 45.0, dy = 12.5, t = 13.7;
  std::vector<double> work, eta(kNx * kNy);
  w.ElevationGrid(x0, dx, kNx, y0, dy, kNy, t, &work, eta.data());
  double largest = 0.0;
  for (int i = 0; i < kNx; ++i) {
    for (int j = 0; j < kNy; ++j) {
      const double expected = w.Elevation(x0 + i * dx, y0 + j * dy, t);
      EXPECT_NEAR(eta[i * kNy + j], expected, kGridTol) << i << " " << j;
      largest = std::max(largest, std::abs(expected));
    }
  }
  EXPECT_GT(largest, 0.1);  // a sea, not calm water
  // calm water: zeros
  const WaveField calm;
  calm.ElevationGrid(x0, dx, kNx, y0, dy, kNy, t, &work, eta.data());
  for (double e : eta) EXPECT_EQ(e, 0.0);
}

TEST(WaveSpectrum, PiersonMoskowitzIsNormalisedInClosedForm) {
  WaveSpectrum s;
  s.kind = WaveSpectrumKind::kPiersonMoskowitz;
  s.hs = 2.5;
  s.tp = 9.0;
  constexpr double kQuadratureRelTol = 1e-6;  // trapezoid, 20000 intervals in ln w
  for (double w : {0.4, 0.6, 0.698, 0.9, 1.5, 3.0}) {
    EXPECT_NEAR(SpectralDensity(s, w), PiersonMoskowitz(2.5, 9.0, w),
                kQuadratureRelTol * PiersonMoskowitz(2.5, 9.0, 2.0 * kPi / 9.0))
        << w;
  }
}

// JONSWAP = A_gamma PM gamma^r: the computed A_gamma against DNV's fit 1 - 0.287 ln gamma,
// which DNV-RP-C205 3.5.5.4 gives as an approximation (it is within about 1 % for 1 <= gamma
// <= 7)
TEST(WaveSpectrum, JonswapScaleMatchesDnvFit) {
  for (double gamma : {1.0, 2.0, 3.3, 5.0}) {
    WaveSpectrum s;
    s.hs = 2.0;
    s.tp = 8.0;
    s.gamma = gamma;
    const double w = 1.3;  // far above the peak: gamma^r = 1
    const double a_gamma = SpectralDensity(s, w) / PiersonMoskowitz(2.0, 8.0, w);
    EXPECT_NEAR(a_gamma, 1.0 - 0.287 * std::log(gamma), 0.015) << gamma;
  }
}

// a 3-hour record of the elevation at one point of a JONSWAP sea
std::vector<double> Record(const WaveField& w, double dt, int n) {
  std::vector<double> eta(n);
  for (int i = 0; i < n; ++i) eta[i] = w.Elevation(12.0, -3.0, i * dt);
  return eta;
}

struct SeaCase {
  double hs, tp, gamma;
  std::uint64_t seed;
};

// Hs = 4 sqrt(m0) from the record's variance, Tp from the peak of its spectrum, and the
// spectrum's shape (its cumulative energy) against the target, for three seas
TEST(IrregularSea, RecordReproducesHsTpAndTheSpectrum) {
  constexpr double kDt = 0.5;      // [s]; Nyquist 2 pi rad/s is above the band's top (~6 w_p)
  constexpr int kSamples = 21600;  // 3 h, the usual length of a sea state
  constexpr int kSegment = 512;    // Welch: 256 s segments, dw = 0.0245 rad/s, 83 averaged
  for (const SeaCase& c :
       {SeaCase{2.0, 8.0, 3.3, 1}, SeaCase{4.0, 12.0, 1.0, 2}, SeaCase{1.0, 6.0, 5.0, 3}}) {
    WaveSpectrum s;
    s.kind = c.gamma == 1.0 ? WaveSpectrumKind::kPiersonMoskowitz : WaveSpectrumKind::kJonswap;
    s.hs = c.hs;
    s.tp = c.tp;
    s.gamma = c.gamma;
    s.components = 100;
    s.seed = c.seed;
    const WaveField w = WaveField::Irregular(s, kInf, kG, 1025.0);
    const std::vector<double> eta = Record(w, kDt, kSamples);
    // Hs from the variance: sum a^2/2 = m0 exactly; over 3 h the cross terms of components
    // in neighbouring bins (dw ~ 0.01 rad/s, dw T ~ 100) leave about 1 %
    constexpr double kHsRelTol = 0.03;
    double mean = 0.0, var = 0.0;
    for (double e : eta) mean += e;
    mean /= kSamples;
    for (double e : eta) var += (e - mean) * (e - mean);
    var /= kSamples;
    const double hs = 4.0 * std::sqrt(var);
    EXPECT_NEAR(hs, c.hs, kHsRelTol * c.hs) << "seed " << c.seed;

    const reference::Spectrum est = reference::WelchSpectrum(eta, kDt, kSegment);
    const double dw = est.omega[1] - est.omega[0];
    // Tp: the peak of the estimate, refined by a parabola through the three bins around it;
    // the bins are 3 % of w_p wide at Tp = 8 s
    size_t peak = 1;
    for (size_t k = 1; k + 1 < est.density.size(); ++k)
      if (est.density[k] > est.density[peak]) peak = k;
    const double y0 = est.density[peak - 1], y1 = est.density[peak], y2 = est.density[peak + 1];
    const double w_peak = est.omega[peak] + 0.5 * dw * (y0 - y2) / (y0 - 2.0 * y1 + y2);
    constexpr double kTpRelTol = 0.05;
    EXPECT_NEAR(2.0 * kPi / w_peak, c.tp, kTpRelTol * c.tp) << "seed " << c.seed;

    // shape: the cumulative energy of the estimate against that of the target spectrum, at
    // every bin; the largest difference (Kolmogorov-Smirnov-like) as a fraction of m0
    constexpr double kShapeTol = 0.04;  // line spectrum of 100 components seen through a Hann
                                        // window 4 bins wide, plus the 0.2 % tails left out
    const double m0 = c.hs * c.hs / 16.0;
    double f_est = 0.0, f_target = 0.0, worst = 0.0;
    for (size_t k = 1; k < est.density.size(); ++k) {
      f_est += est.density[k] * dw;
      f_target += SpectralDensity(s, est.omega[k]) * dw;
      worst = std::max(worst, std::abs(f_est - f_target) / m0);
    }
    EXPECT_LT(worst, kShapeTol) << "seed " << c.seed;
    std::printf(
        "Hs %.2f Tp %.1f gamma %.1f seed %d: record Hs %.4f m (%+.2f %%), Tp %.3f s "
        "(%+.2f %%), worst cumulative-spectrum difference %.2f %% of m0\n",
        c.hs, c.tp, c.gamma, static_cast<int>(c.seed), hs, 100.0 * (hs / c.hs - 1.0),
        2.0 * kPi / w_peak, 100.0 * (2.0 * kPi / w_peak / c.tp - 1.0), 100.0 * worst);
  }
}

// random frequencies within the equal-energy bins: the record does not repeat. The same
// spectrum on equally spaced frequencies dw repeats after 2 pi / dw, and the autocorrelation
// shows it; the random-frequency sea stays decorrelated over a whole hour
TEST(IrregularSea, RecordDoesNotRepeat) {
  constexpr double kDt = 0.5;
  constexpr int kSamples = 7200;  // 1 h
  WaveSpectrum s;
  s.hs = 2.0;
  s.tp = 8.0;
  s.components = 100;
  const WaveField sea = WaveField::Irregular(s, kInf, kG, 1025.0);
  // the same spectrum on a regular grid over the same band, w_i = (i_0 + i) dw, a = sqrt(2 S dw)
  const std::vector<WaveComponent>& c = sea.components();
  const double dw = (c.back().omega - c.front().omega) / (c.size() - 1);
  const double i0 = std::round(c.front().omega / dw);
  WaveField grid(kInf, kG, 1025.0);
  for (size_t i = 0; i < c.size(); ++i) {
    const double w_i = (i0 + i) * dw;
    grid.AddComponent(std::sqrt(2.0 * SpectralDensity(s, w_i) * dw), w_i, 0.0, c[i].phase);
  }
  const double repeat = 2.0 * kPi / dw;  // [s]
  ASSERT_LT(repeat, kSamples * kDt / 2.0);
  const std::vector<double> rho_sea =
      reference::Autocorrelation(Record(sea, kDt, kSamples), kSamples / 2);
  const std::vector<double> rho_grid =
      reference::Autocorrelation(Record(grid, kDt, kSamples), kSamples / 2);
  // beyond 10 Tp: the largest |rho|; the finite record biases rho by (N - k) / N, undone here
  const auto worst_beyond = [&](const std::vector<double>& rho, double from) {
    double worst = 0.0;
    for (size_t k = static_cast<size_t>(from / kDt); k < rho.size(); ++k)
      worst = std::max(worst, std::abs(rho[k]) * kSamples / (kSamples - k));
    return worst;
  };
  const size_t k_repeat = static_cast<size_t>(std::lround(repeat / kDt));
  const double rho_grid_repeat = rho_grid[k_repeat] * kSamples / (kSamples - k_repeat);
  EXPECT_GT(rho_grid_repeat, 0.9);  // the grid sea repeats: the test can tell
  // 100 lines of equal power at incommensurate frequencies: |rho| ~ 1/sqrt(N) = 0.1 typically,
  // its largest over an hour a few times that
  constexpr double kDecorrelated = 0.5;
  const double worst = worst_beyond(rho_sea, 10.0 * s.tp);
  EXPECT_LT(worst, kDecorrelated);
  std::printf(
      "autocorrelation beyond 10 Tp over 1 h: random-frequency sea max %.3f; "
      "equally spaced (dw = %.4f rad/s) at its repeat period %.1f s: %.3f\n",
      worst, dw, repeat, rho_grid_repeat);
}

}  // namespace
}  // namespace towsim::core
