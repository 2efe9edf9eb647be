// Self-checks of the generalized-alpha oscillator reference (generalized_alpha_oscillator.h)
// against the published properties of the method (Chung & Hulbert 1993): energy conservation
// of the trapezoidal rule (rho_inf = 1) and spectral radius rho_inf at omega h -> inf.

#include "generalized_alpha_oscillator.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

namespace towsim::reference {
namespace {

// rho_inf = 1: the trapezoidal rule conserves the energy of a linear system exactly; 1e-12
// allows the round-off of 4000 steps
TEST(GeneralizedAlphaOscillator, TrapezoidalConservesEnergy) {
  for (double wh : {0.01, 0.1, 1.0, 10.0}) {
    const OscillatorEnergy e = GeneralizedAlphaOscillator(1.0, wh, 4000);
    EXPECT_NEAR(e.final_ratio, 1.0, 1e-12) << "omega h = " << wh;
    EXPECT_LT(e.max_step_rise, 1e-12) << "omega h = " << wh;
  }
}

// the spectral radius at omega h -> inf is rho_inf (the defining property), and 1 at
// omega h -> 0 (no dissipation of the resolved modes). At infinity -rho_inf is a double,
// defective root, so finite omega h (and round-off in the badly scaled (x, v, a^) matrix)
// shows up as its square root: 1e-3 at omega h = 1e6
TEST(GeneralizedAlphaOscillator, SpectralRadius) {
  constexpr double kDefectiveRootTol = 1e-3;
  for (double rho : {0.0, 0.3, 0.6, 0.8, 1.0}) {
    EXPECT_NEAR(GeneralizedAlphaSpectralRadius(rho, 1e6), rho, kDefectiveRootTol)
        << "rho_inf " << rho;
    EXPECT_NEAR(GeneralizedAlphaSpectralRadius(rho, 1e-4), 1.0, 1e-6) << "rho_inf " << rho;
  }
}

// rho_inf = 0.6 dissipates over time but the energy is not monotone from step to step: the
// largest one-step rise grows like (omega h)^3 (8x per doubling of omega h) and is 1.4e-5 of E_0
// at omega h = 0.1, far above round-off. (So "never increases beyond round-off" cannot be asked
// of generalized-alpha; see swinging_cable_core_test.cc.)
TEST(GeneralizedAlphaOscillator, DissipativeButNotMonotone) {
  const OscillatorEnergy a = GeneralizedAlphaOscillator(0.6, 0.05, 20000);
  const OscillatorEnergy b = GeneralizedAlphaOscillator(0.6, 0.1, 10000);
  std::printf(
      "rho_inf 0.6: max one-step energy rise %.3e (omega h 0.05), %.3e (0.1); "
      "E_end / E_0 %.4f, %.4f\n",
      a.max_step_rise, b.max_step_rise, a.final_ratio, b.final_ratio);
  EXPECT_LT(b.final_ratio, 1.0);
  EXPECT_NEAR(b.max_step_rise, 1.4003e-5, 1e-8);
  EXPECT_NEAR(b.max_step_rise / a.max_step_rise, 8.0, 0.5);
}

}  // namespace
}  // namespace towsim::reference
