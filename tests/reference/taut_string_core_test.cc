// The core's transverse dynamics, held to the taut string: f1 = sqrt(T / mu) / (2 ell)
// (taut_string.h).
//
// L = 10 m unstretched between pins 10.1 m apart (straight initial shape, uniform Green strain
// 0.01005), no weight, buoyancy, drag, added mass or bending. EA = 1e4 N and rho A = 0.1 kg/m
// give T = 101.505 N and f1 = 1.585087 Hz. The string is set moving with a small half-sine
// transverse velocity through StartFrom, and the frequency is read from the zero crossings of
// the middle node's transverse displacement over 5 periods (trapezoidal rule, h = 1e-3 s).

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"
#include "core/simulation.h"
#include "core/state.h"
#include "signal_analysis.h"
#include "taut_string.h"

namespace towsim::reference {
namespace {

using core::Vec3;

using core::kPi;
constexpr double kLength = 10.0;  // unstretched L [m]
constexpr double kSpan = 10.1;    // ell [m]
constexpr double kDiameter = 0.01;
constexpr double kEA = 1.0e4;  // [N]
constexpr double kRhoA = 0.1;  // [kg/m]

core::Model String() {
  core::Model m;
  m.name = "taut_string";
  core::CableParams& c = m.cables[0];
  c.length = kLength;
  c.elements = 10;
  c.diameter = kDiameter;
  c.SetSolidSection(kRhoA / c.area(), kEA / c.area());
  c.loads = {false, false, false, false, false};
  c.initial = core::InitialShape::kStraight;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.end.kind = core::EndKind::kFixed;
  c.end.position = Vec3(kSpan, 0.0, 0.0);
  m.integrator.scheme = core::Scheme::kTrapezoidal;
  m.integrator.rho_inf = 1.0;
  m.time.step = 1e-3;
  return m;
}

TautString Reference() {
  TautString s;
  s.length = kLength;
  s.span = kSpan;
  s.ea = kEA;
  s.rho_a = kRhoA;
  return s;
}

// the straight stretched string carries exactly the reference tension: a uniform strain is
// represented exactly by the elements, so only the solver tolerance (1e-8) limits it
TEST(TautStringCore, PreTension) {
  const core::Simulation sim(String());
  const double t_ref = TautStringTension(Reference());
  constexpr double kTensionRelTol = 1e-6;
  EXPECT_NEAR(sim.end_force(0).norm(), t_ref, kTensionRelTol * t_ref);
  EXPECT_NEAR(sim.end_force(0).x(), t_ref, kTensionRelTol * t_ref);  // pulls the pin inwards
  EXPECT_NEAR(sim.end_force(1).x(), -t_ref, kTensionRelTol * t_ref);
}

TEST(TautStringCore, FirstFrequency) {
  const double f_ref = TautStringFirstFrequency(Reference());
  core::Simulation sim(String());
  const int nodes = sim.num_nodes();
  const int mid = (nodes - 1) / 2;

  // r_dot = v0 sin(pi X / L) e_z and, consistently, r'_dot = d r_dot / dX
  // = v0 (pi / L) cos(pi X / L) e_z at every node (X = unstretched coordinate);
  // amplitude v0 / omega = 1 mm, so the tension change (pi A / ell)^2 / 4 / eps ~ 2.5e-6
  const double omega = 2.0 * kPi * f_ref;
  const double v0 = 1e-3 * omega;
  core::State s = sim.state();
  for (int i = 0; i < nodes; ++i) {
    const double x = kLength * i / (nodes - 1);
    const int k = sim.cable_dof(i);
    s.v.segment<3>(k) = v0 * std::sin(kPi * x / kLength) * Vec3::UnitZ();
    s.v.segment<3>(k + 3) = v0 * (kPi / kLength) * std::cos(kPi * x / kLength) * Vec3::UnitZ();
  }
  sim.StartFrom(s);

  std::vector<double> t = {sim.time()};
  std::vector<double> z = {sim.node_position(mid).z()};
  const double t_end = 5.2 / f_ref;  // a bit over 5 periods: 10 crossings after t = 0
  while (sim.time() < t_end) {
    const core::StepStatus st = sim.Step();
    ASSERT_TRUE(st.ok()) << st.message;
    t.push_back(sim.time());
    z.push_back(sim.node_position(mid).z());
  }
  const std::vector<double> crossings = ZeroCrossings(t, z);
  ASSERT_GE(crossings.size(), 8u);
  const double f = FrequencyFromCrossings(crossings);
  // trapezoidal period error (omega h)^2 / 12 ~ 8e-6, 10-element string ~1e-5; the issue asks
  // for 1%
  constexpr double kFreqRelTol = 1e-2;
  std::printf("taut string: f1 %.6f Hz (ref %.6f, %+.2e) from %zu crossings\n", f, f_ref,
              f / f_ref - 1.0, crossings.size());
  EXPECT_NEAR(f, f_ref, kFreqRelTol * f_ref);
}

}  // namespace
}  // namespace towsim::reference
