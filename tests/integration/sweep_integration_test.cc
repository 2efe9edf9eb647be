// towsim_sweep run locally as a process (docs/sweeps.md): the table against sim_node run
// directly with the same values, failed cases recorded with sim_node's message, --resume
// rerunning only the missing and failed cases, SIGTERM losing no finished case, bad sweep
// files exiting 2; and sweeps with controllers: sim_node in lockstep beside maneuver_runner,
// towfish_depth and test_controller over loopback DDS (domains 206-211), the table against
// the cases' CSV files, settled, failures with their reasons, the plots.

#include <signal.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "io/csv_reader.h"
#include "temp_dir.h"
#include "testing/process.h"

namespace towsim::testing {
namespace {

namespace fs = std::filesystem;

const std::string kSource = TOWSIM_SOURCE_DIR;
const std::string kLocalSweep = kSource + "/tests/integration/sweeps/local_sweep.yaml";
constexpr double kTimeout = 60.0;  // [s] a sweep that takes longer has hung

// a folder of the test's own (removed at its end): the pid in its name keeps apart the runs of
// other checkouts on the machine
class SweepLocal : public ::testing::Test {
 protected:
  std::string Tmp(const std::string& what) const { return (tmp_.path() / what).string(); }

 private:
  test::TempDir tmp_;
};

struct Sweep {
  int exit_code = -1;
  std::string out, err;
};

Sweep RunSweep(const std::vector<std::string>& args, const std::string& log) {
  std::vector<std::string> argv = {TOWSIM_SWEEP};
  argv.insert(argv.end(), args.begin(), args.end());
  Process p(argv, log);
  EXPECT_TRUE(p.Wait(kTimeout)) << p.command_line();
  return {p.exit_code(), p.out(), p.err()};
}

// the rows of results.csv by case, each a map column -> field
std::map<std::string, std::map<std::string, std::string>> Table(const std::string& path) {
  const io::CsvTable t = io::ReadCsvFile(path);
  std::map<std::string, std::map<std::string, std::string>> rows;
  for (const auto& row : t.rows) {
    for (size_t i = 0; i < t.columns.size(); ++i) rows[row[0]][t.columns[i]] = row[i];
  }
  return rows;
}

// the last row of `body` in a bodies.csv: its fields
std::vector<std::string> LastBodyRow(const std::string& bodies_csv, const std::string& body) {
  const io::CsvTable t = io::ReadCsvFile(bodies_csv);
  std::vector<std::string> last;
  for (const auto& row : t.rows) {
    if (row[1] == body) last = row;
  }
  return last;
}

std::string Contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::file_time_type Mtime(const fs::path& p) { return fs::last_write_time(p); }

TEST_F(SweepLocal, TableEqualsDirectRunsAndFailedCasesAreRecordedThenResumed) {
  const std::string out = Tmp("out");
  const Sweep s = RunSweep({kLocalSweep, "--out", out, "--workers", "2"}, Tmp("log"));
  // two cases fail: the sweep ran to its end and says so with exit 4
  EXPECT_EQ(s.exit_code, 4) << s.err;
  EXPECT_NE(s.err.find("[towsim_sweep] 4/4 cases done, 2 failed, 0 running"), std::string::npos)
      << s.err;
  EXPECT_NE(s.out.find("towsim_sweep: local_sweep.yaml: 4 cases: 2 ok, 2 failed, 0 not run"),
            std::string::npos)
      << s.out;
  EXPECT_EQ(ReadFile(out + "/summary.txt"), s.out);

  // the header: fixed columns, parameters by key path, results by name
  std::ifstream table_in(out + "/results.csv");
  std::string header;
  std::getline(table_in, header);
  EXPECT_EQ(header,
            "case,status,exit_code,message,wall_s,cable.elements,time.step,cable.youngs_modulus,"
            "integrator.max_substep_level,towfish_depth,layback,top_tension_max,"
            "top_tension_rms,towfish_track_error,newton_max,substeps");
  auto rows = Table(out + "/results.csv");
  ASSERT_EQ(rows.size(), 4u);

  // each case against sim_node run directly with the same --set values
  const std::string scene = kSource + "/config/scenes/case1_forward.yaml";
  const std::vector<std::vector<std::string>> sets = {
      {"cable.elements=10", "time.step=0.05", "cable.youngs_modulus=7.0e8",
       "integrator.max_substep_level=6"},
      {"cable.elements=20", "time.step=0.1", "cable.youngs_modulus=7.0e8",
       "integrator.max_substep_level=6"},
      {"cable.elements=20", "time.step=1", "cable.youngs_modulus=7.0e11",
       "integrator.max_substep_level=0"},
      {"cable.elements=0", "time.step=0.05", "cable.youngs_modulus=7.0e8",
       "integrator.max_substep_level=6"}};
  const int expected_codes[] = {0, 0, 3, 2};
  for (int i = 0; i < 4; ++i) {
    const std::string name = "case_000" + std::to_string(i);
    const std::string direct_csv = Tmp("direct_" + std::to_string(i));
    std::vector<std::string> argv = {TOWSIM_SIM_NODE, "--scene",    scene, "--mode",
                                     "offline",       "--duration", "2"};
    for (const std::string& set : sets[i]) argv.insert(argv.end(), {"--set", set});
    argv.insert(argv.end(), {"--csv", direct_csv});
    Process direct(argv, Tmp("direct_log_" + std::to_string(i)));
    ASSERT_TRUE(direct.Wait(kTimeout));
    ASSERT_EQ(direct.exit_code(), expected_codes[i]) << direct.err();
    auto& row = rows[name];
    EXPECT_EQ(row["exit_code"], std::to_string(expected_codes[i])) << name;
    EXPECT_EQ(row["cable.elements"], sets[i][0].substr(sets[i][0].find('=') + 1));
    if (expected_codes[i] != 0) {
      // the message is sim_node's last line on stderr, the results are empty
      EXPECT_EQ(row["status"], "failed");
      std::string err = direct.err();
      while (!err.empty() && err.back() == '\n') err.pop_back();
      EXPECT_EQ(row["message"], err.substr(err.rfind('\n') + 1)) << name;
      EXPECT_EQ(row["towfish_depth"], "");
      continue;
    }
    EXPECT_EQ(row["status"], "ok");
    EXPECT_EQ(row["message"], "");
    // the CSV files of the case are sim_node's own, byte for byte
    for (const char* file : {"bodies.csv", "cable.csv", "forces.csv"}) {
      EXPECT_EQ(ReadFile(out + "/" + name + "/" + file), ReadFile(direct_csv + "/" + file))
          << name << " " << file;
    }
    // the final towfish depth is the z of its last bodies.csv row (both "%.9g")
    EXPECT_EQ(row["towfish_depth"], LastBodyRow(direct_csv + "/bodies.csv", "towfish")[4]);
    // the run totals are those of sim_node's summary line
    const std::string line = direct.out();
    const size_t at = line.find("Newton iterations mean ");
    ASSERT_NE(at, std::string::npos);
    const std::string max = line.substr(line.find(" max ", at) + 5);
    EXPECT_EQ(row["newton_max"], max.substr(0, max.find(','))) << line;
    EXPECT_EQ(row["substeps"], "0");
  }
  // the plot: one point per ok case and result (2 x 7), the failed cases counted per panel
  const std::string svg = ReadFile(out + "/results.svg");
  size_t points = 0;
  for (size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) {
    ++points;
  }
  EXPECT_EQ(points, 14u);
  EXPECT_NE(svg.find("towfish_depth (towfish.depth, final), 2 failed case(s) not shown"),
            std::string::npos);

  // the same folder again without --resume: refused, nothing touched
  const Sweep again = RunSweep({kLocalSweep, "--out", out}, Tmp("again"));
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("holds an earlier sweep (results.csv); pass --resume"),
            std::string::npos)
      << again.err;

  // --resume: case_0001 lost its status (as if the sweep was killed while it ran): it and the
  // two failed cases run again, case_0000 does not
  fs::remove(out + "/case_0001/case_status.txt");
  const auto kept = Mtime(out + "/case_0000/case_status.txt");
  const auto failed_before = Mtime(out + "/case_0003/case_status.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const Sweep resumed = RunSweep({kLocalSweep, "--out", out, "--resume"}, Tmp("resume"));
  EXPECT_EQ(resumed.exit_code, 4) << resumed.err;
  EXPECT_NE(resumed.out.find("2 failed, 0 not run; 3 run in"), std::string::npos) << resumed.out;
  EXPECT_EQ(Mtime(out + "/case_0000/case_status.txt"), kept);
  EXPECT_NE(Mtime(out + "/case_0003/case_status.txt"), failed_before);
  auto resumed_rows = Table(out + "/results.csv");
  ASSERT_EQ(resumed_rows.size(), 4u);
  for (auto& [name, row] : resumed_rows) {
    row.erase("wall_s");
    rows[name].erase("wall_s");
    EXPECT_EQ(row, rows[name]) << name;
  }
}

// the rows of a case's <cable>.csv by time: each time's nodes as (t, node, x, y, z, tension),
// the fields as written and parsed
struct CableRows {
  std::vector<std::vector<std::string>> text;  // the last row set, as written
  std::vector<std::vector<std::vector<double>>> sets;  // every row set, node order
};
CableRows ReadCable(const std::string& path) {
  const io::CsvTable t = io::ReadCsvFile(path);
  CableRows c;
  std::string time;
  for (const auto& row : t.rows) {
    if (row[0] != time) {
      c.sets.emplace_back();
      c.text.clear();
      time = row[0];
    }
    std::vector<double> x;
    for (const std::string& f : row) x.push_back(std::stod(f));
    c.sets.back().push_back(x);
    c.text.push_back(row);
  }
  return c;
}

// a network sweep (tests/integration/sweeps/network_sweep.yaml, offline): the cable signals
// with a cable qualifier read that cable's <cable>.csv, without one the first cable's, checked
// against the cases' own main.csv and tether.csv
TEST_F(SweepLocal, NetworkCableSignalsReadTheirCablesCsv) {
  // the table prints "%.9g": a mean recomputed here agrees to its 9 digits
  constexpr double kPrinted = 1e-8;  // relative
  const std::string out = Tmp("out");
  const Sweep s = RunSweep({kSource + "/tests/integration/sweeps/network_sweep.yaml", "--out",
                            out, "--workers", "2"},
                           Tmp("log"));
  ASSERT_EQ(s.exit_code, 0) << s.err;
  auto rows = Table(out + "/results.csv");
  ASSERT_EQ(rows.size(), 2u);
  std::vector<double> tether_tops;
  for (const std::string name : {"case_0000", "case_0001"}) {
    SCOPED_TRACE(name);
    auto& row = rows[name];
    ASSERT_EQ(row["status"], "ok") << row["message"];
    EXPECT_FALSE(fs::exists(out + "/" + name + "/cable.csv"));  // a network: <cable>.csv
    const CableRows main = ReadCable(out + "/" + name + "/main.csv");
    const CableRows tether = ReadCable(out + "/" + name + "/tether.csv");
    ASSERT_EQ(main.sets.size(), 21u);  // 2 s at 10 Hz, t = 0 included
    ASSERT_EQ(tether.sets.size(), 21u);
    // final values: the last row set's field as written
    EXPECT_EQ(row["main_top"], main.text.front()[5]);
    EXPECT_EQ(row["first_top"], main.text.front()[5]);  // unqualified: the first cable, main
    double top_max = -INFINITY, end_sum = 0.0, first_max = -INFINITY;
    for (const auto& set : tether.sets) {
      top_max = std::max(top_max, set.front()[5]);
      end_sum += set.back()[5];
    }
    for (const auto& node : main.sets.front()) first_max = std::max(first_max, node[5]);
    EXPECT_NEAR(std::stod(row["tether_top_max"]), top_max, kPrinted * top_max);
    const double end_mean = end_sum / 21.0;
    EXPECT_NEAR(std::stod(row["tether_end_mean"]), end_mean, kPrinted * end_mean);
    EXPECT_NEAR(std::stod(row["main_max_tension"]), first_max, kPrinted * first_max);
    const auto& last = tether.sets.back();
    const double layback = std::hypot(last.back()[2] - last.front()[2],
                                      last.back()[3] - last.front()[3]);
    EXPECT_NEAR(std::stod(row["tether_layback"]), layback, kPrinted * layback);
    // the cables differ: the main cable also holds the depressor
    EXPECT_GT(std::stod(row["main_top"]), 1.5 * std::stod(row["tether_top_max"]));
    tether_tops.push_back(top_max);
  }
  // a heavier towfish pulls harder on its tether
  EXPECT_GT(tether_tops[1], tether_tops[0]);

  // a cable the scene does not have: exit 2 naming the scene's cables
  const std::string bad = Tmp("bad_sweep.yaml");
  std::ofstream(bad) << "scene: " << kSource
                     << "/tests/integration/scenes/network_two_part_tow.yaml\n"
                        "duration: 1\nparameters:\n  bodies.towfish.mass: [400]\n"
                        "results:\n  r: {signal: cable.top_tension}\n";
  const Sweep refused = RunSweep({bad, "--out", Tmp("bad_out")}, Tmp("bad_log"));
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("results.r.signal = cable.top_tension"), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("no cable named cable in the scene (cables: main, tether)"),
            std::string::npos)
      << refused.err;
}

TEST_F(SweepLocal, SigtermLosesNoFinishedCaseAndResumeRunsTheRest) {
  // six cases of ~0.3 s each (Case 1 for 400 s) on one worker; SIGTERM during the third
  const std::string dir = Tmp("sweep");
  fs::create_directories(dir);
  const std::string file = dir + "/long.yaml";
  std::ofstream(file) << "scene: " << kSource << "/config/scenes/case1_forward.yaml\n"
                      << "duration: 400\nparameters:\n  cable.elements: [10, 11, 12, 13, 14, 15]\n"
                      << "results:\n  depth: {signal: towfish.depth}\n";
  const std::string out = dir + "/out";
  Process sweep({TOWSIM_SWEEP, file, "--out", out, "--workers", "1"}, dir + "/log");
  // wait for two finished cases, then stop the sweep
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!fs::exists(out + "/case_0001/case_status.txt") &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  sweep.Signal(SIGTERM);
  ASSERT_TRUE(sweep.Wait(kTimeout));
  EXPECT_EQ(sweep.exit_code(), 143) << sweep.err();
  // every case that finished is in the table, the one stopped is not
  auto rows = Table(out + "/results.csv");
  ASSERT_GE(rows.size(), 2u);
  ASSERT_LT(rows.size(), 6u);
  for (auto& [name, row] : rows) {
    EXPECT_EQ(row["status"], "ok") << name;
    EXPECT_TRUE(fs::exists(out + "/" + name + "/case_status.txt")) << name;
  }
  const size_t finished = rows.size();
  EXPECT_FALSE(fs::exists(out + "/case_000" + std::to_string(finished) + "/case_status.txt"));
  EXPECT_NE(sweep.out().find(std::to_string(6 - finished) + " not run"), std::string::npos)
      << sweep.out();

  const Sweep resumed =
      RunSweep({file, "--out", out, "--resume", "--workers", "2"}, dir + "/resume");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(
      resumed.out.find("6 ok, 0 failed, 0 not run; " + std::to_string(6 - finished) + " run in"),
      std::string::npos)
      << resumed.out;
  auto all = Table(out + "/results.csv");
  ASSERT_EQ(all.size(), 6u);
  for (auto& [name, row] : rows) EXPECT_EQ(all[name], row) << name;  // kept as they were
}

// two sweeps into one folder contradicted each other and marked good cases failed: the second
// is refused while the first runs (DIR/.lock), naming the folder and the first one's pid
TEST_F(SweepLocal, SecondSweepIntoARunningSweepsFolderIsRefused) {
  const std::string dir = Tmp("locked");
  fs::create_directories(dir);
  const std::string file = dir + "/long.yaml";
  std::ofstream(file) << "scene: " << kSource << "/config/scenes/case1_forward.yaml\n"
                      << "duration: 400\nparameters:\n  cable.elements: [10, 11, 12, 13]\n";
  const std::string out = dir + "/out";
  Process first({TOWSIM_SWEEP, file, "--out", out, "--workers", "1"}, dir + "/first");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!fs::exists(out + "/results.csv") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  const std::string refused = "towsim_sweep: error: --out " + out + ": another towsim_sweep (pid " +
                              std::to_string(first.pid()) + ") runs in it (" + out +
                              "/.lock); wait for it to end or choose another folder";
  for (const char* flag : {"--resume", "--collect"}) {
    const Sweep second = RunSweep({file, "--out", out, flag}, dir + "/second" + flag);
    EXPECT_EQ(second.exit_code, 2) << flag;
    EXPECT_NE(second.err.find(refused), std::string::npos) << second.err;
  }
  first.Signal(SIGTERM);
  ASSERT_TRUE(first.Wait(kTimeout));
  EXPECT_EQ(first.exit_code(), 143) << first.err();
  // the lock went with the first sweep
  const Sweep after = RunSweep({file, "--out", out, "--collect"}, dir + "/after");
  EXPECT_NE(after.exit_code, 2) << after.err;
}

// a folder belongs to the sweep file that made it: --resume with another one replaced its table
TEST_F(SweepLocal, ResumeWithAnotherSweepFileIsRefused) {
  const std::string dir = Tmp("two");
  fs::create_directories(dir);
  const std::string first = dir + "/first.yaml", second = dir + "/second.yaml";
  for (const auto& [file, elements] : {std::pair{first, "10"}, std::pair{second, "12"}}) {
    std::ofstream(file) << "scene: " << kSource << "/config/scenes/case1_forward.yaml\n"
                        << "duration: 2\nparameters:\n  cable.elements: [" << elements << "]\n";
  }
  const std::string out = dir + "/out";
  Sweep s = RunSweep({first, "--out", out}, dir + "/log1");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const std::string table = Contents(out + "/results.csv");
  s = RunSweep({second, "--out", out, "--resume"}, dir + "/log2");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(
      s.err.find("towsim_sweep: error: --resume: --out " + out + " was made by the sweep file " +
                 first + ", not " + second + "; pass that file, or choose another folder"),
      std::string::npos)
      << s.err;
  s = RunSweep({second, "--out", out, "--collect"}, dir + "/log3");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("--collect: --out " + out + " was made by the sweep file " + first),
            std::string::npos)
      << s.err;
  EXPECT_EQ(Contents(out + "/results.csv"), table);  // untouched
  s = RunSweep({first, "--out", out, "--resume"}, dir + "/log4");
  EXPECT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NE(s.out.find("1 ok, 0 failed, 0 not run; 0 run in"), std::string::npos) << s.out;
}

TEST_F(SweepLocal, BadSweepFilesAndFlagsExit2) {
  const std::string dir = Tmp("bad");
  fs::create_directories(dir);
  const std::string file = dir + "/bad.yaml";
  std::ofstream(file) << "scene: " << kSource << "/config/scenes/steady_tow.yaml\n"
                      << "parameters:\n  cable.elemnts: [10, 20]\n";
  Sweep s = RunSweep({file, "--out", dir + "/out"}, dir + "/log1");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("towsim_sweep: error: parameters.cable.elemnts = [10, 20] (bad.yaml:3): "
                       "cable: unknown key; did you mean elements?"),
            std::string::npos)
      << s.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));  // nothing written for a bad sweep

  std::ofstream(file) << "scene: " << kSource << "/config/scenes/steady_tow.yaml\n"
                      << "parameters:\n  cable.elements: [10, 20]\n"
                      << "results:\n  d: {signal: fish.depth}\n";
  s = RunSweep({file, "--out", dir + "/out"}, dir + "/log2");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("results.d.signal = fish.depth (bad.yaml:5): no body named fish"),
            std::string::npos)
      << s.err;

  // an integer range beyond 2^53 was one case of value -2^63
  std::ofstream(file) << "scene: " << kSource << "/config/scenes/steady_tow.yaml\n"
                      << "parameters:\n  cable.elements: {from: 9223372036854775800, "
                      << "to: 9223372036854775807, step: 1}\n";
  s = RunSweep({file, "--out", dir + "/out"}, dir + "/log5");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("towsim_sweep: error: parameters.cable.elements.from = "
                       "9223372036854775800 (bad.yaml:3): an integer range must lie within "
                       "-(2^53 - 1) .. 2^53 - 1 = 9007199254740991 (exact in a double)"),
            std::string::npos)
      << s.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));

  s = RunSweep({file, "--workers", "0", "--out", dir + "/out"}, dir + "/log3");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("--workers 0: must be an integer from 1 to 4096"), std::string::npos)
      << s.err;
  s = RunSweep({file, "--workers", "100000", "--out", dir + "/out"}, dir + "/log6");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("towsim_sweep: error: --workers 100000: must be an integer from 1 to 4096"),
            std::string::npos)
      << s.err;
  s = RunSweep({file}, dir + "/log4");
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("--out DIR is required"), std::string::npos) << s.err;
}

// --- sweeps with controllers (docs/sweeps.md "Controllers"): every case sim_node in lockstep
// beside real controller processes over loopback DDS, each case on a domain of its own from
// 206 (this test's domains: 206-211) -------------------------------------------------------

// the rows of `body` in a bodies.csv: (t, u, v, w, z)
struct BodyRow {
  double t, z, speed;
};
std::vector<BodyRow> BodyRows(const std::string& bodies_csv, const std::string& body) {
  const io::CsvTable t = io::ReadCsvFile(bodies_csv);
  std::vector<BodyRow> rows;
  for (const auto& r : t.rows) {
    if (r[1] != body) continue;
    const double u = std::stod(r[8]), v = std::stod(r[9]), w = std::stod(r[10]);
    rows.push_back({std::stod(r[0]), std::stod(r[4]), std::sqrt(u * u + v * v + w * w)});
  }
  return rows;
}

// the reference of `settled` (docs/sweeps.md "Settled"), computed here from the rows: max - min
// over t >= t_last - window, below the tolerance
bool SettledHere(const std::vector<std::pair<double, double>>& tx, double window,
                 double tolerance) {
  double lo = 1e300, hi = -1e300;
  for (const auto& [t, x] : tx) {
    if (t < tx.back().first - window - 1e-9) continue;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  return hi - lo < tolerance;
}

bool StartsWith(const std::string& text, const std::string& head) {
  return text.compare(0, head.size(), head) == 0;
}

TEST_F(SweepLocal, ControllersInLockstepTheirSweptArgumentsAndSettledResults) {
  const std::string file = Tmp("controllers.yaml");
  // two parameters: the tow vehicle's thrust, an argument of maneuver_runner, and the cable's
  // elements, a scene key; at thrust 0 the system hangs still (settles), at 4165 N it
  // accelerates for the whole 10 s (made not to settle)
  std::ofstream(file) << "scene: " << kSource << "/config/scenes/case1_forward.yaml\n"
                      << "duration: 10\n"
                      << "domain: 206\n"
                      << "lockstep_timeout: 10\n"  // a loaded machine: no timeout by load
                      << "controllers:\n"
                      << "  - program: " << TOWSIM_MANEUVER_RUNNER << "\n"
                      << "    args: [--maneuver, case1, --body, tow_vehicle, --thrust, "
                         "\"${thrust}\"]\n"
                      << "  - program: " << TOWSIM_TOWFISH_DEPTH << "\n"
                      << "    name: depth\n"
                      << "    args: [--body, towfish, --depth, 200, --log, "
                         "\"${case_dir}/depth.log\"]\n"
                      << "parameters:\n"
                      << "  thrust: [0, 4165]\n"
                      << "  cable.elements: [10, 20]\n"
                      << "results:\n"
                      << "  towfish_depth: {signal: towfish.depth, settled: {window: 4, "
                         "tolerance: 0.5}}\n"
                      << "  tow_speed: {signal: tow_vehicle.speed, stat: max, settled: "
                         "{window: 4, tolerance: 0.2}}\n";
  const std::string out = Tmp("out");
  const Sweep s = RunSweep({file, "--out", out, "--workers", "2"}, Tmp("log"));
  ASSERT_EQ(s.exit_code, 0) << s.out << s.err;
  EXPECT_NE(s.out.find("4 cases: 4 ok (2 not settled), 0 failed, 0 not run"), std::string::npos)
      << s.out;
  std::ifstream table_in(out + "/results.csv");
  std::string header;
  std::getline(table_in, header);
  EXPECT_EQ(header,
            "case,status,exit_code,message,wall_s,thrust,cable.elements,towfish_depth,tow_speed,"
            "towfish_depth.settled,tow_speed.settled");
  auto rows = Table(out + "/results.csv");
  ASSERT_EQ(rows.size(), 4u);
  const char* thrusts[] = {"0", "0", "4165", "4165"};
  const int elements[] = {10, 20, 10, 20};
  for (int i = 0; i < 4; ++i) {
    const std::string name = "case_000" + std::to_string(i);
    const std::string dir = out + "/" + name;
    auto& row = rows[name];
    EXPECT_EQ(row["status"], "ok") << row["message"];
    EXPECT_EQ(row["thrust"], thrusts[i]);
    // sim_node ran in lockstep with both controllers answering every step
    const std::string summary = ReadFile(dir + "/sim_node.out");
    EXPECT_NE(summary.find("lockstep, 200 steps"), std::string::npos) << summary;
    EXPECT_NE(summary.find("failsafes 0, commands 400 (rejected 0"), std::string::npos) << summary;
    // each case on a domain of its own from 206 (the cases at once take different ones)
    const std::string status = ReadFile(dir + "/case_status.txt");
    const size_t at = status.find("domain=");
    ASSERT_NE(at, std::string::npos) << status;
    const int domain = std::stoi(status.substr(at + 7));
    EXPECT_GE(domain, 206);
    EXPECT_LE(domain, 231);
    // the swept argument reached maneuver_runner: its thrust command in actuators.csv
    const io::CsvTable act = io::ReadCsvFile(dir + "/actuators.csv");
    std::string last_thrust;
    for (const auto& r : act.rows) {
      if (r[1] == "tow_vehicle") last_thrust = r[2];
    }
    EXPECT_EQ(std::stod(last_thrust), std::stod(thrusts[i]));
    // the scene parameter reached sim_node: elements + 1 nodes per time
    const io::CsvTable cable = io::ReadCsvFile(dir + "/cable.csv");
    int nodes = 0;
    for (const auto& r : cable.rows) nodes += r[0] == "0" ? 1 : 0;
    EXPECT_EQ(nodes, elements[i] + 1);
    EXPECT_TRUE(fs::exists(dir + "/depth.log"));  // ${case_dir} substituted
    // the table's numbers against this test's own reading of bodies.csv
    const std::vector<BodyRow> fish = BodyRows(dir + "/bodies.csv", "towfish");
    const std::vector<BodyRow> tow = BodyRows(dir + "/bodies.csv", "tow_vehicle");
    ASSERT_FALSE(fish.empty());
    EXPECT_NEAR(fish.back().t, 10.0, 1e-9);
    constexpr double kNineDigits = 1e-8;  // the table holds %.9g of the CSV's %.9g values
    EXPECT_NEAR(std::stod(row["towfish_depth"]), fish.back().z,
                kNineDigits * std::abs(fish.back().z));
    double speed_max = 0.0;
    std::vector<std::pair<double, double>> fish_z, tow_speed;
    for (const BodyRow& b : tow) {
      speed_max = std::max(speed_max, b.speed);
      tow_speed.emplace_back(b.t, b.speed);
    }
    for (const BodyRow& b : fish) fish_z.emplace_back(b.t, b.z);
    EXPECT_NEAR(std::stod(row["tow_speed"]), speed_max, kNineDigits * std::max(1.0, speed_max));
    EXPECT_EQ(row["towfish_depth.settled"], SettledHere(fish_z, 4.0, 0.5) ? "1" : "0") << name;
    EXPECT_EQ(row["tow_speed.settled"], SettledHere(tow_speed, 4.0, 0.2) ? "1" : "0") << name;
    // thrust 0 settles, 4165 N does not: flagged in the table and the summary
    const std::string flag = i < 2 ? "1" : "0";
    EXPECT_EQ(row["towfish_depth.settled"], flag) << name;
    EXPECT_EQ(row["tow_speed.settled"], flag) << name;
    EXPECT_EQ(s.out.find("not settled: " + name + ": towfish_depth (change ") != std::string::npos,
              i >= 2)
        << s.out;
  }

  // --resume: the same controllers and values, nothing to run
  const Sweep again = RunSweep({file, "--out", out, "--resume"}, Tmp("log_resume"));
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("0 run in"), std::string::npos) << again.out;

  // a case again by hand (command.sh: towsim_sweep --run-case): lockstep gives the same run
  const std::string bodies = ReadFile(out + "/case_0003/bodies.csv");
  Process by_hand({"/bin/bash", out + "/case_0003/command.sh"}, Tmp("log_by_hand"));
  ASSERT_TRUE(by_hand.Wait(kTimeout));
  EXPECT_EQ(by_hand.exit_code(), 0) << by_hand.err();
  EXPECT_EQ(ReadFile(out + "/case_0003/bodies.csv"), bodies);

  // the plots of two parameters: a family of curves and a heat map per result, PNG and SVG
  Process plot({"/usr/bin/python3", kSource + "/scripts/plot_sweep.py", out}, Tmp("log_plot"));
  ASSERT_TRUE(plot.Wait(kTimeout));
  ASSERT_EQ(plot.exit_code(), 0) << plot.err()
                                 << "(needs /usr/bin/python3 with matplotlib: python3-matplotlib)";
  for (const std::string result : {"towfish_depth", "tow_speed"}) {
    for (const std::string kind : {"curves", "heatmap"}) {
      const std::string stem = out + "/plots/" + result + "_" + kind;
      EXPECT_TRUE(StartsWith(ReadFile(stem + ".png"), "\x89PNG\r\n\x1a\n")) << stem;
      const std::string svg = ReadFile(stem + ".svg");
      EXPECT_TRUE(StartsWith(svg, "<?xml")) << stem;
      EXPECT_NE(svg.find("<svg"), std::string::npos) << stem;
      EXPECT_NE(plot.out().find(stem + ".png\n"), std::string::npos) << plot.out();
    }
  }
  // and the table's own plot: one curve per number of elements
  const std::string svg = ReadFile(out + "/results.svg");
  EXPECT_NE(svg.find(">cable.elements = 10</text>"), std::string::npos);
  EXPECT_NE(svg.find(">cable.elements = 20</text>"), std::string::npos);
}

// a case fails with its reason: sim_node's lockstep timeout (exit 5, --fail-on-failsafe by
// default) when a controller pauses, a controller's own error
TEST_F(SweepLocal, ControllersThatFailMarkTheirCaseFailedWithTheReason) {
  const std::string file = Tmp("failing.yaml");
  std::ofstream(file) << "scene: " << kSource << "/config/scenes/case1_forward.yaml\n"
                      << "duration: 10\n"
                      << "domain: 206\n"
                      << "lockstep_timeout: 0.5\n"
                      << "combine: zip\n"
                      << "controllers:\n"
                      << "  - {program: " << TOWSIM_TEST_CONTROLLER
                      << ", name: tow, args: [--body, tow_vehicle, --pause, \"${pause}\"]}\n"
                      << "  - {program: " << TOWSIM_TOWFISH_DEPTH
                      << ", args: [--body, towfish, --depth, 200, --kp, \"${kp}\"]}\n"
                      << "parameters:\n"
                      << "  pause: [\"20=3\", \"1000=0\"]\n"
                      << "  kp: [0.15, nan]\n"
                      << "results:\n"
                      << "  d: {signal: towfish.depth}\n";
  const std::string out = Tmp("out");
  const Sweep s = RunSweep({file, "--out", out, "--workers", "2"}, Tmp("log"));
  EXPECT_EQ(s.exit_code, 4) << s.out << s.err;
  auto rows = Table(out + "/results.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows["case_0000"]["status"], "failed");
  EXPECT_EQ(rows["case_0000"]["exit_code"], "5");
  EXPECT_EQ(rows["case_0000"]["message"],
            "sim_node: error: lockstep timeout: body tow_vehicle at step 20 (t = 1 s): no "
            "command after 0.5 s (--lockstep-timeout 0.5) (--fail-on-failsafe)");
  EXPECT_EQ(rows["case_0001"]["status"], "failed");
  EXPECT_EQ(rows["case_0001"]["exit_code"], "2");
  EXPECT_EQ(rows["case_0001"]["message"],
            "controller towfish_depth exited with code 2: towfish_depth: error: --kp nan: must "
            "be a finite number");
  EXPECT_NE(s.out.find("  failed: case_0001 (exit 2): controller towfish_depth exited with code "
                       "2: "),
            std::string::npos)
      << s.out;

  // refused before anything runs (exit 2): too many workers for the domain ids left, no
  // CYCLONEDDS_URI, --domain for a sweep without controllers
  Sweep bad = RunSweep({file, "--out", Tmp("out2"), "--domain", "230", "--workers", "3"},
                       Tmp("log_workers"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("towsim_sweep: error: domain = 230 with 3 workers: the cases running at "
                         "once each take a DDS domain id from 230 up, and the highest is 231"),
            std::string::npos)
      << bad.err;
  Process no_uri({TOWSIM_SWEEP, file, "--out", Tmp("out2")}, Tmp("log_uri"), {"CYCLONEDDS_URI="});
  ASSERT_TRUE(no_uri.Wait(kTimeout));
  EXPECT_EQ(no_uri.exit_code(), 2);
  EXPECT_NE(no_uri.err().find("failing.yaml has controllers: and CYCLONEDDS_URI is not set"),
            std::string::npos)
      << no_uri.err();
  bad = RunSweep({kLocalSweep, "--out", Tmp("out2"), "--domain", "206"}, Tmp("log_domain"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--domain 206: local_sweep.yaml has no controllers:"), std::string::npos)
      << bad.err;
  EXPECT_FALSE(fs::exists(Tmp("out2")));
}

}  // namespace
}  // namespace towsim::testing
