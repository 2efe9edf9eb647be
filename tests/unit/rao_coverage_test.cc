// scene/rao_coverage.h: does an RAO table cover the sea's periods and directions?
#include "scene/rao_coverage.h"

#include <gtest/gtest.h>

#include "core/constants.h"

namespace towsim::scene {
namespace {

constexpr double kPi = core::kPi;
constexpr double kDeg = kPi / 180.0;

core::RaoTable Table(std::vector<double> periods, std::vector<double> directions_deg,
                     bool periodic) {
  core::RaoTable t;
  t.periods = std::move(periods);
  for (double d : directions_deg) t.directions.push_back(d * kDeg);
  t.periodic_directions = periodic;
  return t;
}

core::WaveComponent Component(double period, double direction_deg) {
  core::WaveComponent c;
  c.amplitude = 1.0;
  c.omega = 2.0 * kPi / period;
  c.direction = direction_deg * kDeg;
  return c;
}

TEST(RaoCoverage, PeriodsMustLieWithinTheTable) {
  const core::RaoTable t = Table({3.0, 8.0, 30.0}, {-90.0, 0.0, 90.0}, false);
  EXPECT_EQ(RaoCoverageProblem(t, {Component(3.0, 0.0), Component(30.0, 45.0)}, false, 0.0), "");
  EXPECT_EQ(RaoCoverageProblem(t, {Component(10.0, 0.0), Component(2.5, 10.0)}, false, 0.0),
            "wave component 2 of 2 (period 2.5 s, direction 10 deg relative to the heading) lies "
            "outside the RAO table (periods 3 to 30 s, directions -90 to 90 deg)");
  EXPECT_EQ(RaoCoverageProblem(t, {Component(31.0, 0.0)}, false, 0.0),
            "wave component 1 of 1 (period 31 s, direction 0 deg relative to the heading) lies "
            "outside the RAO table (periods 3 to 30 s, directions -90 to 90 deg)");
  // no sea: nothing to cover
  EXPECT_EQ(RaoCoverageProblem(t, {}, true, 0.0), "");
}

TEST(RaoCoverage, DirectionsAreRelativeToTheHeading) {
  const core::RaoTable t = Table({3.0, 30.0}, {-90.0, 0.0, 90.0}, false);
  // waves toward east (90 deg), ship heading east: following seas, 0 relative
  EXPECT_EQ(RaoCoverageProblem(t, {Component(8.0, 90.0)}, false, 90.0 * kDeg), "");
  // waves toward east, ship heading north: 90 (toward starboard), on the table's edge
  EXPECT_EQ(RaoCoverageProblem(t, {Component(8.0, 90.0)}, false, 0.0), "");
  // waves toward west (270), ship heading north: -90 after wrapping
  EXPECT_EQ(RaoCoverageProblem(t, {Component(8.0, 270.0)}, false, 0.0), "");
  // waves toward south, ship heading north: head seas, 180, outside -90..90
  EXPECT_EQ(RaoCoverageProblem(t, {Component(8.0, 180.0)}, false, 0.0),
            "wave component 1 of 1 (period 8 s, direction 180 deg relative to the heading) lies "
            "outside the RAO table (periods 3 to 30 s, directions -90 to 90 deg)");
  // heading 100 deg, waves toward 30 deg: -70
  EXPECT_EQ(RaoCoverageProblem(t, {Component(8.0, 30.0)}, false, 100.0 * kDeg), "");
  // a table of 0..180 (one side): waves toward port are outside, shown in the table's range
  const core::RaoTable half = Table({3.0, 30.0}, {0.0, 90.0, 180.0}, false);
  EXPECT_EQ(RaoCoverageProblem(half, {Component(8.0, -45.0)}, false, 0.0),
            "wave component 1 of 1 (period 8 s, direction 315 deg relative to the heading) lies "
            "outside the RAO table (periods 3 to 30 s, directions 0 to 180 deg)");
}

TEST(RaoCoverage, AChangingHeadingNeedsTheFullCircle) {
  const core::RaoTable open = Table({3.0, 30.0}, {-90.0, 0.0, 90.0}, false);
  EXPECT_EQ(RaoCoverageProblem(open, {Component(8.0, 0.0)}, true, 0.0),
            "the vessel's heading changes during the run, so the waves may meet it from any "
            "direction, but the RAO table (periods 3 to 30 s, directions -90 to 90 deg) does not "
            "cover the full circle (its directions must span 0 to 360 deg, or -180 to 180)");
  const core::RaoTable circle = Table({3.0, 30.0}, {0.0, 90.0, 180.0, 270.0}, true);
  for (double d : {0.0, 135.0, 300.0, -170.0}) {
    EXPECT_EQ(RaoCoverageProblem(circle, {Component(8.0, d)}, true, 0.3), "") << d;
  }
  EXPECT_EQ(RaoCoverageProblem(circle, {Component(2.0, 0.0)}, true, 0.0),
            "wave component 1 of 1 (period 2 s, direction 0 deg relative to the heading) lies "
            "outside the RAO table (periods 3 to 30 s, directions the full circle)");
}

}  // namespace
}  // namespace towsim::scene
