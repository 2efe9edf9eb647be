// Bodies in linear waves, held to linear wave theory (docs/environment.md):
//   - a small neutrally buoyant sphere below regular deep-water waves moves on the particle
//     orbit of linear theory, a circle of radius a e^{k z} about the depth it was placed at,
//     and drifts with the Stokes drift (Morison's fluid inertia (1 + C_a) rho V Du/Dt with
//     m = rho V leaves it nothing but the water's motion);
//   - the towing vehicle, free (no cable, no thrust) at its design depth, heaves with the
//     surface in waves much longer than its hull (response amplitude operator Z / a -> 1: the
//     waterline's hydrostatic force and the hull's fluid inertia both follow the water) and
//     hardly at all in waves shorter than its hull (the elevation averages out along the
//     waterline, the fluid acceleration decays with depth, and the hull's inertia dominates).
//   - the waves held over a step (sampled once at t_{n+1} at the predicted positions,
//     integrator.h) against the same run with the waves resampled at every Newton iteration:
//     what holding them costs in accuracy, on the shipped Case 3.
// Amplitudes come from a least-squares fit of c0 + c1 t + A cos(w t) + B sin(w t) over whole
// periods after the start-up transient (the linear term takes up the Stokes drift).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/environment_field.h"
#include "core/model.h"
#include "core/simulation.h"
#include "core/state.h"
#include "core/vehicle_model.h"
#include "scene/scene_loader.h"

namespace towsim::core {
namespace {

struct Harmonic {
  double mean;       // c0 + c1 t at the record's middle
  double rate;       // c1, the mean drift
  double amplitude;  // sqrt(A^2 + B^2)
};

Harmonic FitHarmonic(const std::vector<double>& t, const std::vector<double>& y, double omega) {
  const int n = static_cast<int>(t.size());
  Eigen::MatrixXd a(n, 4);
  Eigen::VectorXd b(n);
  const double tm = 0.5 * (t.front() + t.back());
  for (int i = 0; i < n; ++i) {
    a.row(i) << 1.0, t[i] - tm, std::cos(omega * t[i]), std::sin(omega * t[i]);
    b(i) = y[i];
  }
  const Eigen::Vector4d c = a.colPivHouseholderQr().solve(b);
  return {c(0), c(1), std::hypot(c(2), c(3))};
}

// A small neutrally buoyant sphere 10 m under regular deep-water waves (H 2 m, T 8 s: ka =
// 0.063, a e^{kz} = 0.53 m), the waves ramped up over n = 2 periods and then held for 20: with
// the water's material acceleration in Morison's fluid inertia (docs/physics.md, "Fluid inertia
// in waves") it moves with the water particle that starts where it is placed, so
//   - its mean depth stays where the ramp leaves that particle: the vertical Lagrangian drift
//     of steady linear waves is zero to second order (xi . grad w = 0 on the circular orbit);
//     while the amplitude A(t) = r(t) a grows it is A A' k e^{2kz} (xi has the parts
//     (A' / w) e^{kz} [cos th, sin th] besides the orbit), a rise of k a^2 e^{2kz} / 2 = 8.9 mm
//     in all, and the cosine ramp over n periods leaves the orbit's centre a e^{kz} / (4 n^2 - 1)
//     = 35.5 mm above the starting point (the integral of r' cos w t): the level
//     z_m = z0 - a e^{kz0} / (4 n^2 - 1) - k a^2 e^{2 k z0} / 2, which each period's mean depth
//     after the ramp must hold within 1 % of the amplitude;
//   - its orbit is a circle of radius a e^{k z0};
//   - it drifts forward at the Stokes drift U_s = w k a^2 e^{2 k z_m} (0.0141 m/s here).
// With the local acceleration du/dt alone it sank at about 0.09 m/s (9 m in 100 s).
// The tolerances: the orbit's centre z_m lies 44 mm above z0 (e^{k 44 mm} = 1 + 2.8e-3), its
// second-order terms are (k a e^{kz})^2 = 1.1e-3 of it, the generalized-alpha phase error
// (w h)^2 / 12 ~ 5e-6 and the waves held over a step at the predicted position smaller still:
// kOrbitRelTol = 5e-3. The mean depth: the generalized-alpha
// step's error in the mean force leaves a drift of O(h^2) (measured: 2.3e-6 m/s at h = 0.005
// s, 9.4e-6 m/s at 0.01 s, 3.7e-5 m/s at 0.02 s), 1.5 mm over the 20 periods at h = 0.01 s.
// The drift is itself second order; the fourth-order terms of the particle's mean velocity are
// (k a e^{kz})^2 = 1.1e-3 of it, and the fit's linear term over 20 whole periods is exact for a
// constant drift: kStokesDriftRelTol = 1e-2 leaves a factor 5.
constexpr double kOrbitRelTol = 5e-3;
constexpr double kMeanDepthTol = 1e-2;  // of the amplitude a = 1 m
constexpr double kStokesDriftRelTol = 1e-2;

TEST(WaveResponseCore, NeutralSphereKeepsItsDepthOnTheLinearOrbitAndDriftsWithStokes) {
  constexpr double kHeight = 2.0, kPeriod = 8.0, kDepth = 10.0;  // [m], [s], [m]
  constexpr int kPeriods = 20, kRampPeriods = 2;
  Model m;
  m.time.step = 0.01;
  Environment& env = m.environment;
  env.waves =
      WaveField::Regular(kHeight, kPeriod, 0.0, 0.0, std::numeric_limits<double>::infinity(),
                         env.gravity, env.water_density);
  env.waves.set_ramp(kRampPeriods * kPeriod);
  // a short cable hanging far away and deep (e^{-k z} = 1e-14 there): the sphere is free
  m.cables[0].length = 2.0;
  m.cables[0].elements = 1;
  m.cables[0].start.kind = EndKind::kFixed;
  m.cables[0].start.position = Vec3(500.0, 0.0, 500.0);
  m.cables[0].end.kind = EndKind::kFree;
  SphereBody s;
  s.name = "sphere";
  s.volume = 1e-3;  // r = 6.2 cm, 1/1600 of the wavelength
  s.mass = env.water_density * s.volume;
  s.drag_coefficient = 0.5;
  s.added_mass_coefficient = 0.5;
  s.position = Vec3(0.0, 0.0, kDepth);
  m.spheres.push_back(s);
  Simulation sim(m);
  const double a = 0.5 * kHeight;
  const double omega = 2.0 * kPi / kPeriod;
  const double k = omega * omega / env.gravity;
  const double n = kRampPeriods;
  const double orbit = a * std::exp(-k * kDepth);
  const double z_mean = kDepth - orbit / (4.0 * n * n - 1.0) - 0.5 * k * orbit * orbit;
  const double stokes = omega * k * a * a * std::exp(-2.0 * k * z_mean);
  const int steps_per_period = static_cast<int>(std::lround(kPeriod / m.time.step));
  std::vector<double> t, x, z;
  double worst_mean_depth = 0.0;
  for (int period = 0; period < kRampPeriods + kPeriods; ++period) {
    double z_sum = 0.0;
    for (int i = 0; i < steps_per_period; ++i) {
      ASSERT_TRUE(sim.Step().ok());
      const Vec3 p = sim.body_position(0);
      z_sum += p.z();
      if (period >= kRampPeriods) {
        t.push_back(sim.time());
        x.push_back(p.x());
        z.push_back(p.z());
      }
    }
    if (period < kRampPeriods) continue;
    worst_mean_depth = std::max(worst_mean_depth, std::abs(z_sum / steps_per_period - z_mean));
  }
  const Harmonic hx = FitHarmonic(t, x, omega), hz = FitHarmonic(t, z, omega);
  std::printf(
      "sphere placed at %.1f m: mean depth %.5f m (the ramp's level %.5f m, worst period "
      "%.2e m off), %.2e m/s down; orbit x %.5f m, z %.5f m, linear theory %.5f m; drift "
      "%.5f m/s forward, Stokes drift %.5f m/s\n",
      kDepth, hz.mean, z_mean, worst_mean_depth, hz.rate, hx.amplitude, hz.amplitude, orbit,
      hx.rate, stokes);
  EXPECT_LT(worst_mean_depth, kMeanDepthTol * a);
  EXPECT_NEAR(hx.amplitude, orbit, kOrbitRelTol * orbit);
  EXPECT_NEAR(hz.amplitude, orbit, kOrbitRelTol * orbit);
  EXPECT_NEAR(hx.rate, stokes, kStokesDriftRelTol * stokes);
}

// heave response of the free towing vehicle to regular waves of the given period
double HeaveRao(const Model& scene, double period) {
  constexpr double kHeight = 1.0;  // [m]
  const Vehicle& tow = scene.vehicles.at(0);
  Environment env = scene.environment;
  env.waves = WaveField::Regular(kHeight, period, 0.0, 0.0, std::numeric_limits<double>::infinity(),
                                 env.gravity, env.water_density);
  env.waves.set_ramp(3.0 * period);
  const EnvironmentField sea(env);
  VehicleState s;
  s.p_W = Vec3(0.0, 0.0, tow.params.design_depth);
  const double h = std::min(0.02, period / 200.0);
  const double omega = 2.0 * kPi / period;
  std::vector<double> t, z;
  const int steps = static_cast<int>(std::lround(12.0 * period / h));
  for (int i = 0; i < steps; ++i) {
    const double t0 = i * h;
    const VehicleFlow f0 = SampleVehicleFlow(tow.params, sea, s.p_W, s.q_WB, t0);
    const Vec3 p1 = s.p_W + h * (s.q_WB * Vec3(s.nu.head<3>()));
    const VehicleFlow f1 = SampleVehicleFlow(tow.params, sea, p1, s.q_WB, t0 + h);
    AdvanceVehicle(tow.params, env, f0, f1, VehicleCommand(), PointLoad(), h, &s);
    if (t0 + h >= 6.0 * period) {
      t.push_back(t0 + h);
      z.push_back(s.p_W.z());
    }
  }
  return FitHarmonic(t, z, omega).amplitude / (0.5 * kHeight);
}

TEST(WaveResponseCore, TowVehicleHeavesWithLongWavesAndNotWithShortOnes) {
  const Model scene =
      scene::LoadScene(std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case1_forward.yaml");
  ASSERT_GT(scene.vehicles.at(0).params.waterplane_area, 0.0);
  // 30 s: wavelength 1405 m = 170 hull lengths; the single-degree-of-freedom balance of the
  // waterline stiffness rho g A_wp against the hull's inertia at the hull's depth factor
  // e^{-k 3.5 m} = 0.984 gives Z / a = 1.0002
  constexpr double kLongRaoTol = 1e-2;
  // 2 s: wavelength 6.2 m < hull 8.2 m; the estimate above, with the elevation averaged over
  // the waterline (sinc(k L_w / 2) = -0.20) and e^{-k 3.5 m} = 0.03, gives Z / a ~ 0.09
  constexpr double kShortRaoMax = 0.15;
  const double long_rao = HeaveRao(scene, 30.0);
  const double short_rao = HeaveRao(scene, 2.0);
  std::printf("tow vehicle heave RAO: %.4f at T = 30 s, %.4f at T = 2 s\n", long_rao, short_rao);
  EXPECT_NEAR(long_rao, 1.0, kLongRaoTol);
  EXPECT_LT(short_rao, kShortRaoMax);
}

TEST(WaveResponseCore, WavesHeldOverAStepAgreeWithWavesResampledEveryIteration) {
  const Model held =
      scene::LoadScene(std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case3_waves.yaml");
  Model resampled = held;
  resampled.integrator.waves_per_iteration = true;
  Simulation a(held), b(resampled);
  double dz_fish = 0.0, dz_tow = 0.0, dt_abs = 0.0, t_max = 0.0, heave_fish = 0.0, heave_tow = 0.0;
  const double z_fish0 = a.body_position(1).z(), z_tow0 = a.body_position(0).z();
  for (int i = 0; i < 1200; ++i) {  // 60 s: the 20 s ramp and 5 peak periods of the full sea
    ASSERT_TRUE(a.Step().ok());
    ASSERT_TRUE(b.Step().ok());
    dz_fish = std::max(dz_fish, std::abs(a.body_position(1).z() - b.body_position(1).z()));
    dz_tow = std::max(dz_tow, std::abs(a.body_position(0).z() - b.body_position(0).z()));
    // (of the largest top tension: in the head sea the top tension dips to a few N, where a
    // ratio would measure nothing but its smallness)
    dt_abs = std::max(dt_abs, std::abs(a.NodeTension(0) - b.NodeTension(0)));
    t_max = std::max(t_max, std::abs(b.NodeTension(0)));
    heave_fish = std::max(heave_fish, std::abs(a.body_position(1).z() - z_fish0));
    heave_tow = std::max(heave_tow, std::abs(a.body_position(0).z() - z_tow0));
  }
  const double dt_rel = dt_abs / t_max;
  std::printf(
      "waves held over a step vs resampled every iteration, Case 3, 60 s: towfish z "
      "%.2e m (it moved %.3f m), tow vehicle z %.2e m (it moved %.3f m), top tension %.2e "
      "of its largest\n",
      dz_fish, heave_fish, dz_tow, heave_tow, dt_rel);
  // the predicted positions differ from the converged ones by O(h^2) of the acceleration
  // change over a step, a few mm for h = 0.05 s, where the waves vary over metres: the held
  // samples move the motion by well under a millimetre and the tension by well under 1e-3
  constexpr double kHeldMotionTol = 1e-3;  // [m]
  constexpr double kHeldTensionRelTol = 1e-3;
  EXPECT_LT(dz_fish, kHeldMotionTol);
  EXPECT_LT(dz_tow, kHeldMotionTol);
  EXPECT_LT(dt_rel, kHeldTensionRelTol);
}

// The vehicle coupling's joint-force predictor (vehicle_coupling.h): in a sea the joint forces
// follow the waves, and the quadratic extrapolation, whose error on a sinusoid of frequency w
// is 2 sin(w h / 2) of the linear one's (third against second differences: 0.04 for Tp 8 s at
// h 0.05 s; the cable's own response adds faster content), is the usual one once the waves are
// up: taken in most steps (measured 0.80 of Case 3's 20-60 s); in Case 1's calm tow the two
// errors are alike and the quadratic is taken less often than in the sea (measured 0.35)
double QuadraticShare(const std::string& scene, int from, int to) {
  Simulation sim(scene::LoadScene(std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/" + scene));
  int quadratic = 0;
  for (int i = 0; i < to; ++i) {
    EXPECT_TRUE(sim.Step().ok());
    const CouplingHistory& h = sim.state().coupling;
    if (i >= from && h.error_quadratic < 0.5 * h.error_linear) ++quadratic;
  }
  return static_cast<double>(quadratic) / (to - from);
}

TEST(WaveResponseCore, JointForcePredictorFollowsTheSea) {
  const double sea = QuadraticShare("case3_waves.yaml", 400, 1200);  // 20-60 s, past the ramp
  const double calm = QuadraticShare("case1_forward.yaml", 400, 1200);
  std::printf("steps predicted quadratically: Case 3 %.3f, Case 1 %.3f\n", sea, calm);
  EXPECT_GT(sea, 0.5);  // most steps
  EXPECT_LT(calm, sea);
}

// what a towfish's altimeter and pressure sensor would see, against the fields themselves
// (WaveField, Seabed; the outputs read the double WaveField, the loads' sums run in float:
// environment_field.h)
TEST(WaveResponseCore, SensorsReadTheSeaAtTheBody) {
  const Model m =
      scene::LoadScene(std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case3_waves.yaml");
  Simulation sim(m);
  for (int i = 0; i < 600; ++i) ASSERT_TRUE(sim.Step().ok());  // 30 s: past the ramp
  constexpr double kSameFieldTol = 1e-9;                       // [m], [m/s]
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const Vec3 p = sim.body_position(b);
    const double eta = m.environment.waves.Elevation(p.x(), p.y(), sim.time());
    EXPECT_NEAR(sim.SurfaceElevationAt(b), eta, kSameFieldTol) << sim.body_name(b);
    EXPECT_NEAR(sim.BodyDepth(b), p.z() + eta, kSameFieldTol) << sim.body_name(b);
    EXPECT_NEAR(sim.BodyAltitude(b), m.environment.seabed.Depth(p.x(), p.y()) - p.z(),
                kSameFieldTol)
        << sim.body_name(b);
    const Vec3 u = m.environment.waves.Kinematics(p, sim.time()).velocity +
                   m.environment.current.Velocity(p.z(), sim.time());
    EXPECT_LT((sim.WaterVelocityAt(b) - u).norm(), kSameFieldTol) << sim.body_name(b);
  }
  EXPECT_NE(sim.SurfaceElevationAt(0), 0.0);  // the sea is up
  // bottomless: no altitude
  const Model deep =
      scene::LoadScene(std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case1_forward.yaml");
  EXPECT_TRUE(std::isnan(Simulation(deep).BodyAltitude(1)));
}

}  // namespace
}  // namespace towsim::core
