// One lifting surface (lifting_surface.h): Helmbold lift slope, stall, induced drag, force
// directions, and the rudder/elevator sign conventions on a vehicle.

#include "core/lifting_surface.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"

namespace towsim::core {
namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kRho = 1025.0;

// the towfish half-wing of config/vehicles/towfish.yaml: AR 4.8, Helmbold slope
LiftingSurface Wing() {
  LiftingSurface s;
  s.name = "wing";
  s.position_B = Vec3(0.8, 0.35, 0.0);
  s.normal_B = Vec3(0.0, 0.0, -1.0);  // lifts up (-z) at positive angle of attack
  s.area = 0.15;
  s.aspect_ratio = 4.8;
  s.lift_slope = 0.0;
  s.oswald = 0.8;
  s.cd0 = 0.012;
  s.stall_angle = 14.0 * kDeg;
  return s;
}

// velocity of a surface moving forward at speed U with angle of attack alpha (body moving down
// relative to the water, w = U sin alpha > 0, for a wing whose normal is -z)
Vec3 Flow(double speed, double alpha) {
  return Vec3(speed * std::cos(alpha), 0.0, speed * std::sin(alpha));
}

TEST(LiftingSurface, HelmboldSlope) {
  constexpr double kTol = 1e-12;
  // 2 pi AR / (2 + sqrt(AR^2 + 4)): AR 4.8 -> 4.19 /rad (docs/vehicle_coefficients.md §5); -> 2 pi
  // as AR -> infinity;
  // -> pi AR / 2 (slender wing) as AR -> 0
  EXPECT_NEAR(HelmboldLiftSlope(4.8), 2 * kPi * 4.8 / (2 + std::sqrt(4.8 * 4.8 + 4)), kTol);
  EXPECT_NEAR(HelmboldLiftSlope(4.8), 4.19, 0.005);
  EXPECT_NEAR(HelmboldLiftSlope(1e6), 2 * kPi * (1 - 2e-6), 1e-9);  // 2 pi (1 - 2 / AR)
  EXPECT_NEAR(HelmboldLiftSlope(1e-4) / 1e-4, kPi / 2, 1e-6);
  LiftingSurface s = Wing();
  EXPECT_EQ(EffectiveLiftSlope(s), HelmboldLiftSlope(4.8));
  s.lift_slope = 3.12;
  EXPECT_EQ(EffectiveLiftSlope(s), 3.12);
}

// small alpha: L / (1/2 rho S U^2 alpha) = Helmbold slope; L normal to the flow, D along it
TEST(LiftingSurface, LiftSlopeAtSmallAngle) {
  const LiftingSurface s = Wing();
  constexpr double kU = 6.0, kAlpha = 1e-3;
  const SurfaceLoad load = SurfaceForce(s, kRho, Flow(kU, kAlpha), 0.0);
  const double q_s = 0.5 * kRho * s.area * kU * kU;
  const Vec3 flow_dir = -Flow(1.0, kAlpha);  // water relative to the wing
  const double lift = (load.force_B - load.force_B.dot(flow_dir) * flow_dir).norm();
  constexpr double kSlopeTol = 1e-9;  // exact up to round-off: alpha enters linearly
  EXPECT_NEAR(load.alpha, kAlpha, 1e-15);
  EXPECT_NEAR(lift / (q_s * kAlpha), HelmboldLiftSlope(4.8), kSlopeTol);
  EXPECT_LT(load.force_B.z(), 0.0);  // up
  // drag along the flow: cd0 + CL^2 / (pi e AR)
  const double cl = HelmboldLiftSlope(4.8) * kAlpha;
  EXPECT_NEAR(load.force_B.dot(flow_dir) / q_s, 0.012 + cl * cl / (kPi * 0.8 * 4.8), 1e-12);
}

// CL is capped at a alpha_s, falls linearly to 0 at 2 alpha_s and stays 0 beyond; the drag
// grows continuously into the flat-plate value
TEST(LiftingSurface, StallCapsLift) {
  const LiftingSurface s = Wing();
  const double a = HelmboldLiftSlope(4.8), stall = s.stall_angle;
  double cl_max = 0.0, prev_cl = LiftCoefficient(s, -kPi), prev_cd = DragCoefficient(s, -kPi);
  constexpr int kN = 20000;
  for (int i = 1; i <= kN; ++i) {
    const double alpha = -kPi + 2.0 * kPi * i / kN;
    const double cl = LiftCoefficient(s, alpha), cd = DragCoefficient(s, alpha);
    cl_max = std::max(cl_max, std::abs(cl));
    // continuity on a 0.018 deg grid: jumps bounded by slope * step
    EXPECT_LT(std::abs(cl - prev_cl), 1.01 * a * 2.0 * kPi / kN);
    EXPECT_LT(std::abs(cd - prev_cd), 0.01);
    prev_cl = cl;
    prev_cd = cd;
  }
  EXPECT_NEAR(cl_max, a * stall, 1e-3 * a * stall);
  EXPECT_NEAR(LiftCoefficient(s, 1.5 * stall), 0.5 * a * stall, 1e-12);
  EXPECT_EQ(LiftCoefficient(s, 2.0 * stall), 0.0);
  EXPECT_EQ(LiftCoefficient(s, -kPi / 2), 0.0);
  // broadside: cd0 + flat plate
  EXPECT_NEAR(DragCoefficient(s, kPi / 2), 0.012 + kFlatPlateNormal, 1e-12);
  // force at 30 deg (stalled): no lift, only drag along the flow
  const SurfaceLoad load = SurfaceForce(s, kRho, Flow(6.0, 30.0 * kDeg), 0.0);
  const Vec3 flow_dir = -Flow(1.0, 30.0 * kDeg);
  EXPECT_LT((load.force_B - load.force_B.dot(flow_dir) * flow_dir).norm(), 1e-9);
}

// below stall CD - cd0 = CL^2 / (pi e AR) at every alpha
TEST(LiftingSurface, InducedDrag) {
  const LiftingSurface s = Wing();
  for (double deg = -13.0; deg <= 13.0; deg += 1.0) {
    const double cl = LiftCoefficient(s, deg * kDeg);
    EXPECT_NEAR(DragCoefficient(s, deg * kDeg) - s.cd0, cl * cl / (kPi * 0.8 * 4.8), 1e-14);
  }
}

// the angle adds incidence and the signed deflection; the load is zero without flow, and its
// moment is r x F
TEST(LiftingSurface, IncidenceDeflectionAndMoment) {
  LiftingSurface s = Wing();
  s.incidence = 2.0 * kDeg;
  s.deflection_sign = -1.0;
  const SurfaceLoad load = SurfaceForce(s, kRho, Flow(5.0, 3.0 * kDeg), 4.0 * kDeg);
  EXPECT_NEAR(load.alpha, 1.0 * kDeg, 1e-14);
  EXPECT_LT((load.moment_B - s.position_B.cross(load.force_B)).norm(), 1e-12);
  const SurfaceLoad none = SurfaceForce(s, kRho, Vec3::Zero(), 0.3);
  EXPECT_EQ(none.force_B.norm(), 0.0);
  // spanwise flow is ignored
  const SurfaceLoad side = SurfaceForce(Wing(), kRho, Vec3(0.0, 3.0, 0.0), 0.0);
  EXPECT_EQ(side.force_B.norm(), 0.0);
}

// The sign conventions on a vehicle (VehicleCommand): a positive rudder turns the bow to
// starboard (N > 0, so r grows positive), a positive elevator pitches the bow up (M > 0).
// Rudder at the stern, normal +y, deflection_sign -1: it pushes the stern to port.
TEST(LiftingSurface, PositiveRudderGivesPositiveYawMoment) {
  VehicleParams p;
  p.mass = 1000.0;
  p.inertia = Vec3(50.0, 800.0, 800.0);
  LiftingSurface rudder;
  rudder.channel = Channel::kRudder;
  rudder.position_B = Vec3(-2.0, 0.0, 0.0);
  rudder.normal_B = Vec3::UnitY();
  rudder.area = 0.1;
  rudder.lift_slope = 3.12;
  rudder.deflection_sign = -1.0;
  LiftingSurface elevator = rudder;
  elevator.channel = Channel::kElevator;
  elevator.normal_B = Vec3::UnitZ();
  elevator.deflection_sign = 1.0;
  p.surfaces = {rudder, elevator};
  Environment env;
  env.gravity = 0.0;
  VehicleState s;
  s.nu(0) = 6.0;
  s.actuator[kRudder] = 10.0 * kDeg;
  Vec6 tau = HydrodynamicForces(p, env, s);
  EXPECT_GT(tau(5), 0.0);
  EXPECT_LT(tau(1), 0.0);  // side force to port at the stern
  const VehicleDerivative d = VehicleRates(p, env, s, VehicleCommand(), Vec3::Zero(), Vec3::Zero());
  EXPECT_GT(d.nu_dot(5), 0.0);
  // the rudder of 10 deg at 6 m/s: |N| = 1/2 rho S a delta U^2 x (cos delta for the lift axis)
  const double lift = 0.5 * kRho * 0.1 * 3.12 * 10.0 * kDeg * 36.0;
  EXPECT_NEAR(tau(5), 2.0 * lift, 1e-9 * lift);
  s.actuator[kRudder] = 0.0;
  s.actuator[kElevator] = 10.0 * kDeg;
  tau = HydrodynamicForces(p, env, s);
  EXPECT_GT(tau(4), 0.0);  // bow up
  EXPECT_GT(tau(2), 0.0);  // the stern is pushed down
}

}  // namespace
}  // namespace towsim::core
