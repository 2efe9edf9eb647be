// The core's transverse dynamics, held to the taut string: f1 = sqrt(T / mu) / (2 ell)
// (taut_string.h).
//
// L = 10 m unstretched between pins 10.1 m apart (straight initial shape, uniform Green strain
// 0.01005), no weight, buoyancy, drag, added mass or bending. EA = 1e4 N and rho A = 0.1 kg/m
// give T = 101.505 N and f1 = 1.585087 Hz. The string is set moving with a small half-sine
// transverse velocity through StartFrom, and the frequency is read from the zero crossings of
// the middle node's transverse displacement over 5 periods (trapezoidal rule, h = 1e-3 s).

#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "signal_analysis.h"
#include "taut_string.h"
#include "taut_string_model.h"

namespace towsim::reference {
namespace {

// the straight stretched string carries exactly the reference tension: a uniform strain is
// represented exactly by the elements, so only the solver tolerance (1e-8) limits it
TEST(TautStringCore, PreTension) {
  const core::Simulation sim(String(1));
  const double t_ref = TautStringTension(StringReference());
  constexpr double kTensionRelTol = 1e-6;
  EXPECT_NEAR(sim.end_force(0).norm(), t_ref, kTensionRelTol * t_ref);
  EXPECT_NEAR(sim.end_force(0).x(), t_ref, kTensionRelTol * t_ref);  // pulls the pin inwards
  EXPECT_NEAR(sim.end_force(1).x(), -t_ref, kTensionRelTol * t_ref);
}

TEST(TautStringCore, FirstFrequency) {
  const double f_ref = TautStringFirstFrequency(StringReference());
  core::Simulation sim(String(1));
  const int nodes = sim.num_nodes();
  const int mid = (nodes - 1) / 2;

  // amplitude v0 / omega = 1 mm, so the tension change (pi A / ell)^2 / 4 / eps ~ 2.5e-6
  StartHalfSine(&sim, f_ref);

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
