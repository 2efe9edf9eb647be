#pragma once
// A vessel (docs/vessels.md): a kinematic 6-DOF body whose motion is prescribed. Cables hold
// to it at body-fixed points (the A-frame); their loads are reported but do not move it. Its
// pose is the sum of
//   - a course: the reference point moves at speed U(t) along the heading psi(t) on the
//     surface plane, U and psi changed by course entries with smooth, bounded accelerations
//     (vessel_course.h);
//   - harmonic motions about the moving reference (HarmonicMotion);
//   - the response to the scene's waves through displacement RAOs (RaoTable);
// or it is replaced by a time history of poses (TimeHistory), or given each step by another
// program (external: the node sets it, Simulation::SetVesselPose).
//
// Frames: world NED; the vessel's body frame x forward, y starboard, z down. The six degrees
// of freedom, as the RAOs and harmonics use them, about the moving reference frame (origin at
// the course position, x along the heading):
//   surge  x, forward [m]      roll   about x, starboard down positive [rad]
//   sway   y, starboard [m]    pitch  about y, bow up positive [rad]
//   heave  up positive [m]     yaw    about z, bow to starboard positive [rad]
// (heave is -z; the rotations are the ZYX Euler angles' roll, pitch and the yaw added to the
// course's heading).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace towsim::core {

enum class VesselDof { kSurge = 0, kSway, kHeave, kRoll, kPitch, kYaw };
inline constexpr int kVesselDofs = 6;

// A harmonic motion of one degree of freedom about the moving reference:
//   xi(t) = amplitude cos(2 pi t / period - phase)
// (phase is a lag: the maximum comes at t = phase period / (2 pi)).
struct HarmonicMotion {
  VesselDof dof = VesselDof::kHeave;
  double amplitude = 0.0;  // [m] (surge, sway, heave) or [rad] (roll, pitch, yaw)
  double period = 1.0;     // [s], > 0
  double phase = 0.0;      // [rad]
};

// Displacement RAOs on a grid of wave periods and directions (docs/vessels.md "RAOs"): for a
// wave component of amplitude a, period T and direction beta relative to the heading (the
// direction it travels toward, from the bow toward starboard: 0 following seas, 180 deg head
// seas) whose crest phase at the vessel's reference point is theta(t) (increasing in time,
// eta = a cos theta), degree of freedom j answers
//   xi_j(t) = a |H_j(T, beta)| cos(theta(t) - phi_j(T, beta))
// (phi_j the lag of the response's maximum behind the crest). Tables are bilinear in period
// and direction, with the complex value H = |H| e^{-i phi} interpolated (so that phases wrap).
struct RaoTable {
  std::vector<double> periods;     // strictly increasing [s], >= 1 entry
  std::vector<double> directions;  // strictly increasing [rad] within [-pi, pi] or [0, 2 pi)
  // per degree of freedom, row-major [period][direction]: amplitude [m/m or rad/m] and phase
  // lag [rad]; a degree of freedom absent from the file is zero
  std::array<std::vector<double>, kVesselDofs> amplitude;
  std::array<std::vector<double>, kVesselDofs> phase;
  // the sea's periods and directions outside the table: false refuses them when the scene is
  // read; true holds the nearest entry (constant extrapolation)
  bool extrapolate = false;
  // directions cover the full circle (the table spans 360 deg with its wrap-around): the
  // interpolation wraps between the last and the first direction
  bool periodic_directions = false;
  std::string source;  // the file it came from, for messages
};

// A time history of the vessel's pose (docs/vessels.md "Time history"): samples at strictly
// increasing times, world NED position of the reference point [m] and ZYX Euler angles [rad]
// (yaw unwrapped: no jump of 2 pi between samples), interpolated by a cubic spline per channel
// so that velocities and accelerations are continuous.
struct TimeHistory {
  std::vector<double> t;                              // [s]
  std::vector<Eigen::Matrix<double, 6, 1>> pose;      // [x, y, z, roll, pitch, yaw]
  std::string source;
};

// A change of the course at time `at` (scene script entries on a vessel): a new speed, a new
// heading approached at a turn rate, or a steady turn at a rate.
struct CourseChange {
  double at = 0.0;  // [s]
  bool set_speed = false;
  double speed = 0.0;  // [m/s]
  bool set_heading = false;
  double heading = 0.0;  // target heading [rad]; the turn takes the shorter way
  bool set_turn_rate = false;
  // |turn rate| of the turn to `heading` [rad/s] (> 0); without a heading: a steady turn at
  // this signed rate (+ to starboard), kept until the next heading or turn entry
  double turn_rate = 0.0;
};

struct Vessel {
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // reference point at t = 0 [m]
  Eigen::Vector3d euler = Eigen::Vector3d::Zero();     // roll, pitch, heading at t = 0 [rad]
  double speed = 0.0;                                  // along the heading at t = 0 [m/s]
  // the course's limits: the largest |dU/dt| of a speed change [m/s^2] and the largest
  // |d^2 psi / dt^2| of a change of turn rate [rad/s^2]
  double max_acceleration = 0.1;
  double max_yaw_acceleration = 0.01;
  std::vector<CourseChange> course;  // ordered by `at`
  std::vector<HarmonicMotion> harmonics;
  std::optional<RaoTable> raos;
  std::optional<TimeHistory> time_history;  // replaces course, harmonics and RAOs
  bool external = false;  // the pose comes from another program each step (DDS node only)
};

}  // namespace towsim::core
