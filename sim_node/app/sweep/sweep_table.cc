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
  for (const SweepResult& r : spec.results) {
    if (r.settled) header += "," + io::CsvField(r.name + ".settled");
  }
  return header;
}

namespace {

std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\u%04x", c);
      out += hex;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

std::string ColumnsJson(const SweepSpec& spec) {
  std::string json = "{\n  \"parameters\": [";
  for (size_t i = 0; i < spec.parameters.size(); ++i) {
    json +=
        std::string(i ? ",\n" : "\n") + "    {\"name\": " + JsonString(spec.parameters[i].path) +
        ", \"controllers_only\": " + (spec.parameters[i].controllers_only ? "true" : "false") + "}";
  }
  json += "\n  ],\n  \"results\": [";
  for (size_t i = 0; i < spec.results.size(); ++i) {
    const SweepResult& r = spec.results[i];
    json += std::string(i ? ",\n" : "\n") + "    {\"name\": " + JsonString(r.name) +
            ", \"signal\": " + JsonString(r.signal) + ", \"stat\": " + JsonString(r.stat) +
            ", \"settled\": ";
    if (r.settled) {
      json += "{\"window\": " + Number(r.settled->window, "%.17g") +
              ", \"tolerance\": " + Number(r.settled->tolerance, "%.17g") +
              "}, \"settled_column\": " + JsonString(r.name + ".settled") + "}";
    } else {
      json += "null, \"settled_column\": null}";
    }
  }
  return json + "\n  ]\n}\n";
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
    for (size_t i = 0; i < spec.results.size(); ++i) {
      if (!spec.results[i].settled) continue;
      text += ",";
      if (row->ok && i < row->settled.size()) text += row->settled[i].settled ? "1" : "0";
    }
    text += "\n";
  }
  WriteTextFileAtomically(path, text);
}

std::string SweepSummary(const SweepSpec& spec, const std::vector<SweepCase>& cases,
                         const std::vector<std::optional<SweepRow>>& rows,
                         const SweepTiming& timing) {
  int ok = 0, failed = 0, missing = 0, unsettled = 0;
  bool settle_asked = false;
  for (const SweepResult& r : spec.results) settle_asked = settle_asked || r.settled;
  for (const auto& row : rows) {
    if (!row) {
      ++missing;
    } else if (row->ok) {
      ++ok;
      unsettled += row->Unsettled(spec).empty() ? 0 : 1;
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
  const std::string settled_text =
      settle_asked ? " (" + std::to_string(unsettled) + " not settled)" : "";
  std::snprintf(line, sizeof line,
                "towsim_sweep: %s: %zu cases: %d ok%s, %d failed, %d not run; %d run in %.1f s "
                "(%s, %.1f cases/min)\n",
                spec.name.c_str(), cases.size(), ok, settled_text.c_str(), failed, missing,
                timing.ran, timing.wall_s, where.c_str(), per_minute);
  text += line;
  for (const auto& row : rows) {
    if (row && !row->ok) {
      text += "  failed: " + row->case_name + " (exit " + std::to_string(row->exit_code) +
              "): " + row->message + "\n";
    }
  }
  for (const auto& row : rows) {
    if (!row || row->Unsettled(spec).empty()) continue;
    std::string what;
    for (size_t i = 0; i < spec.results.size() && i < row->settled.size(); ++i) {
      const SettledCheck& c = row->settled[i];
      if (!c.asked || c.settled) continue;
      const SweepSettled& s = *spec.results[i].settled;
      char part[256];
      if (c.span < s.window * (1.0 - 1e-9)) {
        std::snprintf(part, sizeof part, "%s (the run's %.6g s are shorter than the window %.6g s)",
                      spec.results[i].name.c_str(), c.span, s.window);
      } else {
        std::snprintf(part, sizeof part, "%s (change %.6g over the final %.6g s, tolerance %.6g)",
                      spec.results[i].name.c_str(), c.change, s.window, s.tolerance);
      }
      what += (what.empty() ? "" : ", ") + std::string(part);
    }
    text += "  not settled: " + row->case_name + ": " + what + "\n";
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
