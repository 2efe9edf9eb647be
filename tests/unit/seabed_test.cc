#include "core/seabed.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/constants.h"

namespace towsim::core {
namespace {

using Vec3 = Eigen::Vector3d;

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

// Shallowest bounds the depth from above everywhere (the vehicles' contact skips a hull above
// it): exact for flat beds and grids, open for a sloping plane
TEST(Seabed, ShallowestIsAtMostTheDepthEverywhere) {
  EXPECT_EQ(Seabed().Shallowest(), std::numeric_limits<double>::infinity());
  EXPECT_EQ(Seabed::Flat(60.0).Shallowest(), 60.0);
  EXPECT_EQ(Seabed::Plane(40.0, 0.0, 0.3).Shallowest(), 40.0);
  EXPECT_EQ(Seabed::Plane(40.0, 5.0 * kPi / 180.0, 0.3).Shallowest(),
            -std::numeric_limits<double>::infinity());
  const std::vector<double> x = {-100.0, -20.0, 0.0, 35.0, 200.0};
  const std::vector<double> y = {-50.0, 10.0, 80.0};
  std::vector<double> d;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ud(20.0, 90.0);
  for (size_t i = 0; i < x.size() * y.size(); ++i) d.push_back(ud(rng));
  const Seabed g = Seabed::Grid(x, y, d);
  const double lo = *std::min_element(d.begin(), d.end());
  EXPECT_EQ(g.Shallowest(), lo);
  // inside and outside the grid (the constant extension): never shallower than the bound, and
  // the bound is attained at its node
  std::uniform_real_distribution<double> ux(-300.0, 400.0), uy(-150.0, 180.0);
  for (int i = 0; i < 2000; ++i) {
    const double px = ux(rng), py = uy(rng);
    EXPECT_GE(g.Depth(px, py), lo) << px << ", " << py;
  }
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

// --- the altimeter's beam: RayRange (seabed.h) ---

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDegToRad = kPi / 180.0;

// beam of a body with roll phi and pitch theta (ZYX, yaw psi): the body z axis in the world,
// R_WB e_z = (cos psi sin theta cos phi + sin psi sin phi, sin psi sin theta cos phi
// - cos psi sin phi, cos theta cos phi)
Vec3 Beam(double phi, double theta, double psi) {
  return Vec3(std::cos(psi) * std::sin(theta) * std::cos(phi) + std::sin(psi) * std::sin(phi),
              std::sin(psi) * std::sin(theta) * std::cos(phi) - std::cos(psi) * std::sin(phi),
              std::cos(theta) * std::cos(phi));
}

// closed-form ray-plane intersection, written from the plane's geometry rather than from
// F(s): the plane through P0 = (0, 0, d_0) with normal N = (g_x, g_y, -1), g = tan(slope)
// (cos c, sin c); s = (P0 - o) . N / (u . N) (no hit: the denominator's sign says the ray
// leaves the plane, or the hit is behind the origin)
double RayPlane(double d0, double slope, double dir, const Vec3& o, const Vec3& u) {
  const Vec3 n(std::tan(slope) * std::cos(dir), std::tan(slope) * std::sin(dir), -1.0);
  const double s = (Vec3(0.0, 0.0, d0) - o).dot(n) / u.dot(n);
  return s >= 0.0 ? s : kInf;
}

// flat bed h below: a beam tilted by pitch theta or roll phi meets it at h / cos(theta),
// h / cos(phi), h / (cos theta cos phi), whatever the heading
TEST(SeabedRay, TiltedBeamOverAFlatBedIsHOverCosine) {
  const Seabed s = Seabed::Flat(60.0);
  const Vec3 o(12.0, -7.0, 35.0);
  const double h = 60.0 - 35.0;
  constexpr double kRangeRelTol = 1e-14;  // one division: round-off only
  for (double deg : {0.0, 5.0, 20.0, 45.0, 70.0}) {
    const double a = deg * kDegToRad;
    EXPECT_NEAR(s.RayRange(o, Beam(0.0, a, 0.0), 500.0), h / std::cos(a), kRangeRelTol * 100)
        << "pitch " << deg;
    EXPECT_NEAR(s.RayRange(o, Beam(a, 0.0, 0.0), 500.0), h / std::cos(a), kRangeRelTol * 100)
        << "roll " << deg;
    EXPECT_NEAR(s.RayRange(o, Beam(-a, 0.5 * a, 2.0), 500.0),
                h / (std::cos(a) * std::cos(0.5 * a)), kRangeRelTol * 100)
        << "roll, pitch and yaw " << deg;
  }
}

// REP 117: no return is +inf (no seabed, level or upward beam, beyond max_range), the origin
// in the bed -inf; on the bed 0
TEST(SeabedRay, NoReturnIsPlusInfinityAndBelowTheBedMinusInfinity) {
  const Vec3 o(0.0, 0.0, 40.0);
  EXPECT_EQ(Seabed().RayRange(o, Vec3::UnitZ(), 200.0), kInf);
  const Seabed flat = Seabed::Flat(60.0);
  EXPECT_EQ(flat.RayRange(o, Beam(0.0, 90.0 * kDegToRad, 0.0), 200.0), kInf);   // level
  EXPECT_EQ(flat.RayRange(o, Beam(0.0, 120.0 * kDegToRad, 0.0), 200.0), kInf);  // above
  EXPECT_EQ(flat.RayRange(o, Vec3::UnitZ(), 19.0), kInf);  // 20 m below, max_range 19 m
  EXPECT_EQ(flat.RayRange(o, Vec3::UnitZ(), 20.0), 20.0);  // at max_range: a return
  EXPECT_EQ(flat.RayRange(Vec3(0.0, 0.0, 61.0), Vec3::UnitZ(), 200.0), -kInf);
  EXPECT_EQ(flat.RayRange(Vec3(0.0, 0.0, 60.0), -Vec3::UnitZ(), 200.0), 0.0);
  // a grid: the same rules
  const Seabed grid = Seabed::Grid({-10.0, 10.0}, {-10.0, 10.0}, {60.0, 60.0, 60.0, 60.0});
  EXPECT_EQ(grid.RayRange(o, Beam(0.0, 90.0 * kDegToRad, 0.0), 200.0), kInf);
  EXPECT_EQ(grid.RayRange(o, Beam(0.0, 150.0 * kDegToRad, 0.0), 200.0), kInf);
  EXPECT_EQ(grid.RayRange(o, Vec3::UnitZ(), 19.0), kInf);
  EXPECT_EQ(grid.RayRange(Vec3(0.0, 0.0, 61.0), Vec3::UnitZ(), 200.0), -kInf);
  EXPECT_NEAR(grid.RayRange(o, Beam(0.0, 30.0 * kDegToRad, 0.0), 200.0),
              20.0 / std::cos(30.0 * kDegToRad), 1e-12);
}

// seeded rays against a sloping plane: the core's F(s) against the geometric closed form;
// some rays climb (u_z < 0) toward the rising side and still meet it
TEST(SeabedRay, PlaneMatchesTheClosedFormRayPlaneIntersection) {
  const double d0 = 40.0, slope = 12.0 * kDegToRad, dir = 30.0 * kDegToRad;
  const Seabed s = Seabed::Plane(d0, slope, dir);
  constexpr double kRangeRelTol = 1e-12;  // both closed forms: round-off of a few operations
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uxy(-100.0, 100.0), uz(0.0, 30.0), angle(-kPi, kPi);
  int hits = 0, climbing_hits = 0, misses = 0;
  for (int i = 0; i < 500; ++i) {
    const Vec3 o(uxy(rng), uxy(rng), uz(rng));
    const Vec3 u = Beam(angle(rng), 0.5 * angle(rng), angle(rng));
    const double expected = RayPlane(d0, slope, dir, o, u);
    const double got = s.RayRange(o, u, 400.0);
    if (o.z() > s.Depth(o.x(), o.y())) {
      EXPECT_EQ(got, -kInf) << i;  // the origin in the bed
      continue;
    }
    if (expected <= 400.0) {
      ++hits;
      if (u.z() < 0.0) ++climbing_hits;
      EXPECT_NEAR(got, expected, kRangeRelTol * expected) << i;
    } else {
      ++misses;
      EXPECT_EQ(got, kInf) << i;
    }
  }
  // the sample covers both outcomes and the climbing case
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 50);
  EXPECT_GT(climbing_hits, 5);
}

// the same plane sampled on an uneven grid (bilinear reproduces a plane): the grid's marching
// and bisection against the closed form, for rays that meet the bed within the grid
TEST(SeabedRay, GridOfAPlaneMatchesTheClosedForm) {
  const double d0 = 55.0, slope = 8.0 * kDegToRad, dir = -40.0 * kDegToRad;
  const std::vector<double> x = {-150.0, -60.0, -20.0, 0.0, 5.0, 35.0, 90.0, 200.0};
  const std::vector<double> y = {-120.0, -50.0, 10.0, 30.0, 80.0, 160.0};
  std::vector<double> d;
  for (double py : y)
    for (double px : x)
      d.push_back(d0 + std::tan(slope) * (px * std::cos(dir) + py * std::sin(dir)));
  const Seabed s = Seabed::Grid(x, y, d);
  // bisection to adjacent doubles on a surface equal to the plane within ~1e-13 m; the range
  // error is that over |dF/ds| >= 0.1 for the rays kept below
  constexpr double kRangeTol = 1e-9;  // [m]
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> uxy(-80.0, 80.0), uz(0.0, 40.0), angle(-kPi, kPi);
  const Vec3 grad(std::tan(slope) * std::cos(dir), std::tan(slope) * std::sin(dir), 0.0);
  int checked = 0;
  for (int i = 0; i < 2000 && checked < 300; ++i) {
    const Vec3 o(uxy(rng), uxy(rng), uz(rng));
    const Vec3 u = Beam(angle(rng), 0.6 * angle(rng), angle(rng));
    const double expected = RayPlane(d0, slope, dir, o, u);
    if (!(expected <= 300.0)) continue;
    const Vec3 hit = o + expected * u;
    // inside the grid, and not grazing (dF/ds = u_z - g . u)
    if (std::abs(hit.x()) > 145.0 || hit.y() < -115.0 || hit.y() > 155.0) continue;
    if (u.z() - grad.dot(u) < 0.1) continue;
    ++checked;
    EXPECT_NEAR(s.RayRange(o, u, 300.0), expected, kRangeTol) << i;
  }
  EXPECT_EQ(checked, 300);
}

// one bilinear cell shaped as a saddle: along its diagonal the bed is d = 10 - 8t + 8t^2
// (t in [0, 1] along it), shallowest (8 m) at t = 1/2; a level beam at z = 8.05 from t = 0.4
// meets it at the first root of 8t^2 - 8t + 10 = 8.05, t = (1 - sqrt(0.025)) / 2, where the
// piece's ends (t = 0.4, 1) and its middle (t = 0.7) all lie above the bed: only the
// quadratic's vertex brackets the hit
TEST(SeabedRay, GridFindsAHumpBetweenItsSamples) {
  const Seabed s = Seabed::Grid({0.0, 1.0}, {0.0, 1.0}, {10.0, 6.0, 6.0, 10.0});
  const Vec3 o(0.4, 0.4, 8.05);
  const Vec3 u = Vec3(1.0, 1.0, 0.0).normalized();
  const double t_hit = 0.5 * (1.0 - std::sqrt(0.025));
  constexpr double kRangeTol = 1e-12;  // [m], bisection to adjacent doubles near 0.03 m
  EXPECT_NEAR(s.RayRange(o, u, 10.0), (t_hit - 0.4) * std::sqrt(2.0), kRangeTol);
  // the same beam 0.1 m higher passes over the saddle and, past the grid (held at 10 m),
  // meets nothing
  EXPECT_EQ(s.RayRange(Vec3(0.4, 0.4, 7.95), u, 10.0), kInf);
}

// a curved bed: the range is a root of F(s) = z(s) - d(x(s), y(s)) and no sample of a dense
// march along the ray before it lies below the bed (the first return)
TEST(SeabedRay, CurvedGridGivesTheFirstRootAlongTheBeam) {
  std::vector<double> x, y, d;
  for (int i = 0; i <= 40; ++i) x.push_back(-100.0 + 5.0 * i + (i % 3) * 0.7);
  for (int j = 0; j <= 30; ++j) y.push_back(-75.0 + 5.0 * j);
  for (double py : y)
    for (double px : x) d.push_back(50.0 + 8.0 * std::sin(0.08 * px) * std::cos(0.06 * py));
  const Seabed s = Seabed::Grid(x, y, d);
  const auto f = [&](const Vec3& o, const Vec3& u, double r) {
    const Vec3 p = o + r * u;
    return p.z() - s.Depth(p.x(), p.y());
  };
  constexpr double kRootTol = 1e-9;  // [m] of F at the returned range (bisection to ulps,
                                     // times slopes of order 1)
  constexpr int kMarchSamples = 20000;
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> uxy(-60.0, 60.0), uz(20.0, 40.0), angle(-kPi, kPi);
  int hits = 0, misses = 0;
  for (int i = 0; i < 100; ++i) {
    const Vec3 o(uxy(rng), uxy(rng), uz(rng));
    const Vec3 u = Beam(0.7 * angle(rng), 0.7 * angle(rng), angle(rng));
    const double r = s.RayRange(o, u, 150.0);
    ASSERT_FALSE(std::isnan(r)) << i;
    if (!std::isfinite(r)) {
      ++misses;
      // no return: the march finds none either
      for (int k = 0; k <= kMarchSamples; ++k)
        ASSERT_LT(f(o, u, 150.0 * k / kMarchSamples), 0.0) << i << " at " << k;
      continue;
    }
    ++hits;
    EXPECT_NEAR(f(o, u, r), 0.0, kRootTol) << i;
    for (int k = 0; k < kMarchSamples; ++k) {
      const double sk = r * k / kMarchSamples;
      ASSERT_LT(f(o, u, sk), 0.0) << i << ": below the bed at " << sk << " before " << r;
    }
  }
  // the sample covers both outcomes
  EXPECT_GT(hits, 20);
  EXPECT_GT(misses, 20);
}

}  // namespace
}  // namespace towsim::core
