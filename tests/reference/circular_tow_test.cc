// Self-checks of the steady circular-tow reference (circular_tow.h).

#include "circular_tow.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace towsim::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// the paper's cable and the 416 kg sphere of config/scenes/steady_tow.yaml (TowedCableProblem's
// defaults), towed at speed U on a circle of radius R at 3.5 m depth
CircularTowProblem Turn(double radius, double speed) {
  CircularTowProblem p;
  p.radius = radius;
  p.turn_rate = speed / radius;
  p.tow_depth = 3.5;
  return p;
}

TowedCableSolution Straight(double speed) {
  TowedCableProblem p;
  p.tow_velocity = Eigen::Vector3d(speed, 0.0, 0.0);
  return SolveTowedCableSteady(p);
}

// (a) a circle of 1e6 m at the same speed is a straight tow: the turn's effects are of order
// (l / R)^2 ~ 4e-8 in the geometry (the flow turns by l / R ~ 2e-4 rad along the cable, the
// sphere's radius differs by l^2 / 2R ~ 2 cm) and the centripetal load U^2 / R = 3.6e-5 m/s^2
// acts sideways (a second-order change of tension and shape), far below 1e-6
TEST(CircularTow, LargeCircleIsTheStraightTow) {
  for (const double speed : {6.0, 3.0}) {
    const CircularTowSolution c = SolveCircularTow(Turn(1e6, speed));
    const TowedCableSolution s = Straight(speed);
    constexpr double kStraightRel = 1e-6;
    EXPECT_NEAR(c.layback, s.layback, kStraightRel * s.layback) << speed;
    EXPECT_NEAR(c.depth, s.depth, kStraightRel * s.depth) << speed;
    EXPECT_NEAR(c.top_tension, s.top_tension, kStraightRel * s.top_tension) << speed;
    std::printf(
        "R = 1e6 m, %.0f m/s: layback %.9f (straight %.9f) m, depth %.9f (%.9f) m, top tension "
        "%.6f (%.6f) N, sphere %.4f m inside the circle, %d Newton iterations\n",
        speed, c.layback, s.layback, c.depth, s.depth, c.top_tension, s.top_tension,
        1e6 - c.sphere_radius, c.newton_iterations);
  }
}

// the loads per unit unstretched length, written out here from circular_tow.h's equations
Eigen::Vector3d CableLoad(const CircularTowProblem& p, const CircularTowPoint& q) {
  const double area = 0.25 * kPi * p.line.diameter * p.line.diameter;
  const double rho = p.line.fluid.density;
  const double omega = p.turn_rate;
  const Eigen::Vector3d v(-omega * q.r.y(), omega * q.r.x(), 0.0);
  const Eigen::Vector3d a = -omega * omega * Eigen::Vector3d(q.r.x(), q.r.y(), 0.0);
  const Eigen::Vector3d t = q.force / q.tension;
  const Eigen::Vector3d a_n = a - a.dot(t) * t;
  return Eigen::Vector3d(0.0, 0.0, (p.line.density - rho) * area * p.line.gravity) +
         CableStretch(p.line, q.tension) *
             CableDragPerStretchedLength(p.line.fluid, p.line.diameter, t, v) -
         p.line.density * area * a - p.added_mass_normal * rho * area * a_n;
}

// the sphere's net weight, drag (C_D on pi r^2) and d'Alembert force at r_s
Eigen::Vector3d SphereLoad(const CircularTowProblem& p, const Eigen::Vector3d& r_s) {
  const double omega = p.turn_rate;
  const Eigen::Vector3d v(-omega * r_s.y(), omega * r_s.x(), 0.0);
  const Eigen::Vector3d a = -omega * omega * Eigen::Vector3d(r_s.x(), r_s.y(), 0.0);
  const double rho = p.line.fluid.density;
  const double radius = std::cbrt(3.0 * p.line.sphere_volume / (4.0 * kPi));
  return Eigen::Vector3d(0.0, 0.0,
                         (p.line.sphere_mass - rho * p.line.sphere_volume) * p.line.gravity) -
         0.5 * rho * p.line.sphere_cd * kPi * radius * radius * v.norm() * v -
         (p.line.sphere_mass + p.sphere_added_mass_coefficient * rho * p.line.sphere_volume) * a;
}

// (b) the returned shape, cable and sphere together as a free body: the sum of the external
// loads (with the d'Alembert forces) is the force on the tow point, and their moment about the
// circle's centre is the moment of that force (the cable carries no moment: (r x F)' = -r x f).
// The loads are integrated over the stored shape by Simpson's rule (2000 intervals of 0.1 m;
// the shape bends over metres: error ~ (h / l)^4 far below 1e-6)
TEST(CircularTow, ShapeIsAFreeBodyInEquilibrium) {
  for (const double speed : {6.0, 3.0}) {
    const CircularTowProblem p = Turn(300.0, speed);
    const CircularTowSolution c = SolveCircularTow(p, 20000, 2000);
    ASSERT_EQ(c.shape.size(), 2001u);
    const double h = p.line.length / 2000;
    Eigen::Vector3d force = SphereLoad(p, c.sphere_position);
    Eigen::Vector3d moment = c.sphere_position.cross(force);
    for (size_t i = 0; i < c.shape.size(); ++i) {
      const double wgt = (i == 0 || i + 1 == c.shape.size()) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      const Eigen::Vector3d f = CableLoad(p, c.shape[i]);
      force += wgt * h / 3.0 * f;
      moment += wgt * h / 3.0 * c.shape[i].r.cross(f);
    }
    const Eigen::Vector3d r_top(p.radius, 0.0, p.tow_depth);
    EXPECT_LT((c.shape.back().r - r_top).norm(), 1e-9) << speed;
    constexpr double kBalanceRel = 1e-6;
    EXPECT_LT((force - c.top_force).norm(), kBalanceRel * c.top_tension) << speed;
    EXPECT_LT((moment - r_top.cross(c.top_force)).norm(),
              kBalanceRel * r_top.norm() * c.top_tension)
        << speed;
    std::printf(
        "free body %.0f m/s, R = 300 m: force balance %.2e N, moment balance %.2e N m "
        "(top tension %.2f N)\n",
        speed, (force - c.top_force).norm(), (moment - r_top.cross(c.top_force)).norm(),
        c.top_tension);
  }
}

// (c) in a turn the sphere runs inside the tow point's circle (the cable is a chord that the
// drag bends only partly toward the arc), so it moves slower than the tow point (U r_s / R)
// and has less drag. Two effects then set its depth against the straight tow at U = Omega R:
//   - the slower sphere hangs at a steeper angle: deeper (alone when the cable has no drag);
//   - the cable, bent along the circle, needs an inward load T / R from its drag: the water
//     crosses it horizontally at beta ~ asin(sqrt(T / (R q))), q = rho_w d C_Dn U^2 / 2
//     (~8.5 deg at the top at 6 m/s, R = 300 m), and the quadratic normal drag |V_n| V_n, with
//     |V_n| ~ U sqrt(sin^2 phi + sin^2 beta) instead of U sin phi, lifts the cable: it flies
//     flatter than the straight tow's critical angle (3.21 deg at 6 m/s: towed_cable_steady_test).
// At 3 m/s (a steep cable, the sphere's pull dominating) the sphere is deeper; at 6 m/s (a
// cable near its critical angle over most of its length) the lift wins and it is shallower.
TEST(CircularTow, TurnPullsTheSphereInside) {
  for (const double speed : {6.0, 3.0}) {
    const CircularTowSolution c = SolveCircularTow(Turn(300.0, speed), 20000, 20);
    const TowedCableSolution s = Straight(speed);
    EXPECT_LT(c.sphere_radius, 300.0) << speed;
    EXPECT_GT(c.sphere_radius, 300.0 - s.layback) << speed;
    // the top inclination (last 10 m of the shape) against the straight tow's
    const auto incline = [](const Eigen::Vector3d& d) {
      return std::atan2(-d.z(), std::hypot(d.x(), d.y()));
    };
    const double phi_turn = incline(c.shape[20].r - c.shape[19].r);
    const double phi_straight = incline(s.shape[20].r - s.shape[19].r);
    EXPECT_LT(phi_turn, phi_straight) << speed;
    if (speed == 3.0) {
      EXPECT_GT(c.depth, s.depth);
    } else {
      EXPECT_LT(c.depth, s.depth);
    }
    std::printf(
        "R = 300 m, %.0f m/s (Omega %.5f rad/s): sphere radius %.4f m (speed %.4f m/s), lag "
        "%.4f rad, depth %.4f m, top tension %.2f N, top inclination %.3f deg, %d Newton "
        "iterations; straight tow: layback %.4f m, depth %.4f m, top tension %.2f N, top "
        "inclination %.3f deg\n",
        speed, speed / 300.0, c.sphere_radius, c.sphere_radius * speed / 300.0, c.lag_angle,
        c.depth, c.top_tension, phi_turn * 180.0 / kPi, c.newton_iterations, s.layback, s.depth,
        s.top_tension, phi_straight * 180.0 / kPi);
  }
}

// without cable drag only the sphere's slowing acts: deeper than the straight tow at every
// speed (the cable then hangs as a catenary under its weight and the centrifugal loads)
TEST(CircularTow, WithoutCableDragTheSlowerSphereHangsDeeper) {
  for (const double speed : {6.0, 3.0}) {
    CircularTowProblem p = Turn(300.0, speed);
    p.line.cable_drag = false;
    const CircularTowSolution c = SolveCircularTow(p, 4000, 20);
    TowedCableProblem q = p.line;
    q.tow_velocity = Eigen::Vector3d(speed, 0.0, 0.0);
    const TowedCableSolution s = SolveTowedCableSteady(q, 4000, 20);
    EXPECT_LT(c.sphere_radius, 300.0) << speed;
    EXPECT_GT(c.depth, s.depth) << speed;
    std::printf("no cable drag, R = 300 m, %.0f m/s: depth %.4f m (straight %.4f m)\n", speed,
                c.depth, s.depth);
  }
}

// a turn to port is the mirror image (y -> -y) of the turn to starboard
TEST(CircularTow, PortTurnIsTheMirrorImage) {
  CircularTowProblem p = Turn(300.0, 6.0);
  const CircularTowSolution a = SolveCircularTow(p, 4000, 20);
  p.turn_rate = -p.turn_rate;
  const CircularTowSolution b = SolveCircularTow(p, 4000, 20);
  EXPECT_NEAR(b.sphere_position.x(), a.sphere_position.x(), 1e-9);
  EXPECT_NEAR(b.sphere_position.y(), -a.sphere_position.y(), 1e-9);
  EXPECT_NEAR(b.sphere_position.z(), a.sphere_position.z(), 1e-9);
  EXPECT_NEAR(b.top_tension, a.top_tension, 1e-8);
  EXPECT_NEAR(b.layback, a.layback, 1e-9);
  EXPECT_GT(a.sphere_position.y(), -300.0);
  EXPECT_LT(a.sphere_position.y(), 0.0);  // starboard: the tow point moves along +y, the sphere
                                          // trails at y < 0
}

// RK4 convergence by halving: the answer at 10000 and 20000 steps
TEST(CircularTow, ConvergedInSteps) {
  const CircularTowSolution a = SolveCircularTow(Turn(300.0, 6.0), 10000, 20);
  const CircularTowSolution b = SolveCircularTow(Turn(300.0, 6.0), 20000, 20);
  constexpr double kConvergedRel = 1e-9;
  EXPECT_NEAR(a.sphere_radius, b.sphere_radius, kConvergedRel * b.sphere_radius);
  EXPECT_NEAR(a.depth, b.depth, kConvergedRel * b.depth);
  EXPECT_NEAR(a.top_tension, b.top_tension, kConvergedRel * b.top_tension);
}

// the inertia loads matter at a tight turn: without them the sphere sits further inside (the
// centrifugal d'Alembert forces push the cable and sphere outward)
TEST(CircularTow, InertiaPushesOutward) {
  CircularTowProblem p = Turn(300.0, 6.0);
  const CircularTowSolution with = SolveCircularTow(p, 4000, 20);
  p.inertia = false;
  const CircularTowSolution without = SolveCircularTow(p, 4000, 20);
  EXPECT_GT(with.sphere_radius, without.sphere_radius);
  std::printf("R = 300 m, 6 m/s: sphere radius %.4f m with inertia, %.4f m without\n",
              with.sphere_radius, without.sphere_radius);
}

TEST(CircularTow, RefusesBadInput) {
  CircularTowProblem p = Turn(300.0, 6.0);
  p.turn_rate = 0.0;
  try {
    SolveCircularTow(p);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("turn_rate = 0"), std::string::npos) << e.what();
  }
  p = Turn(300.0, 6.0);
  p.radius = -1.0;
  EXPECT_THROW(SolveCircularTow(p), std::invalid_argument);
  p = Turn(300.0, 6.0);
  p.line.current = Eigen::Vector3d(0.5, 0.0, 0.0);
  EXPECT_THROW(SolveCircularTow(p), std::invalid_argument);
}

}  // namespace
}  // namespace towsim::reference
