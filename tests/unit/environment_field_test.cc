// The sea every load reads (core/environment_field.h), held to independent references:
//   - its wave kinematics against core::WaveField::Kinematics (the same linear theory, written
//     separately in double: one exponential per component, no depth cut-off, no derivative; the
//     acceleration is the material one, Du/Dt = du/dt + G u),
//   - its derivative along a direction against central finite differences of that reference,
//   - the cubic Hermite interpolation of the waves between two cable nodes against the exact
//     kinematics at the Gauss points, for the shipped Case 1 cable in the case3_waves sea
//     (what holding the waves at the nodes costs in accuracy: docs/environment.md),
//   - the current with its shear against core::CurrentField.

#include "core/environment_field.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include <gtest/gtest.h>

#include "core/ancf_element.h"
#include "core/constants.h"
#include "core/gauss_quadrature.h"

namespace towsim::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Environment JonswapSea(double depth) {
  Environment env;
  WaveSpectrum s;
  s.hs = 2.0;
  s.tp = 8.0;
  s.gamma = 3.3;
  s.direction = 0.3;
  s.components = 100;
  s.seed = 7;
  env.waves = WaveField::Irregular(s, depth, env.gravity, env.water_density);
  env.waves.set_ramp(10.0);
  if (std::isfinite(depth)) env.seabed = Seabed::Flat(depth);
  return env;
}

// The same linear theory, summed by another implementation. The sums run in float once the
// phase is reduced (environment_field.h: a float has 2^-24 = 6e-8 relative precision), so they
// agree to a few float roundings of the largest sum the terms can make, sum a (w + w^2) for
// the velocity and the acceleration (sum a for the elevation; the convective part is second
// order, below these); the cut-off at depth (kDecayCutoff of the surface amplitude) is far
// below. 8 roundings: for the JONSWAP sea below 5.7e-6 m/s, where the sums agree to 6e-8.
constexpr double kFloatRounding = 5.960464477539063e-8;  // 2^-24
constexpr double kFloatRoundings = 8.0;
double KinematicsTol(const WaveField& waves) {
  double s = 0.0;
  for (const WaveComponent& c : waves.components())
    s += c.amplitude * (c.omega + c.omega * c.omega);
  return kFloatRoundings * kFloatRounding * s;  // [m/s], [m/s^2]
}
double ElevationTol(const WaveField& waves) {
  double s = 0.0;
  for (const WaveComponent& c : waves.components()) s += c.amplitude;
  return kFloatRoundings * kFloatRounding * s;  // [m]
}

// w = sea.Waves(p, d, t): its derivatives along d against central differences of the double
// reference with step s: truncation (k s)^2 / 6 of the largest k's term, round-off 1e-16 / s:
// s = 1e-4 m gives about 1e-8 relative to the kinematics' scale (~1 m/s); the float sums'
// rounding (as above, times the largest k, 0.6 / m here) is below 1e-6 as well
constexpr double kStep = 1e-4;              // [m]
constexpr double kDerivativeAbsTol = 1e-6;  // [1/s], [1/s^2]
void ExpectDerivativesAreTheFiniteDifferences(const WaveField& reference, const WaveSample& w,
                                              const Vec3& p, const Vec3& d, double t) {
  const WaveKinematics wp = reference.Kinematics(p + kStep * d, t);
  const WaveKinematics wm = reference.Kinematics(p - kStep * d, t);
  EXPECT_LT((w.d_velocity - (wp.velocity - wm.velocity) / (2 * kStep)).norm(), kDerivativeAbsTol)
      << p.transpose();
  EXPECT_LT((w.d_acceleration - (wp.material_acceleration - wm.material_acceleration) / (2 * kStep))
                .norm(),
            kDerivativeAbsTol)
      << p.transpose();
}

TEST(EnvironmentField, WavesAreTheWaveFieldsKinematics) {
  double worst = 0.0;
  for (const double depth : {kInf, 60.0, 15.0}) {
    const Environment env = JonswapSea(depth);
    const EnvironmentField sea(env);
    ASSERT_TRUE(sea.has_waves());
    ASSERT_FALSE(sea.uniform());
    for (const double t : {3.0, 40.0, 333.3}) {
      for (const Vec3& p : {Vec3(0, 0, 0.5), Vec3(12, -3, 4), Vec3(-50, 20, 14.0), Vec3(5, 5, -0.2),
                            Vec3(100, 0, 80.0)}) {
        const WaveKinematics ref = env.waves.Kinematics(p, t);
        const WaveSample w = sea.Waves(p, Vec3::Zero(), t);
        const double dv = (w.velocity - ref.velocity).norm();
        const double da = (w.acceleration - ref.material_acceleration).norm();
        EXPECT_LT(dv, KinematicsTol(env.waves))
            << "depth " << depth << " t " << t << " p " << p.transpose();
        EXPECT_LT(da, KinematicsTol(env.waves))
            << "depth " << depth << " t " << t << " p " << p.transpose();
        EXPECT_NEAR(sea.Elevation(p.x(), p.y(), t), env.waves.Elevation(p.x(), p.y(), t),
                    ElevationTol(env.waves));
        worst = std::max({worst, dv, da});
      }
    }
  }
  std::printf(
      "float sums against the double reference: largest difference %.2e m/s (m/s^2), "
      "bound %.2e\n",
      worst, KinematicsTol(JonswapSea(kInf).waves));
}

TEST(EnvironmentField, WaveDerivativeAlongADirectionIsTheFiniteDifference) {
  for (const double depth : {kInf, 40.0}) {
    const Environment env = JonswapSea(depth);
    const EnvironmentField sea(env);
    const double t = 25.0;
    for (const Vec3& p : {Vec3(0, 0, 3.7), Vec3(30, -4, 12.0), Vec3(-20, 7, 35.0)}) {
      const Vec3 d = Vec3(0.8, 0.3, 0.5).normalized() * 1.0002;  // a stretched cable slope
      const WaveSample w = sea.Waves(p, d, t);
      ExpectDerivativesAreTheFiniteDifferences(env.waves, w, p, d, t);
    }
  }
}

TEST(EnvironmentField, ShortCrestedSeaResolvesEachComponentsDirection) {
  // components travelling different ways take the per-component path of the sums (a
  // long-crested sea sums along its one direction); three components: an odd count, so the
  // last packet holds one zero-amplitude pad
  for (const double depth : {kInf, 25.0}) {
    Environment env;
    env.waves = WaveField(depth, env.gravity, env.water_density);
    env.waves.AddComponent(0.4, 2.0 * kPi / 9.0, 0.3, 0.2);
    env.waves.AddComponent(0.25, 2.0 * kPi / 5.5, -1.2, 2.5);
    env.waves.AddComponent(0.1, 2.0 * kPi / 3.0, 2.0, -1.0);
    if (std::isfinite(depth)) env.seabed = Seabed::Flat(depth);
    const EnvironmentField sea(env);
    for (const double t : {1.5, 70.0}) {
      for (const Vec3& p : {Vec3(0, 0, 0.3), Vec3(12, -3, 4), Vec3(-30, 20, 14.0)}) {
        const WaveKinematics ref = env.waves.Kinematics(p, t);
        const Vec3 d = Vec3(-0.3, 0.9, 0.4).normalized();
        const WaveSample w = sea.Waves(p, d, t);
        EXPECT_LT((w.velocity - ref.velocity).norm(), KinematicsTol(env.waves)) << p.transpose();
        EXPECT_LT((w.acceleration - ref.material_acceleration).norm(), KinematicsTol(env.waves))
            << p.transpose();
        EXPECT_NEAR(sea.Elevation(p.x(), p.y(), t), env.waves.Elevation(p.x(), p.y(), t),
                    ElevationTol(env.waves));
        ExpectDerivativesAreTheFiniteDifferences(env.waves, w, p, d, t);
      }
    }
  }
}

TEST(EnvironmentField, HermiteWavesBetweenNodesMatchTheExactKinematics) {
  // the Case 1 cable (10 m elements) straight from the tow point at 3.7 m down at 30 deg below
  // the horizontal, in the case3_waves sea (JONSWAP Hs 2 m, Tp 8 s, 60 m deep): the waves held
  // at the nodes with their slopes, interpolated to the 5 Gauss points of every element by the
  // element's cubic Hermite functions. A component varies along the cable as e^{lambda s} with
  // |lambda| <= k, so cubic Hermite interpolation errs by at most (k l)^4 / 384 of its largest
  // value on the element (at the element's top, depth factor C(zeta_top)): the bound below
  // sums that over the components, and the measured error must stay inside it.
  constexpr double kElement = 10.0;  // [m]
  const Environment env = JonswapSea(60.0);
  const EnvironmentField sea(env);
  ElementProperties props;
  props.length = kElement;
  const AncfElement element(props);
  const Vec3 dir = Vec3(std::cos(kPi / 6), 0.0, std::sin(kPi / 6));
  double worst_v = 0.0, worst_a = 0.0, scale_v = 0.0, scale_a = 0.0;
  for (int e = 0; e < 10; ++e) {
    const Vec3 r0 = Vec3(0, 0, 3.7) + e * kElement * dir, r1 = r0 + kElement * dir;
    // the a-priori bound of this element: sum a w^m C(zeta_top) min((k l)^4 / 384, 2)
    double bound_v = 0.0, bound_a = 0.0;
    for (const WaveComponent& c : env.waves.components()) {
      const double h = env.waves.depth();
      const double depth_factor = std::cosh(c.k * (h - r0.z())) / std::sinh(c.k * h);
      const double hermite = std::min(std::pow(c.k * kElement, 4) / 384.0, 2.0);
      bound_v += c.amplitude * c.omega * depth_factor * hermite;
      bound_a += c.amplitude * c.omega * c.omega * depth_factor * hermite;
    }
    for (const double t : {20.0, 47.5, 81.0}) {
      const WaveSample w0 = sea.Waves(r0, dir, t), w1 = sea.Waves(r1, dir, t);
      Vec12 ev, ea, q;
      ev << w0.velocity, w0.d_velocity, w1.velocity, w1.d_velocity;
      ea << w0.acceleration, w0.d_acceleration, w1.acceleration, w1.d_acceleration;
      q << r0, dir, r1, dir;
      for (const ShapeAtPoint& p : element.points()) {
        const WaveSample exact = sea.Waves(Interpolate(p.n, q), Vec3::Zero(), t);
        const double ev_err = (Interpolate(p.n, ev) - exact.velocity).norm();
        const double ea_err = (Interpolate(p.n, ea) - exact.acceleration).norm();
        // each of the 3 components within the bound: the vector within sqrt(3) of it
        EXPECT_LT(ev_err, std::sqrt(3.0) * bound_v) << "element " << e << " t " << t;
        EXPECT_LT(ea_err, std::sqrt(3.0) * bound_a) << "element " << e << " t " << t;
        worst_v = std::max(worst_v, ev_err);
        worst_a = std::max(worst_a, ea_err);
        scale_v = std::max(scale_v, exact.velocity.norm());
        scale_a = std::max(scale_a, exact.acceleration.norm());
      }
    }
    if (e == 0 || e == 2 || e == 9)
      std::printf("element %d (top at %.1f m): bound %.2e m/s, %.2e m/s^2\n", e, r0.z(), bound_v,
                  bound_a);
  }
  std::printf(
      "Hermite waves on 10 m elements: worst velocity error %.2e of %.3f m/s, "
      "acceleration %.2e of %.3f m/s^2 (docs/environment.md)\n",
      worst_v / scale_v, scale_v, worst_a / scale_a, scale_a);
}

TEST(EnvironmentField, BaselineAndAvx2SumsGiveTheSameBits) {
  // the sums compiled for AVX2 and for the SSE2 baseline do the same IEEE operations on the
  // same lanes (packet_math.h): equal bit for bit, deep and finite depth, long- and
  // short-crested, near the surface (the elevation test) and at depth
  for (const double depth : {kInf, 60.0}) {
    Environment env = JonswapSea(depth);
    EnvironmentField fast(env), baseline(env);
    if (!fast.avx2()) GTEST_SKIP() << "no AVX2 on this processor: one path only";
    baseline.set_avx2(false);
    ASSERT_FALSE(baseline.avx2());
    Environment crossed = env;
    crossed.waves.AddComponent(0.3, 2.0 * kPi / 6.0, -1.0, 0.4);  // another direction
    EnvironmentField fast_x(crossed), baseline_x(crossed);
    baseline_x.set_avx2(false);
    const Vec3 d = Vec3(0.8, 0.3, 0.5).normalized();
    for (const double t : {5.0, 61.3}) {
      for (const Vec3& p : {Vec3(0, 0, 0.4), Vec3(-50, 20, 14.0), Vec3(30, -4, 3.7)}) {
        for (const auto* pair : {&fast, &fast_x}) {
          const EnvironmentField& a = *pair;
          const EnvironmentField& b = pair == &fast ? baseline : baseline_x;
          const WaveSample wa = a.Waves(p, d, t), wb = b.Waves(p, d, t);
          EXPECT_EQ(wa.velocity, wb.velocity) << p.transpose();
          EXPECT_EQ(wa.acceleration, wb.acceleration) << p.transpose();
          EXPECT_EQ(wa.d_velocity, wb.d_velocity) << p.transpose();
          EXPECT_EQ(wa.d_acceleration, wb.d_acceleration) << p.transpose();
          EXPECT_EQ(a.Elevation(p.x(), p.y(), t), b.Elevation(p.x(), p.y(), t));
          EXPECT_EQ(a.Flow(p, t).acceleration, b.Flow(p, t).acceleration);
          FlowSample fa[3], fb[3];
          a.FlowsAbout(p, Vec3(1.5, 0.5, 0.3), t, fa);
          b.FlowsAbout(p, Vec3(1.5, 0.5, 0.3), t, fb);
          for (int i = 0; i < 3; ++i) EXPECT_EQ(fa[i].acceleration, fb[i].acceleration);
          const double o[2][2] = {{1.7, 0.2}, {0.7, -0.1}};
          double ea[4], eb[4];
          a.ElevationPairs(p.x(), p.y(), o, 2, t, ea);
          b.ElevationPairs(p.x(), p.y(), o, 2, t, eb);
          for (int i = 0; i < 4; ++i) EXPECT_EQ(ea[i], eb[i]);
        }
      }
    }
  }
}

// FlowsAbout and ElevationPairs (a vehicle's hull and waterline stations) share the centre's
// phase and depth factor among symmetric points: equal to the point-by-point sums to float
// rounding (KinematicsTol), and to them exactly where they fall back to them (a short-crested
// sea; a station above the mean level)
TEST(EnvironmentField, PointsAboutACentreAreThePointByPointFlows) {
  for (const double depth : {kInf, 60.0}) {
    Environment env = JonswapSea(depth);
    env.current = CurrentField::Uniform(Vec3(0.4, -0.1, 0.0));
    const EnvironmentField sea(env);
    const double tol = KinematicsTol(env.waves);
    // an 8.2 m hull 3.5 m down pitched 5 deg, a 3.3 m one 17 m down, a hull reaching deep, one
    // 90 m down (deep water: the shortest components' depth factors underflow float; 60 m:
    // below the bed, point by point)
    const Vec3 o1 = 0.387 * 8.2 * Vec3(std::cos(0.09), 0.1, std::sin(0.09));
    for (const auto& [p, o] :
         {std::pair{Vec3(3, -2, 3.5), o1}, std::pair{Vec3(-40, 11, 17.0), Vec3(1.2, -0.4, -0.1)},
          std::pair{Vec3(5, 5, 30.0), Vec3(2.0, 1.0, 6.0)},
          std::pair{Vec3(0, 0, 90.0), Vec3(1.5, 0.5, 2.0)}}) {
      for (const double t : {12.0, 55.5}) {
        FlowSample about[3];
        sea.FlowsAbout(p, o, t, about);
        const Vec3 points[3] = {p - o, p, p + o};
        for (int i = 0; i < 3; ++i) {
          const FlowSample one = sea.Flow(points[i], t);
          EXPECT_LT((about[i].velocity - one.velocity).norm(), tol) << p.transpose() << " " << i;
          EXPECT_LT((about[i].acceleration - one.acceleration).norm(), tol)
              << p.transpose() << " " << i;
          const WaveKinematics ref = env.waves.Kinematics(points[i], t);
          EXPECT_LT((about[i].velocity - Vec3(0.4, -0.1, 0.0) - ref.velocity).norm(), tol);
        }
        const double offsets[2][2] = {{o.x(), o.y()}, {0.3 * o.x(), -0.5 * o.y()}};
        double eta[4];
        sea.ElevationPairs(p.x(), p.y(), offsets, 2, t, eta);
        for (int j = 0; j < 2; ++j) {
          for (const int sign : {1, -1}) {
            const double x = p.x() + sign * offsets[j][0], y = p.y() + sign * offsets[j][1];
            const double e = eta[2 * j + (sign > 0 ? 0 : 1)];
            EXPECT_NEAR(e, sea.Elevation(x, y, t), ElevationTol(env.waves));
            EXPECT_NEAR(e, env.waves.Elevation(x, y, t), ElevationTol(env.waves));
          }
        }
      }
    }
    // a station above the mean level (a crest may reach it): point by point, exactly
    FlowSample about[3];
    const Vec3 p(1, 2, 0.5), o(2.0, 0.0, -1.0);
    sea.FlowsAbout(p, o, 20.0, about);
    EXPECT_EQ(about[2].velocity, sea.Flow(p + o, 20.0).velocity);
    EXPECT_EQ(about[0].acceleration, sea.Flow(p - o, 20.0).acceleration);
  }
}

TEST(EnvironmentField, CurrentIsTheCurrentFieldWithItsShear) {
  Environment env;
  env.current = CurrentField::Profile({{0.0, Vec3(1.0, 0.2, 0.0)}, {50.0, Vec3(0.4, 0.0, 0.0)}});
  const EnvironmentField sea(env);
  EXPECT_FALSE(sea.uniform());
  EXPECT_FALSE(sea.has_waves());
  Vec3 shear;
  const FlowSample f = sea.Current(Vec3(3, 4, 20.0), 1.0, &shear);
  EXPECT_TRUE(f.velocity.isApprox(env.current.Velocity(20.0, 1.0)));
  EXPECT_TRUE(shear.isApprox(env.current.Shear(20.0, 1.0)));
  EXPECT_TRUE(sea.Flow(Vec3(3, 4, 20.0), 1.0).velocity.isApprox(f.velocity));

  Environment calm;
  calm.current = CurrentField::Uniform(Vec3(0.3, -0.1, 0.0));
  const EnvironmentField still(calm);
  EXPECT_TRUE(still.uniform());
  EXPECT_EQ(still.uniform_current(), Vec3(0.3, -0.1, 0.0));
  EXPECT_EQ(still.Flow(Vec3(0, 0, 100), 5.0).velocity, Vec3(0.3, -0.1, 0.0));
  EXPECT_EQ(still.Flow(Vec3(0, 0, 100), 5.0).acceleration, Vec3::Zero());
}

TEST(EnvironmentField, RelativeVelocityIsTheOnePlaceTheWaterIsTakenOff) {
  FlowSample f;
  f.velocity = Vec3(1.0, -2.0, 0.5);
  EXPECT_EQ(RelativeVelocity(Vec3(3.0, 1.0, 1.0), f), Vec3(2.0, 3.0, 0.5));
}

}  // namespace
}  // namespace towsim::core
