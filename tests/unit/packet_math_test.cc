// The packet functions of core/packet_math.h against the C library's sin, cos and exp (correctly
// rounded to within an ulp or so), over the ranges the wave sums use them on.

#include "core/packet_math.h"

#include <cmath>
#include <cstdint>
#include <random>

#include <gtest/gtest.h>

namespace towsim::core {
namespace {

// uniform in [lo, hi) from a seeded generator (mt19937_64's sequence is fixed by the standard)
double Draw(std::mt19937_64* rng, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>((*rng)() >> 11) * (1.0 / 9007199254740992.0));
}

TEST(PacketMath, SinCosMatchTheLibraryOverWavePhases) {
  // truncation 5e-17 and a few roundings of |r| <= pi/4 (1e-16 each), plus the rounding of
  // n pi/2 and of x itself: relative to |x| at 2 ulps
  constexpr double kAbsTol = 5e-16;
  constexpr double kRelToPhase = 4.5e-16;
  std::mt19937_64 rng(20261201);
  double worst = 0.0;
  for (const double range : {1.0, 10.0, 1e3, 1e5}) {
    for (int i = 0; i < 20000; ++i) {
      const Pack x = {Draw(&rng, -range, range), Draw(&rng, -range, range)};
      Pack s, c;
      SinCos(x, &s, &c);
      for (int l = 0; l < kPackLanes; ++l) {
        const double tol = kAbsTol + kRelToPhase * std::abs(x[l]);
        ASSERT_NEAR(s[l], std::sin(x[l]), tol) << "x = " << x[l];
        ASSERT_NEAR(c[l], std::cos(x[l]), tol) << "x = " << x[l];
        worst = std::max({worst, std::abs(s[l] - std::sin(x[l])) / (1.0 + std::abs(x[l])),
                          std::abs(c[l] - std::cos(x[l])) / (1.0 + std::abs(x[l]))});
      }
    }
  }
  std::printf("SinCos: largest |error| / (1 + |x|) %.2e\n", worst);
  // the quadrant boundaries and exact values
  for (int n = -8; n <= 8; ++n) {
    const double x0 = n * 0.78539816339744831;  // multiples of pi/4
    Pack s, c;
    SinCos(Pack{x0, -x0}, &s, &c);
    EXPECT_NEAR(s[0], std::sin(x0), kAbsTol * 4);
    EXPECT_NEAR(c[0], std::cos(x0), kAbsTol * 4);
    EXPECT_NEAR(s[1], std::sin(-x0), kAbsTol * 4);
    EXPECT_NEAR(c[1], std::cos(-x0), kAbsTol * 4);
  }
}

TEST(PacketMath, ExpNonPositiveMatchesTheLibrary) {
  // truncation 2e-16 relative and a dozen roundings in the Horner sum
  constexpr double kRelTol = 1e-15;
  std::mt19937_64 rng(7);
  double worst = 0.0;
  for (const double range : {1.0, 50.0, 699.0}) {
    for (int i = 0; i < 20000; ++i) {
      const Pack y = {-Draw(&rng, 0.0, range), -Draw(&rng, 0.0, range)};
      const Pack e = ExpNonPositive(y);
      for (int l = 0; l < kPackLanes; ++l) {
        const double ref = std::exp(y[l]);
        ASSERT_NEAR(e[l], ref, kRelTol * ref) << "y = " << y[l];
        worst = std::max(worst, std::abs(e[l] - ref) / ref);
      }
    }
  }
  std::printf("ExpNonPositive: largest relative error %.2e\n", worst);
  const Pack e = ExpNonPositive(Pack{0.0, -701.0});
  EXPECT_EQ(e[0], 1.0);
  EXPECT_EQ(e[1], 0.0);  // below -700: zero (e^-701 = 1e-305)
  const Pack f = ExpNonPositive(Pack{-1e300, -std::log(2.0)});
  EXPECT_EQ(f[0], 0.0);
  EXPECT_NEAR(f[1], 0.5, 1e-16);
}

}  // namespace
}  // namespace towsim::core
