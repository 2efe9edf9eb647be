#pragma once
// Packets of doubles and the elementary functions the wave sums need on them
// (docs/environment.md, "Cost"): sin and cos of any phase, and e^y for y <= 0.
//
// A packet is a GCC/Clang generic vector (`vector_size`): `Pack`, two doubles (SSE2 on every
// x86-64, NEON on AArch64, two scalars elsewhere), and `Pack4`, four doubles. No intrinsics and
// no -march: the compiler maps a Pack4 onto two SSE2 registers by default and onto one AVX
// register inside a function compiled for AVX2 (`__attribute__((target("avx2")))`, chosen at
// run time, environment_field.cc), with the same IEEE operation on every lane either way (no
// fused multiply-add: the AVX2 target does not include FMA), so both give the same bits. The
// functions are templates over the packet type, always inlined into their caller (so that
// they take the caller's target), and have no branches and no table look-ups, so the compiler
// keeps every lane in one register and the wave sums evaluate two or four components per
// instruction.
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
// packet types of one size reinterprets the bits (GCC's vector extension).

#include <cstdint>
#include <cstring>

// A Pack4 passed or returned by value where AVX is off "changes the ABI" (-Wpsabi): these
// functions are always inlined, so no Pack4 ever crosses a call
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace towsim::core {

typedef double Pack __attribute__((vector_size(16)));
typedef std::uint64_t PackBits __attribute__((vector_size(16)));
constexpr int kPackLanes = 2;
// A Pack4's alignment is 16 without AVX and 32 with it: keep them in registers and locals, and
// store arrays of them as doubles (LoadPack4)
typedef double Pack4 __attribute__((vector_size(32)));
typedef std::uint64_t PackBits4 __attribute__((vector_size(32)));

// the bits of a packet type (the unsigned 64-bit vector of its size)
template <class P>
struct PacketBits;
template <>
struct PacketBits<Pack> {
  using Type = PackBits;
};
template <>
struct PacketBits<Pack4> {
  using Type = PackBits4;
};

inline Pack Broadcast(double x) { return Pack{x, x}; }
inline double Sum(Pack p) { return p[0] + p[1]; }
// the lanes of a Pack4 added pairwise, (0 + 1) + (2 + 3)
[[gnu::always_inline]] inline double Sum(const Pack4& p) { return (p[0] + p[1]) + (p[2] + p[3]); }

// the four doubles at p as a packet (no alignment needed)
[[gnu::always_inline]] inline Pack4 LoadPack4(const double* p) {
  Pack4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

namespace packet_internal {
constexpr double kRoundShift = 6755399441055744.0;  // 1.5 * 2^52
}  // namespace packet_internal

// *s = sin x, *c = cos x, lane by lane
template <class P>
[[gnu::always_inline]] inline void SinCos(const P& x, P* s, P* c) {
  using Bits = typename PacketBits<P>::Type;
  using packet_internal::kRoundShift;
  constexpr double kTwoOverPi = 0.63661977236758134;
  constexpr double kPiOver2Hi = 1.5707963267948966, kPiOver2Lo = 6.123233995736766e-17;
  // n = round(x 2 / pi), its low bits in those of m
  const P m = x * kTwoOverPi + kRoundShift;
  const P n = m - kRoundShift;
  const Bits quadrant = (Bits)(m);
  const P r = (x - n * kPiOver2Hi) - n * kPiOver2Lo;
  const P r2 = r * r;
  // sin r = r + r^3 P(r^2), P = -1/3! + r^2/5! - ... - r^12/15!
  P p = P{} - 7.6471637318198164759e-13;   // -1/15!
  p = p * r2 + 1.6059043836821614599e-10;  // 1/13!
  p = p * r2 - 2.5052108385441718775e-08;  // -1/11!
  p = p * r2 + 2.7557319223985890653e-06;  // 1/9!
  p = p * r2 - 1.9841269841269841270e-04;  // -1/7!
  p = p * r2 + 8.3333333333333333333e-03;  // 1/5!
  p = p * r2 - 1.6666666666666666667e-01;  // -1/3!
  const P sin_r = r + (r * r2) * p;
  // cos r = 1 - r^2/2 + r^4 Q(r^2), Q = 1/4! - r^2/6! + ... + r^12/16!
  P q = P{} + 4.7794773323873852974e-14;   // 1/16!
  q = q * r2 - 1.1470745597729724714e-11;  // -1/14!
  q = q * r2 + 2.0876756987868098979e-09;  // 1/12!
  q = q * r2 - 2.7557319223985890653e-07;  // -1/10!
  q = q * r2 + 2.4801587301587301587e-05;  // 1/8!
  q = q * r2 - 1.3888888888888888889e-03;  // -1/6!
  q = q * r2 + 4.1666666666666666667e-02;  // 1/4!
  const P cos_r = (1.0 - 0.5 * r2) + (r2 * r2) * q;
  // quadrant n mod 4: sin x = sin r, cos r, -sin r, -cos r; cos x = cos r, -sin r, -cos r, sin r
  const Bits swap = -(quadrant & 1);  // all ones in odd quadrants
  const Bits sb = (Bits)(sin_r);
  const Bits cb = (Bits)(cos_r);
  const Bits sin_x = ((sb & ~swap) | (cb & swap)) ^ ((quadrant & 2) << 62);
  const Bits cos_x = ((cb & ~swap) | (sb & swap)) ^ (((quadrant + 1) & 2) << 62);
  *s = (P)(sin_x);
  *c = (P)(cos_x);
}

// e^y for y <= 0, lane by lane (0 below -700)
template <class P>
[[gnu::always_inline]] inline P ExpNonPositive(const P& y) {
  using Bits = typename PacketBits<P>::Type;
  using packet_internal::kRoundShift;
  constexpr double kInvLn2 = 1.4426950408889634;
  constexpr double kLn2Hi = 0.6931471803691238, kLn2Lo = 1.9082149292705877e-10;
  // n = round(y / ln 2), its low bits in those of m
  const P m = y * kInvLn2 + kRoundShift;
  const P n = m - kRoundShift;
  const P r = (y - n * kLn2Hi) - n * kLn2Lo;
  // e^r = sum r^j / j!, j <= 12 (Horner)
  P p = P{} + 2.0876756987868098979e-09;  // 1/12!
  p = p * r + 2.5052108385441718775e-08;  // 1/11!
  p = p * r + 2.7557319223985890653e-07;  // 1/10!
  p = p * r + 2.7557319223985890653e-06;  // 1/9!
  p = p * r + 2.4801587301587301587e-05;  // 1/8!
  p = p * r + 1.9841269841269841270e-04;  // 1/7!
  p = p * r + 1.3888888888888888889e-03;  // 1/6!
  p = p * r + 8.3333333333333333333e-03;  // 1/5!
  p = p * r + 4.1666666666666666667e-02;  // 1/4!
  p = p * r + 1.6666666666666666667e-01;  // 1/3!
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  // 2^n: the biased exponent n + 1023 into bits 52-62 (n >= -1010 here)
  const Bits two_n_bits = ((Bits)(m) + 1023) << 52;
  const P e = p * (P)(two_n_bits);
  const Bits keep = (Bits)(e) & ~(Bits)(y < -700.0);
  return (P)(keep);
}

// Single precision: eight floats a packet (one AVX register, two SSE2 ones), for the wave
// sums' polynomials (docs/environment.md, "Cost"). Their phases are formed and reduced to
// [-pi, pi] in double (ReduceTwoPi) and only then rounded to float, so the float error does not
// grow with the phase.
typedef float PackF8 __attribute__((vector_size(32)));
typedef std::uint32_t PackBitsF8 __attribute__((vector_size(32)));
typedef float PackF4 __attribute__((vector_size(16)));

// the lanes of a PackF8 added: lane j to lane j + 4 in float, then the four sums in double
[[gnu::always_inline]] inline double Sum(const PackF8& p) {
  const PackF4 half = __builtin_shufflevector(p, p, 0, 1, 2, 3) +
                      __builtin_shufflevector(p, p, 4, 5, 6, 7);
  return Sum(__builtin_convertvector(half, Pack4));
}

// the eight floats at p as a packet (no alignment needed)
[[gnu::always_inline]] inline PackF8 LoadPackF8(const float* p) {
  PackF8 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// x - 2 pi n, n = round(x / (2 pi)), lane by lane: in [-pi, pi] to a few 1e-16 (2 pi in two
// parts; |x| < 2^51)
template <class P>
[[gnu::always_inline]] inline P ReduceTwoPi(const P& x) {
  using packet_internal::kRoundShift;
  constexpr double kInvTwoPi = 0.15915494309189535;
  constexpr double kTwoPiHi = 6.283185307179586, kTwoPiLo = 2.4492935982947064e-16;
  const P n = (x * kInvTwoPi + kRoundShift) - kRoundShift;
  return (x - n * kTwoPiHi) - n * kTwoPiLo;
}

// two four-double packets rounded to one eight-float packet, lo in lanes 0-3
[[gnu::always_inline]] inline PackF8 ToFloat8(const Pack4& lo, const Pack4& hi) {
  const PackF4 a = __builtin_convertvector(lo, PackF4);
  const PackF4 b = __builtin_convertvector(hi, PackF4);
  return __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7);
}

namespace packet_internal {
constexpr float kRoundShiftF = 12582912.0f;  // 1.5 * 2^23
}  // namespace packet_internal

// *s = sin x, *c = cos x for |x| <= pi (1 + 1e-7), lane by lane, in float: x = n pi/2 + r,
// |r| <= pi/4 (pi/2 in two float parts, n in -2..2), sin r = r P(r^2) and cos r = Q(r^2) with
// P of degree 3 and Q of degree 4, their Chebyshev fits on [0, (pi/4)^2] (mpmath.chebyfit:
// relative error 3.1e-9 and absolute 4.8e-11, below float's rounding 6e-8). Absolute error a
// few 1e-8 (tests/unit/packet_math_test.cc).
[[gnu::always_inline]] inline void SinCosF(const PackF8& x, PackF8* s, PackF8* c) {
  using Bits = PackBitsF8;
  using packet_internal::kRoundShiftF;
  constexpr float kTwoOverPi = 0.636619772f;
  constexpr float kPiOver2Hi = 1.5703125f;                // 8 significant bits: n pi/2 exact
  constexpr float kPiOver2Lo = 4.8382679e-4f;             // pi/2 - kPiOver2Hi
  const PackF8 m = x * kTwoOverPi + kRoundShiftF;
  const PackF8 n = m - kRoundShiftF;
  const Bits quadrant = (Bits)(m);
  const PackF8 r = (x - n * kPiOver2Hi) - n * kPiOver2Lo;
  const PackF8 r2 = r * r;
  PackF8 p = PackF8{} - 1.95039043e-4f;
  p = p * r2 + 8.33203578e-3f;
  p = p * r2 - 1.66666507e-1f;
  p = p * r2 + 9.99999997e-1f;
  const PackF8 sin_r = r * p;
  PackF8 q = PackF8{} + 2.43798313e-5f;
  q = q * r2 - 1.38866180e-3f;
  q = q * r2 + 4.16666167e-2f;
  q = q * r2 - 4.99999996e-1f;
  const PackF8 cos_r = q * r2 + 1.0f;
  // quadrant n mod 4, as in SinCos (the sign bit is bit 31)
  const Bits swap = -(quadrant & 1);
  const Bits sb = (Bits)(sin_r);
  const Bits cb = (Bits)(cos_r);
  const Bits sin_x = ((sb & ~swap) | (cb & swap)) ^ ((quadrant & 2) << 30);
  const Bits cos_x = ((cb & ~swap) | (sb & swap)) ^ (((quadrant + 1) & 2) << 30);
  *s = (PackF8)(sin_x);
  *c = (PackF8)(cos_x);
}

// e^y for y <= 0, lane by lane, in float (0 below y = -87, e^-87 = 1.6e-38): y = n ln 2 + r,
// |r| <= ln 2 / 2, e^r by its degree-6 Chebyshev fit there (mpmath.chebyfit: error 2e-9),
// 2^n from its exponent bits. Relative error a few 1e-8.
[[gnu::always_inline]] inline PackF8 ExpNonPositiveF(const PackF8& y) {
  using Bits = PackBitsF8;
  using packet_internal::kRoundShiftF;
  constexpr float kInvLn2 = 1.44269504f;
  constexpr float kLn2Hi = 0.693145752f;   // 16 significant bits: n ln2 exact
  constexpr float kLn2Lo = 1.42860677e-6f;  // ln 2 - kLn2Hi
  const PackF8 m = y * kInvLn2 + kRoundShiftF;
  const PackF8 n = m - kRoundShiftF;
  const PackF8 r = (y - n * kLn2Hi) - n * kLn2Lo;
  PackF8 p = PackF8{} + 1.39411084e-3f;
  p = p * r + 8.37512640e-3f;
  p = p * r + 4.16663529e-2f;
  p = p * r + 1.66664155e-1f;
  p = p * r + 5.00000005e-1f;
  p = p * r + 1.00000004f;
  p = p * r + 1.0f;
  // 2^n: the biased exponent n + 127 into bits 23-30 (n >= -126 here)
  const Bits two_n_bits = ((Bits)(m) + 127) << 23;
  const PackF8 e = p * (PackF8)(two_n_bits);
  const Bits keep = (Bits)(e) & ~(Bits)(y < -87.0f);
  return (PackF8)(keep);
}

}  // namespace towsim::core

#pragma GCC diagnostic pop
