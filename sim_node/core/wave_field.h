#pragma once
// Linear (Airy) surface waves: a sum of long-crested components over water of depth h (finite
// or infinite), in the world frame NED (x north, y east, z down).
//
// Component i: amplitude a_i [m], angular frequency w_i [rad/s], wave number k_i [1/m] from the
// dispersion relation w^2 = g k tanh(k h), direction b_i [rad] toward which it travels (from +x
// toward +y), phase f_i [rad]. With the phase function
//   th_i(x, y, t) = k_i (x cos b_i + y sin b_i) - w_i t + f_i
// and zeta = -z the height above the mean surface (positive up), linear theory gives
//   elevation     eta   = r(t) sum a_i cos th_i                                 (positive up)
//   potential     phi   = r(t) sum (a_i g / w_i) cosh k_i(zeta + h) / cosh k_i h  sin th_i
//   velocity      u_h   = r(t) sum a_i w_i  C_i(zeta) cos th_i  [cos b_i, sin b_i] (horizontal)
//                 u_up  = r(t) sum a_i w_i  S_i(zeta) sin th_i                  (upward)
//   acceleration  du/dt of the above (including the ramp's dr/dt)
//   dyn. pressure p_d   = -rho dphi/dt = rho g r(t) sum a_i K_i(zeta) cos th_i  (without r')
// with C = cosh k(zeta + h)/sinh kh, S = sinh k(zeta + h)/sinh kh, K = cosh k(zeta + h)/cosh kh.
// In deep water (h infinite) C = S = K = exp(k zeta). They are evaluated with one exponential
// per component: E = exp(k zeta), q = exp(-2 k h), F = q / E,
//   C = (E + F) / (1 - q),  S = (E - F) / (1 - q),  K = (E + F) / (1 + q).
// The NED vertical velocity is w = -u_up. With P = a w k C sin th, Q = a w k S cos th and the
// unit direction e = [cos b, sin b] the velocity gradient G_ij = du_i/dx_j (NED) is, per
// component,
//   G = r(t) [ -P e e^T   -Q e ]
//            [ -Q e^T      P   ]
// (symmetric: the flow is irrotational; trace 0: it is incompressible), and the acceleration a
// fluid particle has is the material derivative
//   Du/Dt = du/dt + (u . grad) u = du/dt + G u.
// The convective part G u is second order in the amplitude, but it is what keeps a body that
// moves with the water at its mean depth: du/dt alone, taken at a particle's displaced
// position, has the mean -(u . grad) u, e.g. a^2 w^2 k e^{2 k zeta} downward in deep water
// (docs/physics.md, "Fluid inertia in waves"). Kinematics gives both, the local du/dt and the
// material Du/Dt.
//
// Where linear theory is silent:
//   - above the instantaneous surface (z < -eta) the flow is zero (velocity, acceleration and
//     pressure all 0; `wet` false);
//   - between the mean and the instantaneous surface (-eta <= z < 0, a crest) the kinematics are
//     those at the mean surface z = 0 ("vertical stretching" by constant extension, as OrcaFlex
//     and MoorDyn offer it), so they stay bounded;
//   - below the seabed depth h (z > h) they are those at z = h;
//   in both the kinematics do not vary with z there: the gradient's last column is zero.
// The ramp r(t) = (1 - cos(pi t / T_r)) / 2 for 0 <= t < T_r, 1 after (and 0 before t = 0),
// lets the waves start from calm water without a start-up shock.
//
// Irregular seas (Irregular): a one-sided spectrum S(w) (JONSWAP or Pierson-Moskowitz, in Hs and
// Tp) split into N bins of equal energy m0/N over the band that holds all but a fraction
// kSpectrumTailFraction at each end; each component gets a = sqrt(2 m0 / N) (so the
// components carry the whole m0 and Hs = 4 sqrt(m0) exactly), a frequency drawn uniformly within
// its bin and a phase uniform in [0, 2 pi). Random frequencies make the frequencies
// incommensurate, so the record never repeats (equally spaced frequencies dw would repeat after
// 2 pi / dw, e.g. 300 s for 100 components); equal energy gives each component the same weight,
// so few components reproduce the spectrum where it matters. The random numbers come from
// std::mt19937_64 (its sequence is fixed by the C++ standard) mapped to [0, 1) by our own
// UniformUnit, not by a std distribution (those differ between standard libraries): the same
// seed gives the same sea everywhere.
//
// Per point, Kinematics costs one exp, one sin/cos pair and about 40 flops per component; the
// per-component constants (k cos b, k sin b, a w, a w^2, rho g a, q, ...) are precomputed.
// Queries never allocate.

#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

namespace towsim::core {

// k [1/m] solving w^2 = g k tanh(k h) for w > 0, h > 0 (h = infinity: k = w^2 / g), g > 0.
// Newton's method on f(k) = g k tanh(k h) - w^2 from Eckart's (1952) explicit approximation,
// to a relative residual at round-off (about 1e-15); returns 0 for w = 0.
double WaveNumber(double omega, double depth, double gravity);

// One Airy component; `k` comes from the dispersion relation.
struct WaveComponent {
  double amplitude = 0.0;  // a [m]
  double omega = 0.0;      // w [rad/s]
  double k = 0.0;          // wave number [1/m]
  double direction = 0.0;  // b [rad], toward which it travels, from +x toward +y
  double phase = 0.0;      // f [rad]
};

// What the water does at a point and time (world frame NED).
struct WaveKinematics {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // u [m/s]
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // du/dt [m/s^2] (local)
  // G_ij = du_i/dx_j [1/s] (NED)
  Eigen::Matrix3d velocity_gradient = Eigen::Matrix3d::Zero();
  // Du/Dt = du/dt + G u [m/s^2]: the acceleration of the water particle at the point
  Eigen::Vector3d material_acceleration = Eigen::Vector3d::Zero();
  double dynamic_pressure = 0.0;  // p_d [Pa] (the hydrostatic rho g z not included)
  double elevation = 0.0;         // eta at the point's (x, y) [m], positive up
  bool wet = false;               // the point is below the instantaneous surface (z >= -eta)
};

enum class WaveSpectrumKind { kJonswap, kPiersonMoskowitz };

// An irregular long-crested sea.
struct WaveSpectrum {
  WaveSpectrumKind kind = WaveSpectrumKind::kJonswap;
  double hs = 0.0;         // significant wave height H_s = 4 sqrt(m0) [m], > 0
  double tp = 0.0;         // peak period T_p = 2 pi / w_p [s], > 0
  double gamma = 3.3;      // JONSWAP peak enhancement, >= 1 (1: Pierson-Moskowitz shape)
  double direction = 0.0;  // [rad], toward which it travels
  int components = 100;    // N >= 1
  std::uint64_t seed = 1;  // of the frequencies and phases
};

// S(w) [m^2 s/rad] of the spectrum, normalised so that its integral over (0, inf) is Hs^2/16:
//   S(w) = A w^-5 exp(-5/4 (w_p/w)^4) gamma^exp(-(w - w_p)^2 / (2 s^2 w_p^2)),
//   s = 0.07 for w <= w_p, 0.09 above (DNV-RP-C205 3.5.5); Pierson-Moskowitz: gamma = 1.
// A is computed by quadrature (not the 1 - 0.287 ln gamma fit), so m0 is exact.
double SpectralDensity(const WaveSpectrum& spectrum, double omega);

// Uniform in [0, 1) with 53 random bits from one draw of mt19937_64: (x >> 11) 2^-53.
double UniformUnit(std::uint64_t draw);

class WaveField {
 public:
  using Vec3 = Eigen::Vector3d;

  // fraction of m0 left out of the band at each end of an irregular sea's spectrum
  static constexpr double kSpectrumTailFraction = 1e-3;

  // calm water
  WaveField() = default;
  // calm water of depth h (infinity: deep), gravity g, density rho; components come later
  WaveField(double depth, double gravity, double density);

  // a regular wave of height H = 2a, period T, direction and phase [rad]
  static WaveField Regular(double height, double period, double direction, double phase,
                           double depth, double gravity, double density);
  // an irregular sea (see the top comment)
  static WaveField Irregular(const WaveSpectrum& spectrum, double depth, double gravity,
                             double density);

  // appends a component; its k from WaveNumber(omega, depth, gravity)
  void AddComponent(double amplitude, double omega, double direction, double phase);
  // cosine ramp of the amplitudes over [0, ramp] [s]; 0: none
  void set_ramp(double ramp) { ramp_ = ramp; }

  // eta(x, y, t) [m], positive up: the surface is at z_NED = -eta
  double Elevation(double x, double y, double t) const;
  // eta at the nodes of the grid x_i = x0 + i dx (i < nx), y_j = y0 + j dy (j < ny) at t:
  // out[i ny + j] (nx ny values). The sum of Elevation with cos(A_i + B_j) = cos A_i cos B_j -
  // sin A_i sin B_j, A_i = kx x_i - w t + f, B_j = ky y_j: 2 (nx + ny) sines and cosines per
  // component instead of nx ny cosines (equal to Elevation to rounding). `work` is resized to
  // 2 (nx + ny) (no allocation once it is that large).
  void ElevationGrid(double x0, double dx, int nx, double y0, double dy, int ny, double t,
                     std::vector<double>* work, double* out) const;
  // velocity, acceleration and dynamic pressure at p_W (NED) and t; zero above the surface
  WaveKinematics Kinematics(const Vec3& p_W, double t) const;

  bool empty() const { return terms_.empty(); }
  const std::vector<WaveComponent>& components() const { return components_; }
  double depth() const { return depth_; }  // h [m], infinity for deep water
  double gravity() const { return gravity_; }
  double density() const { return density_; }
  double ramp() const { return ramp_; }
  // the start-up ramp r(t) of the amplitudes and its first two derivatives
  double Ramp(double t) const;
  double RampRate(double t) const;
  double RampAcceleration(double t) const;

 private:
  // precomputed per component
  struct Term {
    double kx, ky;    // k cos b, k sin b [1/m]
    double k;         // [1/m]
    double omega;     // [rad/s]
    double phase;     // [rad]
    double a;         // a [m]
    double a_omega;   // a w [m/s]
    double a_omega2;  // a w^2 [m/s^2]
    double rho_g_a;   // rho g a [Pa]
    double q;         // exp(-2 k h) (0: deep)
    double inv_1mq;   // 1 / (1 - q)
    double inv_1pq;   // 1 / (1 + q)
    double cos_b, sin_b;
  };
  double depth_ = std::numeric_limits<double>::infinity();
  double gravity_ = 9.81;
  double density_ = 1025.0;
  double ramp_ = 0.0;
  std::vector<WaveComponent> components_;
  std::vector<Term> terms_;
};

}  // namespace towsim::core
