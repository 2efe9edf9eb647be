#include "core/current_field.h"

#include <cmath>

#include <gtest/gtest.h>

namespace towsim::core {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kExactTol = 1e-14;  // interpolation in a few flops: round-off only

TEST(CurrentField, DefaultIsZeroUniformSteady) {
  const CurrentField c;
  EXPECT_TRUE(c.IsZero());
  EXPECT_TRUE(c.IsUniform());
  EXPECT_TRUE(c.IsSteady());
  EXPECT_EQ(c.Velocity(50.0, 3.0), Vec3::Zero());
  EXPECT_EQ(c.Acceleration(50.0, 3.0), Vec3::Zero());
}

TEST(CurrentField, UniformIsTheSameEverywhere) {
  const CurrentField c = CurrentField::Uniform(Vec3(0.5, -0.2, 0.1));
  EXPECT_FALSE(c.IsZero());
  EXPECT_TRUE(c.IsUniform());
  EXPECT_TRUE(c.IsSteady());
  for (double z : {-3.0, 0.0, 200.0}) {
    EXPECT_EQ(c.Velocity(z, 7.0), Vec3(0.5, -0.2, 0.1));
    EXPECT_EQ(c.Shear(z, 7.0), Vec3::Zero());
    EXPECT_EQ(c.Acceleration(z, 7.0), Vec3::Zero());
  }
}

TEST(CurrentField, ProfileInterpolatesLinearlyAndHoldsBeyondTheEnds) {
  const CurrentField c = CurrentField::Profile(
      {{10.0, Vec3(1.0, 0.0, 0.0)}, {30.0, Vec3(0.0, 1.0, 0.0)}, {60.0, Vec3(0.0, 1.0, -0.3)}});
  EXPECT_FALSE(c.IsUniform());
  EXPECT_TRUE(c.IsSteady());
  EXPECT_FALSE(c.IsZero());
  // constant above the first row and below the last
  EXPECT_EQ(c.Velocity(-5.0, 0.0), Vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(c.Velocity(10.0, 0.0), Vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(c.Velocity(60.0, 0.0), Vec3(0.0, 1.0, -0.3));
  EXPECT_EQ(c.Velocity(500.0, 0.0), Vec3(0.0, 1.0, -0.3));
  // z = 15: a quarter of the way from row 0 to row 1; z = 50: two thirds from row 1 to row 2
  EXPECT_LT((c.Velocity(15.0, 0.0) - Vec3(0.75, 0.25, 0.0)).norm(), kExactTol);
  EXPECT_LT((c.Velocity(50.0, 0.0) - Vec3(0.0, 1.0, -0.2)).norm(), kExactTol);
  EXPECT_LT((c.Velocity(30.0, 0.0) - Vec3(0.0, 1.0, 0.0)).norm(), kExactTol);
  // shear: the slope of the interval below, zero beyond the ends
  EXPECT_LT((c.Shear(15.0, 0.0) - Vec3(-0.05, 0.05, 0.0)).norm(), kExactTol);
  EXPECT_LT((c.Shear(30.0, 0.0) - Vec3(0.0, 0.0, -0.01)).norm(), kExactTol);
  EXPECT_EQ(c.Shear(5.0, 0.0), Vec3::Zero());
  EXPECT_EQ(c.Shear(70.0, 0.0), Vec3::Zero());
}

TEST(CurrentField, OneRowProfileIsUniform) {
  const CurrentField c = CurrentField::Profile({{20.0, Vec3(0.3, 0.0, 0.0)}});
  EXPECT_TRUE(c.IsUniform());
  EXPECT_EQ(c.Velocity(0.0, 0.0), Vec3(0.3, 0.0, 0.0));
  EXPECT_EQ(c.Velocity(100.0, 0.0), Vec3(0.3, 0.0, 0.0));
  EXPECT_TRUE(CurrentField::Profile({{0.0, Vec3::Zero()}, {9.0, Vec3::Zero()}}).IsZero());
}

TEST(CurrentField, PowerLawFollowsTheSeventhRootAndStopsAtDepth) {
  const Vec3 us(1.2, 0.4, 0.0);
  const CurrentField c = CurrentField::PowerLaw(us, 80.0, 7.0);
  EXPECT_FALSE(c.IsUniform());
  // U(z) = U_s (1 - z/D)^(1/7): at z = D/2, 0.5^(1/7) = 0.905723664263906
  EXPECT_LT((c.Velocity(40.0, 0.0) - 0.905723664263906 * us).norm(), 1e-14);
  EXPECT_EQ(c.Velocity(0.0, 0.0), us);
  EXPECT_EQ(c.Velocity(-2.0, 0.0), us);  // above the mean surface: U_s
  EXPECT_EQ(c.Velocity(80.0, 0.0), Vec3::Zero());
  EXPECT_EQ(c.Velocity(95.0, 0.0), Vec3::Zero());
  // shear against central differences of the velocity, O(dz^2) with dz = 1e-4
  constexpr double kDz = 1e-4;
  constexpr double kShearTol = 1e-8;  // (dz)^2 |U'''| / 6 ~ 1e-11 plus round-off eps/dz ~ 1e-12
  for (double z : {1.0, 20.0, 55.0, 75.0}) {
    const Vec3 fd = (c.Velocity(z + kDz, 0.0) - c.Velocity(z - kDz, 0.0)) / (2.0 * kDz);
    EXPECT_LT((c.Shear(z, 0.0) - fd).norm(), kShearTol) << "z = " << z;
  }
}

TEST(CurrentField, TimeScaleMultipliesTheProfile) {
  CurrentField c = CurrentField::Uniform(Vec3(1.0, 0.0, 0.0));
  c.SetTimeScale({{0.0, 0.0}, {10.0, 1.0}, {20.0, 1.0}, {30.0, -0.5}});
  EXPECT_FALSE(c.IsSteady());
  EXPECT_FALSE(c.IsZero());
  EXPECT_EQ(c.Velocity(5.0, -1.0), Vec3::Zero());
  EXPECT_LT((c.Velocity(5.0, 2.5) - Vec3(0.25, 0.0, 0.0)).norm(), kExactTol);
  EXPECT_LT((c.Velocity(5.0, 25.0) - Vec3(0.25, 0.0, 0.0)).norm(), kExactTol);
  EXPECT_LT((c.Velocity(5.0, 99.0) - Vec3(-0.5, 0.0, 0.0)).norm(), kExactTol);
  // dU/dt: 0.1 on (0, 10), 0 on (10, 20), -0.15 on (20, 30)
  EXPECT_LT((c.Acceleration(5.0, 5.0) - Vec3(0.1, 0.0, 0.0)).norm(), kExactTol);
  EXPECT_LT((c.Acceleration(5.0, 15.0) - Vec3::Zero()).norm(), kExactTol);
  EXPECT_LT((c.Acceleration(5.0, 25.0) - Vec3(-0.15, 0.0, 0.0)).norm(), kExactTol);
  CurrentField off = CurrentField::Uniform(Vec3(1.0, 0.0, 0.0));
  off.SetTimeScale({{0.0, 0.0}, {10.0, 0.0}});
  EXPECT_TRUE(off.IsZero());
}

// DU/Dt = dU/dt + U_z dU/dz against differences of Velocity in t and z: a current with a
// vertical component over a profile, scaled in time
TEST(CurrentField, AccelerationIsTheMaterialDerivative) {
  CurrentField c = CurrentField::PowerLaw(Vec3(1.0, 0.5, 0.2), 60.0, 5.0);
  c.SetTimeScale({{0.0, 0.5}, {100.0, 1.5}});
  constexpr double kD = 1e-4;
  constexpr double kAccelTol = 1e-8;  // central differences, O(kD^2) and round-off eps/kD
  for (double z : {2.0, 30.0, 50.0}) {
    const double t = 40.0;
    const Vec3 u = c.Velocity(z, t);
    const Vec3 du_dt = (c.Velocity(z, t + kD) - c.Velocity(z, t - kD)) / (2.0 * kD);
    const Vec3 du_dz = (c.Velocity(z + kD, t) - c.Velocity(z - kD, t)) / (2.0 * kD);
    EXPECT_LT((c.Acceleration(z, t) - (du_dt + u.z() * du_dz)).norm(), kAccelTol) << z;
    EXPECT_LT((c.Shear(z, t) - du_dz).norm(), kAccelTol) << z;
  }
}

}  // namespace
}  // namespace towsim::core
