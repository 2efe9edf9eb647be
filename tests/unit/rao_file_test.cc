// scene/rao_file.h: the RAO table file, its units and the message of every rule.
#include "scene/rao_file.h"

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/rao_table.h"
#include "scene/config_error.h"
#include "temp_dir.h"

namespace towsim::scene {
namespace {

constexpr double kDeg = core::kPi / 180.0;
const std::string kKey = "bodies.ship.raos";
const std::string kHeader = "period,direction_deg,dof,amplitude,phase_deg\n";

class RaoFile : public ::testing::Test {
 protected:
  std::string Write(const std::string& text, const std::string& name = "ship_raos.csv") {
    const std::string path = (dir_.path() / name).string();
    std::ofstream(path) << text;
    return path;
  }
  // the message of the ConfigError reading `text` gives, or "no error"
  std::string Error(const std::string& text) {
    const std::string path = Write(text);
    try {
      ReadRaoFile(path, kKey);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "no error";
  }
  test::TempDir dir_;
};

// 2 periods x 3 directions of heave and roll, with comments, blanks and rows out of order
const std::string kSmall =
    "# a test table\n"
    "  period , direction_deg , dof , amplitude , phase_deg  \n"
    "\n"
    "5,0,heave,0.5,10   # short waves\n"
    "5,90,heave,0.4,20\n"
    "5,180,heave,0.3,30\n"
    "12,0,heave,0.95,1\n"
    "12,90,heave,0.9,2\n"
    "12,180,heave,0.85,3\n"
    "12,90,roll,6,-90\n"
    "5,0,roll,0,0\n"
    "5,90,roll,2,-45\n"
    "5,180,roll,0,0\n"
    "12,0,roll,0,0\n"
    "12,180,roll,0,0\n";

TEST_F(RaoFile, ReadsTheGridInSIUnits) {
  const std::string path = Write(kSmall);
  const core::RaoTable t = ReadRaoFile(path, kKey);
  EXPECT_EQ(t.source, path);
  EXPECT_FALSE(t.periodic_directions);
  EXPECT_FALSE(t.extrapolate);
  ASSERT_EQ(t.periods, (std::vector<double>{5.0, 12.0}));
  ASSERT_EQ(t.directions.size(), 3u);
  EXPECT_DOUBLE_EQ(t.directions[1], 90.0 * kDeg);
  EXPECT_DOUBLE_EQ(t.directions[2], 180.0 * kDeg);
  const int heave = static_cast<int>(core::VesselDof::kHeave);
  const int roll = static_cast<int>(core::VesselDof::kRoll);
  // [period][direction]: heave (12 s, 90 deg) = 0.9 m/m at 2 deg
  EXPECT_EQ(t.amplitude[heave][1 * 3 + 1], 0.9);
  EXPECT_DOUBLE_EQ(t.phase[heave][1 * 3 + 1], 2.0 * kDeg);
  // roll in deg/m -> rad/m: 6 deg/m = 0.10472 rad/m, lag -90 deg
  EXPECT_DOUBLE_EQ(t.amplitude[roll][1 * 3 + 1], 6.0 * kDeg);
  EXPECT_DOUBLE_EQ(t.phase[roll][1 * 3 + 1], -90.0 * kDeg);
  // the dofs not given are empty (zero)
  for (core::VesselDof d : {core::VesselDof::kSurge, core::VesselDof::kSway,
                            core::VesselDof::kPitch, core::VesselDof::kYaw}) {
    EXPECT_TRUE(t.amplitude[static_cast<int>(d)].empty());
    EXPECT_EQ(core::RaoAt(t, d, 7.0, 0.3), std::complex<double>(0.0, 0.0));
  }
  // through the lookup: roll at (12 s, 90 deg) = 0.10472 e^{+i 90 deg}
  const std::complex<double> h = core::RaoAt(t, core::VesselDof::kRoll, 12.0, 90.0 * kDeg);
  EXPECT_NEAR(h.real(), 0.0, 1e-16);
  EXPECT_NEAR(h.imag(), 6.0 * kDeg, 1e-16);
}

TEST_F(RaoFile, AFullCircleIsPeriodicAndDropsItsDuplicateColumn) {
  std::string text = kHeader;
  for (double p : {6.0, 10.0}) {
    for (double d : {-180.0, -60.0, 60.0, 180.0}) {
      const double a = std::abs(d) == 180.0 ? 1.0 : 0.5;
      // phases -170 and 190 are one angle
      const double phase = d == -180.0 ? -170.0 : (d == 180.0 ? 190.0 : 0.0);
      text += std::to_string(p) + "," + std::to_string(d) + ",pitch," + std::to_string(a) + "," +
              std::to_string(phase) + "\n";
    }
  }
  const core::RaoTable t = ReadRaoFile(Write(text), kKey);
  EXPECT_TRUE(t.periodic_directions);
  ASSERT_EQ(t.directions.size(), 3u);
  EXPECT_DOUBLE_EQ(t.directions.front(), -core::kPi);
  EXPECT_DOUBLE_EQ(t.directions.back(), 60.0 * kDeg);
  EXPECT_EQ(t.amplitude[static_cast<int>(core::VesselDof::kPitch)].size(), 6u);
}

TEST_F(RaoFile, RefusesEndColumnsOfAFullCircleThatDisagree) {
  std::string text = kHeader;
  for (double d : {0.0, 120.0, 240.0}) text += "8," + std::to_string(d) + ",heave,1,0\n";
  text += "8,360,heave,1.02,0\n";  // line 5
  EXPECT_EQ(Error(text),
            "bodies.ship.raos = 1.02,0 (ship_raos.csv:5): the directions span the full circle (0 "
            "to 360 deg), so the rows of both ends are the same direction and must agree: heave "
            "at period 8 s has amplitude,phase_deg 1.02,0 here and 1,0 at line 2");
  // zero amplitudes at both ends need no phase agreement
  std::string zeros = kHeader;
  for (double d : {0.0, 120.0, 240.0}) zeros += "8," + std::to_string(d) + ",yaw,0,0\n";
  zeros += "8,360,yaw,0,77\n";
  EXPECT_EQ(Error(zeros), "no error");
}

TEST_F(RaoFile, NamesTheFileTheLineAndTheRule) {
  EXPECT_EQ(Error(kHeader + "8,0,heave,nan,0\n"),
            "bodies.ship.raos = nan (ship_raos.csv:2): amplitude must be a finite number >= 0 "
            "(m/m for surge, sway and heave, deg/m for roll, pitch and yaw)");
  EXPECT_EQ(Error(kHeader + "8,0,heave,-0.1,0\n"),
            "bodies.ship.raos = -0.1 (ship_raos.csv:2): amplitude must be a finite number >= 0 "
            "(m/m for surge, sway and heave, deg/m for roll, pitch and yaw)");
  EXPECT_EQ(Error(kHeader + "\n# c\n0,0,heave,1,0\n"),
            "bodies.ship.raos = 0 (ship_raos.csv:4): period must be a finite number > 0 [s]");
  EXPECT_EQ(Error(kHeader + "8s,0,heave,1,0\n"),
            "bodies.ship.raos = 8s (ship_raos.csv:2): period must be a finite number > 0 [s]");
  EXPECT_EQ(Error(kHeader + "8,400,heave,1,0\n"),
            "bodies.ship.raos = 400 (ship_raos.csv:2): direction_deg must be a finite number "
            "within [-180, 360] (the direction the waves travel toward, relative to the "
            "heading)");
  EXPECT_EQ(Error(kHeader + "8,0,Heave,1,0\n"),
            "bodies.ship.raos = Heave (ship_raos.csv:2): dof must be one of surge, sway, heave, "
            "roll, pitch, yaw");
  EXPECT_EQ(Error(kHeader + "8,0,heave,1,inf\n"),
            "bodies.ship.raos = inf (ship_raos.csv:2): phase_deg must be a finite number (the lag "
            "behind the wave crest)");
  EXPECT_EQ(Error(kHeader + "8,0,heave,1\n"),
            "bodies.ship.raos = 8,0,heave,1 (ship_raos.csv:2): must have 5 fields "
            "(period,direction_deg,dof,amplitude,phase_deg), it has 4");
  EXPECT_EQ(Error("period,direction,dof,amplitude,phase\n8,0,heave,1,0\n"),
            "bodies.ship.raos = period,direction,dof,amplitude,phase (ship_raos.csv:1): the "
            "header must be period,direction_deg,dof,amplitude,phase_deg");
  EXPECT_EQ(Error(kHeader + "8,0,heave,1,0\n8.0,0,heave,1,0\n"),
            "bodies.ship.raos = 8.0,0,heave (ship_raos.csv:3): duplicate of line 2 (the same "
            "period, direction_deg and dof)");
  const std::string path = Write(kHeader + "# nothing yet\n");
  EXPECT_EQ(Error(kHeader + "# nothing yet\n"),
            "bodies.ship.raos = " + path + " (ship_raos.csv): holds no RAO rows after its header");
  EXPECT_EQ(Error("# only a comment\n"),
            "bodies.ship.raos = " + path +
                " (ship_raos.csv): holds no header line: the first line that is not blank or a "
                "comment must be period,direction_deg,dof,amplitude,phase_deg");
  EXPECT_EQ(Error(kHeader + "8,-180,heave,1,0\n8,200,heave,1,0\n"),
            "bodies.ship.raos = directions -180 to 200 deg (ship_raos.csv): the directions span "
            "380 deg; at most 360 (a direction and the same plus 360 would be given twice)");
}

TEST_F(RaoFile, RefusesAGridWithAHole) {
  // heave gives (5, 0), (5, 90), (9, 0); pitch gives the whole grid; heave (9, 90) is missing
  const std::string text = kHeader +
                           "5,0,heave,1,0\n5,90,heave,1,0\n9,0,heave,1,0\n"
                           "5,0,pitch,1,0\n5,90,pitch,1,0\n9,0,pitch,1,0\n9,90,pitch,1,0\n";
  EXPECT_EQ(Error(text),
            "bodies.ship.raos = heave (ship_raos.csv): heave has no row for period 9 s, "
            "direction_deg 90 (each dof given must give every period and direction of the "
            "table: 2 periods x 2 directions)");
}

TEST_F(RaoFile, RefusesAMissingFile) {
  const std::string path = (dir_.path() / "nowhere.csv").string();
  try {
    ReadRaoFile(path, kKey);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bodies.ship.raos = " + path + " (nowhere.csv): cannot read the file: no such file");
  }
}

}  // namespace
}  // namespace towsim::scene
