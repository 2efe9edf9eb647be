#include "core/environment_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.h"

// Pack4 values by value inside always-inlined code (packet_math.h); the warning comes at the
// end of the file, where the templates are compiled, so it is off for the whole file
#pragma GCC diagnostic ignored "-Wpsabi"

// the wave sums compiled for AVX2 as well (x86-64 GCC/Clang), chosen at run time
#if defined(__x86_64__) && defined(__GNUC__)
#define TOWSIM_WAVES_AVX2 1
#else
#define TOWSIM_WAVES_AVX2 0
#endif

namespace towsim::core {
namespace {

// a point at depth stops summing at the first component whose depth factor
// cosh k(zeta + h) / sinh kh (deep: e^{k zeta}) has fallen below this: the components are
// sorted by k, so every later one is smaller still (their sum stays below N times this of
// the surface kinematics)
constexpr double kDecayCutoff = 1e-9;

// packet i of a component array (WavePackets)
[[gnu::always_inline]] inline WavePack P(const std::vector<float>& v, size_t i) {
  return LoadPackF8(v.data() + kWaveLanes * i);
}
// half j (0, 1) of packet i of a double array, four lanes
[[gnu::always_inline]] inline Pack4 H(const std::vector<double>& v, size_t i, int j) {
  return LoadPack4(v.data() + kWaveLanes * i + 4 * j);
}

// a point's sums over the components, before the ramp and the resolution along b
struct RawSums {
  double eta = 0.0;
  double uh = 0.0, ah = 0.0;                      // long-crested: along the direction of travel
  double ux = 0.0, uy = 0.0, ax = 0.0, ay = 0.0;  // short-crested: resolved per component
  double uu = 0.0, au = 0.0;                      // upward
  // long-crested gradient: Q = sum a w k S cos th, P = sum a w k C sin th (always), and the
  // derivative: sum a w^2 k S sin th, a w^2 k C cos th, a w k^2 C cos th, a w k^2 S sin th
  double d_sc = 0.0, d_cs = 0.0, d2_ss = 0.0, d2_cc = 0.0, h_cc = 0.0, h_ss = 0.0;
  // short-crested derivative
  double dux = 0.0, duy = 0.0, duu = 0.0, dax = 0.0, day = 0.0, dau = 0.0;
  // short-crested gradient: sum P e e^T (xx, xy, yy), sum Q e (x, y), sum P; and their
  // derivatives along d
  double pxx = 0.0, pxy = 0.0, pyy = 0.0, qx = 0.0, qy = 0.0, pp = 0.0;
  double dpxx = 0.0, dpxy = 0.0, dpyy = 0.0, dqx = 0.0, dqy = 0.0, dpp = 0.0;
};

// where and when: x, y, the clamped height ze and its rate dze along d, the along-track
// coordinate and its rate (long-crested), d's horizontal components, t, and the packets to sum
struct PointArgs {
  double x, y, ze, dze, along, d_along, dx, dy, t;
  size_t packets;
};

// the phases th = k s - w t + f of packet i, formed and reduced to [-pi, pi] in double, then
// rounded to float (s = x cos b + y sin b along a long-crested sea's direction, else
// kx x + ky y per component)
template <bool kLongCrested>
[[gnu::always_inline]] inline WavePack Phases(const WavePackets& s, size_t i, const PointArgs& a) {
  Pack4 th[2];
  for (int j = 0; j < 2; ++j) {
    const Pack4 space = kLongCrested ? H(s.phase_k, i, j) * a.along
                                     : H(s.phase_kx, i, j) * a.x + H(s.phase_ky, i, j) * a.y;
    th[j] = ReduceTwoPi(space + (H(s.phase, i, j) - H(s.omega, i, j) * a.t));
  }
  return ToFloat8(th[0], th[1]);
}

// the phase changes kx ox + ky oy of packet i over a horizontal offset (ox, oy), reduced to
// [-pi, pi] in double as Phases
[[gnu::always_inline]] inline WavePack OffsetPhases(const WavePackets& s, size_t i, double ox,
                                                    double oy) {
  Pack4 d[2];
  for (int j = 0; j < 2; ++j)
    d[j] = ReduceTwoPi(H(s.phase_kx, i, j) * ox + H(s.phase_ky, i, j) * oy);
  return ToFloat8(d[0], d[1]);
}

// the sums of SumWaves over the first a.packets packets (environment_field.h); always
// inlined into the two targets below, so that each compiles it for its own instruction set
template <bool kDerivative, bool kLongCrested, bool kDeep>
[[gnu::always_inline]] inline RawSums SumPackets(const WavePackets& s, const PointArgs& a) {
  const WavePack zero = {};
  WavePack eta = zero, uh_s = zero, ah_s = zero;
  WavePack ux = zero, uy = zero, uu = zero, ax = zero, ay = zero, au = zero;
  WavePack dux = zero, duy = zero, duu = zero, dax = zero, day = zero, dau = zero;
  WavePack d_sc = zero, d_cs = zero, d2_ss = zero, d2_cc = zero, h_cc = zero, h_ss = zero;
  WavePack pxx = zero, pxy = zero, pyy = zero, qx = zero, qy = zero, pp = zero;
  WavePack dpxx = zero, dpxy = zero, dpyy = zero, dqx = zero, dqy = zero, dpp = zero;
  const float ze = static_cast<float>(a.ze), dze = static_cast<float>(a.dze);
  const float dx = static_cast<float>(a.dx), dy = static_cast<float>(a.dy);
  for (size_t i = 0; i < a.packets; ++i) {
    const WavePack k = P(s.k, i);
    // C = cosh k(zeta + h) / sinh kh, S = sinh k(zeta + h) / sinh kh (deep: C = S = E):
    // E = e^{k zeta}, F = q / E, C = (E + F) / (1 - q), S = (E - F) / (1 - q)
    WavePack y = k * ze;
    // finite depth: kept above float's underflow, so that F = q / E stays finite (where
    // k zeta < -87, kh > 40 and q = 0: F = 0)
    if (!kDeep) y = y < -87.0f ? WavePack{} - 87.0f : y;
    const WavePack e = ExpNonPositiveF(y);
    WavePack cc = e, ss = e;
    if (!kDeep) {
      const WavePack f = P(s.q, i) / e;
      const WavePack inv = P(s.inv_1mq, i);
      cc = (e + f) * inv, ss = (e - f) * inv;
    }
    WavePack sn, c;
    SinCosF(Phases<kLongCrested>(s, i, a), &sn, &c);
    eta += P(s.a, i) * c;
    const WavePack aw = P(s.a_omega, i), aw2 = P(s.a_omega2, i);
    // u_h = a w C cos th, u_up = a w S sin th; du/dt: th_t = -w
    const WavePack cc_c = cc * c, cc_sn = cc * sn;
    const WavePack ss_sn = kDeep ? cc_sn : ss * sn, ss_c = kDeep ? cc_c : ss * c;
    const WavePack uh = aw * cc_c, ah = aw2 * cc_sn;
    uu += aw * ss_sn;
    au -= aw2 * ss_c;
    // the velocity gradient's P = a w k C sin th and Q = a w k S cos th (wave_field.h)
    const WavePack awk = P(s.a_omega_k, i);
    const WavePack gp = awk * cc_sn, gq = awk * ss_c;
    if (kLongCrested) {
      uh_s += uh;
      ah_s += ah;
      // (also d u_h / ds = a w k (S cos th dzeta/ds - C sin th ds_along/ds), and alike: the
      // point's two rates come out of the sums, SumWaves)
      d_sc += gq;
      d_cs += gp;
      if (!kDerivative) continue;
      // along d: dth/ds = k ds_along/ds, dzeta/ds = -dz; dC/dzeta = k S, dS/dzeta = k C
      const WavePack aw2k = P(s.a_omega2_k, i), awk2 = P(s.a_omega_k2, i);
      d2_ss += aw2k * ss_sn;
      d2_cc += aw2k * cc_c;
      h_cc += awk2 * cc_c;
      h_ss += awk2 * ss_sn;
      continue;
    }
    const WavePack cb = P(s.cos_b, i), sb = P(s.sin_b, i);
    ux += uh * cb, uy += uh * sb;
    ax += ah * cb, ay += ah * sb;
    const WavePack gpc = gp * cb, gps = gp * sb;
    pxx += gpc * cb, pxy += gpc * sb, pyy += gps * sb;
    qx += gq * cb, qy += gq * sb, pp += gp;
    if (!kDerivative) continue;
    // along d: dth/ds = kx dx + ky dy, dzeta/ds = -dz; dC/dzeta = k S, dS/dzeta = k C
    const WavePack g = P(s.kx, i) * dx + P(s.ky, i) * dy;
    // dP/ds = a w k (k S sin th dzeta/ds + C cos th dth/ds), dQ/ds = a w k (k C cos th dzeta/ds
    // - S sin th dth/ds)
    const WavePack dgp = awk * (k * ss_sn * dze + cc_c * g);
    const WavePack dgq = awk * (k * cc_c * dze - ss_sn * g);
    const WavePack dgpc = dgp * cb, dgps = dgp * sb;
    dpxx += dgpc * cb, dpxy += dgpc * sb, dpyy += dgps * sb;
    dqx += dgq * cb, dqy += dgq * sb, dpp += dgp;
    const WavePack dcc = k * ss * dze, dss = k * cc * dze;
    const WavePack duh = aw * (dcc * c - cc * sn * g), dah = aw2 * (dcc * sn + cc * c * g);
    duu += aw * (dss * sn + ss * c * g);
    dau -= aw2 * (dss * c - ss * sn * g);
    dux += duh * P(s.cos_b, i), duy += duh * P(s.sin_b, i);
    dax += dah * P(s.cos_b, i), day += dah * P(s.sin_b, i);
  }
  RawSums r;
  r.eta = Sum(eta);
  r.uu = Sum(uu), r.au = Sum(au);
  if (kLongCrested) {
    r.uh = Sum(uh_s), r.ah = Sum(ah_s);
    r.d_sc = Sum(d_sc), r.d_cs = Sum(d_cs);
    if (kDerivative) {
      r.d2_ss = Sum(d2_ss), r.d2_cc = Sum(d2_cc);
      r.h_cc = Sum(h_cc), r.h_ss = Sum(h_ss);
    }
  } else {
    r.ux = Sum(ux), r.uy = Sum(uy), r.ax = Sum(ax), r.ay = Sum(ay);
    r.pxx = Sum(pxx), r.pxy = Sum(pxy), r.pyy = Sum(pyy);
    r.qx = Sum(qx), r.qy = Sum(qy), r.pp = Sum(pp);
    if (kDerivative) {
      r.dux = Sum(dux), r.duy = Sum(duy), r.duu = Sum(duu);
      r.dax = Sum(dax), r.day = Sum(day), r.dau = Sum(dau);
      r.dpxx = Sum(dpxx), r.dpxy = Sum(dpxy), r.dpyy = Sum(dpyy);
      r.dqx = Sum(dqx), r.dqy = Sum(dqy), r.dpp = Sum(dpp);
    }
  }
  return r;
}

// eta / r = sum a cos th at (x, y, t)
[[gnu::always_inline]] inline double SumElevation(const WavePackets& s, double x, double y,
                                                  double t) {
  WavePack eta = {};
  PointArgs a{};
  a.x = x, a.y = y, a.t = t;
  for (size_t i = 0; i < s.packets; ++i) {
    WavePack sn, c;
    SinCosF(Phases<false>(s, i, a), &sn, &c);
    eta += P(s.a, i) * c;
  }
  return Sum(eta);
}

// Points about a centre p, p +- o (FlowsAbout, ElevationPairs): the phase and the depth
// factor of p + o and p - o follow from those of p and of the offset by the angle-addition and
// exponential rules, cos(th +- d) = cos th cos d -+ sin th sin d, e^{k (zeta +- dz)} =
// e^{k zeta} e^{+-k dz}: the phases of p and of o in double and their sines and cosines, and
// two exponentials, instead of three of each.

// a long-crested sea's sums without derivative at one point (SumPackets' kDerivative = false,
// kLongCrested = true), one packet at a time
struct LongSums {
  WavePack eta = {}, uh = {}, ah = {}, uu = {}, au = {}, gq = {}, gp = {};
  template <bool kDeep>
  [[gnu::always_inline]] void Add(const WavePackets& s, size_t i, const WavePack& e,
                                  const WavePack& sn, const WavePack& c) {
    WavePack cc = e, ss = e;
    if (!kDeep) {
      const WavePack f = P(s.q, i) / e;
      const WavePack inv = P(s.inv_1mq, i);
      cc = (e + f) * inv, ss = (e - f) * inv;
    }
    eta += P(s.a, i) * c;
    const WavePack aw = P(s.a_omega, i), aw2 = P(s.a_omega2, i), awk = P(s.a_omega_k, i);
    const WavePack cc_c = cc * c, cc_sn = cc * sn;
    const WavePack ss_sn = kDeep ? cc_sn : ss * sn, ss_c = kDeep ? cc_c : ss * c;
    uh += aw * cc_c;
    ah += aw2 * cc_sn;
    uu += aw * ss_sn;
    au -= aw2 * ss_c;
    gq += awk * ss_c;
    gp += awk * cc_sn;
  }
  RawSums Raw() const {
    RawSums r;
    r.eta = Sum(eta), r.uh = Sum(uh), r.ah = Sum(ah), r.uu = Sum(uu), r.au = Sum(au);
    r.d_sc = Sum(gq), r.d_cs = Sum(gp);
    return r;
  }
};

// the sums at p - o, p, p + o (out[0], out[1], out[2]) of a long-crested sea: a.x, a.y, a.ze
// those of p, (ox, oy) and d_ze the offset's (all three points inside the water column)
template <bool kDeep>
[[gnu::always_inline]] inline void SumAbout(const WavePackets& s, const PointArgs& a, double ox,
                                            double oy, double d_ze, RawSums out[3]) {
  LongSums minus, centre, plus;
  const float ze = static_cast<float>(a.ze);
  const float dz = static_cast<float>(std::abs(d_ze));
  const bool up = d_ze >= 0.0;  // p + o is shallower (zeta larger)
  for (size_t i = 0; i < a.packets; ++i) {
    const WavePack k = P(s.k, i);
    const WavePack e = ExpNonPositiveF(k * ze);
    const WavePack eo = ExpNonPositiveF(-(k * dz));  // e^{-k |dz|}
    const WavePack e_deeper = e * eo, e_shallower = e / eo;
    WavePack sn, c, sd, cd;
    SinCosF(Phases<true>(s, i, a), &sn, &c);
    SinCosF(OffsetPhases(s, i, ox, oy), &sd, &cd);
    const WavePack sc = sn * cd, cs = c * sd, cc = c * cd, ss = sn * sd;
    centre.Add<kDeep>(s, i, e, sn, c);
    plus.Add<kDeep>(s, i, up ? e_shallower : e_deeper, sc + cs, cc - ss);
    minus.Add<kDeep>(s, i, up ? e_deeper : e_shallower, sc - cs, cc + ss);
  }
  out[0] = minus.Raw(), out[1] = centre.Raw(), out[2] = plus.Raw();
}

// eta / r at c + o_j and c - o_j (out[2 j], out[2 j + 1]) for `pairs` offsets whose phase
// changes are d_j = kx o_jx + ky o_jy per component
[[gnu::always_inline]] inline void SumElevationPairs(const WavePackets& s, double x, double y,
                                                     double t, const double (*o)[2], int pairs,
                                                     double* out) {
  WavePack eta[2 * EnvironmentField::kMaxElevationPairs] = {};
  PointArgs a{};
  a.x = x, a.y = y, a.t = t;
  for (size_t i = 0; i < s.packets; ++i) {
    WavePack sn, c;
    SinCosF(Phases<false>(s, i, a), &sn, &c);
    const WavePack amp = P(s.a, i);
    const WavePack ac = amp * c, as = amp * sn;
    for (int j = 0; j < pairs; ++j) {
      WavePack sd, cd;
      SinCosF(OffsetPhases(s, i, o[j][0], o[j][1]), &sd, &cd);
      // a cos(th +- d) = a cos th cos d -+ a sin th sin d
      eta[2 * j] += ac * cd - as * sd;
      eta[2 * j + 1] += ac * cd + as * sd;
    }
  }
  for (int j = 0; j < 2 * pairs; ++j) out[j] = Sum(eta[j]);
}

// the two instruction sets (packet_math.h): the x86-64 baseline (SSE2), and AVX2 where the
// processor has it; the same operations on the same lanes, so the same bits
template <bool kDerivative, bool kLongCrested, bool kDeep>
RawSums SumBaseline(const WavePackets& s, const PointArgs& a) {
  return SumPackets<kDerivative, kLongCrested, kDeep>(s, a);
}
double ElevationBaseline(const WavePackets& s, double x, double y, double t) {
  return SumElevation(s, x, y, t);
}
template <bool kDeep>
void AboutBaseline(const WavePackets& s, const PointArgs& a, double ox, double oy, double d_ze,
                   RawSums out[3]) {
  SumAbout<kDeep>(s, a, ox, oy, d_ze, out);
}
void PairsBaseline(const WavePackets& s, double x, double y, double t, const double (*o)[2],
                   int pairs, double* out) {
  SumElevationPairs(s, x, y, t, o, pairs, out);
}
#if TOWSIM_WAVES_AVX2
template <bool kDerivative, bool kLongCrested, bool kDeep>
__attribute__((target("avx2"))) RawSums SumAvx2(const WavePackets& s, const PointArgs& a) {
  return SumPackets<kDerivative, kLongCrested, kDeep>(s, a);
}
__attribute__((target("avx2"))) double ElevationAvx2(const WavePackets& s, double x, double y,
                                                     double t) {
  return SumElevation(s, x, y, t);
}
template <bool kDeep>
__attribute__((target("avx2"))) void AboutAvx2(const WavePackets& s, const PointArgs& a, double ox,
                                               double oy, double d_ze, RawSums out[3]) {
  SumAbout<kDeep>(s, a, ox, oy, d_ze, out);
}
__attribute__((target("avx2"))) void PairsAvx2(const WavePackets& s, double x, double y, double t,
                                               const double (*o)[2], int pairs, double* out) {
  SumElevationPairs(s, x, y, t, o, pairs, out);
}
bool HaveAvx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}
#endif

template <bool kDerivative, bool kLongCrested, bool kDeep>
RawSums Sums(bool avx2, const WavePackets& s, const PointArgs& a) {
#if TOWSIM_WAVES_AVX2
  if (avx2) return SumAvx2<kDerivative, kLongCrested, kDeep>(s, a);
#endif
  (void)avx2;
  return SumBaseline<kDerivative, kLongCrested, kDeep>(s, a);
}

void About(bool avx2, bool deep, const WavePackets& s, const PointArgs& a, double ox, double oy,
           double d_ze, RawSums out[3]) {
#if TOWSIM_WAVES_AVX2
  if (avx2) {
    if (deep) return AboutAvx2<true>(s, a, ox, oy, d_ze, out);
    return AboutAvx2<false>(s, a, ox, oy, d_ze, out);
  }
#endif
  (void)avx2;
  if (deep) return AboutBaseline<true>(s, a, ox, oy, d_ze, out);
  AboutBaseline<false>(s, a, ox, oy, d_ze, out);
}

// a long-crested sea's velocity u, local acceleration du/dt and convective acceleration G u
// from its sums, before the ramp (wave_field.h: along (cos b, sin b) and up, c_h = -P u_h +
// Q u_up, c_up = Q u_h + P u_up; vf 0 where the kinematics are clamped: G's last column zero)
void LongCrestedKinematics(const RawSums& m, double vf, double cos_b, double sin_b, Vec3* u,
                           Vec3* a, Vec3* c) {
  *u << m.uh * cos_b, m.uh * sin_b, -m.uu;
  *a << m.ah * cos_b, m.ah * sin_b, -m.au;
  const double gp = m.d_cs, gq = m.d_sc;
  const double ch = -gp * m.uh + vf * gq * m.uu, cu = gq * m.uh + vf * gp * m.uu;
  *c << ch * cos_b, ch * sin_b, -cu;
}

}  // namespace

EnvironmentField::EnvironmentField(const Environment& env) : env_(env) {
  const CurrentField& c = env_.current;
  const WaveField& w = env_.waves;
  has_waves_ = !w.empty();
  has_seabed_ = env_.seabed.present();
  steady_uniform_current_ = c.IsUniform() && c.IsSteady();
  uniform_ = !has_waves_ && steady_uniform_current_;
  if (steady_uniform_current_) uniform_current_ = c.Velocity(0.0, 0.0);
  if (!has_waves_) return;
  wave_depth_ = w.depth();
  deep_ = !std::isfinite(wave_depth_);
  ramp_ = w.ramp();
  std::vector<WaveComponent> comps = w.components();
  std::stable_sort(comps.begin(), comps.end(),
                   [](const WaveComponent& a, const WaveComponent& b) { return a.k < b.k; });
  long_crested_ = std::all_of(comps.begin(), comps.end(), [&](const WaveComponent& c) {
    return c.direction == comps.front().direction;
  });
  cos_b_ = std::cos(comps.front().direction);
  sin_b_ = std::sin(comps.front().direction);
#if TOWSIM_WAVES_AVX2
  avx2_ = HaveAvx2();
#endif
  WavePackets& s = waves_;
  const size_t n = comps.size();
  const size_t packets = (n + kWaveLanes - 1) / kWaveLanes;
  s.packets = packets;
  for (std::vector<double>* v : {&s.phase_kx, &s.phase_ky, &s.phase_k, &s.omega, &s.phase})
    v->assign(packets * kWaveLanes, 0.0);
  for (std::vector<float>* v : {&s.kx, &s.ky, &s.k, &s.a, &s.a_omega, &s.a_omega2, &s.a_omega_k,
                                &s.a_omega2_k, &s.a_omega_k2, &s.q, &s.inv_1mq, &s.cos_b, &s.sin_b})
    v->assign(packets * kWaveLanes, 0.0f);
  for (size_t j = 0; j < packets * kWaveLanes; ++j) {
    // the padding repeats the last component with zero amplitude: it adds exactly 0
    const WaveComponent& p = comps[std::min(j, n - 1)];
    const double a = j < n ? p.amplitude : 0.0;
    const double q = std::isfinite(wave_depth_) ? std::exp(-2.0 * p.k * wave_depth_) : 0.0;
    s.phase_kx[j] = p.k * std::cos(p.direction);
    s.phase_ky[j] = p.k * std::sin(p.direction);
    s.phase_k[j] = p.k;
    s.omega[j] = p.omega;
    s.phase[j] = p.phase;
    // the rest rounded to float once, from their double values
    s.kx[j] = static_cast<float>(s.phase_kx[j]);
    s.ky[j] = static_cast<float>(s.phase_ky[j]);
    s.k[j] = static_cast<float>(p.k);
    s.a[j] = static_cast<float>(a);
    s.a_omega[j] = static_cast<float>(a * p.omega);
    s.a_omega2[j] = static_cast<float>(a * p.omega * p.omega);
    s.a_omega_k[j] = static_cast<float>(a * p.omega * p.k);
    s.a_omega2_k[j] = static_cast<float>(a * p.omega * p.omega * p.k);
    s.a_omega_k2[j] = static_cast<float>(a * p.omega * p.k * p.k);
    s.q[j] = static_cast<float>(q);
    s.inv_1mq[j] = static_cast<float>(1.0 / (1.0 - q));
    s.cos_b[j] = static_cast<float>(std::cos(p.direction));
    s.sin_b[j] = static_cast<float>(std::sin(p.direction));
    if (j < n) {
      s.k_scalar.push_back(p.k);
      s.log_inv_1mq.push_back(-std::log1p(-q));
    }
  }
  for (const WaveComponent& p : comps) amplitude_sum_ += p.amplitude;
}

void EnvironmentField::set_avx2(bool on) {
#if TOWSIM_WAVES_AVX2
  avx2_ = on && HaveAvx2();
#else
  (void)on;
#endif
}

double EnvironmentField::Ramp(double t, double* rate) const {
  // r(t) = (1 - cos(pi t / T)) / 2 on [0, T), 1 after, 0 before 0 (wave_field.h)
  *rate = 0.0;
  if (ramp_ <= 0.0) return t < 0.0 ? 0.0 : 1.0;
  if (t <= 0.0) return 0.0;
  if (t >= ramp_) return 1.0;
  const double w = kPi / ramp_;
  *rate = 0.5 * w * std::sin(w * t);
  return 0.5 * (1.0 - std::cos(w * t));
}

FlowSample EnvironmentField::Current(const Vec3& p_W, double t, Vec3* shear) const {
  FlowSample f;
  if (steady_uniform_current_) {
    f.velocity = uniform_current_;
    if (shear) shear->setZero();
    return f;
  }
  const CurrentField& c = env_.current;
  f.velocity = c.Velocity(p_W.z(), t);
  f.acceleration = c.Acceleration(p_W.z(), t);
  if (shear) *shear = c.Shear(p_W.z(), t);
  return f;
}

double EnvironmentField::Elevation(double x, double y, double t) const {
  if (!has_waves_) return 0.0;
  double rate;
  const double r = Ramp(t, &rate);
  if (r == 0.0) return 0.0;
    // eta = r sum a cos th, eight components a packet
#if TOWSIM_WAVES_AVX2
  if (avx2_) return r * ElevationAvx2(waves_, x, y, t);
#endif
  return r * ElevationBaseline(waves_, x, y, t);
}

WaveSample EnvironmentField::Waves(const Vec3& p_W, const Vec3& d_W, double t) const {
  return SumWaves<true>(p_W, d_W, t);
}

size_t EnvironmentField::PacketsToSum(double zeta_e, bool always_wet) const {
  const WavePackets& s = waves_;
  if (!always_wet) return s.packets;
  // component j has decayed where C_j(zeta) <= e^{k_j zeta} / (1 - q_j) < kDecayCutoff, i.e.
  // k_j zeta + ln(1 / (1 - q_j)) < ln kDecayCutoff; both terms fall as k_j grows (zeta <= 0),
  // so the components to sum are a prefix of the sorted list
  const double log_cutoff = std::log(kDecayCutoff);
  size_t lo = 0, hi = s.k_scalar.size();
  while (lo < hi) {
    const size_t mid = (lo + hi) / 2;
    if (s.k_scalar[mid] * zeta_e + s.log_inv_1mq[mid] >= log_cutoff) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return (lo + kWaveLanes - 1) / kWaveLanes;
}

template <bool kDerivative>
WaveSample EnvironmentField::SumWaves(const Vec3& p_W, const Vec3& d_W, double t) const {
  if (!long_crested_) return SumWaves<kDerivative, false, false>(p_W, d_W, t);
  return deep_ ? SumWaves<kDerivative, true, true>(p_W, d_W, t)
               : SumWaves<kDerivative, true, false>(p_W, d_W, t);
}

template <bool kDerivative, bool kLongCrested, bool kDeep>
WaveSample EnvironmentField::SumWaves(const Vec3& p_W, const Vec3& d_W, double t) const {
  WaveSample out;
  if (!has_waves_) return out;
  double r_rate;
  const double r = Ramp(t, &r_rate);
  if (r == 0.0 && r_rate == 0.0) return out;
  const double zeta = -p_W.z();  // height above the mean level
  PointArgs pa;
  pa.x = p_W.x(), pa.y = p_W.y(), pa.t = t;
  pa.dx = d_W.x(), pa.dy = d_W.y();
  // crest rule: between the mean and the instantaneous surface, the kinematics at zeta = 0;
  // below the seabed those at zeta = -h (wave_field.h); the clamped coordinate does not move
  pa.ze = zeta, pa.dze = -d_W.z();
  double vf = 1.0;  // the kinematics vary with z here (0: clamped, they do not)
  if (pa.ze > 0.0) pa.ze = 0.0, pa.dze = 0.0, vf = 0.0;
  if (pa.ze < -wave_depth_) pa.ze = -wave_depth_, pa.dze = 0.0, vf = 0.0;
  // a point below every possible trough is always wet: its elevation is not needed, and it
  // may stop at the first decayed component
  const bool always_wet = zeta < -r * amplitude_sum_;
  pa.packets = PacketsToSum(pa.ze, always_wet);
  // long-crested: th = k s + phase - w t with s = x cos b + y sin b, and dth/ds = k ds along d
  pa.along = pa.x * cos_b_ + pa.y * sin_b_;
  pa.d_along = pa.dx * cos_b_ + pa.dy * sin_b_;
  // eight components a packet; the horizontal parts are summed along the direction of travel
  // (long-crested) or resolved per component
  const RawSums m = Sums<kDerivative, kLongCrested, kDeep>(avx2_, waves_, pa);
  // above the instantaneous surface (zeta > eta) the water is not there
  if (!always_wet && zeta > r * m.eta) return out;
  // the horizontal sums resolved along (cos b, sin b); c = G u, the convective acceleration
  // before the ramp (wave_field.h: G = [-P e e^T, -Q e; -Q e^T, P], its last column zero where
  // the kinematics are clamped), and dc/ds = dG/ds u + G du/ds
  Vec3 u, a, du, da, c, dc;
  if (kLongCrested) {
    LongCrestedKinematics(m, vf, cos_b_, sin_b_, &u, &a, &c);
    const double gp = m.d_cs, gq = m.d_sc;
    if (kDerivative) {
      // du_h/ds = dzeta sum awk S c - ds_along sum awk C s, du_up/ds = dzeta sum awk C s +
      // ds_along sum awk S c; da_h/ds = dzeta sum aw2k S s + ds_along sum aw2k C c,
      // da_up/ds = -(dzeta sum aw2k C c - ds_along sum aw2k S s)
      const double dze = pa.dze, dal = pa.d_along;
      const double duh = dze * m.d_sc - dal * m.d_cs, dah = dze * m.d2_ss + dal * m.d2_cc;
      const double duu = dze * m.d_cs + dal * m.d_sc;
      du << duh * cos_b_, duh * sin_b_, -duu;
      da << dah * cos_b_, dah * sin_b_, dze * m.d2_cc - dal * m.d2_ss;
      // dP/ds = dzeta sum awk2 S s + ds_along sum awk2 C c, dQ/ds = dzeta sum awk2 C c -
      // ds_along sum awk2 S s
      const double dgp = dze * m.h_ss + dal * m.h_cc, dgq = dze * m.h_cc - dal * m.h_ss;
      const double dch = -dgp * m.uh - gp * duh + vf * (dgq * m.uu + gq * duu);
      const double dcu = dgq * m.uh + gq * duh + vf * (dgp * m.uu + gp * duu);
      dc << dch * cos_b_, dch * sin_b_, -dcu;
    }
  } else {
    u << m.ux, m.uy, -m.uu;
    a << m.ax, m.ay, -m.au;
    Eigen::Matrix3d g;
    g << -m.pxx, -m.pxy, -vf * m.qx, -m.pxy, -m.pyy, -vf * m.qy, -m.qx, -m.qy, vf * m.pp;
    c = g * u;
    if (kDerivative) {
      du << m.dux, m.duy, -m.duu;
      da << m.dax, m.day, -m.dau;
      Eigen::Matrix3d dg;
      dg << -m.dpxx, -m.dpxy, -vf * m.dqx, -m.dpxy, -m.dpyy, -vf * m.dqy, -m.dqx, -m.dqy,
          vf * m.dpp;
      dc = dg * u + g * du;
    }
  }
  // NED: w = -u_up; the ramp scales the velocity, and its rate adds r' u to the acceleration;
  // the material acceleration Du/Dt = du/dt + (r G)(r u)
  out.velocity = r * u;
  out.acceleration = r * a + r_rate * u + (r * r) * c;
  if (kDerivative) {
    out.d_velocity = r * du;
    out.d_acceleration = r * da + r_rate * du + (r * r) * dc;
  }
  return out;
}

template WaveSample EnvironmentField::SumWaves<true>(const Vec3&, const Vec3&, double) const;
template WaveSample EnvironmentField::SumWaves<false>(const Vec3&, const Vec3&, double) const;

FlowSample EnvironmentField::Flow(const Vec3& p_W, double t) const {
  FlowSample f = Current(p_W, t);
  if (has_waves_) {
    const WaveSample w = SumWaves<false>(p_W, Vec3::Zero(), t);
    f.velocity += w.velocity;
    f.acceleration += w.acceleration;
  }
  return f;
}

void EnvironmentField::FlowsAbout(const Vec3& p_W, const Vec3& o_W, double t,
                                  FlowSample out[3]) const {
  const Vec3 points[3] = {p_W - o_W, p_W, p_W + o_W};
  double r_rate = 0.0;
  const double r = has_waves_ ? Ramp(t, &r_rate) : 0.0;
  // zeta of p, and of p + o: zeta + dz
  const double zeta = -p_W.z(), dz = -o_W.z();
  const double k_max = has_waves_ ? waves_.k_scalar.back() : 0.0;
  // the shared sums: a long-crested sea, the three points below the mean level and above the
  // seabed (no clamping: wave_field.h), the offset's depth factor within float's range (e^-80:
  // E / e^{-k |dz|} stays finite) and in finite depth every point's (F = q / E stays finite)
  const bool shared = has_waves_ && (r != 0.0 || r_rate != 0.0) && long_crested_ &&
                      zeta + std::abs(dz) <= 0.0 && zeta - std::abs(dz) >= -wave_depth_ &&
                      k_max * std::abs(dz) <= 80.0 &&
                      (deep_ || k_max * (std::abs(zeta) + std::abs(dz)) <= 80.0);
  if (!shared) {
    for (int i = 0; i < 3; ++i) out[i] = Flow(points[i], t);
    return;
  }
  bool always_wet[3], all_wet = true;
  for (int i = 0; i < 3; ++i) {
    out[i] = Current(points[i], t);
    always_wet[i] = -points[i].z() < -r * amplitude_sum_;
    all_wet = all_wet && always_wet[i];
  }
  PointArgs pa{};
  pa.x = p_W.x(), pa.y = p_W.y(), pa.t = t, pa.ze = zeta;
  pa.along = pa.x * cos_b_ + pa.y * sin_b_;
  // the shallowest point decays last: its components are summed for all three
  pa.packets = PacketsToSum(zeta + std::abs(dz), all_wet);
  RawSums m[3];
  About(avx2_, deep_, waves_, pa, o_W.x(), o_W.y(), dz, m);
  for (int i = 0; i < 3; ++i) {
    // above the instantaneous surface the water is not there (the current alone, as Flow)
    if (!always_wet[i] && -points[i].z() > r * m[i].eta) continue;
    Vec3 u, a, c;
    LongCrestedKinematics(m[i], 1.0, cos_b_, sin_b_, &u, &a, &c);
    out[i].velocity += r * u;
    out[i].acceleration += r * a + r_rate * u + (r * r) * c;
  }
}

void EnvironmentField::ElevationPairs(double x, double y, const double (*o)[2], int pairs, double t,
                                      double* out) const {
  double rate;
  const double r = has_waves_ ? Ramp(t, &rate) : 0.0;
  if (r == 0.0 || pairs > kMaxElevationPairs) {
    for (int j = 0; j < pairs; ++j) {
      out[2 * j] = Elevation(x + o[j][0], y + o[j][1], t);
      out[2 * j + 1] = Elevation(x - o[j][0], y - o[j][1], t);
    }
    return;
  }
#if TOWSIM_WAVES_AVX2
  if (avx2_) {
    PairsAvx2(waves_, x, y, t, o, pairs, out);
  } else {
    PairsBaseline(waves_, x, y, t, o, pairs, out);
  }
#else
  PairsBaseline(waves_, x, y, t, o, pairs, out);
#endif
  for (int j = 0; j < 2 * pairs; ++j) out[j] *= r;
}

}  // namespace towsim::core
