// The seabed contact law (core/seabed_contact.h) against its definition: the penalty force of
// a resting point, Coulomb friction along and across the cable with their own coefficients,
// the continuous onset, and the Jacobians against central finite differences.

#include "core/seabed_contact.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/environment_field.h"
#include "core/vehicle_model.h"

namespace towsim::core {
namespace {

using Mat3 = Eigen::Matrix3d;

constexpr double kWidth = 0.041;  // [m], the shipped cable's diameter

EnvironmentField Bed(double friction, double lateral) {
  Environment env;
  env.seabed = Seabed::Flat(50.0);
  SeabedContact c;
  c.stiffness = 3.0e6;
  c.damping = 3.0e4;
  c.friction = friction;
  c.friction_lateral = lateral;
  env.seabed.set_contact(c);
  return EnvironmentField(env);
}

TEST(SeabedContact, RestingPointCarriesThePenaltyForce) {
  const EnvironmentField sea = Bed(0.0, 0.0);
  // 5 mm in, beyond the 1 mm onset: w k (delta - d0 / 2), straight up (-z)
  const ContactLoad c = SeabedContactLoad(sea, kWidth, Vec3(1, 2, 50.005), Vec3::Zero(),
                                          Vec3::UnitX(), false);
  ASSERT_TRUE(c.active);
  const double expected = kWidth * 3.0e6 * (0.005 - 0.5 * kContactOnset);
  EXPECT_NEAR(c.f.z(), -expected, 1e-9 * expected);
  EXPECT_NEAR(c.f.head<2>().norm(), 0.0, 1e-12);
  // above the bed: nothing
  EXPECT_FALSE(SeabedContactLoad(sea, kWidth, Vec3(1, 2, 49.99), Vec3::Zero(), Vec3::UnitX(),
                                 false)
                   .active);
  // the onset is continuous at d0 (value) and starts from zero
  const auto fz = [&](double delta) {
    return SeabedContactLoad(sea, kWidth, Vec3(0, 0, 50.0 + delta), Vec3::Zero(), Vec3::UnitX(),
                             false)
        .f.z();
  };
  EXPECT_NEAR(fz(kContactOnset * (1 - 1e-9)), fz(kContactOnset * (1 + 1e-9)), 1e-6);
  EXPECT_NEAR(fz(1e-9), 0.0, 1e-6);
}

TEST(SeabedContact, CoulombAlongAndAcrossTheCable) {
  constexpr double kAxial = 0.3, kLateral = 0.9;
  const EnvironmentField sea = Bed(kAxial, kLateral);
  const Vec3 r(0, 0, 50.005), tangent(1, 0, 0);
  // sliding at 10 x the slip speed: tanh(10) = 1 - 4e-9
  constexpr double kLawRelTol = 1e-8;
  const double v = 10.0 * kFrictionSlipSpeed;
  const ContactLoad along = SeabedContactLoad(sea, kWidth, r, Vec3(v, 0, 0), tangent, false);
  const ContactLoad across = SeabedContactLoad(sea, kWidth, r, Vec3(0, v, 0), tangent, false);
  EXPECT_NEAR(along.f.x(), -kAxial * along.normal, kLawRelTol * along.normal);
  EXPECT_NEAR(across.f.y(), -kLateral * across.normal, kLawRelTol * across.normal);
  EXPECT_NEAR(along.f.y(), 0.0, 1e-12);
  EXPECT_NEAR(across.f.x(), 0.0, 1e-12);
  // without a tangent (a body's contact point) the axial coefficient in every direction
  const ContactLoad point = SeabedContactLoad(sea, kWidth, r, Vec3(0, v, 0), Vec3::Zero(), false);
  EXPECT_NEAR(point.f.y(), -kAxial * point.normal, kLawRelTol * point.normal);
}

TEST(SeabedContact, JacobiansMatchFiniteDifferences) {
  const EnvironmentField sea = Bed(0.4, 0.8);
  const Vec3 r(0.3, -0.2, 50.004), v(0.004, -0.007, 0.002), a(0.9, 0.3, 0.05);
  const ContactLoad c = SeabedContactLoad(sea, kWidth, r, v, a, true);
  ASSERT_TRUE(c.active);
  constexpr double kStep = 1e-8;  // [m], [m/s]: well inside the onset and the slip speed
  Mat3 dr, dv, da;
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = kStep * Vec3::Unit(i);
    dr.col(i) = (SeabedContactLoad(sea, kWidth, r + e, v, a, false).f -
                 SeabedContactLoad(sea, kWidth, r - e, v, a, false).f) /
                (2 * kStep);
    dv.col(i) = (SeabedContactLoad(sea, kWidth, r, v + e, a, false).f -
                 SeabedContactLoad(sea, kWidth, r, v - e, a, false).f) /
                (2 * kStep);
    da.col(i) = (SeabedContactLoad(sea, kWidth, r, v, a + e, false).f -
                 SeabedContactLoad(sea, kWidth, r, v, a - e, false).f) /
                (2 * kStep);
  }
  constexpr double kJacRelTol = 1e-6;  // central differences
  EXPECT_LT((c.df_dr - dr).norm(), kJacRelTol * dr.norm());
  EXPECT_LT((c.df_dv - dv).norm(), kJacRelTol * dv.norm());
  EXPECT_LT((c.df_da - da).norm(), kJacRelTol * (da.norm() + 1.0));
}

// A hull's contact wrench (SeabedContactWrench): the sum over its contact points of the point
// loads, against that sum built here point by point; a hull whose origin lies above the bed
// by less than its reach can touch it (pitched nose down), one beyond its reach cannot
TEST(SeabedContact, HullWrenchIsTheSumOverItsContactPoints) {
  const EnvironmentField sea = Bed(0.3, 0.3);
  VehicleParams p;
  p.length = 3.3;
  p.volume = 0.5;
  LiftingSurface fin;
  fin.position_B = Vec3(-1.4, 0.0, 0.6);  // a lower fin, 1.52 m from O: within L/2 = 1.65 m
  p.surfaces.push_back(fin);
  const double area = p.volume / p.length;
  // the sum the wrench is defined as, at a pose
  auto by_hand = [&](const VehicleState& s) {
    const Mat3 r = s.q_WB.toRotationMatrix();
    Eigen::Matrix<double, 6, 1> tau = Eigen::Matrix<double, 6, 1>::Zero();
    for (const Vec3& r_b : {Vec3(0.5 * p.length, 0, 0), Vec3(-0.5 * p.length, 0, 0),
                            fin.position_B}) {
      const Vec3 v_w = r * (s.nu.head<3>() + Vec3(s.nu.tail<3>()).cross(r_b));
      const ContactLoad c =
          SeabedContactLoad(sea, area, s.p_W + r * r_b, v_w, Vec3::Zero(), false);
      if (!c.active) continue;
      const Vec3 f_b = r.transpose() * c.f;
      tau.head<3>() += f_b;
      tau.tail<3>() += r_b.cross(f_b);
    }
    return tau;
  };
  constexpr double kExact = 1e-12;  // relative: the same operations in another order
  VehicleState s;
  s.nu << 0.5, 0.1, 0.05, 0.0, 0.02, 0.0;
  // nose down 30 deg, the origin 0.8 m above the bed: the nose (0.825 m below O) touches
  s.p_W = Vec3(3.0, -2.0, 50.0 - 0.8);
  s.q_WB = QuaternionFromEulerZYX(Vec3(0.0, -30.0 * kPi / 180.0, 0.2));
  const auto touching = SeabedContactWrench(p, sea, s);
  EXPECT_GT(touching.head<3>().norm(), 0.0);
  EXPECT_LE((touching - by_hand(s)).norm(), kExact * by_hand(s).norm());
  // level 1.6 m above: the fin hangs 0.6 m below O, nothing touches; and beyond the reach
  for (const double above : {1.6, 1.66, 10.0}) {
    s.p_W.z() = 50.0 - above;
    s.q_WB = QuaternionFromEulerZYX(Vec3(0.0, 0.0, 0.2));
    EXPECT_EQ(SeabedContactWrench(p, sea, s), by_hand(s)) << above;
    EXPECT_EQ(by_hand(s).norm(), 0.0) << above;
  }
  // the fin below the bed with the origin above it: level, 0.5 m above (the fin 0.1 m in)
  s.p_W.z() = 50.0 - 0.5;
  const auto fin_in = SeabedContactWrench(p, sea, s);
  EXPECT_GT(fin_in.head<3>().norm(), 0.0);
  EXPECT_LE((fin_in - by_hand(s)).norm(), kExact * by_hand(s).norm());
}

}  // namespace
}  // namespace towsim::core
