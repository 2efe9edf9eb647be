#include "app/sweep/sweep_table.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "app/common/text_file.h"
#include "io/csv_writer.h"

namespace towsim::app {
namespace {

std::string Number(double x, const char* format = "%.9g") {
  char text[40];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

}  // namespace

std::string ResultsHeader(const SweepSpec& spec) {
  std::string header = "case,status,exit_code,message,wall_s";
  for (const SweepParameter& p : spec.parameters) header += "," + io::CsvField(p.path);
  for (const SweepResult& r : spec.results) header += "," + io::CsvField(r.name);
  return header;
}

void WriteResultsTable(const std::string& path, const SweepSpec& spec,
                       const std::vector<std::optional<SweepRow>>& rows) {
  std::string text = ResultsHeader(spec) + "\n";
  for (const std::optional<SweepRow>& row : rows) {
    if (!row) continue;
    text += io::CsvField(row->case_name) + "," + (row->ok ? "ok" : "failed") + "," +
            std::to_string(row->exit_code) + "," + io::CsvField(row->message) + "," +
            Number(row->wall_s, "%.3f");
    for (const std::string& v : row->parameters) text += "," + io::CsvField(v);
    for (size_t i = 0; i < spec.results.size(); ++i) {
      text += ",";
      if (row->ok && i < row->results.size()) text += Number(row->results[i]);
    }
    text += "\n";
  }
  WriteTextFileAtomically(path, text);
}

std::string SweepSummary(const SweepSpec& spec, const std::vector<SweepCase>& cases,
                         const std::vector<std::optional<SweepRow>>& rows,
                         const SweepTiming& timing) {
  int ok = 0, failed = 0, missing = 0;
  for (const auto& row : rows) {
    if (!row) {
      ++missing;
    } else if (row->ok) {
      ++ok;
    } else {
      ++failed;
    }
  }
  std::string text;
  char line[512];
  const double per_minute = timing.wall_s > 0.0 ? 60.0 * timing.ran / timing.wall_s : 0.0;
  const std::string where =
      timing.slurm ? "on Slurm"
                   : std::to_string(timing.workers) + " worker" + (timing.workers == 1 ? "" : "s");
  std::snprintf(line, sizeof line,
                "towsim_sweep: %s: %zu cases: %d ok, %d failed, %d not run; %d run in %.1f s "
                "(%s, %.1f cases/min)\n",
                spec.name.c_str(), cases.size(), ok, failed, missing, timing.ran, timing.wall_s,
                where.c_str(), per_minute);
  text += line;
  for (const auto& row : rows) {
    if (row && !row->ok) {
      text += "  failed: " + row->case_name + " (exit " + std::to_string(row->exit_code) +
              "): " + row->message + "\n";
    }
  }
  for (size_t i = 0; i < spec.results.size(); ++i) {
    double lo = INFINITY, hi = -INFINITY, sum = 0.0;
    std::string lo_case, hi_case;
    int n = 0;
    for (const auto& row : rows) {
      if (!row || !row->ok) continue;
      const double x = row->results[i];
      if (x < lo) lo = x, lo_case = row->case_name;
      if (x > hi) hi = x, hi_case = row->case_name;
      sum += x;
      ++n;
    }
    if (n == 0) continue;
    std::snprintf(line, sizeof line, "  %s: min %.6g (%s), max %.6g (%s), mean %.6g\n",
                  spec.results[i].name.c_str(), lo, lo_case.c_str(), hi, hi_case.c_str(), sum / n);
    text += line;
  }
  return text;
}

}  // namespace towsim::app
