// core/vessel_motion.h: the vessel's pose against its definitions (docs/vessels.md). The
// references: the harmonic's cosine; the sea's own elevation at the vessel's reference point
// (wave_field.h) for a heave RAO of 1 with no lag; the definition of a lag for a roll RAO;
// central differences of the pose for the velocity, the Euler rates, the acceleration and the
// body twist (the rotation of the surge and sway motions by the heading while the vessel
// turns is where a sign would go wrong).

#include "core/vessel_motion.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/vehicle_model.h"

namespace towsim::core {
namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kExact = 1e-9;
constexpr double kFdDt = 1e-4;  // central differences: O(dt^2 w^3 A) ~ 1e-8 for these motions
constexpr double kFdTol = 1e-6;

WaveField Sea(double height, double period, double direction_deg) {
  return WaveField::Regular(height, period, direction_deg * kDeg, 0.3, 50.0, 9.81, 1025.0);
}

// a table of one period and one direction: the same H for every wave
RaoTable Uniform(VesselDof dof, double amplitude, double phase) {
  RaoTable t;
  t.periods = {8.0};
  t.directions = {0.0};
  t.extrapolate = true;
  t.amplitude[static_cast<int>(dof)] = {amplitude};
  t.phase[static_cast<int>(dof)] = {phase};
  return t;
}

TEST(VesselMotion, HarmonicHeaveIsACosineUp) {
  Vessel v;
  v.position = Eigen::Vector3d(0.0, 0.0, -2.0);
  v.harmonics.push_back({VesselDof::kHeave, 1.5, 9.0, 40.0 * kDeg});
  const WaveField calm;
  const VesselMotion motion(v, calm);
  for (double t = 0.0; t < 20.0; t += 0.7) {
    const double xi = 1.5 * std::cos(2.0 * kPi * t / 9.0 - 40.0 * kDeg);
    EXPECT_NEAR(motion.At(t).position.z(), -2.0 - xi, kExact) << "t = " << t;
  }
  // the maximum (highest: least z) comes phase / (2 pi) periods after t = 0
  EXPECT_NEAR(motion.At(9.0 * 40.0 / 360.0).position.z(), -3.5, kExact);
}

TEST(VesselMotion, RatesAreTheDerivativesWhileTurningAndOscillating) {
  Vessel v;
  v.position = Eigen::Vector3d(5.0, 3.0, 0.0);
  v.euler = Eigen::Vector3d(0.0, 1.0 * kDeg, 20.0 * kDeg);
  v.speed = 3.0;
  CourseChange turn;
  turn.at = 0.0;
  turn.set_turn_rate = true;
  turn.turn_rate = 2.0 * kDeg;
  v.course = {turn};
  v.harmonics = {{VesselDof::kSurge, 0.8, 7.0, 0.0},  {VesselDof::kSway, 0.5, 6.0, 1.0},
                 {VesselDof::kHeave, 1.0, 8.0, 0.3},  {VesselDof::kRoll, 5 * kDeg, 10.0, 0.5},
                 {VesselDof::kPitch, 2 * kDeg, 6.5, 2.0}, {VesselDof::kYaw, 1 * kDeg, 12.0, 0.1}};
  const WaveField calm;
  const VesselMotion motion(v, calm);
  for (double t = 0.5; t < 60.0; t += 3.1) {
    const VesselPose a = motion.At(t - kFdDt), b = motion.At(t + kFdDt), p = motion.At(t);
    EXPECT_LT(((b.position - a.position) / (2 * kFdDt) - p.velocity).norm(), kFdTol) << t;
    EXPECT_LT(((b.euler - a.euler) / (2 * kFdDt) - p.euler_rate).norm(), kFdTol) << t;
    EXPECT_LT(((b.velocity - a.velocity) / (2 * kFdDt) - p.acceleration).norm(), 1e-5) << t;
    // the body rates: omega_B from the attitude's change, R^T dR/dt = S(omega_B)
    const Eigen::Matrix3d r = p.attitude().toRotationMatrix();
    const Eigen::Matrix3d dr =
        (b.attitude().toRotationMatrix() - a.attitude().toRotationMatrix()) / (2 * kFdDt);
    const Eigen::Matrix3d s = r.transpose() * dr;
    const Eigen::Vector3d omega(s(2, 1), s(0, 2), s(1, 0));
    const Eigen::Matrix<double, 6, 1> nu = p.twist();
    EXPECT_LT((omega - nu.tail<3>()).norm(), kFdTol) << t;
    EXPECT_LT((r.transpose() * p.velocity - nu.head<3>()).norm(), kExact) << t;
  }
}

TEST(VesselMotion, HeaveRaoOfOneFollowsTheSurfaceAtTheReferencePoint) {
  // a moving vessel meets the waves at its encounter frequency: its heave is the elevation
  // under its (course) reference point, whatever its speed and heading
  const WaveField sea = Sea(2.0, 8.0, 150.0);
  Vessel v;
  v.position = Eigen::Vector3d(0.0, 0.0, 0.0);
  v.euler = Eigen::Vector3d(0.0, 0.0, 30.0 * kDeg);
  v.speed = 4.0;
  v.raos = Uniform(VesselDof::kHeave, 1.0, 0.0);
  const VesselMotion motion(v, sea);
  for (double t = 0.0; t < 60.0; t += 0.9) {
    const Eigen::Vector3d ref =
        v.position + 4.0 * t * Eigen::Vector3d(std::cos(30 * kDeg), std::sin(30 * kDeg), 0.0);
    EXPECT_NEAR(-motion.At(t).position.z(), sea.Elevation(ref.x(), ref.y(), t), kExact) << t;
  }
}

TEST(VesselMotion, RollRaoLagsTheCrestByItsPhase) {
  // beam seas toward starboard (relative direction 90 deg); roll RAO 2 deg/m lagging 90 deg:
  // roll = a 2 deg cos(theta - 90 deg), starboard down positive, largest a quarter period
  // after the crest passes the reference point
  const double a = 1.0, period = 10.0;
  const WaveField sea = WaveField::Regular(2.0 * a, period, 90.0 * kDeg, 0.0,
                                           std::numeric_limits<double>::infinity(), 9.81, 1025.0);
  Vessel v;
  v.raos = Uniform(VesselDof::kRoll, 2.0 * kDeg, 90.0 * kDeg);
  const VesselMotion motion(v, sea);
  // at the origin theta = -w t: the crest at t = 0, the roll's maximum at t = T / 4
  EXPECT_NEAR(motion.At(0.0).euler.x(), 0.0, kExact);
  EXPECT_NEAR(motion.At(0.25 * period).euler.x(), 2.0 * kDeg * a, kExact);
  EXPECT_NEAR(motion.At(0.75 * period).euler.x(), -2.0 * kDeg * a, kExact);
  EXPECT_NEAR(sea.Elevation(0.0, 0.0, 0.0), a, kExact);
}

TEST(VesselMotion, ExternalPoseIsCarriedForwardByItsRates) {
  Vessel v;
  v.external = true;
  v.position = Eigen::Vector3d(1.0, 2.0, 0.0);
  const WaveField calm;
  VesselMotion motion(v, calm);
  EXPECT_LT((motion.At(5.0).position - v.position).norm(), kExact);  // speed 0: held
  VesselPose p;
  p.position = Eigen::Vector3d(10.0, 0.0, -1.0);
  p.velocity = Eigen::Vector3d(2.0, 0.0, 0.5);
  p.euler_rate = Eigen::Vector3d(0.0, 0.0, 0.1);
  motion.SetExternal(3.0, p);
  EXPECT_LT((motion.At(3.0).position - p.position).norm(), kExact);
  EXPECT_LT((motion.At(3.5).position - Eigen::Vector3d(11.0, 0.0, -0.75)).norm(), kExact);
  EXPECT_NEAR(motion.At(3.5).euler.z(), 0.05, kExact);
}

// at its own time an external pose is returned as given, to the bit (a -0 stays -0, the
// attitude and twist given are kept); carried to another time it is computed again
TEST(VesselMotion, ExternalPoseAtItsOwnTimeIsAsGiven) {
  Vessel v;
  v.external = true;
  const WaveField calm;
  VesselMotion motion(v, calm);
  VesselPose p;
  p.position = Eigen::Vector3d(-0.0, 3.0, -0.0);
  p.velocity = Eigen::Vector3d(1.0, 0.0, 0.0);
  VesselPose::Given g;
  g.q_WB = Eigen::Quaterniond(0.5, 0.5, 0.5, 0.5);
  g.twist << 1, 2, 3, 4, 5, 6;
  p.given = g;
  motion.SetExternal(0.3, p);
  const VesselPose at = motion.At(0.3);
  EXPECT_TRUE(std::signbit(at.position.x()));
  EXPECT_TRUE(std::signbit(at.position.z()));
  ASSERT_TRUE(at.given.has_value());
  EXPECT_EQ(at.attitude().coeffs(), g.q_WB.coeffs());
  EXPECT_EQ(at.twist(), g.twist);
  const VesselPose later = motion.At(0.4);
  EXPECT_FALSE(later.given.has_value());
  EXPECT_NEAR(later.position.x(), 0.1, kExact);
  EXPECT_EQ(later.attitude().coeffs(), Eigen::Quaterniond::Identity().coeffs());
}

}  // namespace
}  // namespace towsim::core
