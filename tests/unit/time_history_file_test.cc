// scene/time_history_file.h: the time-history file, the unwrapping of yaw, the messages of
// every rule, and the coverage of the run.
#include "scene/time_history_file.h"

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/pose_spline.h"
#include "scene/config_error.h"
#include "temp_dir.h"

namespace towsim::scene {
namespace {

constexpr double kPi = core::kPi;
const std::string kKey = "bodies.ship.time_history";
const std::string kHeader = "t,x,y,z,roll,pitch,yaw\n";

class TimeHistoryFile : public ::testing::Test {
 protected:
  std::string Write(const std::string& text) {
    const std::string path = (dir_.path() / "ship_log.csv").string();
    std::ofstream(path) << text;
    return path;
  }
  std::string Error(const std::string& text) {
    const std::string path = Write(text);
    try {
      ReadTimeHistoryFile(path, kKey);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "no error";
  }
  test::TempDir dir_;
};

TEST_F(TimeHistoryFile, ReadsTheSamples) {
  const std::string path = Write(
      "# logged on the trial\n"
      " t , x , y , z , roll , pitch , yaw \n"
      "0, 1, 2, -0.5, 0.01, -0.02, 0.3\n"
      "\n"
      "0.5, 2, 2.5, -0.4, 0.02, -0.01, 0.31  # half a second\n"
      "1.0, 3, 3, -0.3, 0.03, 0.0, 0.32\n");
  const core::TimeHistory h = ReadTimeHistoryFile(path, kKey);
  EXPECT_EQ(h.source, path);
  ASSERT_EQ(h.t, (std::vector<double>{0.0, 0.5, 1.0}));
  ASSERT_EQ(h.pose.size(), 3u);
  Eigen::Matrix<double, 6, 1> second;
  second << 2, 2.5, -0.4, 0.02, -0.01, 0.31;
  EXPECT_EQ(h.pose[1], second);
  // and the spline passes through them
  const core::PoseSpline s(h);
  EXPECT_NEAR((s.Evaluate(0.5).pose - second).norm(), 0.0, 1e-15);
}

TEST_F(TimeHistoryFile, UnwrapsYawAcrossTheWrapOfTheLogger) {
  // a ship turning to starboard through south: the logger writes yaw within (-pi, pi]
  const std::string path = Write(kHeader +
                                 "0,0,0,0,0,0,2.9\n"
                                 "1,0,0,0,0,0,3.1\n"
                                 "2,0,0,0,0,0,-3.0\n"   // 3.28318: +0.183
                                 "3,0,0,0,0,0,-2.8\n"   // 3.48318
                                 "4,0,0,0,0,0,-3.1\n"   // 3.18318: turning back
                                 "5,0,0,0,0,0,3.0\n");  // 3.0 (no wrap)
  const core::TimeHistory h = ReadTimeHistoryFile(path, kKey);
  const double want[] = {2.9, 3.1, -3.0 + 2 * kPi, -2.8 + 2 * kPi, -3.1 + 2 * kPi, 3.0};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(h.pose[i](5), want[i], 1e-15) << i;
  // several turns: +2 pi per crossing, kept across a long run
  std::string text = kHeader;
  for (int i = 0; i <= 40; ++i) {
    const double yaw = 0.5 * i;  // 20 rad: more than three turns
    text += std::to_string(i) + ",0,0,0,0,0," + std::to_string(std::remainder(yaw, 2 * kPi)) + "\n";
  }
  const core::TimeHistory turns = ReadTimeHistoryFile(Write(text), kKey);
  EXPECT_NEAR(turns.pose.back()(5), 20.0, 1e-5);  // the file's 6 decimals
}

TEST_F(TimeHistoryFile, NamesTheFileTheLineAndTheRule) {
  EXPECT_EQ(Error(kHeader + "0,0,0,0,0,0,0\n1,0,nan,0,0,0,0\n"),
            "bodies.ship.time_history = nan (ship_log.csv:3): y must be a finite number [m]");
  EXPECT_EQ(Error(kHeader + "0,0,0,0,0,0,0\n0.5,0,0,0,0,0,0\n0.5,1,0,0,0,0,0\n"),
            "bodies.ship.time_history = 0.5 (ship_log.csv:4): t must increase strictly: 0.5 "
            "after 0.5 at line 3");
  EXPECT_EQ(Error(kHeader + "1,0,0,0,0,0,0\n# gap\n0.9,0,0,0,0,0,0\n"),
            "bodies.ship.time_history = 0.9 (ship_log.csv:4): t must increase strictly: 0.9 "
            "after 1 at line 2");
  EXPECT_EQ(Error(kHeader + "0,0,0,0,3.2,0,0\n1,0,0,0,0,0,0\n"),
            "bodies.ship.time_history = 3.2 (ship_log.csv:2): roll must lie within (-pi, pi] rad "
            "(ZYX Euler angles)");
  EXPECT_EQ(Error(kHeader + "0,0,0,0,0,1.5708,0\n1,0,0,0,0,0,0\n"),
            "bodies.ship.time_history = 1.5708 (ship_log.csv:2): pitch must lie within (-pi/2, "
            "pi/2) rad (ZYX Euler angles)");
  EXPECT_EQ(Error(kHeader + "0,0,0,0,0,0\n"),
            "bodies.ship.time_history = 0,0,0,0,0,0 (ship_log.csv:2): must have 7 fields "
            "(t,x,y,z,roll,pitch,yaw), it has 6");
  EXPECT_EQ(Error("t,x,y,z,phi,theta,psi\n"),
            "bodies.ship.time_history = t,x,y,z,phi,theta,psi (ship_log.csv:1): the header must "
            "be t,x,y,z,roll,pitch,yaw");
  const std::string path = Write("");
  EXPECT_EQ(Error(kHeader + "0,0,0,0,0,0,0\n"),
            "bodies.ship.time_history = " + path +
                " (ship_log.csv): holds 1 sample(s); a time history needs at least 2");
  const std::string missing = (dir_.path() / "none.csv").string();
  try {
    ReadTimeHistoryFile(missing, kKey);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), "bodies.ship.time_history = " + missing +
                                         " (none.csv): cannot read the file: no such file");
  }
}

TEST(TimeHistoryCoverage, TheHistoryMustSpanTheRun) {
  core::TimeHistory h;
  h.t = {0.0, 50.0, 100.0};
  h.pose.resize(3, Eigen::Matrix<double, 6, 1>::Zero());
  EXPECT_EQ(TimeHistoryCoverageProblem(h, 100.0), "");
  EXPECT_EQ(TimeHistoryCoverageProblem(h, 60.0), "");
  EXPECT_EQ(TimeHistoryCoverageProblem(h, 100.5),
            "the time history spans t = 0 to 100 s, but the run needs t = 0 to 100.5 s (the "
            "history must start at t <= 0 and end at t >= the duration)");
  h.t = {0.1, 50.0, 200.0};
  EXPECT_EQ(TimeHistoryCoverageProblem(h, 100.0),
            "the time history spans t = 0.1 to 200 s, but the run needs t = 0 to 100 s (the "
            "history must start at t <= 0 and end at t >= the duration)");
  h.t = {-10.0, 50.0, 200.0};
  EXPECT_EQ(TimeHistoryCoverageProblem(h, 100.0), "");
}

}  // namespace
}  // namespace towsim::scene
