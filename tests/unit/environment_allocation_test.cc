// The environment's queries do not allocate (wave_field.h, current_field.h, seabed.h: the loads
// call them at every Gauss point of every step). Built against the core compiled with
// EIGEN_RUNTIME_NO_MALLOC and asserts on, so an Eigen heap allocation aborts; std containers
// are caught by counting the global operator new while the queries run.

#include <cmath>
#include <cstdlib>
#include <limits>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/current_field.h"
#include "core/seabed.h"
#include "core/wave_field.h"
#include "counting_new.h"

namespace towsim::core {
namespace {

using Vec3 = Eigen::Vector3d;

TEST(EnvironmentAllocation, QueriesDoNotAllocate) {
  // every kind, built before counting (construction may allocate)
  WaveSpectrum spectrum;
  spectrum.hs = 2.0;
  spectrum.tp = 8.0;
  WaveField sea = WaveField::Irregular(spectrum, 60.0, 9.81, 1025.0);
  sea.set_ramp(20.0);
  const WaveField deep =
      WaveField::Regular(1.0, 7.0, 0.3, 0.0, std::numeric_limits<double>::infinity(), 9.81, 1025.0);
  CurrentField profile = CurrentField::Profile(
      {{0.0, Vec3(1.0, 0.0, 0.0)}, {20.0, Vec3(0.5, 0.2, 0.0)}, {50.0, Vec3::Zero()}});
  profile.SetTimeScale({{0.0, 0.0}, {30.0, 1.0}});
  const CurrentField law = CurrentField::PowerLaw(Vec3(1.0, 0.0, 0.0), 60.0, 7.0);
  const Seabed grid = Seabed::Grid({0.0, 10.0, 20.0}, {0.0, 10.0}, {50, 51, 52, 53, 54, 55});
  const Seabed plane = Seabed::Plane(40.0, 0.05, 1.0);

  Eigen::internal::set_is_malloc_allowed(false);
  g_news = 0;
  g_counting = true;
  double sum = 0.0;
  for (int i = 0; i < 50; ++i) {
    const Vec3 p(3.0 * i, -2.0 * i, 0.5 * i);
    const double t = 0.7 * i;
    const WaveKinematics k = sea.Kinematics(p, t);
    sum += k.velocity.sum() + k.acceleration.sum() + k.dynamic_pressure;
    sum += sea.Elevation(p.x(), p.y(), t) + deep.Kinematics(p, t).velocity.x();
    sum += profile.Velocity(p.z(), t).sum() + profile.Shear(p.z(), t).sum() +
           profile.Acceleration(p.z(), t).sum() + law.Velocity(p.z(), t).x();
    sum += grid.Depth(p.x(), p.y()) + grid.Normal(p.x(), p.y()).sum() +
           plane.Normal(p.x(), p.y()).z() + plane.WaveDepth();
  }
  g_counting = false;
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_EQ(g_news.load(), 0);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace towsim::core
