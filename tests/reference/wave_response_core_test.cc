// Bodies in linear waves, held to linear wave theory (docs/environment.md):
//   - a small neutrally buoyant sphere below regular deep-water waves moves on the particle
//     orbit of linear theory, a circle of radius a e^{k z} about its mean depth z (Morison's
//     fluid inertia (1 + C_a) rho V a_w with m = rho V leaves it nothing but the water's
//     motion);
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
#include "core/vehicle_model.h"
#include "scene/scene_loader.h"

namespace towsim::core {
namespace {

struct Harmonic {
  double mean;       // c0 + c1 t at the record's middle
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
  return {c(0), std::hypot(c(2), c(3))};
}

// ka = 0.031: second-order terms of the orbit are (ka)^2 ~ 1e-3 of it; the waves held over a
// step at the predicted position and the generalized-alpha phase error (w h)^2 / 12 ~ 2e-5 are
// smaller still
constexpr double kOrbitRelTol = 5e-3;

TEST(WaveResponseCore, NeutralSphereMovesOnTheLinearOrbit) {
  constexpr double kHeight = 1.0, kPeriod = 8.0, kDepth = 5.0;  // [m], [s], [m]
  Model m;
  m.time.step = 0.02;
  Environment& env = m.environment;
  env.waves =
      WaveField::Regular(kHeight, kPeriod, 0.0, 0.0, std::numeric_limits<double>::infinity(),
                         env.gravity, env.water_density);
  env.waves.set_ramp(2.0 * kPeriod);
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
  const double omega = 2.0 * kPi / kPeriod;
  const double k = omega * omega / env.gravity;
  std::vector<double> t, x, z;
  const double t_fit = 4.0 * kPeriod, t_end = 10.0 * kPeriod;
  while (sim.time() < t_end - 1e-9) {
    ASSERT_TRUE(sim.Step().ok());
    if (sim.time() >= t_fit) {
      t.push_back(sim.time());
      x.push_back(sim.body_position(0).x());
      z.push_back(sim.body_position(0).z());
    }
  }
  const Harmonic hx = FitHarmonic(t, x, omega), hz = FitHarmonic(t, z, omega);
  const double expected = 0.5 * kHeight * std::exp(-k * hz.mean);
  std::printf("sphere orbit at mean depth %.3f m: x %.5f m, z %.5f m, linear theory %.5f m\n",
              hz.mean, hx.amplitude, hz.amplitude, expected);
  EXPECT_NEAR(hx.amplitude, expected, kOrbitRelTol * expected);
  EXPECT_NEAR(hz.amplitude, expected, kOrbitRelTol * expected);
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
  double dz_fish = 0.0, dz_tow = 0.0, dt_rel = 0.0, heave_fish = 0.0, heave_tow = 0.0;
  const double z_fish0 = a.body_position(1).z(), z_tow0 = a.body_position(0).z();
  for (int i = 0; i < 1200; ++i) {  // 60 s: the 20 s ramp and 5 peak periods of the full sea
    ASSERT_TRUE(a.Step().ok());
    ASSERT_TRUE(b.Step().ok());
    dz_fish = std::max(dz_fish, std::abs(a.body_position(1).z() - b.body_position(1).z()));
    dz_tow = std::max(dz_tow, std::abs(a.body_position(0).z() - b.body_position(0).z()));
    dt_rel = std::max(dt_rel, std::abs(a.NodeTension(0) / b.NodeTension(0) - 1.0));
    heave_fish = std::max(heave_fish, std::abs(a.body_position(1).z() - z_fish0));
    heave_tow = std::max(heave_tow, std::abs(a.body_position(0).z() - z_tow0));
  }
  std::printf(
      "waves held over a step vs resampled every iteration, Case 3, 60 s: towfish z "
      "%.2e m (it moved %.3f m), tow vehicle z %.2e m (it moved %.3f m), top tension %.2e "
      "relative\n",
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

// what a towfish's altimeter and pressure sensor would see, against the fields themselves
// (WaveField, Seabed: written separately from the loads' sums)
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
