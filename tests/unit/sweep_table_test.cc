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

// settled: one column per result that has it, the summary names the cases that did not
// settle with their change; columns.json says what each column is
SweepSpec SettledSpec() {
  SweepSpec spec = Spec();
  spec.parameters[1].controllers_only = true;
  spec.results[0].settled = SweepSettled{5.0, 0.5};
  SweepResult n;
  n.name = "n";
  n.signal = "newton_iterations_max";
  spec.results.push_back(n);
  return spec;
}

std::vector<std::optional<SweepRow>> SettledRows() {
  SweepRow settled{"case_0000", true, 0, "", 1.25, {"10", "[0, 0, 1]"}, {12.5, 3}};
  settled.settled = {SettledCheck{true, true, 0.125, 20.0}, SettledCheck{}};
  SweepRow moving{"case_0001", true, 0, "", 1.5, {"20", "[0, 0, 1]"}, {14.5, 4}};
  moving.settled = {SettledCheck{true, false, 2.25, 20.0}, SettledCheck{}};
  SweepRow shorter{"case_0002", true, 0, "", 1.5, {"30", "[0, 0, 1]"}, {16.5, 4}};
  shorter.settled = {SettledCheck{true, false, 0.0, 2.0}, SettledCheck{}};
  SweepRow failed{"case_0003",         false, 5, "sim_node: error: lockstep timeout", 0.5,
                  {"40", "[0, 0, 1]"}, {}};
  return {settled, moving, shorter, failed};
}

TEST(SweepTable, SettledColumnsAndSummary) {
  test::TempDir dir;
  const std::string path = (dir.path() / "results.csv").string();
  WriteResultsTable(path, SettledSpec(), SettledRows());
  EXPECT_EQ(ReadTextFile(path),
            "case,status,exit_code,message,wall_s,cable.elements,cable.start.at,depth,n,"
            "depth.settled\n"
            "case_0000,ok,0,,1.250,10,\"[0, 0, 1]\",12.5,3,1\n"
            "case_0001,ok,0,,1.500,20,\"[0, 0, 1]\",14.5,4,0\n"
            "case_0002,ok,0,,1.500,30,\"[0, 0, 1]\",16.5,4,0\n"
            "case_0003,failed,5,sim_node: error: lockstep timeout,0.500,40,\"[0, 0, 1]\",,,\n");
  std::vector<SweepCase> cases(4);
  SweepTiming timing;
  timing.wall_s = 60.0;
  timing.ran = 4;
  EXPECT_EQ(SweepSummary(SettledSpec(), cases, SettledRows(), timing),
            "towsim_sweep: s.yaml: 4 cases: 3 ok (2 not settled), 1 failed, 0 not run; 4 run in "
            "60.0 s (1 worker, 4.0 cases/min)\n"
            "  failed: case_0003 (exit 5): sim_node: error: lockstep timeout\n"
            "  not settled: case_0001: depth (change 2.25 over the final 5 s, tolerance 0.5)\n"
            "  not settled: case_0002: depth (the run's 2 s are shorter than the window 5 s)\n"
            "  depth: min 12.5 (case_0000), max 16.5 (case_0002), mean 14.5\n"
            "  n: min 3 (case_0000), max 4 (case_0001), mean 3.66667\n");
  EXPECT_EQ(ColumnsJson(SettledSpec()),
            "{\n"
            "  \"parameters\": [\n"
            "    {\"name\": \"cable.elements\", \"controllers_only\": false},\n"
            "    {\"name\": \"cable.start.at\", \"controllers_only\": true}\n"
            "  ],\n"
            "  \"results\": [\n"
            "    {\"name\": \"depth\", \"signal\": \"towfish.depth\", \"stat\": \"final\", "
            "\"settled\": {\"window\": 5, \"tolerance\": 0.5}, \"settled_column\": "
            "\"depth.settled\"},\n"
            "    {\"name\": \"n\", \"signal\": \"newton_iterations_max\", \"stat\": \"\", "
            "\"settled\": null, \"settled_column\": null}\n"
            "  ]\n"
            "}\n");
}

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// two parameters: one curve per value of the second, in a colour of its own, with a legend;
// the unsettled points hollow
TEST(SweepPlot, AFamilyOfCurvesWithALegend) {
  SweepSpec spec = SettledSpec();
  spec.results.resize(1);
  auto row = [](const std::string& name, const std::string& a, const std::string& b, double y,
                bool settled) {
    SweepRow r{name, true, 0, "", 1.0, {a, b}, {y}};
    r.settled = {SettledCheck{true, settled, 0.0, 10.0}};
    return std::optional<SweepRow>(r);
  };
  const std::string svg = SweepPlotSvg(
      spec, {row("c0", "10", "[0, 0, 1]", 1.0, true), row("c1", "10", "[0, 0, 2]", 2.0, true),
             row("c2", "20", "[0, 0, 1]", 1.5, false), row("c3", "20", "[0, 0, 2]", 2.5, true),
             row("c4", "30", "[0, 0, 1]", 1.7, true)});
  EXPECT_EQ(Count(svg, "<polyline"), 2u);  // one curve per value of cable.start.at
  EXPECT_EQ(Count(svg, "<circle"), 5u);
  EXPECT_EQ(Count(svg, "fill=\"white\" stroke="), 1u);  // c2 did not settle
  EXPECT_NE(svg.find(">cable.start.at = [0, 0, 1]</text>"), std::string::npos);  // the legend
  EXPECT_NE(svg.find(">cable.start.at = [0, 0, 2]</text>"), std::string::npos);
  EXPECT_EQ(Count(svg, "stroke=\"#1f77b4\" stroke-width=\"1.5\""), 1u);
  EXPECT_EQ(Count(svg, "stroke=\"#ff7f0e\" stroke-width=\"1.5\""), 1u);
  EXPECT_NE(svg.find("hollow: not settled"), std::string::npos);
  // the first curve joins c0, c2, c4 in x order: 3 points
  const size_t at = svg.find("<polyline points=\"");
  const std::string points = svg.substr(at + 18, svg.find('"', at + 18) - at - 18);
  EXPECT_EQ(Count(points, ","), 3u);
}

}  // namespace
}  // namespace towsim::app
