#include "core/vessel_motion.h"

#include <cmath>
#include <complex>

#include "core/constants.h"
#include "core/rao_table.h"
#include "core/pose_spline.h"
#include "core/vehicle_model.h"

namespace towsim::core {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

// S [x, y] = [-y, x]
Eigen::Vector2d Perp(const Eigen::Vector2d& x) { return {-x.y(), x.x()}; }

Eigen::Vector2d Rotate(double psi, const Eigen::Vector2d& x) {
  const double c = std::cos(psi), s = std::sin(psi);
  return {c * x.x() - s * x.y(), s * x.x() + c * x.y()};
}

}  // namespace

Eigen::Quaterniond VesselPose::attitude() const {
  return given ? given->q_WB : QuaternionFromEulerZYX(euler);
}

Eigen::Matrix<double, 6, 1> VesselPose::twist() const {
  if (given) return given->twist;
  // body rates from the ZYX Euler rates: p = phi' - psi' sin theta,
  // q = theta' cos phi + psi' cos theta sin phi, r = -theta' sin phi + psi' cos theta cos phi
  const double phi = euler.x(), theta = euler.y();
  const double dphi = euler_rate.x(), dtheta = euler_rate.y(), dpsi = euler_rate.z();
  Vec6 nu;
  nu.head<3>() = attitude().conjugate() * velocity;
  nu(3) = dphi - dpsi * std::sin(theta);
  nu(4) = dtheta * std::cos(phi) + dpsi * std::cos(theta) * std::sin(phi);
  nu(5) = -dtheta * std::sin(phi) + dpsi * std::cos(theta) * std::cos(phi);
  return nu;
}

Eigen::Vector3d VesselPose::PointAt(const Eigen::Vector3d& at_B) const {
  return position + attitude() * at_B;
}

VesselMotion::VesselMotion(const Vessel& vessel, const WaveField& waves)
    : vessel_(&vessel), waves_(&waves), course_(vessel), external_(vessel.external) {
  if (vessel.time_history) history_ = std::make_unique<PoseSpline>(*vessel.time_history);
  external_pose_.position = vessel.position;
  external_pose_.euler = vessel.euler;
  external_pose_.velocity = QuaternionFromEulerZYX(vessel.euler) *
                            Eigen::Vector3d(vessel.speed, 0.0, 0.0);
}

VesselMotion::~VesselMotion() = default;
VesselMotion::VesselMotion(VesselMotion&&) noexcept = default;
VesselMotion& VesselMotion::operator=(VesselMotion&&) noexcept = default;

void VesselMotion::SetExternal(double t, const VesselPose& pose) {
  external_time_ = t;
  external_pose_ = pose;
}

void VesselMotion::Motions(double t, const CourseSample& course, Vec6* xi, Vec6* xi_dot,
                           Vec6* xi_ddot) const {
  xi->setZero();
  xi_dot->setZero();
  xi_ddot->setZero();
  for (const HarmonicMotion& h : vessel_->harmonics) {
    const int j = static_cast<int>(h.dof);
    const double w = 2.0 * kPi / h.period, arg = w * t - h.phase;
    (*xi)(j) += h.amplitude * std::cos(arg);
    (*xi_dot)(j) -= h.amplitude * w * std::sin(arg);
    (*xi_ddot)(j) -= h.amplitude * w * w * std::cos(arg);
  }
  if (!vessel_->raos || waves_->empty()) return;
  const RaoTable& table = *vessel_->raos;
  // R(t) and its derivatives: xi = R g, xi' = R' g + R g', xi'' = R'' g + 2 R' g' + R g''
  const double r0 = waves_->Ramp(t), r1 = waves_->RampRate(t), r2 = waves_->RampAcceleration(t);
  const Eigen::Vector3d& x = course.position;
  const Eigen::Vector3d& u = course.velocity;
  const Eigen::Vector3d& a = course.acceleration;
  for (const WaveComponent& c : waves_->components()) {
    if (c.amplitude == 0.0 || c.omega <= 0.0) continue;
    const double kx = c.k * std::cos(c.direction), ky = c.k * std::sin(c.direction);
    // the crest phase increasing in time (eta = a cos theta): the negative of wave_field.h's
    const double theta = c.omega * t - kx * x.x() - ky * x.y() - c.phase;
    const double dtheta = c.omega - kx * u.x() - ky * u.y();
    const double ddtheta = -(kx * a.x() + ky * a.y());
    const std::complex<double> e = std::polar(1.0, theta);
    const std::complex<double> i(0.0, 1.0);
    const double period = 2.0 * kPi / c.omega;
    const double beta = c.direction - course.heading;
    const std::array<std::complex<double>, kVesselDofs> raos = RaosAt(table, period, beta);
    for (int j = 0; j < kVesselDofs; ++j) {
      if (table.amplitude[j].empty()) continue;
      const std::complex<double> h = raos[j] * e;
      const double g = h.real();
      const double g1 = (i * dtheta * h).real();
      const double g2 = ((i * ddtheta - dtheta * dtheta) * h).real();
      (*xi)(j) += c.amplitude * r0 * g;
      (*xi_dot)(j) += c.amplitude * (r1 * g + r0 * g1);
      (*xi_ddot)(j) += c.amplitude * (r2 * g + 2.0 * r1 * g1 + r0 * g2);
    }
  }
}

VesselPose VesselMotion::At(double t) const {
  VesselPose p;
  if (external_) {
    p = external_pose_;
    // at the pose's own time: as given, untouched (-0 + 0 would turn a -0 into +0)
    if (t == external_time_) return p;
    const double dt = t - external_time_;
    p.position += dt * external_pose_.velocity;
    p.euler += dt * external_pose_.euler_rate;
    p.given.reset();
    return p;
  }
  if (history_) {
    const PoseSample s = history_->Evaluate(t);
    p.position = s.pose.head<3>();
    p.euler = s.pose.tail<3>();
    p.velocity = s.velocity.head<3>();
    p.euler_rate = s.velocity.tail<3>();
    p.acceleration = s.acceleration.head<3>();
    return p;
  }
  const CourseSample c = course_.At(t);
  Vec6 xi, xi1, xi2;
  Motions(t, c, &xi, &xi1, &xi2);
  const double psi = c.heading, r = c.turn_rate, dr = c.yaw_acceleration;
  const Eigen::Vector2d d(xi(0), xi(1)), d1(xi1(0), xi1(1)), d2(xi2(0), xi2(1));
  p.position = c.position;
  p.position.head<2>() += Rotate(psi, d);
  p.position.z() -= xi(2);
  p.velocity = c.velocity;
  p.velocity.head<2>() += Rotate(psi, d1 + r * Perp(d));
  p.velocity.z() -= xi1(2);
  p.acceleration = c.acceleration;
  p.acceleration.head<2>() +=
      Rotate(psi, d2 + 2.0 * r * Perp(d1) + dr * Perp(d) + r * r * Perp(Perp(d)));
  p.acceleration.z() -= xi2(2);
  p.euler = Eigen::Vector3d(vessel_->euler.x() + xi(3), vessel_->euler.y() + xi(4), psi + xi(5));
  p.euler_rate = Eigen::Vector3d(xi1(3), xi1(4), r + xi1(5));
  return p;
}

}  // namespace towsim::core
