// The two vehicles of config/vehicles/ at the paper's 6 m/s (Park & Kim, "Numerical
// simulation"): thrust for steady speed, turning circle at 20 deg rudder, the U-turn of Case 2,
// and stability with the fins centred (docs/vehicles.md reports these numbers).

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"
#include "core/vehicle_model.h"
#include "vehicle_file.h"

namespace towsim::core {
namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kSpeed = 6.0;  // the paper's steady speed [m/s]
// the towfish tow point: its bow, on the axis (paper: "attached to the bow")
const Vec3 kBow(1.65, 0.0, 0.0);

// the paper's running depth of the towing vehicle, where its waterplane is at design draft
constexpr double kDepth = 3.5;  // [m]

VehicleState Running(double speed, double thrust) {
  VehicleState s;
  s.p_W.z() = kDepth;
  s.nu(0) = speed;
  s.actuator[kThrust] = thrust;
  return s;
}

// thrust = axial drag at speed U, straight and level with the fins centred
double ThrustFor(const VehicleParams& p, const Environment& env, double speed) {
  return -HydrodynamicForces(p, env, Running(speed, 0.0))(0);
}

// the towfish's steady tow load at 6 m/s, level: the world force at the bow that balances its
// drag and net weight, F = -tau_hyd (force part)
Vec3 SteadyTowForce(const VehicleParams& fish, const Environment& env) {
  return -HydrodynamicForces(fish, env, Running(kSpeed, 0.0)).head<3>();
}

// Jacobian of the attitude-free dynamics about straight running (x = [nu, roll, pitch, yaw]),
// with a constant world-frame load at point_B (zero for the free vehicle) and the command held
// constant, by central differences.
using Mat9 = Eigen::Matrix<double, 9, 9>;
using Vec9 = Eigen::Matrix<double, 9, 1>;
Mat9 Linearize(const VehicleParams& p, const Environment& env, const VehicleCommand& cmd,
               const Vec3& force_W, const Vec3& point_B) {
  auto f = [&](const Vec9& x) {
    VehicleState s;
    s.p_W.z() = kDepth;
    s.nu = x.head<6>();
    s.actuator[kThrust] = cmd.thrust;
    const Vec3 rpy = x.tail<3>();
    s.q_WB = QuaternionFromEulerZYX(rpy);
    const Vec3 f_b = s.q_WB.toRotationMatrix().transpose() * force_W;
    const VehicleDerivative d = VehicleRates(p, env, s, cmd, f_b, point_B.cross(f_b));
    Vec9 y;
    y.head<6>() = d.nu_dot;
    // Euler-angle rates (Fossen 2011 ch. 2)
    const double sp = std::sin(rpy.x()), cp = std::cos(rpy.x()), tt = std::tan(rpy.y());
    const double q = x(4), r = x(5);
    y(6) = x(3) + tt * (sp * q + cp * r);
    y(7) = cp * q - sp * r;
    y(8) = (sp * q + cp * r) / std::cos(rpy.y());
    return y;
  };
  Vec9 x0 = Vec9::Zero();
  x0(0) = kSpeed;
  Mat9 j;
  constexpr double kEps = 1e-6;
  for (int i = 0; i < 9; ++i) {
    Vec9 a = x0, b = x0;
    a(i) += kEps;
    b(i) -= kEps;
    j.col(i) = (f(a) - f(b)) / (2 * kEps);
  }
  return j;
}

std::vector<std::complex<double>> Eigenvalues(const Eigen::MatrixXd& m) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(m);
  std::vector<std::complex<double>> ev(es.eigenvalues().data(), es.eigenvalues().data() + m.rows());
  return ev;
}

void Print(const char* what, const std::vector<std::complex<double>>& ev) {
  std::printf("%s eigenvalues [1/s]:", what);
  for (const auto& e : ev) std::printf(" (%.3f%+.3fi)", e.real(), e.imag());
  std::printf("\n");
}

double Heading(const VehicleState& s) { return EulerZYX(s.q_WB).z(); }

// the files carry the design choices docs/vehicles.md explains
TEST(VehicleFiles, DesignChoices) {
  const Environment env;
  const VehicleParams veh = test::ReadProjectVehicle("tow_vehicle");
  const VehicleParams fish = test::ReadProjectVehicle("towfish");
  // paper Table 1
  EXPECT_EQ(veh.mass, 6950.0);
  EXPECT_EQ(fish.mass, 416.0);
  EXPECT_EQ(fish.r_g, Vec3(1.0, 0.0, 0.12));
  // the towing vehicle alone is neutrally buoyant (0.1 kg)
  EXPECT_NEAR(env.water_density * veh.volume, veh.mass, 0.1);
  // the towfish is trimmed: its CB on the vertical through its CG, BG = 0.12 m, and it is
  // 1 % heavy in water (0.1 kg)
  const double buoyant = env.water_density * fish.volume;
  EXPECT_NEAR(fish.r_b.x(), fish.r_g.x(), 1e-12);
  EXPECT_NEAR(fish.r_g.z() - fish.r_b.z(), 0.12, 1e-12);
  EXPECT_NEAR(fish.mass - buoyant, 0.01 * fish.mass, 0.1);
  EXPECT_NEAR(kBow.x(), fish.length / 2, 1e-12);
  // the remedy: Kirchhoff's C_A complete (Munk moment kept), tail fins sized for stability
  EXPECT_TRUE(veh.munk_moment);
  EXPECT_TRUE(fish.munk_moment);
  EXPECT_TRUE(veh.has_propeller);
  EXPECT_FALSE(fish.has_propeller);
  // the added-mass matrices are symmetric positive definite
  for (const VehicleParams* p : {&veh, &fish}) {
    EXPECT_LT((p->added_mass - p->added_mass.transpose()).norm(), 1e-9);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat6>(p->added_mass).eigenvalues().minCoeff(), 0.0);
  }
}

// 3. thrust = drag at 6 m/s; from rest, that thrust settles at 6 m/s straight and level.
// Surge time constant (m - X_udot) / (2 |X_uu| U) ~ 17 s; after 300 s (~18 of them) the speed
// error is below kSpeedTol = 1e-3 m/s.
TEST(VehicleManeuver, ThrustForSixMetresPerSecond) {
  constexpr double kSpeedTol = 1e-3;
  const Environment env;
  const VehicleParams veh = test::ReadProjectVehicle("tow_vehicle");
  const double thrust = ThrustFor(veh, env, kSpeed);
  std::printf("tow vehicle: thrust for %.1f m/s (no cable) = %.1f N (hull %.1f N, fins %.1f N)\n",
              kSpeed, thrust, -veh.x_uu * kSpeed * kSpeed, thrust + veh.x_uu * kSpeed * kSpeed);
  EXPECT_GT(thrust, 1000.0);  // docs/vehicle_coefficients.md §2, §6: 1.2-2.2 kN for the hull alone
  EXPECT_LT(thrust, 2500.0);
  ASSERT_LT(thrust, veh.max_thrust);
  VehicleCommand cmd;
  cmd.thrust = thrust;
  VehicleState s;
  s.p_W.z() = kDepth;
  constexpr double kH = 0.02;
  for (int k = 0; k < static_cast<int>(300.0 / kH); ++k) {
    AdvanceVehicle(veh, env, cmd, PointLoad(), kH, &s);
  }
  // the thrust line (through O) lies 0.2 m above the CG: the acceleration pitches the vehicle
  // and it changes depth on the way; at the end it runs straight and level
  std::printf("tow vehicle from rest: u(300 s) = %.4f m/s, depth change %.2f m\n", s.nu(0),
              s.p_W.z() - kDepth);
  EXPECT_NEAR(s.nu(0), kSpeed, kSpeedTol);
  EXPECT_LT(s.nu.tail<5>().norm(), 1e-6);
  EXPECT_LT(EulerZYX(s.q_WB).norm(), 1e-6);
}

// 4. free-running turning circle at 20 deg rudder from 6 m/s, thrust held at its 6 m/s value.
// Steadiness: the radius of each of the last two revolutions (least-squares circle through the
// horizontal track) agrees to kRadiusTol = 0.5 %, and the speed and yaw rate settle.
struct Circle {
  Vec3 centre;
  double radius;
};
Circle FitCircle(const std::vector<Vec3>& pts) {
  // Kasa fit: x^2 + y^2 = 2 a x + 2 b y + c
  Eigen::MatrixXd a(pts.size(), 3);
  Eigen::VectorXd b(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    a.row(i) << 2 * pts[i].x(), 2 * pts[i].y(), 1.0;
    b(i) = pts[i].x() * pts[i].x() + pts[i].y() * pts[i].y();
  }
  const Eigen::Vector3d sol = a.colPivHouseholderQr().solve(b);
  return {Vec3(sol(0), sol(1), 0.0), std::sqrt(sol(2) + sol(0) * sol(0) + sol(1) * sol(1))};
}

TEST(VehicleManeuver, TurningCircleAtTwentyDegreesRudder) {
  constexpr double kRadiusTol = 5e-3;
  const Environment env;
  const VehicleParams veh = test::ReadProjectVehicle("tow_vehicle");
  VehicleCommand cmd;
  cmd.thrust = ThrustFor(veh, env, kSpeed);
  cmd.rudder = 20.0 * kDeg;
  VehicleState s = Running(kSpeed, cmd.thrust);
  constexpr double kH = 0.02;
  // run 4 revolutions, record the last two
  double turned = 0.0, last = 0.0;
  std::vector<Vec3> rev[4];
  double r_min = 1e9;
  while (turned < 8 * kPi) {
    AdvanceVehicle(veh, env, cmd, PointLoad(), kH, &s);
    const double psi = Heading(s);
    turned += std::remainder(psi - last, 2 * kPi);
    last = psi;
    r_min = std::min(r_min, s.nu(5));
    rev[std::min(3, static_cast<int>(turned / (2 * kPi)))].push_back(s.p_W);
    ASSERT_LT(rev[0].size() + rev[1].size() + rev[2].size() + rev[3].size(), 100000u);
  }
  const Circle c2 = FitCircle(rev[2]), c3 = FitCircle(rev[3]);
  const double speed = s.nu.head<2>().norm();
  const Vec3 rpy = EulerZYX(s.q_WB);
  std::printf(
      "tow vehicle, 20 deg rudder at %.0f m/s: R = %.1f m (R/L = %.2f), U = %.2f m/s, "
      "u = %.2f m/s, r = %.2f deg/s, drift = %.1f deg, roll = %.2f deg, pitch = %.2f deg, "
      "sink rate %.3f m/s, U/r = %.1f m\n",
      kSpeed, c3.radius, c3.radius / veh.length, speed, s.nu(0), s.nu(5) / kDeg,
      std::atan2(-s.nu(1), s.nu(0)) / kDeg, rpy.x() / kDeg, rpy.y() / kDeg,
      (s.q_WB.toRotationMatrix() * s.nu.head<3>()).z(), speed / s.nu(5));
  // positive rudder: bow to starboard, r > 0 throughout (after the first step)
  EXPECT_GT(s.nu(5), 0.0);
  EXPECT_GT(r_min, -1e-9);
  EXPECT_NEAR(c3.radius, c2.radius, kRadiusTol * c3.radius);
  EXPECT_LT((c3.centre - c2.centre).norm(), kRadiusTol * c3.radius);
  // the kinematic radius U / r agrees with the track
  EXPECT_NEAR(speed / s.nu(5), c3.radius, 0.01 * c3.radius);
  // docs/vehicle_coefficients.md §4: 24.5 m for Prestero's combined set (Munk kept), 71 m with the
  // Munk moment removed
  EXPECT_GT(c3.radius, 2 * veh.length);
  EXPECT_LT(c3.radius, 10 * veh.length);
}

// the paper's Case 2 manoeuvre on the free vehicle: 20 deg rudder until the heading reaches
// 170 deg, then 0: the vehicle must end running straight (yaw rate -> 0) at its 6 m/s.
TEST(VehicleManeuver, UTurnEndsRunningStraight) {
  const Environment env;
  const VehicleParams veh = test::ReadProjectVehicle("tow_vehicle");
  VehicleCommand cmd;
  cmd.thrust = ThrustFor(veh, env, kSpeed);
  cmd.rudder = 20.0 * kDeg;
  VehicleState s = Running(kSpeed, cmd.thrust);
  constexpr double kH = 0.02;
  double turned = 0.0, last = 0.0, t = 0.0, t_release = -1.0;
  for (; t < 250.0; t += kH) {
    AdvanceVehicle(veh, env, cmd, PointLoad(), kH, &s);
    const double psi = Heading(s);
    turned += std::remainder(psi - last, 2 * kPi);
    last = psi;
    if (t_release < 0 && turned >= 170.0 * kDeg) {
      t_release = t;
      cmd.rudder = 0.0;
    }
  }
  ASSERT_GT(t_release, 0.0);
  std::printf(
      "U-turn: 170 deg reached %.1f s after the rudder command; final heading %.1f deg, "
      "r = %.2e rad/s, u = %.3f m/s, depth change %.2f m\n",
      t_release, turned / kDeg, s.nu(5), s.nu(0), s.p_W.z() - kDepth);
  EXPECT_LT(std::abs(s.nu(5)), 1e-4);  // straight: < 0.006 deg/s
  EXPECT_NEAR(s.nu(0), kSpeed, 0.01);
  // the yaw rate decays within ~20 deg of heading after the release (no runaway turn)
  EXPECT_GT(turned, 170.0 * kDeg);
  EXPECT_LT(turned, 200.0 * kDeg);
  EXPECT_LT(std::abs(EulerZYX(s.q_WB).y()), 1e-3);
}

// 5a. linear stability of straight running at 6 m/s, fins centred: every eigenvalue of the
// Jacobian in (nu, roll, pitch) has a negative real part (heading and position are neutral
// for a free vehicle and left out).
TEST(VehicleStability, TowVehicleLinearizedAtSixMetresPerSecond) {
  const Environment env;
  const VehicleParams veh = test::ReadProjectVehicle("tow_vehicle");
  VehicleCommand cmd;
  cmd.thrust = ThrustFor(veh, env, kSpeed);
  const Mat9 j = Linearize(veh, env, cmd, Vec3::Zero(), Vec3::Zero());
  const auto ev = Eigenvalues(j.topLeftCorner<8, 8>());
  Print("tow vehicle", ev);
  // surge ~ -2 X_uu U / (m - X_udot) = -0.07 /s is the slowest mode
  for (const auto& e : ev) EXPECT_LT(e.real(), -0.05) << e;
  // the remedy matters: with the fins at the area that reproduces Prestero's coefficients
  // (1/3), the set is unstable as docs/vehicle_coefficients.md §4 reports (+0.58, +0.12 pitch;
  // +0.80 yaw)
  VehicleParams raw = veh;
  for (LiftingSurface& s : raw.surfaces) s.area /= 3.0;
  double worst = -1e9;
  for (const auto& e :
       Eigenvalues(Linearize(raw, env, cmd, Vec3::Zero(), Vec3::Zero()).topLeftCorner<8, 8>())) {
    worst = std::max(worst, e.real());
  }
  std::printf("tow vehicle with Prestero-size fins: largest real part %+.3f 1/s\n", worst);
  EXPECT_GT(worst, 0.1);
}

// 5d. why the Munk moment is kept (docs/vehicles.md): the cable pulls the towing vehicle at its
// CG (paper), and in a turn the towfish trails inside, pulling sideways. A hull made statically
// stable by removing the Munk moment has its neutral point aft of the CG, so a steady side pull
// at the CG turns it *toward* the pull, and the coupled system can circle with the rudder at 0.
// With the Munk moment the neutral point lies ahead of the CG and the vehicle turns *away* from
// the pull (r > 0 for a pull to port), straightening the tow.
TEST(VehicleStability, SidePullAtTheCentreOfGravityTurnsTheVehicleAway) {
  const Environment env;
  const VehicleParams veh = test::ReadProjectVehicle("tow_vehicle");
  VehicleCommand cmd;
  cmd.thrust = ThrustFor(veh, env, kSpeed);
  auto steady_yaw_rate = [&](const VehicleParams& p) {
    VehicleState s = Running(kSpeed, cmd.thrust);
    const Vec3 pull_B(0.0, -300.0, 0.0);  // 300 N to port, turning with the body
    constexpr double kH = 0.02;
    for (int k = 0; k < static_cast<int>(200.0 / kH); ++k) {
      PointLoad load;
      load.force_W0 = load.force_W1 = s.q_WB.toRotationMatrix() * pull_B;
      load.point_B = veh.r_g;
      AdvanceVehicle(p, env, cmd, load, kH, &s);
    }
    return s.nu(5);
  };
  const double r = steady_yaw_rate(veh);
  VehicleParams no_munk = veh;
  no_munk.munk_moment = false;
  const double r_no_munk = steady_yaw_rate(no_munk);
  std::printf(
      "300 N side pull to port at the CG: steady r = %+.4f rad/s (Munk kept), %+.4f "
      "rad/s (Munk removed)\n",
      r, r_no_munk);
  EXPECT_GT(r, 1e-3);
  EXPECT_LT(r_no_munk, -1e-3);
}

// the perturbations of the stability tests: one velocity component set (index into nu, value)
// and an initial attitude
struct Perturbation {
  const char* name;
  int index;
  double value;
  Vec3 rpy;
};
const Perturbation kPerturbations[] = {{"yaw rate 0.1 rad/s", 5, 0.1, Vec3::Zero()},
                                       {"sway 0.5 m/s", 1, 0.5, Vec3::Zero()},
                                       {"pitch 5 deg", 0, kSpeed, Vec3(0, 5 * kDeg, 0)},
                                       {"roll 10 deg", 0, kSpeed, Vec3(10 * kDeg, 0, 0)}};

// 5b. the towing vehicle under its own thrust, perturbed in yaw rate, sway and pitch, returns
// to straight, level running at 6 m/s (heading is neutral: it keeps the new one)
TEST(VehicleStability, TowVehiclePerturbedReturnsToStraightLevelRunning) {
  const Environment env;
  const VehicleParams veh = test::ReadProjectVehicle("tow_vehicle");
  VehicleCommand cmd;
  cmd.thrust = ThrustFor(veh, env, kSpeed);
  for (const Perturbation& c : kPerturbations) {
    VehicleState s = Running(kSpeed, cmd.thrust);
    s.nu(c.index) = c.value;
    s.q_WB = QuaternionFromEulerZYX(c.rpy);
    constexpr double kH = 0.02, kT = 120.0;
    for (int k = 0; k < static_cast<int>(kT / kH); ++k) {
      AdvanceVehicle(veh, env, cmd, PointLoad(), kH, &s);
    }
    const Vec3 rpy = EulerZYX(s.q_WB);
    std::printf(
        "tow vehicle, %s: after %.0f s |v,w| = %.1e m/s, |p,q,r| = %.1e rad/s, roll "
        "%.1e deg, pitch %.1e deg, heading %.2f deg, depth change %.2f m\n",
        c.name, kT, s.nu.segment<2>(1).norm(), s.nu.tail<3>().norm(), rpy.x() / kDeg,
        rpy.y() / kDeg, rpy.z() / kDeg, s.p_W.z() - kDepth);
    // slowest mode ~0.06 /s (surge) and ~0.6 /s (lateral, vertical): after 120 s the
    // perturbations are down by > 1e3
    EXPECT_NEAR(s.nu(0), kSpeed, 1e-3) << c.name;
    EXPECT_LT(s.nu.segment<2>(1).norm(), 1e-4) << c.name;
    EXPECT_LT(s.nu.tail<3>().norm(), 1e-5) << c.name;
    EXPECT_LT(std::abs(rpy.x()), 1e-4) << c.name;
    EXPECT_LT(std::abs(rpy.y()), 1e-4) << c.name;
  }
}

// 5c. the towfish, towed by a constant world-frame force at its bow equal to its steady tow
// load (drag forward, net weight upward: what the cable's lower end supplies in a steady tow;
// a constant force rather than a spring so that only the towfish's own hydrodynamics and the
// tow point geometry set the stability). Heading is no longer neutral: the bow force turns
// with the attitude, so all nine states (nu, roll, pitch, yaw) must decay.
TEST(VehicleStability, TowfishTowedAtItsBow) {
  const Environment env;
  const VehicleParams fish = test::ReadProjectVehicle("towfish");
  const Vec3 force = SteadyTowForce(fish, env);
  std::printf("towfish steady tow load at 6 m/s: drag %.1f N, net weight %.1f N\n", force.x(),
              -force.z());
  // level running: the only moment left is the small net weight (1 %) acting 0.65 m aft of the
  // bow, m_net g (x_bow - x_g), which the towfish takes with a small trim angle
  const Vec6 tau = HydrodynamicForces(fish, env, Running(kSpeed, 0.0));
  const double net_weight = (fish.mass - env.water_density * fish.volume) * env.gravity;
  EXPECT_NEAR((tau.tail<3>() + kBow.cross(force)).y(),
              net_weight * (kBow.x() - fish.r_g.x()), 1e-6 * fish.mass * env.gravity);
  const Mat9 j = Linearize(fish, env, VehicleCommand(), force, kBow);
  const auto ev = Eigenvalues(j);
  Print("towfish (constant bow load)", ev);
  for (const auto& e : ev) EXPECT_LT(e.real(), -0.05) << e;

  PointLoad load;
  load.force_W0 = load.force_W1 = force;
  load.point_B = kBow;
  // the trimmed equilibrium under this load (a small pitch: see above), reached unperturbed
  constexpr double kH = 0.01, kT = 60.0;
  VehicleState trim = Running(kSpeed, 0.0);
  for (int k = 0; k < static_cast<int>(kT / kH); ++k) {
    AdvanceVehicle(fish, env, VehicleCommand(), load, kH, &trim);
  }
  const Vec3 trim_rpy = EulerZYX(trim.q_WB);
  std::printf("towfish trim under the bow load: pitch %.3f deg, u %.4f m/s\n",
              trim_rpy.y() / kDeg, trim.nu(0));
  for (const Perturbation& c : kPerturbations) {
    VehicleState s = Running(kSpeed, 0.0);
    s.nu(c.index) = c.value;
    s.q_WB = QuaternionFromEulerZYX(c.rpy);
    for (int k = 0; k < static_cast<int>(kT / kH); ++k) {
      AdvanceVehicle(fish, env, VehicleCommand(), load, kH, &s);
    }
    const Vec3 rpy = EulerZYX(s.q_WB);
    std::printf(
        "towfish, %s: after %.0f s |v,w| = %.1e m/s, |p,q,r| = %.1e rad/s, roll %.1e "
        "deg, pitch %.1e deg, heading %.1e deg\n",
        c.name, kT, s.nu.segment<2>(1).norm(), s.nu.tail<3>().norm(), rpy.x() / kDeg,
        rpy.y() / kDeg, rpy.z() / kDeg);
    // back at the trimmed equilibrium (the slowest mode decays at 0.078 /s: e^-4.7 in 60 s)
    EXPECT_NEAR(s.nu(0), trim.nu(0), 1e-3) << c.name;
    EXPECT_LT((s.nu - trim.nu).segment<2>(1).norm(), 1e-3) << c.name;
    EXPECT_LT((s.nu - trim.nu).tail<3>().norm(), 1e-4) << c.name;
    EXPECT_LT((rpy - trim_rpy).norm(), 1e-3) << c.name;
  }
}

}  // namespace
}  // namespace towsim::core
