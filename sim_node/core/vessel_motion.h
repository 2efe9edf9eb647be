#pragma once
// A vessel's prescribed pose over time (vessel.h, docs/vessels.md): the course (vessel_course.h)
// plus the harmonic motions and the response to the waves about the moving reference, or a
// time history (pose_spline.h), or the pose another program gives (external).
//
// About the reference moving with the course (origin p_c, heading psi, turn rate r), the six
// motions xi = [surge, sway, heave, roll, pitch, yaw] give, with R_psi the rotation by psi about
// z and d = [xi_surge, xi_sway, -xi_heave] (heave up is -z),
//   position  p = p_c + R_psi d
//   velocity  v = v_c + R_psi (d' + r S d)
//   accel.    a = a_c + R_psi (d'' + 2 r S d' + r' S d + r^2 S^2 d)
// (S the 90 deg rotation of the horizontal plane, S [x, y] = [-y, x]; z is not rotated), and the
// ZYX Euler angles [roll_0 + xi_roll, pitch_0 + xi_pitch, psi + xi_yaw] (roll_0, pitch_0 the
// scene's trim).
//   harmonic:  xi = A cos(w t - phi),  xi' = -A w sin(w t - phi),  xi'' = -w^2 xi.
//   waves:     per component i (wave_field.h) and degree of freedom j, with the crest phase
//              theta_i = w_i t - k_i (x_c cos b_i + y_c sin b_i) - f_i at the course's reference
//              point (increasing in time, eta = a cos theta; the vessel meets the wave at its
//              encounter frequency w_e = w_i - k_i (u_c cos b_i + v_c sin b_i)) and
//              H = RaoAt(T_i, b_i - psi) = |H| e^{-i phi} (phi the lag; rao_table.h),
//                xi_j = R(t) sum_i a_i Re(H e^{i theta_i}),
//              R(t) the sea's start-up ramp (wave_field.h); the derivatives take theta' and
//              theta'' from the course's velocity and acceleration and R', R'' (H's change as
//              the vessel turns is slow and left out of the derivatives).
//   time history: the pose and its derivatives from the spline (pose_spline.h).
//   external: the pose last given (SetExternal) at its time t_e, carried forward to t by its
//              velocity and Euler rates: p(t) = p_e + v_e (t - t_e), euler(t) = euler_e +
//              euler_rate_e (t - t_e) (a late pose holds the last motion, docs/vessels.md
//              "External vessels"); at t = t_e exactly the pose as given, to the last bit.

#include <memory>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/vessel.h"
#include "core/vessel_course.h"
#include "core/wave_field.h"

namespace towsim::core {

class PoseSpline;  // pose_spline.h

// A vessel's pose and its rates at a time (world NED).
struct VesselPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      // the reference point (origin) [m]
  Eigen::Vector3d euler = Eigen::Vector3d::Zero();         // ZYX roll, pitch, yaw [rad]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();      // of the origin, world [m/s]
  Eigen::Vector3d euler_rate = Eigen::Vector3d::Zero();    // d/dt of euler [rad/s]
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();  // of the origin, world [m/s^2]

  // The attitude and the body twist exactly as another program gave them (an external
  // vessel's odometry, docs/vessels.md "External vessels"); unset for a computed pose. When
  // set, attitude() and twist() return them rather than recomputing them from euler and the
  // rates (which were derived from them and would round differently), so a pose fed back from
  // the node's own odometry reproduces the run to the last bit. A pose carried forward in time
  // drops them.
  struct Given {
    Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
    Eigen::Matrix<double, 6, 1> twist = Eigen::Matrix<double, 6, 1>::Zero();  // [u v w p q r]
  };
  std::optional<Given> given;

  Eigen::Quaterniond attitude() const;  // q_WB
  // [u v w p q r]: the origin's velocity and the angular velocity in the body frame
  Eigen::Matrix<double, 6, 1> twist() const;
  // the world position of the body-fixed point at_B: p + R_WB at_B
  Eigen::Vector3d PointAt(const Eigen::Vector3d& at_B) const;
};

class VesselMotion {
 public:
  // `waves` (the scene's sea) outlives the motion; it answers the RAOs
  VesselMotion(const Vessel& vessel, const WaveField& waves);
  ~VesselMotion();
  VesselMotion(VesselMotion&&) noexcept;
  VesselMotion& operator=(VesselMotion&&) noexcept;

  VesselPose At(double t) const;
  // the six motions about the moving reference at t and their first and second derivatives
  // (harmonics and waves; zero for a time history or an external vessel)
  void Motions(double t, const CourseSample& course, Eigen::Matrix<double, 6, 1>* xi,
               Eigen::Matrix<double, 6, 1>* xi_dot, Eigen::Matrix<double, 6, 1>* xi_ddot) const;

  // an external vessel: the pose at time t (from another program; ignored otherwise)
  void SetExternal(double t, const VesselPose& pose);
  bool external() const { return external_; }

 private:
  const Vessel* vessel_;
  const WaveField* waves_;
  VesselCourse course_;
  std::unique_ptr<PoseSpline> history_;
  bool external_ = false;
  double external_time_ = 0.0;
  VesselPose external_pose_;
};

}  // namespace towsim::core
