// Self-checks of the steady towed-cable reference (towed_cable_steady.h).

#include "towed_cable_steady.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "elastic_catenary.h"

namespace towsim::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

// the paper's system at 6 m/s (the shipped steady_tow scene)
TowedCableProblem PaperTow() { return TowedCableProblem{}; }

// sphere force by hand: r = (3 * 0.2 / 4 pi)^(1/3) = 0.362783 m, pi r^2 = 0.413470 m^2,
// drag = 0.5 * 1025 * 0.5 * 0.413470 * 36 = 3814.26 N, net weight (416 - 205) 9.81 = 2069.91 N
TEST(TowedCableSteady, SphereForceHandValues) {
  const Eigen::Vector3d f = SphereExternalForce(PaperTow());
  EXPECT_NEAR(f.x(), -3814.26, 0.01);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
  EXPECT_NEAR(f.z(), 2069.91, 0.01);
}

// no cable loads: the cable is a straight line along the sphere's pull, stretched by
// lambda(T) (Hooke): layback / depth = drag / net weight, length L (1 + T/EA)
TEST(TowedCableSteady, UnloadedCableIsStraight) {
  TowedCableProblem p = PaperTow();
  p.cable_drag = false;
  p.cable_weight = false;
  p.stretch_law = StretchLaw::kHooke;
  const TowedCableSolution s = SolveTowedCableSteady(p, 200, 20);
  const Eigen::Vector3d f = -SphereExternalForce(p);
  const double ea = p.youngs_modulus * 0.25 * kPi * p.diameter * p.diameter;
  const double stretched = p.length * (1.0 + f.norm() / ea);
  EXPECT_NEAR(s.layback, stretched * f.x() / f.norm(), 1e-9);
  EXPECT_NEAR(s.depth, -stretched * f.z() / f.norm(), 1e-9);
  EXPECT_NEAR(s.top_tension, f.norm(), 1e-9);
}

// weight but no cable drag: an elastic catenary hanging from the tow point with the sphere's
// pull at its lower end; Irvine's closed form (elastic_catenary.h) with A = the sphere,
// H = sphere drag, V_A = -(sphere net weight) must give the same top point
TEST(TowedCableSteady, WeightOnlyIsElasticCatenary) {
  TowedCableProblem p = PaperTow();
  p.cable_drag = false;
  p.stretch_law = StretchLaw::kHooke;
  const TowedCableSolution s = SolveTowedCableSteady(p, 2000, 20);
  const Eigen::Vector3d f_sphere = SphereExternalForce(p);
  CatenaryProblem c;
  c.length = p.length;
  c.weight = (p.density - p.fluid.density) * 0.25 * kPi * p.diameter * p.diameter * p.gravity;
  c.ea = p.youngs_modulus * 0.25 * kPi * p.diameter * p.diameter;
  const CatenaryPoint top = CatenaryShape(c, -f_sphere.x(), -f_sphere.z(), p.length);
  constexpr double kRk4Tol = 1e-8;  // [m], RK4 with 2000 steps on a smooth solution
  EXPECT_NEAR(s.layback, top.x, kRk4Tol);
  EXPECT_NEAR(s.depth, top.y, kRk4Tol);
  EXPECT_NEAR(s.top_tension, top.tension, 1e-7);
}

// a long cable approaches the critical angle phi_c, where the normal drag balances the
// normal component of the weight: w cos(phi) = 1/2 rho d C_Dn(Re_n) V^2 sin^2(phi)
// (tangential drag changes T but not the angle of a straight cable). Inextensible (E huge).
TEST(TowedCableSteady, LongCableReachesCriticalAngle) {
  TowedCableProblem p = PaperTow();
  p.length = 3000.0;
  p.youngs_modulus = 1e20;
  const TowedCableSolution s = SolveTowedCableSteady(p, 60000, 300);
  const Eigen::Vector3d d = s.shape.back().r - s.shape[s.shape.size() - 2].r;
  const double phi_top = std::atan2(-d.z(), d.x());
  const double w = (p.density - p.fluid.density) * 0.25 * kPi * p.diameter * p.diameter * p.gravity;
  const double v = p.tow_velocity.norm();
  auto balance = [&](double phi) {
    const double vn = v * std::sin(phi);
    const double re = p.fluid.density * vn * p.diameter / p.fluid.dynamic_viscosity;
    return 0.5 * p.fluid.density * p.diameter * NormalDragCoefficient(re) * vn * vn -
           w * std::cos(phi);
  };
  double lo = 1e-6;
  double hi = 0.5 * kPi;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (balance(mid) > 0.0 ? hi : lo) = mid;
  }
  const double phi_c = 0.5 * (lo + hi);
  // the approach is exponential in s; after 3000 m the remaining difference is round-off
  constexpr double kAngleTol = 1e-6;  // [rad]
  EXPECT_NEAR(phi_top, phi_c, kAngleTol) << "phi_c = " << phi_c;
}

// the same with constant coefficients (a line type's drag): the critical angle in closed form
// (Pode 1951), w cos(phi) = 1/2 rho d C_n V^2 sin^2(phi), a quadratic in c = cos(phi):
//   q c^2 + w c - q = 0,  q = 1/2 rho d C_n V^2,  c = (sqrt(w^2 + 4 q^2) - w) / (2 q)
TEST(TowedCableSteady, ConstantCoefficientsReachPodesCriticalAngle) {
  TowedCableProblem p = PaperTow();
  p.length = 3000.0;
  p.youngs_modulus = 1e20;
  p.drag_coefficients = ConstantDragCoefficients{1.5, 0.01};
  const TowedCableSolution s = SolveTowedCableSteady(p, 60000, 300);
  const Eigen::Vector3d d = s.shape.back().r - s.shape[s.shape.size() - 2].r;
  const double phi_top = std::atan2(-d.z(), d.x());
  const double w = (p.density - p.fluid.density) * 0.25 * kPi * p.diameter * p.diameter * p.gravity;
  const double v = p.tow_velocity.norm();
  const double q = 0.5 * p.fluid.density * p.diameter * 1.5 * v * v;
  const double phi_c = std::acos((std::sqrt(w * w + 4.0 * q * q) - w) / (2.0 * q));
  constexpr double kAngleTol = 1e-6;  // [rad], as with Choo & Casarella's law above
  EXPECT_NEAR(phi_top, phi_c, kAngleTol) << "phi_c = " << phi_c;
  // the shipped cable at 6 m/s: w = 3.5617 N/m, q = 1134.7 N/m: phi_c = 3.209 deg
  EXPECT_NEAR(phi_c * 180.0 / kPi, 3.209, 1e-3);
}

// RK4 convergence by halving: the paper tow at 5000 and 10000 steps
TEST(TowedCableSteady, ConvergedInSteps) {
  const TowedCableSolution a = SolveTowedCableSteady(PaperTow(), 5000, 20);
  const TowedCableSolution b = SolveTowedCableSteady(PaperTow(), 10000, 20);
  const TowedCableSolution c = SolveTowedCableSteady(PaperTow(), 20000, 20);
  constexpr double kConvergedRel = 1e-9;  // far below the 1% the core is held to
  EXPECT_NEAR(b.layback, c.layback, kConvergedRel * c.layback);
  EXPECT_NEAR(b.depth, c.depth, kConvergedRel * c.depth);
  EXPECT_NEAR(b.top_tension, c.top_tension, kConvergedRel * c.top_tension);
  // and the error falls at order 4 (a factor ~16 per halving) unless already at round-off
  const double e_ab = std::abs(a.depth - b.depth);
  const double e_bc = std::abs(b.depth - c.depth);
  std::printf("RK4 depth change 5000->10000 steps %.3e m, 10000->20000 %.3e m\n", e_ab, e_bc);
  std::printf(
      "paper tow 6 m/s: layback %.6f m, depth %.6f m, top tension %.4f N, "
      "bottom tension %.4f N\n",
      c.layback, c.depth, c.top_tension, c.bottom_tension);
}

// Green (the core's law) vs Hooke stretch: a second-order difference, ~1.5 (T/EA)^2
TEST(TowedCableSteady, StretchLawDifferenceIsSecondOrder) {
  TowedCableProblem p = PaperTow();
  const TowedCableSolution green = SolveTowedCableSteady(p);
  p.stretch_law = StretchLaw::kHooke;
  const TowedCableSolution hooke = SolveTowedCableSteady(p);
  const double ea = p.youngs_modulus * 0.25 * kPi * p.diameter * p.diameter;
  const double e = green.top_tension / ea;
  const double bound = 1.5 * e * e;  // relative, at the largest tension
  EXPECT_LT(std::abs(green.layback / hooke.layback - 1.0), bound);
  EXPECT_LT(std::abs(green.depth / hooke.depth - 1.0), 10.0 * bound);
  std::printf(
      "stretch law: Green vs Hooke layback %.3e, depth %.3e, tension %.3e "
      "(relative; 1.5 e_max^2 = %.3e)\n",
      green.layback / hooke.layback - 1.0, green.depth / hooke.depth - 1.0,
      green.top_tension / hooke.top_tension - 1.0, bound);
}

// towing along y gives the same answer, rotated (no hidden x-axis assumption)
TEST(TowedCableSteady, RotationInvariant) {
  TowedCableProblem p = PaperTow();
  const TowedCableSolution x = SolveTowedCableSteady(p, 2000, 20);
  p.tow_velocity = {0.0, 6.0, 0.0};
  const TowedCableSolution y = SolveTowedCableSteady(p, 2000, 20);
  EXPECT_NEAR(y.top_minus_sphere.y(), x.top_minus_sphere.x(), 1e-9);
  EXPECT_NEAR(y.depth, x.depth, 1e-9);
  EXPECT_NEAR(y.top_tension, x.top_tension, 1e-8);
}

}  // namespace
}  // namespace towsim::reference

namespace towsim::reference {
namespace {

// a profile that is the same at every depth is the uniform current: the shooting finds the
// sphere's depth and the shape is the uniform reference's, to round-off
TEST(TowedCableSteadyProfile, UniformProfileIsTheUniformReference) {
  TowedCableProblem uniform;
  uniform.current = Eigen::Vector3d(-0.8, 0.3, 0.0);
  const TowedCableSolution a = SolveTowedCableSteady(uniform, 4000, 20);
  TowedCableProblem profiled = uniform;
  profiled.current_profile = [](double) { return Eigen::Vector3d(-0.8, 0.3, 0.0); };
  profiled.tow_depth = 3.5;
  const TowedCableSolution b = SolveTowedCableSteady(profiled, 4000, 20);
  constexpr double kRoundOffRel = 1e-12;  // the same RK4 arithmetic, other call path
  EXPECT_NEAR(b.layback, a.layback, kRoundOffRel * a.layback);
  EXPECT_NEAR(b.depth, a.depth, kRoundOffRel * a.depth);
  EXPECT_NEAR(b.top_tension, a.top_tension, kRoundOffRel * a.top_tension);
  EXPECT_NEAR(b.top_minus_sphere.y(), a.top_minus_sphere.y(), 1e-9);
  EXPECT_NEAR(b.sphere_z, 3.5 + a.depth, 1e-9);
  EXPECT_GE(b.shooting_iterations, 1);
}

// water moving with the tow point at every depth: no relative flow, so the cable hangs
// straight down from the tow point, T(s) = W_sphere + w s, and (Hooke) its length is
// L + (W_sphere L + w L^2 / 2) / EA
TEST(TowedCableSteadyProfile, WaterMovingWithTheTowHangsTheCableStraight) {
  TowedCableProblem p;
  p.stretch_law = StretchLaw::kHooke;
  p.current_profile = [u = p.tow_velocity](double z) {
    return Eigen::Vector3d(u.x(), u.y(), u.z() + 0.0 * z);
  };
  p.tow_depth = 3.5;
  const TowedCableSolution s = SolveTowedCableSteady(p, 2000, 20);
  const double area = 0.25 * kPi * p.diameter * p.diameter;
  const double w = (p.density - p.fluid.density) * area * p.gravity;
  const double ws = (p.sphere_mass - p.fluid.density * p.sphere_volume) * p.gravity;
  const double ea = p.youngs_modulus * area;
  EXPECT_NEAR(s.layback, 0.0, 1e-9);
  EXPECT_NEAR(s.depth, p.length + (ws * p.length + 0.5 * w * p.length * p.length) / ea, 1e-8);
  EXPECT_NEAR(s.top_tension, ws + w * p.length, 1e-7);
}

// a sheared current (a 1/7 power law of 1 m/s against the tow, zero at 30 m): RK4 converges at
// order 4 and the tow lies between the uniform tows in the profile's extreme values
TEST(TowedCableSteadyProfile, ShearedCurrentConvergesAndLiesBetweenItsExtremes) {
  const auto profile = [](double z) {
    const double f = z <= 0.0 ? 1.0 : (z >= 30.0 ? 0.0 : std::pow(1.0 - z / 30.0, 1.0 / 7.0));
    return Eigen::Vector3d(-1.0 * f, 0.0, 0.0);
  };
  TowedCableProblem p;
  p.current_profile = profile;
  p.tow_depth = 3.5;
  const TowedCableSolution a = SolveTowedCableSteady(p, 5000, 20);
  const TowedCableSolution b = SolveTowedCableSteady(p, 10000, 20);
  constexpr double kConvergedRel = 1e-9;
  EXPECT_NEAR(a.depth, b.depth, kConvergedRel * b.depth);
  EXPECT_NEAR(a.layback, b.layback, kConvergedRel * b.layback);
  TowedCableProblem slow, fast;
  slow.current = profile(b.sphere_z);   // the weakest current along the cable (at the sphere)
  fast.current = profile(p.tow_depth);  // the strongest (at the tow point)
  const TowedCableSolution s_slow = SolveTowedCableSteady(slow, 5000, 20);
  const TowedCableSolution s_fast = SolveTowedCableSteady(fast, 5000, 20);
  // a stronger opposing current: more drag, more layback, less depth, more tension
  EXPECT_GT(b.layback, s_slow.layback);
  EXPECT_LT(b.layback, s_fast.layback);
  EXPECT_LT(b.depth, s_slow.depth);
  EXPECT_GT(b.depth, s_fast.depth);
  EXPECT_GT(b.top_tension, s_slow.top_tension);
  EXPECT_LT(b.top_tension, s_fast.top_tension);
  std::printf(
      "power-law current 1 m/s against a 6 m/s tow: layback %.4f m, depth %.4f m, "
      "top tension %.2f N (uniform at the sphere's %.3f m/s: %.4f / %.4f / %.2f; at the "
      "tow point's 1 m/s: %.4f / %.4f / %.2f), %d secant iterations\n",
      b.layback, b.depth, b.top_tension, -slow.current.x(), s_slow.layback, s_slow.depth,
      s_slow.top_tension, s_fast.layback, s_fast.depth, s_fast.top_tension, b.shooting_iterations);
}

}  // namespace
}  // namespace towsim::reference
