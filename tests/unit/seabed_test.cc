#include "core/seabed.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace towsim::core {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;

TEST(Seabed, NoneIsBottomless) {
  const Seabed s;
  EXPECT_FALSE(s.present());
  EXPECT_TRUE(std::isinf(s.Depth(3.0, 4.0)));
  EXPECT_TRUE(std::isinf(s.WaveDepth()));
  EXPECT_EQ(s.Normal(3.0, 4.0), Vec3(0.0, 0.0, -1.0));
}

TEST(Seabed, FlatHasOneDepthAndAnUpwardNormal) {
  Seabed s = Seabed::Flat(60.0);
  s.set_contact({1e5, 2e3, 0.4});
  EXPECT_TRUE(s.present());
  EXPECT_EQ(s.Depth(-100.0, 250.0), 60.0);
  EXPECT_EQ(s.WaveDepth(), 60.0);
  EXPECT_EQ(s.Normal(1.0, 2.0), Vec3(0.0, 0.0, -1.0));
  EXPECT_EQ(s.contact().friction, 0.4);
}

// a plane 40 m deep at the origin, 5 deg, deepening toward 30 deg (north-east-ish)
TEST(Seabed, PlaneDeepensAlongItsSlopeDirection) {
  const double slope = 5.0 * kPi / 180.0, dir = 30.0 * kPi / 180.0;
  const Seabed s = Seabed::Plane(40.0, slope, dir);
  constexpr double kTol = 1e-12;
  EXPECT_NEAR(s.Depth(0.0, 0.0), 40.0, kTol);
  // 100 m along the slope direction: 100 tan 5 deg deeper; across it: no change
  EXPECT_NEAR(s.Depth(100.0 * std::cos(dir), 100.0 * std::sin(dir)), 40.0 + 100.0 * std::tan(slope),
              kTol);
  EXPECT_NEAR(s.Depth(-50.0 * std::sin(dir), 50.0 * std::cos(dir)), 40.0, kTol);
  // the normal makes the slope angle with the vertical, tilted against the slope direction
  const Vec3 n = s.Normal(7.0, -3.0);
  EXPECT_NEAR(n.norm(), 1.0, kTol);
  EXPECT_NEAR(std::acos(-n.z()), slope, kTol);
  EXPECT_GT(n.x() * std::cos(dir) + n.y() * std::sin(dir), 0.0);  // (d_x, d_y) = +grad d
  EXPECT_NEAR(s.WaveDepth(), 40.0, kTol);
}

// depths of a plane sampled on an uneven grid: bilinear interpolation reproduces a plane
// exactly (to round-off) everywhere inside, and holds the edge values outside
TEST(Seabed, BilinearGridIsExactOnAPlane) {
  const std::vector<double> x = {-100.0, -20.0, 0.0, 35.0, 200.0};
  const std::vector<double> y = {-50.0, 10.0, 80.0};
  auto plane = [](double px, double py) { return 55.0 + 0.03 * px - 0.05 * py; };
  std::vector<double> d;
  for (double py : y)
    for (double px : x) d.push_back(plane(px, py));
  const Seabed s = Seabed::Grid(x, y, d);
  EXPECT_TRUE(s.present());
  constexpr double kTol = 1e-12;  // a few flops on values ~ 60 m
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ux(-100.0, 200.0), uy(-50.0, 80.0);
  for (int i = 0; i < 200; ++i) {
    const double px = ux(rng), py = uy(rng);
    EXPECT_NEAR(s.Depth(px, py), plane(px, py), kTol) << px << ", " << py;
    const Vec3 n = s.Normal(px, py);
    const Vec3 n_exact = Vec3(0.03, -0.05, -1.0).normalized();
    EXPECT_LT((n - n_exact).norm(), kTol) << px << ", " << py;
  }
  // nodes exactly
  EXPECT_NEAR(s.Depth(35.0, 10.0), plane(35.0, 10.0), kTol);
  EXPECT_NEAR(s.WaveDepth(), 55.0, kTol);
  // outside: the nearest edge value, no slope across that edge
  EXPECT_NEAR(s.Depth(500.0, 0.0), plane(200.0, 0.0), kTol);
  EXPECT_NEAR(s.Depth(-300.0, -90.0), plane(-100.0, -50.0), kTol);
  const Vec3 n_out = s.Normal(500.0, 0.0);
  EXPECT_LT((n_out - Vec3(0.0, -0.05, -1.0).normalized()).norm(), kTol);
}

// a curved bed: the normal from the bilinear patch against central differences of Depth
TEST(Seabed, GridNormalMatchesDifferencesOfTheDepth) {
  std::vector<double> x, y, d;
  for (int i = 0; i <= 8; ++i) x.push_back(-40.0 + 10.0 * i + (i % 2) * 1.5);
  for (int j = 0; j <= 6; ++j) y.push_back(-30.0 + 10.0 * j);
  for (double py : y)
    for (double px : x) d.push_back(50.0 + 5.0 * std::sin(0.05 * px) * std::cos(0.07 * py));
  const Seabed s = Seabed::Grid(x, y, d);
  constexpr double kH = 1e-5;          // inside a cell: the patch is smooth there
  constexpr double kNormalTol = 1e-8;  // central differences of a bilinear patch: exact in x
                                       // and y separately, round-off eps d / kH ~ 1e-9
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(-39.0, 39.0), uy(-29.0, 29.0);
  for (int i = 0; i < 100; ++i) {
    const double px = ux(rng), py = uy(rng);
    const double dx = (s.Depth(px + kH, py) - s.Depth(px - kH, py)) / (2.0 * kH);
    const double dy = (s.Depth(px, py + kH) - s.Depth(px, py - kH)) / (2.0 * kH);
    const Vec3 n_fd = Vec3(dx, dy, -1.0).normalized();
    EXPECT_LT((s.Normal(px, py) - n_fd).norm(), kNormalTol) << px << ", " << py;
    EXPECT_NEAR(s.Normal(px, py).norm(), 1.0, 1e-14);
  }
}

}  // namespace
}  // namespace towsim::core
