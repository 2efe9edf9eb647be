// The 6-DOF vehicle dynamics (vehicle_model.h) against analytic references: torque-free motion
// (energy and impulse conservation), constant-force acceleration with and without quadratic
// drag, the impulse balance in the world frame (finite differences), Galilean invariance under
// a uniform current, actuators, the point load, and the Euler-angle conversions.

#include "core/vehicle_model.h"

#include <cmath>
#include <cstdio>
#include <random>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"

namespace towsim::core {
namespace {

constexpr double kDeg = kPi / 180.0;

// an asymmetric test body: CG off every axis, full added-mass matrix with the couplings of
// config/vehicles (Prestero pattern) plus an off-pattern one, so that no term hides by symmetry
VehicleParams TumblingBody(bool added_mass) {
  VehicleParams p;
  p.length = 2.0;
  p.mass = 100.0;
  p.inertia = Vec3(2.0, 5.0, 8.0);
  p.r_g = Vec3(0.1, -0.05, 0.2);
  p.volume = 0.0;
  if (added_mass) {
    p.added_mass.diagonal() << 5.0, 60.0, 80.0, 0.5, 6.0, 7.0;
    p.added_mass(1, 5) = p.added_mass(5, 1) = -3.0;
    p.added_mass(2, 4) = p.added_mass(4, 2) = 2.0;
    p.added_mass(0, 3) = p.added_mass(3, 0) = 0.4;
  }
  return p;
}

Environment NoGravity() {
  Environment env;
  env.gravity = 0.0;
  return env;
}

// Kirchhoff impulses in W: P = R dT/dnu1, H (about the world origin) = R dT/dnu2 + p x P
struct Impulse {
  Vec3 linear, angular;
};
Impulse WorldImpulse(const VehicleParams& p, const VehicleState& s) {
  const Vec6 h = (RigidBodyMassMatrix(p) + p.added_mass) * s.nu;
  const Eigen::Matrix3d r = s.q_WB.normalized().toRotationMatrix();
  const Vec3 lin = r * h.head<3>();
  return {lin, r * h.tail<3>() + s.p_W.cross(lin)};
}

struct Drift {
  double energy, linear, angular;  // relative drifts
};

Drift TumbleDrift(const VehicleParams& p, double h, double duration) {
  const Environment env = NoGravity();
  VehicleState s;
  s.p_W = Vec3(1.0, -2.0, 3.0);
  s.q_WB = QuaternionFromEulerZYX(Vec3(0.3, -0.2, 1.0));
  s.nu << 1.0, 0.5, -0.3, 0.8, -1.2, 0.6;
  const double e0 = VehicleKineticEnergy(p, s);
  const Impulse i0 = WorldImpulse(p, s);
  const int n = static_cast<int>(std::lround(duration / h));
  for (int k = 0; k < n; ++k) AdvanceVehicle(p, env, VehicleCommand(), PointLoad(), h, &s);
  const Impulse i1 = WorldImpulse(p, s);
  return {std::abs(VehicleKineticEnergy(p, s) - e0) / e0,
          (i1.linear - i0.linear).norm() / i0.linear.norm(),
          (i1.angular - i0.angular).norm() / i0.angular.norm()};
}

// 1. torque-free tumbling: T = 1/2 nu^T M nu, P_W and H_W are invariants of Kirchhoff's
// equations (paper Eq. 27-28 without loads). RK4's global error is O(h^4): at h = 1 ms and
// |omega| ~ 1.6 rad/s the per-step error (omega h)^5 / 120 ~ 1e-16 sits near round-off, so over
// 20 000 steps the drifts stay below kInvariantTol = 1e-9 (observed 1e-14 to 2e-13). A step-size
// study (20, 10, 5 ms) checks the order of the scheme.
TEST(VehicleModel, TorqueFreeTumblingConservesEnergyAndImpulse) {
  constexpr double kInvariantTol = 1.0e-9;
  for (const bool added_mass : {false, true}) {
    SCOPED_TRACE(added_mass ? "with added mass" : "rigid body only");
    const Drift d = TumbleDrift(TumblingBody(added_mass), 1.0e-3, 20.0);
    EXPECT_LT(d.energy, kInvariantTol);
    EXPECT_LT(d.linear, kInvariantTol);
    EXPECT_LT(d.angular, kInvariantTol);
    // fourth order: halving h divides the energy drift by ~16
    const double coarse = TumbleDrift(TumblingBody(added_mass), 0.02, 20.0).energy;
    const double fine = TumbleDrift(TumblingBody(added_mass), 0.01, 20.0).energy;
    const double finer = TumbleDrift(TumblingBody(added_mass), 0.005, 20.0).energy;
    std::printf("energy drift over 20 s: h = 20 ms %.2e, 10 ms %.2e, 5 ms %.2e, 1 ms %.2e\n",
                coarse, fine, finer, d.energy);
    // RK4: global error O(h^4) (the energy error is observed O(h^5)): halving the step must
    // divide it by more than 2^3.5 = 11
    EXPECT_GT(coarse / fine, 11.0);
    EXPECT_GT(fine / finer, 11.0);
  }
}

// 2. a neutral body (CG = CB = O) pushed from rest along x_B by a constant force through O:
// (m - X_udot) u_dot = F  ->  u = F t / (m - X_udot);
// with X = x_uu u|u|: u = U tanh(t F / (U (m - X_udot))), U = sqrt(F / |x_uu|).
TEST(VehicleModel, ConstantForceFromRest) {
  const Environment env;  // gravity on, balanced by buoyancy
  VehicleParams p;
  p.mass = 500.0;
  p.inertia = Vec3(10.0, 80.0, 80.0);
  p.volume = p.mass / env.water_density;
  p.added_mass.diagonal() << 25.0, 400.0, 400.0, 2.0, 60.0, 60.0;
  const double force = 300.0, m_eff = p.mass + p.added_mass(0, 0);
  PointLoad load;
  load.force_W0 = load.force_W1 = Vec3(force, 0.0, 0.0);
  constexpr double kH = 0.01, kT = 20.0;

  // linear in t: RK4 is exact up to round-off
  constexpr double kLinearTol = 1.0e-10;  // relative
  VehicleState s;
  for (int k = 0; k < static_cast<int>(kT / kH); ++k) {
    AdvanceVehicle(p, env, VehicleCommand(), load, kH, &s);
  }
  EXPECT_NEAR(s.nu(0), force * kT / m_eff, kLinearTol * force * kT / m_eff);
  EXPECT_NEAR(s.p_W.x(), 0.5 * force * kT * kT / m_eff, kLinearTol * force * kT * kT / m_eff);
  EXPECT_LT(s.nu.tail<5>().norm(), 1e-12);

  // tanh: time constant m_eff U / F = 4.2 s >> h; RK4 error ~ (h / tau)^4 ~ 1e-11
  constexpr double kTanhTol = 1.0e-8;  // relative to U
  p.x_uu = -12.0;
  const double u_max = std::sqrt(force / -p.x_uu);
  s = VehicleState();
  for (int k = 0; k < static_cast<int>(kT / kH); ++k) {
    AdvanceVehicle(p, env, VehicleCommand(), load, kH, &s);
    const double t = (k + 1) * kH;
    ASSERT_NEAR(s.nu(0), u_max * std::tanh(t * force / (u_max * m_eff)), kTanhTol * u_max);
  }
}

// 7a. M nu_dot = tau: the world-frame impulse balance, checked by central differences along
// the state rate (independent of the body-frame Coriolis matrices):
//   d/dt (R dT/dnu1) = R tau1,   d/dt (R dT/dnu2 + p x R dT/dnu1) = R tau2 + p x R tau1,
// tau = all loads except the added-mass Coriolis terms (HydrodynamicForces of a copy without
// added mass) plus the external wrench. Central differences with eps = 1e-5 s: error
// ~ eps^2 |dddot| ~ 1e-9 of the impulse; kFdTol = 1e-6 relative.
TEST(VehicleModel, RatesSatisfyWorldImpulseBalance) {
  constexpr double kEps = 1.0e-5, kFdTol = 1.0e-6;
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  VehicleParams p = TumblingBody(true);
  p.volume = 0.09;
  p.r_b = Vec3(-0.05, 0.0, -0.02);
  p.x_uu = -5.0;
  p.y_vv = p.z_ww = -80.0;
  p.y_uv = p.z_uw = -20.0;
  p.m_uw = -4.0;
  p.n_uv = 4.0;
  p.n_rr = p.m_qq = -9.0;
  p.k_p = -1.0;
  LiftingSurface fin;
  fin.position_B = Vec3(-0.9, 0.2, 0.1);
  fin.normal_B = Vec3(0.0, 0.0, 1.0);
  fin.area = 0.05;
  fin.channel = Channel::kElevator;
  p.surfaces.push_back(fin);
  const Environment env;
  for (int trial = 0; trial < 5; ++trial) {
    VehicleState s;
    s.p_W = Vec3(uni(rng), uni(rng), 5.0 + uni(rng));
    s.q_WB = QuaternionFromEulerZYX(Vec3(0.5 * uni(rng), 0.5 * uni(rng), 3.0 * uni(rng)));
    s.nu << 2.0 + uni(rng), uni(rng), uni(rng), uni(rng), uni(rng), uni(rng);
    s.actuator[kElevator] = 0.2 * uni(rng);
    const Vec3 f_b(50.0 * uni(rng), 50.0 * uni(rng), 50.0 * uni(rng));
    const Vec3 m_b(20.0 * uni(rng), 20.0 * uni(rng), 20.0 * uni(rng));
    const VehicleDerivative d = VehicleRates(p, env, s, VehicleCommand(), f_b, m_b);

    // the residual of M nu_dot = rhs is round-off
    VehicleParams no_am = p;
    no_am.added_mass.setZero();
    Vec6 tau = HydrodynamicForces(no_am, env, s);
    tau.head<3>() += f_b;
    tau.tail<3>() += m_b;

    auto moved = [&](double dt) {
      VehicleState x = s;
      x.p_W += dt * d.p_dot_W;
      const Eigen::Quaterniond w(0.0, d.omega_B.x(), d.omega_B.y(), d.omega_B.z());
      const Eigen::Quaterniond qd = s.q_WB * w;
      x.q_WB.coeffs() += 0.5 * dt * qd.coeffs();
      x.q_WB.normalize();
      x.nu += dt * d.nu_dot;
      return WorldImpulse(p, x);
    };
    const Impulse plus = moved(kEps), minus = moved(-kEps);
    const Eigen::Matrix3d r = s.q_WB.toRotationMatrix();
    const Vec3 f_w = r * tau.head<3>();
    const Vec3 m_w = r * tau.tail<3>() + s.p_W.cross(f_w);
    const Vec3 dp = (plus.linear - minus.linear) / (2.0 * kEps);
    const Vec3 dh = (plus.angular - minus.angular) / (2.0 * kEps);
    EXPECT_LT((dp - f_w).norm(), kFdTol * (f_w.norm() + p.mass)) << "trial " << trial;
    EXPECT_LT((dh - m_w).norm(), kFdTol * (m_w.norm() + p.mass)) << "trial " << trial;
  }
}

// M_RB about O (Fossen 2011 ch. 3): I_O = I_g - m S(r_g)^2, e.g. I_xx,O = I_xx + m (y^2 + z^2)
TEST(VehicleModel, RigidBodyMassMatrixAboutTheOrigin) {
  const VehicleParams p = TumblingBody(false);
  const Mat6 m = RigidBodyMassMatrix(p);
  constexpr double kTol = 1e-12;
  EXPECT_LT((m - m.transpose()).norm(), kTol);
  const double x = p.r_g.x(), y = p.r_g.y(), z = p.r_g.z();
  EXPECT_NEAR(m(3, 3), p.inertia.x() + p.mass * (y * y + z * z), kTol);
  EXPECT_NEAR(m(4, 4), p.inertia.y() + p.mass * (x * x + z * z), kTol);
  EXPECT_NEAR(m(3, 4), -p.mass * x * y, kTol);
  // m S(r_g) below the diagonal: the moment of m a about O, r_g x (m a)
  EXPECT_NEAR(m(4, 0), p.mass * z, kTol);
  EXPECT_NEAR(m(5, 0), -p.mass * y, kTol);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat6>(m).eigenvalues().minCoeff(), 0.0);
}

// A uniform steady current only shifts the water: the motion relative to the water is the
// still-water motion (Galilean invariance; Fossen 2011 ch. 10). With nu_c(0) = nu(0) + [R^T U; 0]:
// p_c(t) = p(t) + U t, nu_c(t) = nu(t) + [R(t)^T U; 0], same attitude. Checked in a turn (omega
// != 0, so the M_A [omega x v_c; 0] term matters) with thrust, rudder and the fins active.
TEST(VehicleModel, UniformCurrentIsGalileanInvariant) {
  // RK4 is not frame-invariant (the body components R^T U of the current are not linear in the
  // state), so the two runs differ by their O(h^4) truncation errors: ~2e-7 at h = 10 ms over
  // 30 s (and 16x less at 5 ms); kTol = 1e-6
  constexpr double kTol = 1.0e-6;
  VehicleParams p = TumblingBody(true);
  p.r_g = Vec3(0.0, 0.0, 0.05);
  p.volume = p.mass / 1025.0;
  p.x_uu = -5.0;
  p.y_vv = p.z_ww = -80.0;
  p.y_uv = p.z_uw = -20.0;
  p.n_uv = 4.0;
  p.m_uw = -4.0;
  p.n_rr = p.m_qq = -9.0;
  p.has_propeller = true;
  p.max_thrust = 200.0;
  LiftingSurface rudder;
  rudder.channel = Channel::kRudder;
  rudder.position_B = Vec3(-0.9, 0.0, 0.0);
  rudder.normal_B = Vec3::UnitY();
  rudder.area = 0.04;
  rudder.deflection_sign = -1.0;
  p.surfaces.push_back(rudder);
  Environment still, moving;
  const Vec3 u_current(0.5, -0.3, 0.1);
  moving.current = CurrentField::Uniform(u_current);
  VehicleCommand cmd;
  cmd.thrust = 100.0;
  cmd.rudder = 15.0 * kDeg;
  VehicleState a, b;
  a.nu(0) = 1.5;
  a.q_WB = QuaternionFromEulerZYX(Vec3(0.0, 0.1, 0.4));
  b = a;
  b.nu.head<3>() += a.q_WB.toRotationMatrix().transpose() * u_current;
  constexpr double kH = 0.01;
  constexpr int kSteps = 3000;
  for (int k = 0; k < kSteps; ++k) {
    AdvanceVehicle(p, still, cmd, PointLoad(), kH, &a);
    AdvanceVehicle(p, moving, cmd, PointLoad(), kH, &b);
  }
  ASSERT_GT(std::abs(a.nu(5)), 0.1);  // it did turn
  const double t = kSteps * kH;
  EXPECT_LT((b.p_W - a.p_W - t * u_current).norm(), kTol * (1.0 + a.p_W.norm()));
  EXPECT_LT(a.q_WB.angularDistance(b.q_WB), kTol);
  const Vec3 v_c = b.q_WB.toRotationMatrix().transpose() * u_current;
  EXPECT_LT((b.nu.head<3>() - a.nu.head<3>() - v_c).norm(), kTol);
  EXPECT_LT((b.nu.tail<3>() - a.nu.tail<3>()).norm(), kTol);
}

// actuators: thrust = T (1 - exp(-t / tau)) with the command clamped to [-max/4, max]; fins
// slew at max_rate and stop at max_deflection.
TEST(VehicleModel, ActuatorsLagClampAndRateLimit) {
  VehicleParams p;
  p.has_propeller = true;
  p.max_thrust = 1000.0;
  p.thrust_time_constant = 2.0;
  p.rudder.max_deflection = 30.0 * kDeg;
  p.rudder.max_rate = 20.0 * kDeg;
  p.elevator = p.rudder;
  const Environment env = NoGravity();
  VehicleCommand cmd;
  cmd.thrust = 5000.0;          // clamped to 1000
  cmd.rudder = 45.0 * kDeg;     // clamped to 30 deg
  cmd.elevator = -10.0 * kDeg;  // within limits
  VehicleState s;
  constexpr double kH = 0.01;
  constexpr double kLagTol = 1e-8;  // RK4 on a linear ODE, h / tau = 0.005
  for (int k = 1; k <= 300; ++k) {
    AdvanceVehicle(p, env, cmd, PointLoad(), kH, &s);
    const double t = k * kH;
    ASSERT_NEAR(s.actuator[kThrust], 1000.0 * (1.0 - std::exp(-t / 2.0)), kLagTol * 1000.0);
    // rate limit: while far from the target the rudder moves at exactly max_rate
    if (t <= 1.0) {
      ASSERT_NEAR(s.actuator[kRudder], 20.0 * kDeg * t, 1e-12);
    }
  }
  // after 3 s: the rudder has reached its 30 deg stop (1.5 s of slewing + 0.05 s servo lag),
  // the elevator its command
  EXPECT_NEAR(s.actuator[kRudder], 30.0 * kDeg, 1e-6);
  EXPECT_NEAR(s.actuator[kElevator], -10.0 * kDeg, 1e-6);
  cmd.thrust = -5000.0;  // reverse: clamped to -max/4
  for (int k = 0; k < 5000; ++k) AdvanceVehicle(p, env, cmd, PointLoad(), kH, &s);
  EXPECT_NEAR(s.actuator[kThrust], -250.0, 1e-6);
}

// the point load: a world force ramped over the step (force_W0 -> force_W1) integrates to
// h (f0 + f1) / 2 (RK4 is exact for a linear-in-time force); at an off-centre point it turns
// the body with point_B x force_B.
TEST(VehicleModel, PointLoadIsInterpolatedAndAppliedAtItsPoint) {
  VehicleParams p;
  p.mass = 10.0;
  p.inertia = Vec3(1.0, 2.0, 2.0);
  const Environment env = NoGravity();
  VehicleState s;
  PointLoad load;
  load.force_W0 = Vec3(0.0, 0.0, 0.0);
  load.force_W1 = Vec3(4.0, 0.0, 0.0);
  constexpr double kH = 0.1;
  AdvanceVehicle(p, env, VehicleCommand(), load, kH, &s);
  EXPECT_NEAR(s.nu(0), kH * 2.0 / p.mass, 1e-14);
  EXPECT_NEAR(s.p_W.x(), kH * kH * 4.0 / 6.0 / p.mass, 1e-14);  // int int f = f1 h^2 / 6

  // a sideways push at the stern turns the bow to port: N = x F_y < 0 for x < 0, F_y > 0
  s = VehicleState();
  const VehicleDerivative d = VehicleRates(p, env, s, VehicleCommand(), Vec3(0.0, 1.0, 0.0),
                                           Vec3(-0.5, 0.0, 0.0).cross(Vec3(0.0, 1.0, 0.0)));
  EXPECT_NEAR(d.nu_dot(5), -0.5 / 2.0, 1e-14);
  EXPECT_NEAR(d.nu_dot(1), 0.1, 1e-14);
}

// 7b. EulerZYX(QuaternionFromEulerZYX(x)) = x on a seeded sample (pitch away from +-90 deg)
// the packed layout (VehicleStateLayout): p_W, q_WB as (w, x, y, z), nu, the actuators
TEST(VehicleModel, PackedStateLayoutAndRoundTrip) {
  VehicleState s;
  s.p_W = Vec3(1.0, 2.0, 3.0);
  s.q_WB = Eigen::Quaterniond(4.0, 5.0, 6.0, 7.0);  // not unit: stored as given
  s.nu << 8.0, 9.0, 10.0, 11.0, 12.0, 13.0;
  s.actuator[kThrust] = 14.0;
  s.actuator[kRudder] = 15.0;
  s.actuator[kElevator] = 16.0;
  const VehicleVector x = PackVehicleState(s);
  ASSERT_EQ(x.size(), 16);
  for (int i = 0; i < x.size(); ++i) EXPECT_EQ(x(i), i + 1.0) << "entry " << i;
  const VehicleState back = UnpackVehicleState(x);
  EXPECT_EQ(back.p_W, s.p_W);
  EXPECT_EQ(back.q_WB.coeffs(), s.q_WB.coeffs());
  EXPECT_EQ(back.nu, s.nu);
  EXPECT_EQ(back.actuator, s.actuator);
}

TEST(VehicleModel, EulerAnglesRoundTrip) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> roll(-kPi + 1e-6, kPi - 1e-6);
  std::uniform_real_distribution<double> pitch(-0.49 * kPi, 0.49 * kPi);
  constexpr double kTol = 1e-12;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 x(roll(rng), pitch(rng), roll(rng));
    EXPECT_LT((EulerZYX(QuaternionFromEulerZYX(x)) - x).norm(), kTol) << x.transpose();
  }
  // R = Rz Ry Rx: a pure yaw of 90 deg maps x_B to y_W; a pitch of +10 deg lifts the bow (-z_W)
  const Eigen::Matrix3d r = QuaternionFromEulerZYX(Vec3(0, 0, kPi / 2)).toRotationMatrix();
  EXPECT_LT((r * Vec3::UnitX() - Vec3::UnitY()).norm(), kTol);
  const Eigen::Matrix3d rp = QuaternionFromEulerZYX(Vec3(0, 10 * kDeg, 0)).toRotationMatrix();
  EXPECT_LT((rp * Vec3::UnitX()).z(), 0.0);
}

// Semi-submersible hydrostatics: 1 m of sinkage adds rho g A_wp of buoyancy at the waterplane
// point, a pitch of theta a moment -rho g I_L sin(theta), a roll -rho g I_T sin(phi).
TEST(VehicleModel, WaterplaneRestoringOfASurfacePiercingFairing) {
  VehicleParams p;
  p.mass = 1000.0;
  p.volume = 1000.0 / 1025.0;  // neutral at design depth
  p.waterplane_area = 2.0;
  p.waterplane_point_B = Vec3(0.5, 0.0, -0.5);
  p.design_depth = 3.0;
  p.waterplane_inertia_long = 4.0;
  p.waterplane_inertia_trans = 0.3;
  Environment env;
  const double rho_g = env.water_density * env.gravity;
  constexpr double kHydrostaticTol = 1e-9;  // closed-form forces, round-off only
  VehicleState s;
  s.p_W.z() = 4.0;  // 1 m below design depth
  Vec6 f = HydrodynamicForces(p, env, s);
  EXPECT_NEAR(f(2), -rho_g * 2.0, kHydrostaticTol * rho_g);
  // applied at x = 0.5 ahead of the origin: a nose-up moment M = -x F_z
  EXPECT_NEAR(f(4), 0.5 * rho_g * 2.0, kHydrostaticTol * rho_g);
  for (const double angle : {0.05, -0.2}) {
    s.p_W.z() = 3.0;
    s.q_WB = QuaternionFromEulerZYX(Vec3(0.0, angle, 0.0));
    f = HydrodynamicForces(p, env, s);
    EXPECT_NEAR(f(4), -rho_g * 4.0 * std::sin(angle), kHydrostaticTol * rho_g) << angle;
    s.q_WB = QuaternionFromEulerZYX(Vec3(angle, 0.0, 0.0));
    f = HydrodynamicForces(p, env, s);
    EXPECT_NEAR(f(3), -rho_g * 0.3 * std::sin(angle), kHydrostaticTol * rho_g) << angle;
  }
}

}  // namespace
}  // namespace towsim::core
