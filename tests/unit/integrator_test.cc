#include "core/integrator.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/initial_shape.h"
#include "core/simulation.h"
#include "core/state.h"
#include "core/system.h"
#include "steady_tow_model.h"

namespace towsim::core {
namespace {

TEST(AlphaParameters, TrapezoidalAtRhoOneAndSecondOrderConditions) {
  IntegratorSettings s;
  s.rho_inf = 1.0;
  AlphaParameters p = AlphaParameters::FromSettings(s);
  EXPECT_DOUBLE_EQ(p.gamma, 0.5);
  EXPECT_DOUBLE_EQ(p.beta, 0.25);
  for (double rho : {0.0, 0.3, 0.8}) {
    s.rho_inf = rho;
    p = AlphaParameters::FromSettings(s);
    // Chung & Hulbert: gamma = 1/2 - alpha_m + alpha_f for second order
    EXPECT_NEAR(p.gamma, 0.5 - p.alpha_m + p.alpha_f, 1e-15);
    EXPECT_NEAR(p.beta, 0.25 * (1 - p.alpha_m + p.alpha_f) * (1 - p.alpha_m + p.alpha_f), 1e-15);
  }
}

// A cable hanging from a fixed point with a heavy sphere, released from rest at the static
// shape, must stay there; a sphere sinking on its own reaches the terminal speed
// v = sqrt(2 (m - rho V) g / (rho C_D pi r^2)).
TEST(Integrator, SphereReachesItsTerminalSpeed) {
  Model m;
  m.cable.length = 10;
  m.cable.elements = 2;
  m.cable.start.kind = EndKind::kFixed;
  m.cable.end.kind = EndKind::kFree;
  SphereBody b;
  b.name = "ball";
  b.mass = 100;
  b.volume = 0.05;
  b.drag_coefficient = 0.5;
  b.position = Vec3(5, 0, 0);
  m.bodies.push_back(b);
  m.time.step = 0.05;
  Simulation sim(m);
  for (int k = 0; k < 1200; ++k) ASSERT_TRUE(sim.Step().ok());
  const double rho = 1025, g = 9.81, pi = 3.14159265358979323846;
  const double r = std::cbrt(3 * b.volume / (4 * pi));
  const double v = std::sqrt(2 * (b.mass - rho * b.volume) * g / (rho * 0.5 * pi * r * r));
  constexpr double kTerminalRelTol = 1e-6;  // 60 s >> the e-folding time of ~0.5 s
  EXPECT_NEAR(sim.body_velocity(0).z(), v, kTerminalRelTol * v);
}

TEST(Integrator, FailedNewtonEndsWithADiagnosis) {
  Model m;
  m.cable.length = 100;
  m.cable.elements = 10;
  m.cable.start.kind = EndKind::kDriven;
  m.cable.start.velocity = Vec3(5, 0, 0);
  m.cable.end.kind = EndKind::kFree;
  m.cable.initial_velocity = Vec3::Zero();  // the top jerks to 5 m/s: Newton must work
  m.integrator.max_iterations = 1;
  m.integrator.max_substep_level = 2;
  m.integrator.tolerance = 1e-14;
  Simulation sim(m);
  const StepStatus s = sim.Step();
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.code, StepStatus::kNotConverged);
  EXPECT_NE(s.message.find("Newton did not converge"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("cable node"), std::string::npos) << s.message;
  EXPECT_NE(s.message.find("t = 0"), std::string::npos) << s.message;
}

TEST(Integrator, SubsteppingRescuesAHardStep) {
  Model m;
  m.cable.length = 100;
  m.cable.elements = 10;
  m.cable.start.kind = EndKind::kDriven;
  m.cable.start.velocity = Vec3(5, 0, 0);
  m.cable.end.kind = EndKind::kFree;
  m.time.step = 1.0;  // a large step from a jerk start
  m.integrator.max_iterations = 4;
  m.integrator.max_substep_level = 8;
  Simulation sim(m);
  const StepStatus s = sim.Step();
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_GT(s.substeps, 1);
  EXPECT_NEAR(sim.time(), 1.0, 1e-12);
  EXPECT_NEAR(sim.node_position(0).x(), 5.0, 1e-6);
}

// Modified Newton (issue 7): the factored Newton matrix is kept across steps, and the states it
// accepts agree with a run converged far tighter. The steady tow from vertical (the towing
// point jerks to 6 m/s, the cable swings back) over its first 10 s, 20 elements, h = 0.05 s.
Model SteadyTowFromVertical(double tolerance) {
  Model m = test::SteadyTowModel();
  m.integrator.tolerance = tolerance;
  return m;
}

TEST(Integrator, KeepsTheNewtonMatrixAndConvergesToTheTolerance) {
  constexpr int kSteps = 200;
  State states[2];
  long refreshes[2] = {0, 0};
  const double tolerances[2] = {1e-8, 1e-12};
  for (int k = 0; k < 2; ++k) {
    const Model m = SteadyTowFromVertical(tolerances[k]);
    const System system(m);
    Integrator integrator(system);
    State& s = states[k];
    BuildInitialState(system, &s);
    ASSERT_TRUE(integrator.InitializeAcceleration(&s));
    for (int i = 0; i < kSteps; ++i) ASSERT_TRUE(integrator.Step(&s, m.time.step).ok()) << i;
    refreshes[k] = integrator.tangent_refreshes();
  }
  std::printf("Newton matrices factored in %d steps: %ld (tolerance 1e-8), %ld (1e-12)\n", kSteps,
              refreshes[0], refreshes[1]);
  // the matrix is kept for most steps (classic Newton would factor at every iteration)
  EXPECT_LT(refreshes[0], kSteps / 4);
  // every accepted state is within tolerance x L of the converged one (error estimate
  // theta / (1 - theta) |dq| <= tol L); the differences propagate through the damped scheme
  // but do not grow: 10 x tol x L bounds them over the run
  constexpr double kAgreement = 10 * 1e-8 * 200.0;  // [m]
  const double diff = (states[0].q - states[1].q).lpNorm<Eigen::Infinity>();
  std::printf("largest coordinate difference after %d steps: %.3g m\n", kSteps, diff);
  EXPECT_LT(diff, kAgreement);
}

}  // namespace
}  // namespace towsim::core
