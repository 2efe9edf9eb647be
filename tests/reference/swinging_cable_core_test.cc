// A cable swinging in vacuum: energy conservation of the trapezoidal rule, dissipation of
// generalized-alpha, and the measured order of time convergence.
//
// L = 10 m, d = 0.01 m, rho = 2000 kg/m^3 (rho A = 0.157 kg/m, weight 15.4 N), E = 1e8 Pa
// (EA = 7854 N: strains below 1%, first axial mode ~35 rad/s), 10 elements. Pinned (not
// clamped) at the origin, free end; loads: gravity and bending only. Released from rest,
// straight and horizontal along +x. The core builds a free-ended cable hanging vertically
// whatever the requested shape (initial_shape.cc: a free end has no position to aim at), so
// the horizontal start is set with StartFrom: r_i = (X_i, 0, 0), r'_i = (1, 0, 0), v = 0.
//
// The energy scale is the potential-energy swing from horizontal to hanging,
// dPE = rho A g L^2 / 2 = 77.0 J.
//
// The motion is violent: the free end whips through at up to ~45 m/s and the strain energy
// reaches ~20% of dPE, i.e. high axial modes are strongly excited. The highest axial frequency
// of the 10-element mesh is about 2 sqrt(15) c / l_e = 1.7e3 rad/s (c = sqrt(E / rho) =
// 224 m/s, l_e = 1 m), so steps must satisfy omega_max h <~ 1 for the time error to be in its
// asymptotic regime; the step sizes below are chosen for that (measured numbers in each test).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "core/state.h"
#include "signal_analysis.h"
#include "swinging_cable_model.h"

namespace towsim::reference {
namespace {

using core::Vec3;

double PotentialSwing(const core::Model& m) {
  const core::CableParams& c = m.cables[0];
  return c.mass_per_length * m.environment.gravity * c.length * c.length / 2.0;
}

// the simulation, released from rest straight along +x
core::Simulation Released(const core::Model& m) {
  core::Simulation sim(m);
  ReleaseStraight(&sim);
  return sim;
}

double Energy(const core::Simulation& sim) {
  return sim.KineticEnergy() + sim.PotentialEnergy() + sim.StrainEnergy();
}

// The trapezoidal rule conserves the energy of linear systems exactly; on this nonlinear,
// whipping cable its energy error is a truncation error. Measured max |E - E0| over 20 s
// (fraction of dPE): h 1e-3: 2.7e-2, 5e-4: ~1e-2, 2.5e-4: ~4e-3, 1.25e-4: 7.1e-4, 1e-4: 5.0e-4
// (second order once omega_max h < 1), so h = 1e-4 is the step that resolves this motion.
TEST(SwingingCableCore, TrapezoidalConservesEnergy) {
  const core::Model m = SwingingCable(core::Scheme::kTrapezoidal, 1.0, 1e-4, 1);
  core::Simulation sim = Released(m);
  const double swing = PotentialSwing(m);
  const double e0 = Energy(sim);
  double max_dev = 0.0;
  double pe_min = sim.PotentialEnergy();
  while (sim.time() < 20.0 - 1e-9) {
    const core::StepStatus st = sim.Step();
    ASSERT_TRUE(st.ok()) << st.message << " at t = " << sim.time();
    max_dev = std::max(max_dev, std::abs(Energy(sim) - e0));
    pe_min = std::min(pe_min, sim.PotentialEnergy());
  }
  const double drift = Energy(sim) - e0;
  std::printf(
      "trapezoidal, h 1e-4, 20 s: energy drift at end %+.3e J, max |E - E0| %.3e J "
      "(%.2e of dPE %.2f J); lowest PE reached %.2f J below start\n",
      drift, max_dev, max_dev / swing, swing, e0 - pe_min);
  // the cable did swing through most of the potential drop
  EXPECT_GT(e0 - pe_min, 0.5 * swing);
  // issue requirement: below 0.1% of the potential-energy swing over 20 s
  constexpr double kDriftRelTol = 1e-3;
  EXPECT_LT(max_dev, kDriftRelTol * swing);
}

// Generalized-alpha with rho_inf = 0.6 must dissipate: the energy ends below where it started
// and never climbs above it. The issue also asked that E never rise from one step to the next
// beyond round-off (1e-9 dPE). That is not a property of generalized-alpha: even on a linear
// oscillator its physical energy rises in some steps by ~1.5e-2 (omega h)^3 E
// (generalized_alpha_oscillator_test.cc: 1.4e-5 at omega h = 0.1), and on this cable the
// truncation error of the energy (see the trapezoidal test) is of the same order. The
// one-step rises are therefore printed, not asserted.
TEST(SwingingCableCore, GeneralizedAlphaDissipates) {
  const core::Model m = SwingingCable(core::Scheme::kGeneralizedAlpha, 0.6, 1e-3, 1);
  core::Simulation sim = Released(m);
  const double swing = PotentialSwing(m);
  const double e0 = Energy(sim);
  constexpr double kRoundOffRel = 1e-9;  // the one-step criterion, reported only
  double e_prev = e0;
  double e_max = e0;
  double max_rise = 0.0;
  double t_max_rise = 0.0;
  int rises = 0;
  while (sim.time() < 20.0 - 1e-9) {
    const core::StepStatus st = sim.Step();
    ASSERT_TRUE(st.ok()) << st.message << " at t = " << sim.time();
    const double e = Energy(sim);
    if (e - e_prev > max_rise) {
      max_rise = e - e_prev;
      t_max_rise = sim.time();
    }
    if (e - e_prev > kRoundOffRel * swing) ++rises;
    e_max = std::max(e_max, e);
    e_prev = e;
  }
  std::printf(
      "generalized-alpha rho_inf 0.6, h 1e-3, 20 s: E_end - E0 %+.3e J (%.1f%% of dPE); "
      "max E - E0 %+.3e J; largest one-step rise %.3e J (%.2e of dPE) at t = %.3f s; "
      "%d of 20000 steps rose by more than %.0e dPE\n",
      e_prev - e0, 100.0 * (e_prev - e0) / swing, e_max - e0, max_rise, max_rise / swing,
      t_max_rise, rises, kRoundOffRel);
  EXPECT_LT(e_prev, e0);
  // never a net gain: E(t) - E0 below the round-off of a sum of ~77 J terms
  EXPECT_LE(e_max - e0, kRoundOffRel * swing);
}

// free-end position at t = 1 s for h, h/2, h/4, h/8 against h/64; fitted order in [1.8, 2.2].
// h = 1e-3 (omega_max h from 1.7 down to 0.22): with h = 1e-2 the same study measures 1.79
// (trapezoidal), because the axial modes are then unresolved (omega_max h up to 17) and
// their errors do not yet shrink like h^2; with a softer cable (E = 1e6) h = 1e-2 gives
// ratios 3.0, 4.0, 4.0, i.e. order 2.
void ConvergenceOrder(core::Scheme scheme, double rho_inf, const char* label) {
  const double h0 = 1e-3;
  auto tip_at_1s = [&](double h) {
    core::Simulation sim = Released(SwingingCable(scheme, rho_inf, h, 1));
    const int n = static_cast<int>(std::lround(1.0 / h));
    for (int i = 0; i < n; ++i) {
      const core::StepStatus st = sim.StepBy(h);
      EXPECT_TRUE(st.ok()) << st.message;
      if (!st.ok()) break;
    }
    return sim.node_position(sim.num_nodes() - 1);
  };
  const Vec3 reference = tip_at_1s(h0 / 64.0);
  std::vector<double> hs;
  std::vector<double> errors;
  for (int k = 0; k < 4; ++k) {
    const double h = h0 / (1 << k);
    hs.push_back(h);
    errors.push_back((tip_at_1s(h) - reference).norm());
    std::printf("%s: h %.5f s, free-end error at 1 s %.3e m\n", label, h, errors.back());
  }
  const double order = FitConvergenceOrder(hs, errors);
  std::printf("%s: fitted order %.3f (tip at 1 s: %.4f %.4f %.4f)\n", label, order, reference.x(),
              reference.y(), reference.z());
  // issue requirement: second order; the band allows the pre-asymptotic h = 1e-2 point and
  // the reference's own error ((1/64)^2 = 2.4e-4 of the h error)
  EXPECT_GE(order, 1.8) << label;
  EXPECT_LE(order, 2.2) << label;
}

TEST(SwingingCableCore, TrapezoidalIsSecondOrder) {
  ConvergenceOrder(core::Scheme::kTrapezoidal, 1.0, "trapezoidal");
}

TEST(SwingingCableCore, GeneralizedAlphaIsSecondOrder) {
  ConvergenceOrder(core::Scheme::kGeneralizedAlpha, 0.8, "generalized-alpha 0.8");
}

}  // namespace
}  // namespace towsim::reference
