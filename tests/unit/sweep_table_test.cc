// app/sweep/sweep_table, app/sweep/sweep_progress, app/sweep/sweep_plot: the table's columns and
// quoting, the summary's counts, the progress line, the plot's points.

#include "app/sweep/sweep_table.h"

#include <cstdio>

#include <gtest/gtest.h>

#include "app/common/text_file.h"
#include "app/sweep/sweep_plot.h"
#include "app/sweep/sweep_progress.h"
#include "io/csv_reader.h"
#include "temp_dir.h"

namespace towsim::app {
namespace {

SweepSpec Spec() {
  SweepSpec spec;
  spec.name = "s.yaml";
  spec.parameters = {{"cable.elements", {"10", "20"}, ""}, {"cable.start.at", {"[0, 0, 1]"}, ""}};
  SweepResult r;
  r.name = "depth";
  r.signal = "towfish.depth";
  r.stat = "final";
  spec.results = {r};
  return spec;
}

std::vector<std::optional<SweepRow>> Rows() {
  SweepRow ok{"case_0000", true, 0, "", 1.25, {"10", "[0, 0, 1]"}, {12.5}};
  SweepRow failed{"case_0001",         false, 2, "sim_node: error: a = 1, b (--set): rule", 0.5,
                  {"20", "[0, 0, 1]"}, {}};
  return {ok, failed, std::nullopt};
}

TEST(SweepTable, ColumnsQuotingAndEmptyResultsOfFailedCases) {
  test::TempDir dir;
  const std::string path = (dir.path() / "results.csv").string();
  WriteResultsTable(path, Spec(), Rows());
  EXPECT_EQ(ReadTextFile(path),
            "case,status,exit_code,message,wall_s,cable.elements,cable.start.at,depth\n"
            "case_0000,ok,0,,1.250,10,\"[0, 0, 1]\",12.5\n"
            "case_0001,failed,2,\"sim_node: error: a = 1, b (--set): rule\",0.500,20,"
            "\"[0, 0, 1]\",\n");
  // and it reads back field by field
  const io::CsvTable t = io::ReadCsvFile(path);
  EXPECT_EQ(t.rows[1][3], "sim_node: error: a = 1, b (--set): rule");
}

TEST(SweepTable, SummaryCountsAndRanges) {
  std::vector<SweepCase> cases(3);
  SweepTiming timing;
  timing.wall_s = 30.0;
  timing.workers = 2;
  timing.ran = 2;
  const std::string text = SweepSummary(Spec(), cases, Rows(), timing);
  EXPECT_EQ(text,
            "towsim_sweep: s.yaml: 3 cases: 1 ok, 1 failed, 1 not run; 2 run in 30.0 s (2 "
            "workers, 4.0 cases/min)\n"
            "  failed: case_0001 (exit 2): sim_node: error: a = 1, b (--set): rule\n"
            "  depth: min 12.5 (case_0000), max 12.5 (case_0000), mean 12.5\n");
}

TEST(SweepProgress, LineAndTimeLeft) {
  test::TempDir dir;
  const std::string path = (dir.path() / "progress.txt").string();
  std::FILE* f = std::fopen(path.c_str(), "w");
  SweepProgress p(10, 2, f);
  p.Update(0, 0, 2, 0.0, true);
  p.Update(4, 1, 2, 20.0, true);  // 5 s per case, 4 cases left: 20 s
  p.Finish();
  std::fclose(f);
  EXPECT_EQ(ReadTextFile(path),
            "\r[towsim_sweep] 2/10 cases done, 0 failed, 2 running, about -- left   "
            "\r[towsim_sweep] 6/10 cases done, 1 failed, 2 running, about 0m20s left   \n");
}

TEST(SweepPlot, OnePointPerOkCaseOnALinearAxis) {
  const std::string svg = SweepPlotSvg(Spec(), Rows());
  size_t points = 0;
  for (size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) {
    ++points;
  }
  EXPECT_EQ(points, 1u);
  EXPECT_NE(svg.find("depth (towfish.depth, final), 1 failed case(s) not shown"),
            std::string::npos);
  EXPECT_NE(svg.find(">cable.elements</text>"), std::string::npos);  // the x axis
}

}  // namespace
}  // namespace towsim::app
