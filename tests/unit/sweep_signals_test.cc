// app/sweep/sweep_signals: the results of a case from its CSV files and summary line. The files are
// written here with values whose statistics are known by hand.

#include "app/sweep/sweep_signals.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "app/common/run_stats.h"
#include "io/csv_writer.h"
#include "scene/config_error.h"
#include "temp_dir.h"

namespace towsim::app {
namespace {

constexpr double kExact = 1e-12;  // the files hold the values to 9 digits; these are exact

void Write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

SweepResult R(const std::string& signal, const std::string& stat,
              std::optional<double> from = std::nullopt) {
  SweepResult r;
  r.name = "r";
  r.signal = signal;
  r.stat = stat;
  r.from = from;
  r.location = "sweep.yaml:1";
  return r;
}

class SweepSignals : public ::testing::Test {
 protected:
  void SetUp() override {
    // the towfish starts at (10, 20) heading 90 deg (east, +y): its track is the line x = 10,
    // starboard is -x; it drifts to x = 7 (3 m to starboard) and to z = 30
    const std::string yaw = "1.57079632679";
    Write(dir_.path() / "bodies.csv", std::string(io::kCsvBodiesHeader) + "\n" +
                                          "0,tow,0,0,3,0,0,0,1,0,0,0,0,0\n"
                                          "0,towfish,10,20,25,0,0," +
                                          yaw +
                                          ",3,4,0,0,0,0\n"
                                          "1,tow,1,0,3,0,0,0,1,0,0,0,0,0\n"
                                          "1,towfish,8,25,28,0,0," +
                                          yaw +
                                          ",0,0,0,0,0,0\n"
                                          "2,tow,2,0,3,0,0,0,1,0,0,0,0,0\n"
                                          "2,towfish,7,30,30,0,0," +
                                          yaw + ",0,0,0,0,0,0\n");
    // two nodes: tensions 3, 4 at t=0; 5, 1 at t=1; layback from node 0 to node 1
    Write(dir_.path() / "cable.csv", std::string(io::kCsvCableHeader) + "\n" +
                                         "0,0,0,0,0,3\n0,1,3,4,10,4\n"
                                         "1,0,0,0,0,5\n1,1,6,8,10,1\n");
    Write(dir_.path() / "forces.csv",
          std::string(io::kCsvForcesHeader) + "\n" + "0,tow,3,4,12,0,0,0\n0,towfish,0,0,0,0,0,0\n");
    Write(dir_.path() / "status.csv", std::string(io::kCsvStatusHeader) + "\n" +
                                          "0,0,0,0,0,2\n1,10,4,1e-9,200,2\n2,20,2,3e-9,100,2\n");
  }
  double One(const SweepResult& r, const std::string& out = "") {
    return ComputeSweepResults({r}, dir_.path().string(), out).at(0);
  }
  test::TempDir dir_;
};

TEST_F(SweepSignals, StatisticsOfBodyCableAndStatusSignals) {
  EXPECT_NEAR(One(R("towfish.depth", "final")), 30.0, kExact);
  EXPECT_NEAR(One(R("towfish.z", "initial")), 25.0, kExact);
  EXPECT_NEAR(One(R("towfish.speed", "max")), 5.0, kExact);        // |(3, 4, 0)|
  EXPECT_NEAR(One(R("towfish.track_error", "final")), 3.0, 1e-9);  // yaw to 12 digits
  EXPECT_NEAR(One(R("towfish.track_error", "max_abs")), 3.0, 1e-9);
  EXPECT_NEAR(One(R("tow.x", "mean")), 1.0, kExact);
  EXPECT_NEAR(One(R("tow.cable_force", "final")), 13.0, kExact);  // |(3, 4, 12)|
  EXPECT_NEAR(One(R("layback", "initial")), 5.0, kExact);
  EXPECT_NEAR(One(R("layback", "final")), 10.0, kExact);
  EXPECT_NEAR(One(R("top_tension", "rms")), std::sqrt((9.0 + 25.0) / 2.0), kExact);
  EXPECT_NEAR(One(R("top_tension", "std")), 1.0, kExact);  // 3 and 5 about 4
  EXPECT_NEAR(One(R("max_tension", "min")), 4.0, kExact);
  EXPECT_NEAR(One(R("end_tension", "max")), 4.0, kExact);
  EXPECT_NEAR(One(R("newton_iterations", "max")), 4.0, kExact);
  EXPECT_NEAR(One(R("newton_iterations", "mean", 0.5)), 3.0, kExact);  // t = 1, 2 only
  EXPECT_NEAR(One(R("step_wall_us", "final")), 100.0, kExact);
  EXPECT_NEAR(One(R("residual", "max")), 3e-9, kExact);
}

TEST_F(SweepSignals, RunTotalsComeFromTheSummaryLine) {
  RunStats stats;
  stats.steps = 100;
  stats.sim_time = 5.0;
  stats.wall_time = 0.25;
  stats.iterations_sum = 150;
  stats.iterations_max = 7;
  stats.substepped_steps = 2;
  stats.has_vehicles = true;
  stats.coupling_sum = 120;
  const std::string out = SummaryLine("steady: tow", stats) + "\n";
  EXPECT_EQ(One(R("steps", ""), out), 100.0);
  EXPECT_EQ(One(R("run_wall_s", ""), out), 0.25);
  EXPECT_EQ(One(R("rtf", ""), out), 20.0);
  EXPECT_EQ(One(R("newton_iterations_mean", ""), out), 1.5);
  EXPECT_EQ(One(R("newton_iterations_max", ""), out), 7.0);
  EXPECT_EQ(One(R("substeps", ""), out), 2.0);
  EXPECT_EQ(One(R("coupling_iterations_mean", ""), out), 1.2);
  EXPECT_THROW(One(R("steps", ""), "no summary here\n"), std::runtime_error);
}

TEST_F(SweepSignals, MissingFilesAndEmptyWindowsThrow) {
  std::filesystem::remove(dir_.path() / "cable.csv");
  try {
    One(R("layback", "final"));
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cable.csv: cannot be read"), std::string::npos);
  }
  EXPECT_THROW(One(R("towfish.z", "final", 5.0)), std::runtime_error);
}

// a network's cables (docs/sweeps.md "Results"): a qualified cable signal reads <cable>.csv, an
// unqualified one the scene's first cable (CheckSweepResults sets SweepResult::cable)
TEST_F(SweepSignals, CableSignalsTakeACableQualifier) {
  // main: tensions 7, 9 at t=0; 8, 6 at t=1. tether: 2, 1 at t=0; 3, 2 at t=1
  Write(dir_.path() / "main.csv", std::string(io::kCsvCableHeader) + "\n" +
                                      "0,0,0,0,0,7\n0,1,30,40,10,9\n"
                                      "1,0,0,0,0,8\n1,1,60,80,10,6\n");
  Write(dir_.path() / "tether.csv", std::string(io::kCsvCableHeader) + "\n" +
                                        "0,0,30,40,10,2\n0,1,33,44,20,1\n"
                                        "1,0,60,80,10,3\n1,1,66,88,20,2\n");
  std::vector<SweepResult> r = {R("main.top_tension", "final"), R("tether.top_tension", "max"),
                                R("top_tension", "initial"),    R("tether.end_tension", "mean"),
                                R("main.max_tension", "min"),   R("tether.layback", "final"),
                                R("layback", "final")};
  CheckSweepResults(&r, {"depressor", "towfish"}, {"main", "tether"});
  EXPECT_EQ(r[0].cable, "main");
  EXPECT_EQ(r[1].cable, "tether");
  EXPECT_EQ(r[2].cable, "main");  // unqualified: the first cable
  const std::vector<double> v = ComputeSweepResults(r, dir_.path().string(), "");
  EXPECT_NEAR(v[0], 8.0, kExact);
  EXPECT_NEAR(v[1], 3.0, kExact);
  EXPECT_NEAR(v[2], 7.0, kExact);
  EXPECT_NEAR(v[3], 1.5, kExact);
  EXPECT_NEAR(v[4], 8.0, kExact);   // max over the nodes: 9 at t=0, 8 at t=1
  EXPECT_NEAR(v[5], 10.0, kExact);  // |(6, 8)|
  EXPECT_NEAR(v[6], 100.0, kExact);  // main: |(60, 80)|
  // the one cable of a `cable:` scene answers to "cable" too: cable.csv
  std::vector<SweepResult> one = {R("cable.top_tension", "final"), R("top_tension", "final")};
  CheckSweepResults(&one, {"tow", "towfish"});
  const std::vector<double> w = ComputeSweepResults(one, dir_.path().string(), "");
  EXPECT_NEAR(w[0], 5.0, kExact);
  EXPECT_NEAR(w[1], 5.0, kExact);
  // an unknown cable names the scene's cables
  std::vector<SweepResult> bad = {R("riser.top_tension", "final")};
  try {
    CheckSweepResults(&bad, {"depressor", "towfish"}, {"main", "tether"});
    ADD_FAILURE() << "no exception";
  } catch (const scene::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "results.r.signal = riser.top_tension (sweep.yaml:1): no cable named riser in the "
              "scene (cables: main, tether)");
  }
}

TEST(SweepSignalNames, UnknownSignalsAreBadInput) {
  const std::vector<std::string> bodies = {"tow", "towfish"};
  auto error = [&](const std::string& signal, const std::string& stat) -> std::string {
    std::vector<SweepResult> r = {R(signal, stat)};
    try {
      CheckSweepResults(&r, bodies);
    } catch (const scene::ConfigError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error("towfish.depth", ""), "");
  EXPECT_EQ(error("fish.depth", "max"),
            "results.r.signal = fish.depth (sweep.yaml:1): no body named fish in the scene "
            "(bodies: tow, towfish)");
  EXPECT_NE(error("towfish.altitude", "max").find("unknown quantity altitude of a body"),
            std::string::npos);
  EXPECT_NE(error("tension", "max").find("unknown signal"), std::string::npos);
  EXPECT_NE(error("rtf", "max").find("it takes no stat"), std::string::npos);
  // a time signal without a statistic is its final value
  std::vector<SweepResult> r = {R("layback", "")};
  CheckSweepResults(&r, bodies);
  EXPECT_EQ(r[0].stat, "final");
}

}  // namespace
}  // namespace towsim::app

namespace towsim::app {
namespace {

// settled (docs/sweeps.md "Settled"): change = max - min over t >= t_last - window, below the
// tolerance, over a run at least as long as the window; the values by hand
TEST(SweepSettled, ChangeOverTheFinalWindowAgainstTheTolerance) {
  const std::vector<std::pair<double, double>> rows = {
      {0, 1.0}, {1, 2.0}, {2, 1.5}, {3, 1.75}, {4, 1.625}};
  // window 2: t >= 2: 1.5, 1.75, 1.625: change 0.25 (exact in binary)
  SettledCheck c = CheckSettled(rows, {2.0, 0.3});
  EXPECT_TRUE(c.asked);
  EXPECT_EQ(c.change, 0.25);
  EXPECT_EQ(c.span, 4.0);
  EXPECT_TRUE(c.settled);
  EXPECT_FALSE(CheckSettled(rows, {2.0, 0.25}).settled);  // below: not equal
  // window 3: t >= 1 takes 2.0 in: change 0.5
  c = CheckSettled(rows, {3.0, 0.3});
  EXPECT_EQ(c.change, 0.5);
  EXPECT_FALSE(c.settled);
  // window 4 = the run: every row; window 5 > the run: not shown to settle, whatever the change
  EXPECT_EQ(CheckSettled(rows, {4.0, 2.0}).change, 1.0);
  EXPECT_TRUE(CheckSettled(rows, {4.0, 2.0}).settled);
  c = CheckSettled(rows, {5.0, 2.0});
  EXPECT_EQ(c.change, 1.0);
  EXPECT_FALSE(c.settled);
  // a window of one row is refused
  try {
    CheckSettled(rows, {0.5, 1.0});
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "settled.window 0.5 s holds 1 output row(s) before t = 4 s; it needs at least 2 "
              "(a longer window, or a higher time.output_rate)");
  }
}

// through the case's files: towfish z is 25, 28, 30 at t = 0, 1, 2; the window within the
// result's [from, to]
TEST_F(SweepSignals, SettledOfAResultFromItsFiles) {
  SweepResult r = R("towfish.depth", "final");
  r.settled = SweepSettled{1.0, 2.5};  // t >= 1: 28, 30: change 2 < 2.5
  std::vector<SettledCheck> checks;
  const std::vector<double> v =
      ComputeSweepResults({R("towfish.x", "final"), r}, dir_.path().string(), "", &checks);
  ASSERT_EQ(checks.size(), 2u);
  EXPECT_FALSE(checks[0].asked);
  EXPECT_TRUE(checks[1].asked);
  EXPECT_NEAR(checks[1].change, 2.0, kExact);
  EXPECT_TRUE(checks[1].settled);
  EXPECT_NEAR(v[1], 30.0, kExact);
  r.settled = SweepSettled{1.0, 2.0};  // change 2 is not below 2
  ComputeSweepResults({r}, dir_.path().string(), "", &checks);
  EXPECT_FALSE(checks[0].settled);
  r.to = 1.0;  // the rows t <= 1: 25, 28; the final window t >= 0: change 3
  r.settled = SweepSettled{1.0, 2.5};
  ComputeSweepResults({r}, dir_.path().string(), "", &checks);
  EXPECT_NEAR(checks[0].change, 3.0, kExact);
  EXPECT_FALSE(checks[0].settled);
  // a run total has no time series
  SweepResult total;
  total.name = "rtf";
  total.signal = "rtf";
  total.settled = SweepSettled{1.0, 1.0};
  total.location = "sweep.yaml:3";
  std::vector<SweepResult> results = {total};
  try {
    CheckSweepResults(&results, {"towfish"});
    ADD_FAILURE() << "no error";
  } catch (const scene::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "results.rtf.signal = rtf (sweep.yaml:3): is a total of the whole run (sim_node's "
              "summary line): it takes no stat, from, to or settled");
  }
}

}  // namespace
}  // namespace towsim::app
