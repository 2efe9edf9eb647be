#include "core/integrator.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/constants.h"
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
  m.cables[0].length = 10;
  m.cables[0].elements = 2;
  m.cables[0].start.kind = EndKind::kFixed;
  m.cables[0].end.kind = EndKind::kFree;
  SphereBody b;
  b.name = "ball";
  b.mass = 100;
  b.volume = 0.05;
  b.drag_coefficient = 0.5;
  b.position = Vec3(5, 0, 0);
  m.spheres.push_back(b);
  m.time.step = 0.05;
  Simulation sim(m);
  for (int k = 0; k < 1200; ++k) ASSERT_TRUE(sim.Step().ok());
  const double rho = 1025, g = 9.81, pi = kPi;
  const double r = std::cbrt(3 * b.volume / (4 * pi));
  const double v = std::sqrt(2 * (b.mass - rho * b.volume) * g / (rho * 0.5 * pi * r * r));
  constexpr double kTerminalRelTol = 1e-6;  // 60 s >> the e-folding time of ~0.5 s
  EXPECT_NEAR(sim.body_velocity(0).z(), v, kTerminalRelTol * v);
}

TEST(Integrator, FailedNewtonEndsWithADiagnosis) {
  Model m;
  m.cables[0].length = 100;
  m.cables[0].elements = 10;
  m.cables[0].start.kind = EndKind::kDriven;
  m.cables[0].start.velocity = Vec3(5, 0, 0);
  m.cables[0].end.kind = EndKind::kFree;
  m.cables[0].initial_velocity = Vec3::Zero();  // the top jerks to 5 m/s: Newton must work
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
  m.cables[0].length = 100;
  m.cables[0].elements = 10;
  m.cables[0].start.kind = EndKind::kDriven;
  m.cables[0].start.velocity = Vec3(5, 0, 0);
  m.cables[0].end.kind = EndKind::kFree;
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

// Modified Newton: the factored Newton matrix is kept across steps, and the states it
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
    StepInputs inputs;
    Integrator integrator(system, &inputs);
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

// The kept matrix's age (core/integrator.h, docs/benchmarks.md): the steady tow from vertical
// after 100 s, where its steps converge in one iteration with a matrix of small rate. The
// state after kSettle steps, its kept matrix rebuilt in `integrator`.
constexpr int kSettle = 2000;

State SettledSteadyTow(const System& system, Integrator* integrator) {
  State s;
  BuildInitialState(system, &s);
  EXPECT_TRUE(integrator->InitializeAcceleration(&s));
  for (int i = 0; i < kSettle; ++i) EXPECT_TRUE(integrator->Step(&s, 0.05).ok()) << i;
  return s;
}

// one step from `start` with its kept matrix's rate measured `age` steps before the step (the
// step counts one more); a velocity kick of `kick` [m/s] at a mid-cable node makes the first
// increment fail the acceptance test. Returns the step's status; *refreshes the Newton
// matrices it factored, *out the state after it
StepStatus StepAged(const System& system, const State& start, int age, double kick, long* refreshes,
                    State* out) {
  StepInputs inputs;
  Integrator integrator(system, &inputs);
  *out = start;
  EXPECT_TRUE(integrator.RestoreNewtonMatrix(*out));
  out->newton.theta_age = age;
  out->v(system.CableDof(10)) += kick;
  const StepStatus st = integrator.Step(out, 0.05);
  *refreshes = integrator.tangent_refreshes();
  return st;
}

TEST(Integrator, ReplacesAMatrixOfUnknownRateForTheSecondEvaluation) {
  const Model m = SteadyTowFromVertical(1e-8);
  const System system(m);
  StepInputs inputs;
  Integrator integrator(system, &inputs);
  const State settled = SettledSteadyTow(system, &integrator);
  ASSERT_TRUE(settled.newton.valid);
  ASSERT_LT(settled.newton.theta, Integrator::kRefreshRate);  // kept at the next step
  // 1 mm/s at node 10: about 0.05 s x 1e-3 m/s = 5e-5 m = 25 tol of first increment
  constexpr double kKick = 1e-3;
  long refreshes[2];
  State after[2];
  // measured kMaxKeepAge steps before this step's first evaluation: kept for the second
  const StepStatus young =
      StepAged(system, settled, Integrator::kMaxKeepAge - 1, kKick, &refreshes[0], &after[0]);
  // one step more: replaced for the second evaluation, which then converges (quadratically)
  const StepStatus old =
      StepAged(system, settled, Integrator::kMaxKeepAge, kKick, &refreshes[1], &after[1]);
  std::printf(
      "kicked step, rate measured %d / %d steps before: %d / %d iterations, %ld / %ld "
      "matrices factored\n",
      Integrator::kMaxKeepAge, Integrator::kMaxKeepAge + 1, young.iterations, old.iterations,
      refreshes[0], refreshes[1]);
  ASSERT_TRUE(young.ok());
  ASSERT_TRUE(old.ok());
  EXPECT_GE(young.iterations, 2);  // the first increment was not accepted
  EXPECT_EQ(refreshes[0], 0);
  EXPECT_EQ(old.iterations, 2);
  EXPECT_EQ(refreshes[1], 1);
  // both accepted states are within the error estimate's tolerance x L of the solution
  constexpr double kAgreement = 2 * 1e-8 * 200.0;  // [m]
  EXPECT_LT((after[0].q - after[1].q).lpNorm<Eigen::Infinity>(), kAgreement);
}

TEST(Integrator, ReMeasuresASmallRateLessOften) {
  const Model m = SteadyTowFromVertical(1e-8);
  const System system(m);
  StepInputs inputs;
  Integrator integrator(system, &inputs);
  const State settled = SettledSteadyTow(system, &integrator);
  long refreshes = 0;
  State after;
  // the rate measured kMaxThetaAge steps ago, no re-measurement yet: accepted on it
  StepStatus st = StepAged(system, settled, Integrator::kMaxThetaAge - 1, 0.0, &refreshes, &after);
  ASSERT_TRUE(st.ok());
  EXPECT_EQ(st.iterations, 1);
  // one step more: re-measured (a second iteration), and found small
  State fresh = settled;
  fresh.newton.theta_steady = false;
  st = StepAged(system, fresh, Integrator::kMaxThetaAge, 0.0, &refreshes, &after);
  ASSERT_TRUE(st.ok());
  EXPECT_EQ(st.iterations, 2);
  EXPECT_EQ(refreshes, 0);
  std::printf("re-measured rate %.3g (steady below %.2g)\n", after.newton.theta,
              Integrator::kSteadyRate);
  ASSERT_LT(after.newton.theta, Integrator::kSteadyRate);
  EXPECT_TRUE(after.newton.theta_steady);
  EXPECT_EQ(after.newton.theta_age, 0);
  // after that the interval is kMaxThetaAgeSteady: the same age is accepted on the rate ...
  State steady = after;
  st = StepAged(system, steady, Integrator::kMaxThetaAge, 0.0, &refreshes, &after);
  ASSERT_TRUE(st.ok());
  EXPECT_EQ(st.iterations, 1);
  // ... until kMaxThetaAgeSteady steps have passed
  st = StepAged(system, steady, Integrator::kMaxThetaAgeSteady, 0.0, &refreshes, &after);
  ASSERT_TRUE(st.ok());
  EXPECT_EQ(st.iterations, 2);
}

}  // namespace
}  // namespace towsim::core
