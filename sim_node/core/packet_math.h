#pragma once
// Two-lane packets of doubles and the elementary functions the wave sums need on them
// (docs/environment.md, "Cost"): sin and cos of any phase, and e^y for y <= 0.
//
// A packet is a GCC/Clang generic vector (`vector_size`), two doubles: SSE2 on every x86-64,
// NEON on AArch64, two scalars elsewhere; no intrinsics, no -march. The functions have no
// branches and no table look-ups, so the compiler keeps both lanes in one register, and the
// wave sums (environment_field.cc) evaluate two components per instruction.
//
// Accuracy (tests/unit/packet_math_test.cc, against the C library):
//   SinCos: x = n pi/2 + r, |r| <= pi/4 (Cody-Waite, pi/2 in two parts), the Taylor series of
//     sin r to r^15 and of cos r to r^16 (truncation (pi/4)^17 / 17! = 5e-17), the quadrant
//     from the two low bits of n; |x| < 2^51 (wave phases: |w t| < 1e9 rad). Absolute error a
//     few 1e-16 plus the rounding of n pi/2 (|x| 1e-16).
//   ExpNonPositive: y = n ln 2 + r, |r| <= ln 2 / 2, Taylor to r^12 (truncation 0.347^13 / 13!
//     = 2e-16), 2^n from its exponent bits; 0 below y = -700 (e^-700 = 1e-304). Relative
//     error a few 1e-16.
// Both use the 1.5 * 2^52 shift to round to an integer whose low bits are n in two's
// complement (IEEE addition; the build does not re-associate: no -ffast-math). A cast between
// packet types reinterprets the bits (GCC's vector extension).

#include <cstdint>

namespace towsim::core {

typedef double Pack __attribute__((vector_size(16)));
typedef std::uint64_t PackBits __attribute__((vector_size(16)));
constexpr int kPackLanes = 2;

inline Pack Broadcast(double x) { return Pack{x, x}; }
inline double Sum(Pack p) { return p[0] + p[1]; }

namespace packet_internal {
constexpr double kRoundShift = 6755399441055744.0;  // 1.5 * 2^52
}  // namespace packet_internal

// *s = sin x, *c = cos x, lane by lane
inline void SinCos(Pack x, Pack* s, Pack* c) {
  using packet_internal::kRoundShift;
  constexpr double kTwoOverPi = 0.63661977236758134;
  constexpr double kPiOver2Hi = 1.5707963267948966, kPiOver2Lo = 6.123233995736766e-17;
  // n = round(x 2 / pi), its low bits in those of m
  const Pack m = x * kTwoOverPi + kRoundShift;
  const Pack n = m - kRoundShift;
  const PackBits quadrant = (PackBits)(m);
  const Pack r = (x - n * kPiOver2Hi) - n * kPiOver2Lo;
  const Pack r2 = r * r;
  // sin r = r + r^3 P(r^2), P = -1/3! + r^2/5! - ... - r^12/15!
  Pack p = Broadcast(-7.6471637318198164759e-13);  // -1/15!
  p = p * r2 + 1.6059043836821614599e-10;          // 1/13!
  p = p * r2 - 2.5052108385441718775e-08;          // -1/11!
  p = p * r2 + 2.7557319223985890653e-06;          // 1/9!
  p = p * r2 - 1.9841269841269841270e-04;          // -1/7!
  p = p * r2 + 8.3333333333333333333e-03;          // 1/5!
  p = p * r2 - 1.6666666666666666667e-01;          // -1/3!
  const Pack sin_r = r + (r * r2) * p;
  // cos r = 1 - r^2/2 + r^4 Q(r^2), Q = 1/4! - r^2/6! + ... + r^12/16!
  Pack q = Broadcast(4.7794773323873852974e-14);  // 1/16!
  q = q * r2 - 1.1470745597729724714e-11;         // -1/14!
  q = q * r2 + 2.0876756987868098979e-09;         // 1/12!
  q = q * r2 - 2.7557319223985890653e-07;         // -1/10!
  q = q * r2 + 2.4801587301587301587e-05;         // 1/8!
  q = q * r2 - 1.3888888888888888889e-03;         // -1/6!
  q = q * r2 + 4.1666666666666666667e-02;         // 1/4!
  const Pack cos_r = (1.0 - 0.5 * r2) + (r2 * r2) * q;
  // quadrant n mod 4: sin x = sin r, cos r, -sin r, -cos r; cos x = cos r, -sin r, -cos r, sin r
  const PackBits swap = -(quadrant & 1);  // all ones in odd quadrants
  const PackBits sb = (PackBits)(sin_r);
  const PackBits cb = (PackBits)(cos_r);
  const PackBits sin_x = ((sb & ~swap) | (cb & swap)) ^ ((quadrant & 2) << 62);
  const PackBits cos_x = ((cb & ~swap) | (sb & swap)) ^ (((quadrant + 1) & 2) << 62);
  *s = (Pack)(sin_x);
  *c = (Pack)(cos_x);
}

// e^y for y <= 0, lane by lane (0 below -700)
inline Pack ExpNonPositive(Pack y) {
  using packet_internal::kRoundShift;
  constexpr double kInvLn2 = 1.4426950408889634;
  constexpr double kLn2Hi = 0.6931471803691238, kLn2Lo = 1.9082149292705877e-10;
  // n = round(y / ln 2), its low bits in those of m
  const Pack m = y * kInvLn2 + kRoundShift;
  const Pack n = m - kRoundShift;
  const Pack r = (y - n * kLn2Hi) - n * kLn2Lo;
  // e^r = sum r^j / j!, j <= 12 (Horner)
  Pack p = Broadcast(2.0876756987868098979e-09);  // 1/12!
  p = p * r + 2.5052108385441718775e-08;          // 1/11!
  p = p * r + 2.7557319223985890653e-07;          // 1/10!
  p = p * r + 2.7557319223985890653e-06;          // 1/9!
  p = p * r + 2.4801587301587301587e-05;          // 1/8!
  p = p * r + 1.9841269841269841270e-04;          // 1/7!
  p = p * r + 1.3888888888888888889e-03;          // 1/6!
  p = p * r + 8.3333333333333333333e-03;          // 1/5!
  p = p * r + 4.1666666666666666667e-02;          // 1/4!
  p = p * r + 1.6666666666666666667e-01;          // 1/3!
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  // 2^n: the biased exponent n + 1023 into bits 52-62 (n >= -1010 here)
  const PackBits two_n_bits = ((PackBits)(m) + 1023) << 52;
  const Pack e = p * (Pack)(two_n_bits);
  const PackBits keep = (PackBits)(e) & ~(PackBits)(y < -700.0);
  return (Pack)(keep);
}

}  // namespace towsim::core
