// The packet functions of core/packet_math.h against the C library's sin, cos and exp (correctly
// rounded to within an ulp or so), over the ranges the wave sums use them on.

#include "core/packet_math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>

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

TEST(PacketMath, PhasesReducedInDoubleThenFloatSinCosMatchTheLibrary) {
  // ReduceTwoPi: x - 2 pi n in [-pi, pi] to a few 1e-16 of |x| (2 pi in two parts); then
  // rounded to float (|r| <= pi: 2^-24 pi = 1.9e-7 at most, half of that typically) and
  // SinCosF: its truncation 1.7e-9, a few float roundings of values <= 1 (6e-8 each). Against
  // sin and cos of the double phase: the float rounding of r dominates
  constexpr double kReduceRelTol = 4.5e-16;
  constexpr double kFloatAbsTol = 3.5e-7;  // 2^-24 (pi + 3), the phase's rounding and 3 more
  std::mt19937_64 rng(20261203);
  double worst = 0.0;
  for (const double range : {1.0, 10.0, 1e3, 1e5}) {
    for (int i = 0; i < 5000; ++i) {
      Pack4 lo, hi;
      for (int l = 0; l < 4; ++l) lo[l] = Draw(&rng, -range, range), hi[l] = Draw(&rng, -range, range);
      const Pack4 rlo = ReduceTwoPi(lo), rhi = ReduceTwoPi(hi);
      for (int l = 0; l < 4; ++l) {
        for (const auto& [x, r] : {std::pair{lo[l], rlo[l]}, std::pair{hi[l], rhi[l]}}) {
          ASSERT_LE(std::abs(r), 3.1415926535897936) << "x = " << x;
          ASSERT_NEAR(std::sin(r), std::sin(x), 1e-16 + kReduceRelTol * std::abs(x)) << x;
          ASSERT_NEAR(std::cos(r), std::cos(x), 1e-16 + kReduceRelTol * std::abs(x)) << x;
        }
      }
      const PackF8 r8 = ToFloat8(rlo, rhi);
      PackF8 s, c;
      SinCosF(r8, &s, &c);
      for (int l = 0; l < 8; ++l) {
        const double x = l < 4 ? lo[l] : hi[l - 4];
        ASSERT_NEAR(s[l], std::sin(x), kFloatAbsTol + kReduceRelTol * std::abs(x)) << "x = " << x;
        ASSERT_NEAR(c[l], std::cos(x), kFloatAbsTol + kReduceRelTol * std::abs(x)) << "x = " << x;
        worst = std::max({worst, std::abs(s[l] - std::sin(x)), std::abs(c[l] - std::cos(x))});
      }
    }
  }
  std::printf("ReduceTwoPi + SinCosF: largest |error| %.2e\n", worst);
  // exact values at the quadrant boundaries of [-pi, pi]
  const PackF8 q = {0.0f, 1.5707964f, -1.5707964f, 3.1415927f, -3.1415927f, 0.7853982f,
                    -2.3561945f, 2.3561945f};
  PackF8 s, c;
  SinCosF(q, &s, &c);
  for (int l = 0; l < 8; ++l) {
    EXPECT_NEAR(s[l], std::sin(double(q[l])), 1.2e-7) << q[l];
    EXPECT_NEAR(c[l], std::cos(double(q[l])), 1.2e-7) << q[l];
  }
}

TEST(PacketMath, ExpNonPositiveFMatchesTheLibrary) {
  // truncation 5.6e-9 and a dozen float roundings (6e-8 each) of values near 1, relative
  constexpr double kRelTol = 4e-7;
  std::mt19937_64 rng(11);
  double worst = 0.0;
  for (const double range : {1.0, 20.0, 86.0}) {
    for (int i = 0; i < 5000; ++i) {
      PackF8 y;
      for (int l = 0; l < 8; ++l) y[l] = static_cast<float>(-Draw(&rng, 0.0, range));
      const PackF8 e = ExpNonPositiveF(y);
      for (int l = 0; l < 8; ++l) {
        const double ref = std::exp(double(y[l]));
        ASSERT_NEAR(e[l], ref, kRelTol * ref) << "y = " << y[l];
        worst = std::max(worst, std::abs(e[l] - ref) / ref);
      }
    }
  }
  std::printf("ExpNonPositiveF: largest relative error %.2e\n", worst);
  const PackF8 e = ExpNonPositiveF(PackF8{0.0f, -88.0f, -1e30f, -0.6931472f, -87.0f, -1.0f, -2.0f, -3.0f});
  EXPECT_EQ(e[0], 1.0f);
  EXPECT_EQ(e[1], 0.0f);  // below -87: zero
  EXPECT_EQ(e[2], 0.0f);
  EXPECT_NEAR(e[3], 0.5, 1e-7);
  EXPECT_NEAR(e[4], std::exp(-87.0), 4e-7 * std::exp(-87.0));
}

TEST(PacketMath, LanesOfAFloatPacketSumInDouble) {
  const PackF8 p = {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f, 1e-8f};
  EXPECT_EQ(Sum(p), 28.0);  // lanes j and j + 4 added in float: 4 + 1e-8 rounds to 4
  const PackF8 q = ToFloat8(Pack4{1.0, 2.0, 3.0, 4.0}, Pack4{5.0, 6.0, 7.0, 8.0});
  for (int l = 0; l < 8; ++l) EXPECT_EQ(q[l], float(l + 1));
}

}  // namespace
}  // namespace towsim::core
