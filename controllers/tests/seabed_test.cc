// The towfish depth controller's altitude mode: target depth = seabed - altitude,
// flat or piecewise-linear along track, the profile parser's rules, along-track distance.

#include "towfish_depth/seabed.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

namespace towsim::controllers {
namespace {

TEST(Seabed, FlatSeabedTargetIsDepthMinusAltitude) {
  const SeabedProfile flat = FlatSeabed(60.0);
  for (double s : {-10.0, 0.0, 123.0, 1e6}) {
    EXPECT_DOUBLE_EQ(AltitudeTargetDepth(flat, s, 35.0), 25.0);
  }
}

TEST(Seabed, PiecewiseLinearProfileInterpolatesAndHoldsItsEnds) {
  // a seabed rising from 80 m to 50 m between 100 m and 400 m of track, then falling to 70 m
  const SeabedProfile p = ParseSeabedProfile("100:80,400:50,600:70", "--seabed-profile");
  EXPECT_DOUBLE_EQ(SeabedDepth(p, 0.0), 80.0);  // before the first point: held
  EXPECT_DOUBLE_EQ(SeabedDepth(p, 100.0), 80.0);
  EXPECT_DOUBLE_EQ(SeabedDepth(p, 250.0), 65.0);  // half way: (80 + 50) / 2
  EXPECT_DOUBLE_EQ(SeabedDepth(p, 400.0), 50.0);
  EXPECT_DOUBLE_EQ(SeabedDepth(p, 550.0), 65.0);  // 50 + 0.75 * 20
  EXPECT_DOUBLE_EQ(SeabedDepth(p, 1000.0), 70.0);
  EXPECT_DOUBLE_EQ(AltitudeTargetDepth(p, 250.0, 20.0), 45.0);
}

TEST(Seabed, ProfileParserRules) {
  auto message = [](const std::string& text) {
    try {
      ParseSeabedProfile(text, "--seabed-profile");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("0:50,abc").find("'abc' is not s:depth"), std::string::npos);
  EXPECT_NE(message("100:50,50:60").find("must increase"), std::string::npos);
  EXPECT_NE(message("0:-5").find("must be > 0"), std::string::npos);
  EXPECT_NE(message("").find("at least one"), std::string::npos);
  EXPECT_NE(message("0:50;60:40").find("--seabed-profile 0:50;60:40"), std::string::npos);
}

TEST(Seabed, AlongTrackIsTheHorizontalDistanceRun) {
  AlongTrack a;
  EXPECT_DOUBLE_EQ(a.Update(10, 10), 0.0);
  EXPECT_DOUBLE_EQ(a.Update(13, 14), 5.0);
  EXPECT_DOUBLE_EQ(a.Update(13, 10), 9.0);  // turning back still adds distance
}

}  // namespace
}  // namespace towsim::controllers
