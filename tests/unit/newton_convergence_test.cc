// The force bound's parts (core/newton_convergence.h) against hand-computed values.
#include "core/newton_convergence.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"
#include "core/system.h"

namespace towsim::core {
namespace {

constexpr double kExact = 1e-12;  // relative: sums of a few products

// a 100 m cable of 4 elements from a fixed point to a sphere
Model HangingCable() {
  Model m;
  CableParams& c = m.cables[0];
  c.length = 100.0;
  c.elements = 4;
  c.diameter = 0.04;
  c.mass_per_length = 3.0;
  c.start.kind = EndKind::kFixed;
  c.end.kind = EndKind::kSphere;
  c.end.body = 0;
  SphereBody b;
  b.name = "ball";
  b.mass = 200.0;
  b.volume = 0.1;
  b.position = Vec3(0, 0, 100);
  m.spheres.push_back(b);
  return m;
}

TEST(NewtonConvergence, WetWeightIsTheCablesAndTheBodiesInWater) {
  const Model m = HangingCable();
  const double rho = m.environment.water_density, g = m.environment.gravity;
  const double area = 0.25 * kPi * 0.04 * 0.04;
  const double expected = (3.0 - rho * area) * g * 100.0 + (200.0 - rho * 0.1) * g;
  EXPECT_NEAR(WetWeightScale(m), expected, kExact * expected);
  // a buoyant body counts by the size of its net force, and the scale is never below 1 N
  Model buoyant = m;
  buoyant.spheres[0].mass = 50.0;
  const double net = (3.0 - rho * area) * g * 100.0 + (rho * 0.1 - 50.0) * g;
  EXPECT_NEAR(WetWeightScale(buoyant), net, kExact * net);
  Model neutral = m;
  neutral.cables[0].mass_per_length = rho * area;
  neutral.spheres[0].mass = rho * 0.1;
  EXPECT_EQ(WetWeightScale(neutral), kMinForceScale);
}

TEST(NewtonConvergence, JointForceScaleIsTheLargestEndForceAtLeastTheWeight) {
  const Model m = HangingCable();
  const System system(m);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(system.num_lambda());
  const double w = WetWeightScale(m);
  EXPECT_EQ(JointForceScale(system, lambda, w), w);  // no force yet: the weight
  lambda.segment<3>(system.EndLambda(0)) = Vec3(300.0, 0.0, -4000.0);  // |.| = 4011.23
  lambda.segment<3>(system.EndLambda(1)) = Vec3(0.0, 1000.0, 1000.0);
  const double top = std::hypot(300.0, 4000.0);
  EXPECT_NEAR(JointForceScale(system, lambda, w), top, kExact * top);
  EXPECT_NEAR(JointForceScale(system, lambda, 1e5), 1e5, 0.0);
}

TEST(NewtonConvergence, ResidualNormTakesSlopeRowsPerElementLength) {
  const Model m = HangingCable();
  const System system(m);
  const double le = 25.0;  // 100 m / 4
  Eigen::VectorXd r = Eigen::VectorXd::Zero(system.num_q());
  int worst = -1;
  EXPECT_EQ(ForceResidualNorm(system, r, &worst), 0.0);
  // a slope row of 500 N m at node 2 is 20 N
  const int slope_row = system.CableDof(2) + 4;
  r[slope_row] = -500.0;
  EXPECT_NEAR(ForceResidualNorm(system, r, &worst), 500.0 / le, kExact * 20.0);
  EXPECT_EQ(worst, slope_row);
  // a position row of 30 N at node 3 is larger
  const int position_row = system.CableDof(3) + 2;
  r[position_row] = 30.0;
  EXPECT_NEAR(ForceResidualNorm(system, r, &worst), 30.0, 0.0);
  EXPECT_EQ(worst, position_row);
  // the body's rows count in N
  r[system.SphereDof(0) + 1] = 31.0;
  EXPECT_NEAR(ForceResidualNorm(system, r, &worst), 31.0, 0.0);
  EXPECT_EQ(worst, system.SphereDof(0) + 1);
}

}  // namespace
}  // namespace towsim::core
