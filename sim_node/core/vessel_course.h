#pragma once
// A vessel's course (docs/vessels.md "Course"): its reference point moves on the horizontal
// plane at speed U(t) along the heading psi(t) (NED: psi from north toward east),
//   dx/dt = U cos psi,  dy/dt = U sin psi,  z constant,
// with U and the turn rate r = dpsi/dt changed by course entries (CourseChange) through
// cosine ramps: a change of a quantity from f_a to f_b over T,
//   f(s) = f_a + (f_b - f_a) (1 - cos(pi s / T)) / 2,   0 <= s <= T,
// has the largest rate pi |f_b - f_a| / (2 T) at mid-ramp and zero rate at both ends, so the
// acceleration (of U) and the yaw acceleration (of r) are continuous through a change that
// starts from rest and bounded by the vessel's limits: T = pi |f_b - f_a| / (2 f'_max).
//
//   speed entry {speed: U_b}:    U ramps from its value at `at` to U_b (max_acceleration).
//   turn entry {turn_rate: r_b}: r ramps to r_b and holds it (a steady turn; + to starboard).
//   heading entry {heading, turn_rate R}: the turn takes the shorter way, dpsi wrapped into
//     (-pi, pi]; r ramps from r_0 to +-R, holds, and ramps back to 0 so that psi ends at the
//     target: the heading gained on a ramp is (r_a + r_b) T / 2. A change too small to reach R
//     ramps up to the peak P with P^2 = (4 alpha |dpsi| / pi + rho_0^2) / 2 (rho_0 = r_0 in the
//     turn's direction) and straight back down; a vessel already turning too fast to stop in
//     time ramps down at once and overshoots (docs/vessels.md).
// An entry that comes while a ramp of its quantity runs starts from the values at its time:
// the ramp is cut there (the acceleration jumps by at most its limit).
//
// Each quantity is a list of pieces (ramps and holds) in closed form; psi on a ramp is
//   psi(s) = psi_a + r_a s + (r_b - r_a) (s - (T / pi) sin(pi s / T)) / 2.
// The position integrates U cos psi, U sin psi: in closed form where both hold (a straight
// line or a circle of radius U / r), by 5-point Gauss-Legendre on pieces of at most 0.5 s
// where one ramps (exact to degree 9 on an integrand smooth over seconds: the error is far
// below a micrometre); the
// positions at the pieces' joints are computed once, so a query costs at most one ramp's
// quadrature. Pure: a function of time only.

#include <vector>

#include <Eigen/Core>

#include "core/vessel.h"

namespace towsim::core {

// The course's motion at a time (world NED).
struct CourseSample {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      // [m]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // [m/s]
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // [m/s^2]
  double heading = 0.0;       // psi [rad] (unwrapped: continuous through turns)
  double turn_rate = 0.0;     // r = dpsi/dt [rad/s]
  double yaw_acceleration = 0.0;  // dr/dt [rad/s^2]
  double speed = 0.0;         // U [m/s]
};

class VesselCourse {
 public:
  VesselCourse() = default;
  explicit VesselCourse(const Vessel& vessel);

  CourseSample At(double t) const;

 private:
  // f(t) on [t0, t1): a cosine ramp from fa to fb over [t0, t0 + T] (a hold when T == 0); t1
  // infinite for the last piece, t1 < t0 + T when a later entry cut the ramp
  struct Piece {
    double t0 = 0.0, t1 = 0.0;
    double T = 0.0;
    double fa = 0.0, fb = 0.0;
    double ga = 0.0;  // the integral of f at t0 (the heading, for the turn rate's pieces)
  };
  static void Eval(const Piece& p, double t, double* f, double* df, double* integral);
  static int Find(const std::vector<Piece>& pieces, double t);
  // ends *pieces at `at` (a piece starting there is dropped) and gives the value, its rate
  // and its integral there
  static void CutAt(std::vector<Piece>* pieces, double at, double* f, double* integral);
  // appends a ramp from the last piece's end value to fb over T (a hold when T == 0), ending
  // at t1 (infinite: the last)
  static void Append(std::vector<Piece>* pieces, double t0, double T, double fa, double fb,
                     double ga);
  // a ramp from the value at `at` to fb at rate limit `limit`, then a hold
  static void RampTo(std::vector<Piece>* pieces, double at, double fb, double limit);
  // a turn from the heading at `at` to `target` at |rate| `rate`, yaw acceleration <= alpha
  void Heading(double at, double target, double rate, double alpha);
  // speed and heading at t, and d/dt of the position
  Eigen::Vector2d Velocity(double t) const;
  // the horizontal position at t from the joint `j` (joints_[j] <= t)
  Eigen::Vector2d Integrate(double t0, const Eigen::Vector2d& x0, double t) const;

  double z_ = 0.0;
  std::vector<Piece> speed_;  // U(t)
  std::vector<Piece> turn_;   // r(t), ga: psi at t0
  // the joints of both lists, ordered, and the horizontal position at each
  std::vector<double> joints_;
  std::vector<Eigen::Vector2d> joint_position_;
};

}  // namespace towsim::core
