// Self-checks of the taut-string reference (taut_string.h).

#include "taut_string.h"

#include <cmath>

#include <gtest/gtest.h>

namespace towsim::reference {
namespace {

// hand-checked: L = 10, ell = 10.1, EA = 1e4 N, rho A = 0.1 kg/m
//   lambda = 1.01, eps = (1.0201 - 1) / 2 = 0.01005, T = 1e4 * 0.01005 * 1.01 = 101.505 N
//   mu = 0.1 * 10 / 10.1 = 0.0990099 kg/m, c = sqrt(T / mu) = 32.018752 m/s,
//   f1 = c / 20.2 = 1.585087 Hz
TEST(TautString, HandChecked) {
  TautString s;
  s.length = 10.0;
  s.span = 10.1;
  s.ea = 1.0e4;
  s.rho_a = 0.1;
  EXPECT_NEAR(TautStringTension(s), 101.505, 1e-9);
  EXPECT_NEAR(TautStringMassPerLength(s), 0.1 * 10.0 / 10.1, 1e-15);
  EXPECT_NEAR(TautStringFirstFrequency(s), 1.585087, 1e-6);
}

// small pre-stretch: T -> EA (ell/L - 1), the linear (Hooke) string
TEST(TautString, SmallStretchIsHooke) {
  TautString s;
  s.length = 1.0;
  s.span = 1.0 + 1e-6;
  s.ea = 1.0;
  EXPECT_NEAR(TautStringTension(s), 1e-6, 1e-11);  // Green vs engineering: 1.5 e^2
}

}  // namespace
}  // namespace towsim::reference
