// A folded cable through the real sim_node, offline (docs/faults.md "Folded cable"): a fold that
// persists for FoldWatch's 1 s ends the run with exit 3 naming the element, the times and the
// strain, and still leaves the summary line and complete CSV files (every row set up to the last
// output before the failure); a fold that opens again within 1 s leaves only its warning. The
// scenes are in scenes/ (fold_clamped_overrun.yaml, fold_impulsive_start.yaml). No DDS.

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testing/csv_file.h"
#include "testing/process.h"

namespace towsim::testing {
namespace {

const std::string kScenes = std::string(TOWSIM_SOURCE_DIR) + "/tests/integration/scenes/";
constexpr double kProcessTimeout = 120.0;  // [s] a run that takes longer has hung
constexpr double kOutputPeriod = 0.1;      // both scenes' 1 / time.output_rate [s]
constexpr double kStep = 0.02;             // both scenes' time.step [s]
constexpr int kNodes = 21;                 // 20 elements
// times in the CSV are written with 9 significant digits: the output time within this [s]
constexpr double kTimeTolerance = 1e-9;
// positions are written with 9 significant digits: a few parts in 1e9 of 400 m [m]
constexpr double kPositionTolerance = 1e-6;

struct OfflineRun {
  int exit_code = -1;
  std::string out, err;
};

OfflineRun RunOffline(const std::string& scene, const std::string& csv) {
  Process node({TOWSIM_SIM_NODE, "--scene", kScenes + scene, "--mode", "offline", "--csv", csv},
               LogPrefix("node"));
  OfflineRun r;
  EXPECT_TRUE(node.Wait(kProcessTimeout)) << node.command_line();
  r.exit_code = node.exit_code();
  r.out = node.out();
  r.err = node.err();
  return r;
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

double Number(const std::string& field) { return std::strtod(field.c_str(), nullptr); }

// the file is complete: it ends with a newline, every row has every column of the header, the
// times rise by one output period from 0 with `per_time` rows each, the last at `t_last`
void ExpectComplete(const std::string& path, std::size_t columns, int per_time, double t_last) {
  SCOPED_TRACE(path);
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const CsvTable table = ReadCsv(path);
  ASSERT_EQ(table.header.size(), columns);
  const long times = std::lround(t_last / kOutputPeriod) + 1;
  ASSERT_EQ(table.rows.size(), static_cast<std::size_t>(times * per_time));
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    ASSERT_EQ(table.rows[i].size(), columns) << "row " << i << ": " << JoinCsvRow(table.rows[i]);
    const double t = static_cast<double>(i / per_time) * kOutputPeriod;
    ASSERT_NEAR(Number(table.rows[i][0]), t, kTimeTolerance) << "row " << i;
  }
}

// A towing point driven at 20 m/s along the line overruns the far end, which is clamped along
// +x: from t = 19.2 s the last element is folded (compressed, then doubled back over its clamp)
// at every check, and at t = 20.2 s (step 1010) the run ends with exit 3. The CSV files hold
// every output up to t = 20.1 s, the last before the failure; the failed step's state is not
// written.
TEST(FoldedCable, PersistentFoldEndsTheRunWithExit3AndCompleteFiles) {
  const std::string csv = LogPrefix("csv");
  const OfflineRun r = RunOffline("fold_clamped_overrun.yaml", csv);
  ASSERT_EQ(r.exit_code, 3) << r.err;
  // the warning when the fold was first seen, then the failure: element, times and strain
  EXPECT_TRUE(Contains(r.err,
                       "sim_node: warning: cable 'cable' element 19 (nodes 19-20) folded: "))
      << r.err;
  EXPECT_TRUE(Contains(r.err, "at t = 19.2 s (the run fails if it stays folded for 1 s)"))
      << r.err;
  const std::regex failure(
      "sim_node: solver failure at t = 20\\.2 s \\(step 1010\\): folded cable since t = 19\\.2 "
      "s, still at t = 20\\.2 s: cable 'cable' element 19 \\(nodes 19-20\\) folded: a slope "
      "turned against its chord \\(cos (-[0-9.]+)\\), strain ([-0-9.e+]+) ");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, failure)) << r.err;
  EXPECT_LT(Number(m[1]), 0.0);  // the slope against its chord
  EXPECT_TRUE(std::isfinite(Number(m[2])));
  // the summary line, the steps taken including the failed check's
  EXPECT_TRUE(Contains(r.out, "fold_clamped_overrun: 1010 steps, 20.2 s simulated")) << r.out;

  // every file complete up to t = 20.1 s: status.csv's final row is step 1005
  constexpr double kLastOutput = 20.1;
  ExpectComplete(csv + "/status.csv", 6, 1, kLastOutput);
  ExpectComplete(csv + "/cable.csv", 6, kNodes, kLastOutput);
  ExpectComplete(csv + "/forces.csv", 8, 2, kLastOutput);  // cable.start, cable.end
  const CsvTable status = ReadCsv(csv + "/status.csv");
  ASSERT_FALSE(status.rows.empty());
  EXPECT_EQ(status.rows.back()[1], std::to_string(std::lround(kLastOutput / kStep)));

  // independently of the fold check, from the positions written: at the last output the towing
  // point is 20 m/s x 20.1 s = 402 m out, far past the clamp at x = 199 m, and the last
  // element's chord from node 19 to node 20 (the clamp) points against the clamped direction
  // +x: the element is doubled back over its clamp
  const CsvTable cable = ReadCsv(csv + "/cable.csv");
  ASSERT_GE(cable.rows.size(), static_cast<std::size_t>(kNodes));
  const std::vector<std::string>& node19 = cable.rows[cable.rows.size() - 2];
  const std::vector<std::string>& node20 = cable.rows[cable.rows.size() - 1];
  ASSERT_EQ(node19[1], "19");
  ASSERT_EQ(node20[1], "20");
  EXPECT_NEAR(Number(node20[2]), 199.0, kPositionTolerance);  // x of the clamp [m]
  EXPECT_LT(Number(node20[2]) - Number(node19[2]), 0.0)
      << "chord x " << Number(node20[2]) - Number(node19[2]);
  const std::vector<std::string>& node0 = cable.rows[cable.rows.size() - kNodes];
  ASSERT_EQ(node0[1], "0");
  EXPECT_NEAR(Number(node0[2]), 20.0 * kLastOutput, kPositionTolerance);  // the driven start [m]
}

// The same cable at rest, its start jerked to 10 m/s toward the fixed end: the first element is
// whipped round, folded at the checks from t = 1.1 s and again from t = 1.5 s, each for less
// than 1 s. The run goes on to its end, exit 0, the warnings its only trace.
TEST(FoldedCable, TransientFoldThatOpensWithinASecondDoesNotEndTheRun) {
  const std::string csv = LogPrefix("csv");
  const OfflineRun r = RunOffline("fold_impulsive_start.yaml", csv);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(Contains(r.err,
                       "sim_node: warning: cable 'cable' element 0 (nodes 0-1) folded: a slope "
                       "turned against its chord"))
      << r.err;
  EXPECT_TRUE(Contains(r.err, "at t = 1.1 s (the run fails if it stays folded for 1 s)")) << r.err;
  // a second warning: the first fold had opened again before t = 1.5 s
  EXPECT_TRUE(Contains(r.err, "at t = 1.5 s (the run fails if it stays folded for 1 s)")) << r.err;
  EXPECT_FALSE(Contains(r.err, "solver failure")) << r.err;
  EXPECT_TRUE(Contains(r.out, "fold_impulsive_start: 500 steps, 10 s simulated")) << r.out;
  constexpr double kEnd = 10.0;  // time.duration [s]
  ExpectComplete(csv + "/status.csv", 6, 1, kEnd);
  ExpectComplete(csv + "/cable.csv", 6, kNodes, kEnd);
  ExpectComplete(csv + "/forces.csv", 8, 2, kEnd);
}

}  // namespace
}  // namespace towsim::testing
