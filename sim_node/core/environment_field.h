#pragma once
// The sea as every load sees it (docs/environment.md): at a point p_W (world NED, z down) and a
// time t, the water's velocity and acceleration (current + linear waves), the free-surface
// elevation and the seabed's depth and normal. Built once from Model::environment; the cable,
// the sphere bodies and the vehicles read the water only through it, and take the water's
// velocity off their own in one place, RelativeVelocity below.
//
//   u(p, t) = U_c(z, t) + u_w(p, t)     [m/s]   current (current_field.h) + waves (wave_field.h)
//   a(p, t) = DU_c/Dt  + Du_w/Dt        [m/s^2] each one's material acceleration,
//             Du_w/Dt = du_w/dt + (u_w . grad) u_w   (wave_field.h; docs/physics.md, "Fluid
//             inertia in waves")
// The waves ride on the current without interacting with it (their frequencies and
// dispersion are those of still water), and the cross terms of the material derivative of the
// sum, (U_c . grad) u_w + (u_w . grad) U_c, which are that interaction's Doppler shift and
// refraction, are left out with it.
//
// Two costs are kept apart because they differ by two orders of magnitude:
//   - the current is a table look-up: loads evaluate it exactly wherever and whenever they
//     need it (every Gauss point, every Newton iteration), with its shear dU/dz for the Newton
//     matrix;
//   - the waves cost a sine, a cosine and an exponential per component and point: the
//     integrator samples them once per step (at t_{n+1}, at the predicted positions) at the
//     cable nodes, with their derivative along the cable, and the loads interpolate them to the
//     Gauss points with the element's own cubic Hermite shape functions (WaveSample below).
//     The error this costs is measured in tests/unit/environment_field_test.cc and
//     docs/environment.md.
// A steady uniform current without waves is flagged uniform(): loads take the one velocity and
// never evaluate the field per point, so a scene without waves or a current profile pays
// nothing for them.

#include <vector>

#include <Eigen/Core>

#include "core/flow_sample.h"
#include "core/model.h"
#include "core/packet_math.h"

namespace towsim::core {

// The wave components as the sums read them: a structure of arrays of eight-component packets
// (packet_math.h; packet i is the entries [8 i, 8 i + 8) of each array), sorted by increasing k
// (so that a point at depth can stop at the first component that has decayed, see
// kDecayCutoff), padded with zero-amplitude copies of the last one to a whole packet. The
// phase k s - w t + f is formed and reduced to [-pi, pi] in double (its constants in double);
// everything after it, in float (docs/environment.md, "Cost").
constexpr int kWaveLanes = 8;
using WavePack = PackF8;
struct WavePackets {
  size_t packets = 0;
  // the phase's constants (double)
  std::vector<double> phase_kx, phase_ky, phase_k, omega, phase;
  std::vector<float> kx, ky, k, a, a_omega, a_omega2, q, inv_1mq, cos_b, sin_b;
  // a w k, a w^2 k, a w k^2: the velocity gradient and the sums' derivative along a direction
  std::vector<float> a_omega_k, a_omega2_k, a_omega_k2;
  // per component (unpadded): k and ln(1 / (1 - q)), for the depth cut-off's search
  std::vector<double> k_scalar, log_inv_1mq;
};

// The waves' kinematics at a point and their derivative along a direction d:
// d/ds u_w(p + s d) at s = 0 (d = r' at a cable node: the derivative along the cable).
struct WaveSample {
  Vec3 velocity = Vec3::Zero();      // [m/s]
  Vec3 acceleration = Vec3::Zero();  // Du/Dt = du/dt + (u . grad) u [m/s^2] (material)
  Vec3 d_velocity = Vec3::Zero();    // d u / ds [1/s] (per unit s of p + s d)
  Vec3 d_acceleration = Vec3::Zero();
};

class EnvironmentField {
 public:
  explicit EnvironmentField(const Environment& env);

  const Environment& environment() const { return env_; }
  // the same flow at every point and time (a steady uniform current, no waves)
  bool uniform() const { return uniform_; }
  // the current's velocity where uniform() or steady_uniform_current()
  const Vec3& uniform_current() const { return uniform_current_; }
  // the current alone is the same everywhere and always (waves may still be there)
  bool steady_uniform_current() const { return steady_uniform_current_; }
  bool has_waves() const { return has_waves_; }
  bool has_seabed() const { return has_seabed_; }
  // the wave sums run compiled for AVX2 (where the processor has it; environment_field.cc);
  // set_avx2(false) takes the baseline path, which gives the same bits (a test checks it);
  // set_avx2(true) where there is no AVX2 changes nothing
  bool avx2() const { return avx2_; }
  void set_avx2(bool on);

  // the current alone at p_W, t (cheap); dU/dz in *shear [1/s] when asked
  FlowSample Current(const Vec3& p_W, double t, Vec3* shear = nullptr) const;
  // the waves alone at p_W, t, with their derivative along d_W (zero above the instantaneous
  // surface; see wave_field.h for the crest and seabed rules, which this follows)
  WaveSample Waves(const Vec3& p_W, const Vec3& d_W, double t) const;
  // current + waves at p_W, t
  FlowSample Flow(const Vec3& p_W, double t) const;
  // Flow at p_W - o_W, p_W, p_W + o_W (out[0..2]; a vehicle's hull stations): in a
  // long-crested sea, with the three points inside the water column, the phases and depth
  // factors of the outer two by the angle-addition and exponential rules from those of p_W and
  // o_W (environment_field.cc); else three Flow. Equal to three Flow to float rounding.
  void FlowsAbout(const Vec3& p_W, const Vec3& o_W, double t, FlowSample out[3]) const;
  // free-surface elevation eta(x, y, t), positive UP [m] (the surface is at z_W = -eta)
  double Elevation(double x, double y, double t) const;
  // Elevation at (x, y) + o_j and (x, y) - o_j (out[2 j], out[2 j + 1]) for `pairs` horizontal
  // offsets o_j (a waterline's stations): the phase of (x, y) once, each offset's change by
  // the angle-addition rule (at most kMaxElevationPairs pairs, else point by point). Equal to
  // Elevation to float rounding.
  void ElevationPairs(double x, double y, const double (*o)[2], int pairs, double t,
                      double* out) const;
  static constexpr int kMaxElevationPairs = 4;  // more: point by point

  // seabed (has_seabed()): depth of the bottom at (x, y) (its NED z) [m], unit normal into
  // the water (mostly -z) and the contact parameters (seabed_contact.h gives their meaning)
  double SeabedDepth(double x, double y) const { return env_.seabed.Depth(x, y); }
  Vec3 SeabedNormal(double x, double y) const { return env_.seabed.Normal(x, y); }
  double SeabedShallowest() const { return env_.seabed.Shallowest(); }
  // range from `origin` along the unit `direction` to the bed, at most max_range [m]
  // (Seabed::RayRange: +inf no return, also without a seabed; -inf origin below the bed)
  double SeabedRayRange(const Vec3& origin, const Vec3& direction, double max_range) const {
    return env_.seabed.RayRange(origin, direction, max_range);
  }
  const SeabedContact& seabed_contact() const { return env_.seabed.contact(); }

 private:
  // packets to sum at a point of height zeta_e above the mean level (all, or those before the
  // first decayed component when the point is always wet)
  size_t PacketsToSum(double zeta_e, bool always_wet) const;
  // kDeep: infinitely deep water (q = 0: C = S = e^{k zeta}, no division)
  template <bool kDerivative, bool kLongCrested, bool kDeep>
  WaveSample SumWaves(const Vec3& p_W, const Vec3& d_W, double t) const;
  template <bool kDerivative>
  WaveSample SumWaves(const Vec3& p_W, const Vec3& d_W, double t) const;
  double Ramp(double t, double* rate) const;

  Environment env_;
  bool uniform_ = true;
  bool steady_uniform_current_ = true;
  bool has_waves_ = false;
  bool has_seabed_ = false;
  Vec3 uniform_current_ = Vec3::Zero();
  WavePackets waves_;
  bool avx2_ = false;           // the sums compiled for AVX2 run here (environment_field.cc)
  double wave_depth_ = 0.0;     // h [m], infinity for deep water
  bool deep_ = false;           // h infinite
  double ramp_ = 0.0;           // [s]
  double amplitude_sum_ = 0.0;  // sum a_i: no crest rises higher [m]
  // every component travels the same way (b, a long-crested sea): the horizontal sums are
  // formed along it once, and the phase is k (x cos b + y sin b)
  bool long_crested_ = false;
  double cos_b_ = 1.0, sin_b_ = 0.0;
};

}  // namespace towsim::core
