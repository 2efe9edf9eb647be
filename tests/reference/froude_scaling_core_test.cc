// Froude scaling of a free-running vehicle: the towing vehicle of config/vehicles/tow_vehicle.yaml
// and the same file read with `scale: lambda` (bodies.NAME.scale, core/vehicle_scaling.h), each
// alone (no cable), driven by the model's thrust times lambda^3. Froude's law of similitude
// (Newman 1977, "Marine Hydrodynamics", ch. 2; the basis of every towing-tank extrapolation of
// the ITTC) says that geometrically similar bodies at equal Froude number U / sqrt(g L) in the
// same fluid move similarly when every force scales by lambda^3:
//   steady speed       U_lambda = sqrt(lambda) U_1,
//   turning radius     R_lambda = lambda R_1           (the same rudder angle),
//   yaw rate           r_lambda = r_1 / sqrt(lambda).
// Our vehicle model is exactly Froude-similar (docs/vehicles.md §9: every term scales with its
// dimensions; the fin servo's fixed lag and the time step are the only things that do not
// scale, and neither enters a steady state), so the laws hold to the runs' convergence to
// their steady states, not to a modelling approximation.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"
#include "core/vehicle_model.h"
#include "scene/scene_loader.h"

namespace towsim::core {
namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kH = 0.02;  // RK4 step [s], the same for every size (as a scene would have)
// the model's design depth (waterplane.design_depth of tow_vehicle.yaml): where it floats level
constexpr double kDepth = 3.5;           // [m]
constexpr double kModelThrust = 1500.0;  // the model's thrust [N] (about 6 m/s)

// tow_vehicle.yaml read through the scene loader, with `scale: lambda` unless lambda is 1
VehicleParams TowVehicle(double lambda) {
  char scale[64] = "";
  if (lambda != 1.0) std::snprintf(scale, sizeof scale, ", scale: %.17g", lambda);
  const std::string scene =
      "name: froude\n"
      "time: {step: 0.02, duration: 1, output_rate: 10}\n"
      "cable: {length: 10, elements: 1, diameter: 0.01, density: 1300, youngs_modulus: 1e9,\n"
      "        initial: vertical, start: {body: v}, end: {free: true}}\n"
      "bodies:\n"
      "  v: {model: '" +
      std::string(TOWSIM_SOURCE_DIR) + "/config/vehicles/tow_vehicle.yaml'" + scale +
      ", position: [0, 0, 0]}\n";
  return scene::LoadSceneFromString(scene, "froude.yaml", "/", {}).vehicles.at(0).params;
}

// 1. from rest at the design depth (lambda x the model's), thrust lambda^3 x kModelThrust, for the
// same number of the vehicle's own time units: t = 400 s sqrt(lambda), about 23 surge time
// constants (m - X_udot) / (2 |X_uu| U) = 17 s x sqrt(lambda)
double SteadySpeed(const VehicleParams& p, double lambda) {
  const Environment env;
  VehicleCommand cmd;
  cmd.thrust = kModelThrust * lambda * lambda * lambda;
  VehicleState s;
  s.p_W.z() = kDepth * lambda;
  const int steps = static_cast<int>(std::lround(400.0 * std::sqrt(lambda) / kH));
  for (int k = 0; k < steps; ++k) AdvanceVehicle(p, env, cmd, PointLoad(), kH, &s);
  EXPECT_LT(s.nu.tail<5>().norm(), 1e-6 * s.nu(0));  // straight and level
  return s.nu(0);
}

struct Turn {
  double radius_kinematic;  // U / r at the end [m]
  double radius_track;      // least-squares circle through the last revolution's track [m]
  double speed;             // U = |(u, v)| [m/s]
  double yaw_rate;          // r [rad/s]
};

// Kasa fit: x^2 + y^2 = 2 a x + 2 b y + c
double FitRadius(const std::vector<Vec3>& pts) {
  Eigen::MatrixXd a(pts.size(), 3);
  Eigen::VectorXd b(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    a.row(i) << 2 * pts[i].x(), 2 * pts[i].y(), 1.0;
    b(i) = pts[i].x() * pts[i].x() + pts[i].y() * pts[i].y();
  }
  const Eigen::Vector3d sol = a.colPivHouseholderQr().solve(b);
  return std::sqrt(sol(2) + sol(0) * sol(0) + sol(1) * sol(1));
}

// 2. from straight running at the model's steady speed x sqrt(lambda), 20 deg of rudder (the
// servo starts at 0), thrust held: six revolutions, the last one measured
Turn SteadyTurn(const VehicleParams& p, double lambda, double u0) {
  const Environment env;
  VehicleCommand cmd;
  cmd.thrust = kModelThrust * lambda * lambda * lambda;
  cmd.rudder = 20.0 * kDeg;
  VehicleState s;
  s.p_W.z() = kDepth * lambda;
  s.nu(0) = u0;
  s.actuator[kThrust] = cmd.thrust;
  double turned = 0.0, last = 0.0;
  std::vector<Vec3> track;
  while (turned < 12 * kPi) {
    AdvanceVehicle(p, env, cmd, PointLoad(), kH, &s);
    const double psi = EulerZYX(s.q_WB).z();
    turned += std::remainder(psi - last, 2 * kPi);
    last = psi;
    if (turned >= 10 * kPi) track.push_back(s.p_W);
    if (track.size() > 1000000u) break;
  }
  Turn t;
  t.speed = s.nu.head<2>().norm();
  t.yaw_rate = s.nu(5);
  t.radius_kinematic = t.speed / t.yaw_rate;
  t.radius_track = FitRadius(track);
  return t;
}

TEST(FroudeScaling, SteadySpeedAndTurningRadiusOfTheScaledTowVehicle) {
  // Tolerance. Speed: after 23 surge time constants each run is within e^-23 ~ 1e-10 of its
  // steady speed, which RK4 reaches exactly (nu_dot = 0 is a fixed point of the step at any
  // h). Turn: the steady turn is the same kind of fixed point (nu, fin angle), reached after
  // 5 revolutions to ~1e-9 (the slowest mode decays at 0.07 /s x 1 / sqrt(lambda), over 5
  // revolutions of 50 s x sqrt(lambda)); the fitted track circle adds RK4's position error on
  // a circle, (r h)^4 / 120 ~ 3e-13 relative at r h = 2.5e-3 rad. kRatioRelTol = 1e-6 leaves
  // room for round-off over the 2e4-5e4 steps (measured: 1e-13 at most). A model that is only
  // approximately similar would need per cent (0.5 % on speed, 1 % on radius); this one is
  // exactly similar, so the bound is far tighter and a wrong exponent in any term that acts in
  // these runs fails it.
  constexpr double kRatioRelTol = 1e-6;
  const VehicleParams model = TowVehicle(1.0);
  const double u1 = SteadySpeed(model, 1.0);
  const Turn t1 = SteadyTurn(model, 1.0, u1);
  std::printf(
      "model (8.2 m): thrust %.0f N, steady u = %.6f m/s; 20 deg rudder: R = %.4f m "
      "(track %.4f m), U = %.5f m/s, r = %.4f deg/s\n",
      kModelThrust, u1, t1.radius_kinematic, t1.radius_track, t1.speed, t1.yaw_rate / kDeg);
  // a sanity anchor on the model itself (docs/vehicles.md §6: 6 m/s needs 1509.9 N, R = 24.0 m
  // at that thrust)
  EXPECT_NEAR(u1, 6.0, 0.05);
  EXPECT_NEAR(t1.radius_kinematic, 24.0, 0.5);
  for (const double lambda : {0.5, 2.0, 3.0}) {
    SCOPED_TRACE("lambda = " + std::to_string(lambda));
    const VehicleParams scaled = TowVehicle(lambda);
    ASSERT_DOUBLE_EQ(scaled.length, 8.2 * lambda);
    const double u = SteadySpeed(scaled, lambda);
    const Turn t = SteadyTurn(scaled, lambda, u);
    const double speed_ratio = u / u1, radius_ratio = t.radius_kinematic / t1.radius_kinematic;
    std::printf(
        "scale %.1f (%.1f m): thrust %.0f N, steady u = %.6f m/s, u / u_1 = %.9f "
        "(sqrt lambda x (1 %+.1e)); R = %.4f m, R / R_1 = %.9f (lambda x (1 %+.1e)), "
        "track R / R_1 = lambda x (1 %+.1e); r / r_1 = 1 / sqrt lambda x (1 %+.1e)\n",
        lambda, scaled.length, kModelThrust * lambda * lambda * lambda, u, speed_ratio,
        speed_ratio / std::sqrt(lambda) - 1.0, t.radius_kinematic, radius_ratio,
        radius_ratio / lambda - 1.0, t.radius_track / t1.radius_track / lambda - 1.0,
        t.yaw_rate / t1.yaw_rate * std::sqrt(lambda) - 1.0);
    EXPECT_NEAR(speed_ratio, std::sqrt(lambda), kRatioRelTol * std::sqrt(lambda));
    EXPECT_NEAR(radius_ratio, lambda, kRatioRelTol * lambda);
    EXPECT_NEAR(t.radius_track / t1.radius_track, lambda, kRatioRelTol * lambda);
    EXPECT_NEAR(t.yaw_rate / t1.yaw_rate, 1.0 / std::sqrt(lambda),
                kRatioRelTol / std::sqrt(lambda));
  }
}

}  // namespace
}  // namespace towsim::core
