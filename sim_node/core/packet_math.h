#pragma once
// Packets of doubles and floats and the elementary functions the wave sums need on them
// (docs/environment.md, "Cost"): a phase reduced to [-pi, pi] in double, then in float its sine
// and cosine, and e^y for y <= 0.
//
// A packet is a GCC/Clang generic vector (`vector_size`): `Pack4`, four doubles, and
// `PackF8`, eight floats (the same 32 bytes). No intrinsics and no -march: the compiler maps a
// packet onto two SSE2 registers by default (NEON on AArch64, scalars elsewhere) and onto one
// AVX register inside a function compiled for AVX2 (`__attribute__((target("avx2")))`, chosen at
// run time, environment_field.cc), with the same IEEE operation on every lane either way (no
// fused multiply-add: the AVX2 target does not include FMA), so both give the same bits. The
// functions are always inlined into their caller (so that they take the caller's target), and
// have no branches and no table look-ups, so the compiler keeps every lane in one register and
// the wave sums evaluate eight components per instruction.
//
// Accuracy (tests/unit/packet_math_test.cc, against the C library): ReduceTwoPi a few 1e-16 of
// |x|; SinCosF and ExpNonPositiveF a few float roundings (6e-8 each), below.
// Both round to an integer with the 1.5 * 2^52 (double) or 1.5 * 2^23 (float) shift, whose
// low bits are then n in two's complement (IEEE addition; the build does not re-associate: no
// -ffast-math). A cast between packet types of one size reinterprets the bits (GCC's vector
// extension).

#include <cstdint>
#include <cstring>

// A packet passed or returned by value where AVX is off "changes the ABI" (-Wpsabi): these
// functions are always inlined, so no packet ever crosses a call
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace towsim::core {

// A packet's alignment is 16 without AVX and 32 with it: keep them in registers and locals, and
// store arrays of them as doubles or floats (LoadPack4, LoadPackF8)
typedef double Pack4 __attribute__((vector_size(32)));

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

// Single precision: eight floats a packet (one AVX register, two SSE2 ones), for the wave
// sums' polynomials (docs/environment.md, "Cost"). Their phases are formed and reduced to
// [-pi, pi] in double (ReduceTwoPi) and only then rounded to float, so the float error does not
// grow with the phase.
typedef float PackF8 __attribute__((vector_size(32)));
typedef std::uint32_t PackBitsF8 __attribute__((vector_size(32)));
typedef float PackF4 __attribute__((vector_size(16)));

// the lanes of a PackF8 added: lane j to lane j + 4 in float, then the four sums in double
[[gnu::always_inline]] inline double Sum(const PackF8& p) {
  const PackF4 half =
      __builtin_shufflevector(p, p, 0, 1, 2, 3) + __builtin_shufflevector(p, p, 4, 5, 6, 7);
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
  constexpr float kPiOver2Hi = 1.5703125f;     // 8 significant bits: n pi/2 exact
  constexpr float kPiOver2Lo = 4.8382679e-4f;  // pi/2 - kPiOver2Hi
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
  constexpr float kLn2Hi = 0.693145752f;    // 16 significant bits: n ln2 exact
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
