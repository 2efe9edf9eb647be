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
      for (int l = 0; l < 4; ++l)
        lo[l] = Draw(&rng, -range, range), hi[l] = Draw(&rng, -range, range);
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
  const PackF8 q = {0.0f,        1.5707964f, -1.5707964f, 3.1415927f,
                    -3.1415927f, 0.7853982f, -2.3561945f, 2.3561945f};
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
  const PackF8 e =
      ExpNonPositiveF(PackF8{0.0f, -88.0f, -1e30f, -0.6931472f, -87.0f, -1.0f, -2.0f, -3.0f});
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
