#include "app/sweep/sweep_signals.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>

#include "app/common/run_stats.h"
#include "io/csv_reader.h"
#include "io/csv_writer.h"
#include "scene/config_error.h"

namespace towsim::app {
namespace {

const std::vector<std::string> kBodyColumns = {"x", "y", "z", "roll", "pitch", "yaw",
                                               "u", "v", "w", "p",    "q",     "r"};
const std::vector<std::string> kBodyDerived = {"depth", "speed", "track_error"};
const std::vector<std::string> kForceColumns = {"fx", "fy", "fz", "mx", "my", "mz"};
const std::vector<std::string> kCableSignals = {"layback", "top_tension", "end_tension",
                                                "max_tension"};
const std::vector<std::string> kStatusSignals = {"newton_iterations", "residual", "step_wall_us"};
const std::vector<std::string> kRunTotals = {"steps",
                                             "rtf",
                                             "run_wall_s",
                                             "newton_iterations_mean",
                                             "newton_iterations_max",
                                             "substeps",
                                             "coupling_iterations_mean"};

bool In(const std::vector<std::string>& list, const std::string& word) {
  return std::find(list.begin(), list.end(), word) != list.end();
}

std::string Join(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ", ") + w;
  return text;
}

// a signal name split at its first dot: body and quantity, or ("", name)
std::pair<std::string, std::string> Split(const std::string& signal) {
  const size_t dot = signal.find('.');
  if (dot == std::string::npos) return {"", signal};
  return {signal.substr(0, dot), signal.substr(dot + 1)};
}

using Series = std::vector<std::pair<double, double>>;  // (t, value) in time order

double Number(const std::string& text, const std::string& file) {
  try {
    size_t used = 0;
    const double x = std::stod(text, &used);
    if (used == text.size()) return x;
  } catch (const std::exception&) {
  }
  if (text == "inf") return INFINITY;
  if (text == "-inf") return -INFINITY;
  if (text == "nan" || text == "-nan") return NAN;
  throw std::runtime_error(file + ": " + text + " is not a number");
}

// the CSV files of one case, read once
class CaseFiles {
 public:
  explicit CaseFiles(std::string dir) : dir_(std::move(dir)) {}

  const io::CsvTable& Get(const std::string& name, const char* header) {
    auto it = tables_.find(name);
    if (it == tables_.end()) {
      it = tables_.emplace(name, io::ReadCsvFile(dir_ + "/" + name, header)).first;
    }
    return it->second;
  }
  std::string Path(const std::string& name) const { return dir_ + "/" + name; }

 private:
  std::string dir_;
  std::map<std::string, io::CsvTable> tables_;
};

// rows of `table` whose column 1 (body) is `body`, as (t, value) of the function of the row
Series BodySeries(const io::CsvTable& table, const std::string& file, const std::string& body,
                  const std::function<double(const std::vector<double>&)>& value) {
  Series s;
  for (const std::vector<std::string>& row : table.rows) {
    if (row[1] != body) continue;
    std::vector<double> x(row.size(), 0.0);
    for (size_t i = 0; i < row.size(); ++i) {
      if (i != 1) x[i] = Number(row[i], file);
    }
    s.emplace_back(x[0], value(x));
  }
  return s;
}

// cable.csv: one value per time from the rows of that time (node order)
Series CableSeries(const io::CsvTable& table, const std::string& file,
                   const std::function<double(const std::vector<std::vector<double>>&)>& value) {
  Series s;
  std::vector<std::vector<double>> nodes;
  std::string t_text;
  auto flush = [&]() {
    if (!nodes.empty()) s.emplace_back(nodes.front()[0], value(nodes));
    nodes.clear();
  };
  for (const std::vector<std::string>& row : table.rows) {
    if (row[0] != t_text) flush();
    t_text = row[0];
    std::vector<double> x;
    for (const std::string& f : row) x.push_back(Number(f, file));
    nodes.push_back(std::move(x));
  }
  flush();
  return s;
}

Series SignalSeries(const SweepResult& r, CaseFiles* files) {
  const auto [body, quantity] = Split(r.signal);
  if (In(kCableSignals, quantity)) {
    // <cable>.csv: the qualifier's, else the cable CheckSweepResults chose (the first)
    const std::string csv = (!body.empty() ? body : r.cable.empty() ? "cable" : r.cable) + ".csv";
    const io::CsvTable& t = files->Get(csv, io::kCsvCableHeader);
    const std::string file = files->Path(csv);
    // columns t,node,x,y,z,tension
    if (quantity == "layback") {
      return CableSeries(t, file, [](const auto& n) {
        return std::hypot(n.back()[2] - n.front()[2], n.back()[3] - n.front()[3]);
      });
    }
    if (quantity == "top_tension") {
      return CableSeries(t, file, [](const auto& n) { return n.front()[5]; });
    }
    if (quantity == "end_tension") {
      return CableSeries(t, file, [](const auto& n) { return n.back()[5]; });
    }
    return CableSeries(t, file, [](const auto& n) {
      double m = -INFINITY;
      for (const auto& node : n) m = std::max(m, node[5]);
      return m;
    });
  }
  if (!body.empty() && (In(kBodyColumns, quantity) || In(kBodyDerived, quantity))) {
    const io::CsvTable& t = files->Get("bodies.csv", io::kCsvBodiesHeader);
    const std::string file = files->Path("bodies.csv");
    if (quantity == "track_error") {
      // the line through the t = 0 position along the t = 0 heading
      const Series x = BodySeries(t, file, body, [](const auto& r) { return r[2]; });
      const Series y = BodySeries(t, file, body, [](const auto& r) { return r[3]; });
      const Series yaw = BodySeries(t, file, body, [](const auto& r) { return r[7]; });
      Series s;
      for (size_t i = 0; i < x.size(); ++i) {
        const double dx = x[i].second - x[0].second, dy = y[i].second - y[0].second;
        s.emplace_back(x[i].first, -dx * std::sin(yaw[0].second) + dy * std::cos(yaw[0].second));
      }
      return s;
    }
    if (quantity == "speed") {
      return BodySeries(t, file, body, [](const auto& r) {
        return std::sqrt(r[8] * r[8] + r[9] * r[9] + r[10] * r[10]);
      });
    }
    const std::string column = quantity == "depth" ? "z" : quantity;
    const int c = t.Column(column);
    return BodySeries(t, file, body, [c](const auto& r) { return r[c]; });
  }
  if (!body.empty()) {  // forces.csv
    const io::CsvTable& t = files->Get("forces.csv", io::kCsvForcesHeader);
    const std::string file = files->Path("forces.csv");
    if (quantity == "cable_force") {
      return BodySeries(t, file, body, [](const auto& r) {
        return std::sqrt(r[2] * r[2] + r[3] * r[3] + r[4] * r[4]);
      });
    }
    const int c = t.Column(quantity);
    return BodySeries(t, file, body, [c](const auto& r) { return r[c]; });
  }
  // status.csv: t,step,newton_iterations,residual,wall_us,cable_length
  const io::CsvTable& t = files->Get("status.csv", io::kCsvStatusHeader);
  const std::string file = files->Path("status.csv");
  const int c = quantity == "newton_iterations" ? 2 : quantity == "residual" ? 3 : 4;
  Series s;
  for (const auto& row : t.rows) s.emplace_back(Number(row[0], file), Number(row[c], file));
  return s;
}

double Statistic(const Series& s, const std::string& stat) {
  if (stat == "final") return s.back().second;
  if (stat == "initial") return s.front().second;
  double min = INFINITY, max = -INFINITY, max_abs = 0.0, sum = 0.0, sum2 = 0.0;
  for (const auto& [t, x] : s) {
    min = std::min(min, x);
    max = std::max(max, x);
    max_abs = std::max(max_abs, std::abs(x));
    sum += x;
    sum2 += x * x;
  }
  const double n = static_cast<double>(s.size());
  if (stat == "min") return min;
  if (stat == "max") return max;
  if (stat == "max_abs") return max_abs;
  if (stat == "mean") return sum / n;
  if (stat == "rms") return std::sqrt(sum2 / n);
  // std: population standard deviation, sqrt(mean(x^2) - mean(x)^2) from the deviations
  const double mean = sum / n;
  double dev2 = 0.0;
  for (const auto& [t, x] : s) dev2 += (x - mean) * (x - mean);
  return std::sqrt(dev2 / n);
}

double RunTotal(const std::string& signal, const RunSummary& r) {
  if (signal == "steps") return static_cast<double>(r.steps);
  if (signal == "rtf") return r.real_time_factor;
  if (signal == "run_wall_s") return r.wall_time;
  if (signal == "newton_iterations_mean") return r.iterations_mean;
  if (signal == "newton_iterations_max") return r.iterations_max;
  if (signal == "substeps") return static_cast<double>(r.substepped_steps);
  return r.coupling_mean.value_or(NAN);
}

}  // namespace

SettledCheck CheckSettled(const std::vector<std::pair<double, double>>& rows,
                          const SweepSettled& settled) {
  SettledCheck c;
  c.asked = true;
  const double t_last = rows.back().first;
  c.span = t_last - rows.front().first;
  // the final window t >= t_last - window, with the CSV's 9-digit times
  const double from = t_last - settled.window - 1e-9 * std::max(1.0, std::abs(t_last));
  double lo = INFINITY, hi = -INFINITY;
  int n = 0;
  for (const auto& [t, x] : rows) {
    if (t < from) continue;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    ++n;
  }
  if (n < 2) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "settled.window %g s holds %d output row(s) before t = %g s; it needs at "
                  "least 2 (a longer window, or a higher time.output_rate)",
                  settled.window, n, t_last);
    throw std::runtime_error(text);
  }
  c.change = hi - lo;
  const bool spans = c.span >= settled.window * (1.0 - 1e-9);
  c.settled = spans && c.change < settled.tolerance;
  return c;
}

void CheckSweepResults(std::vector<SweepResult>* results,
                       const std::vector<std::string>& body_names,
                       const std::vector<std::string>& cable_names) {
  for (SweepResult& r : *results) {
    const std::string key = "results." + r.name + ".signal";
    auto fail = [&](const std::string& rule) {
      throw scene::ConfigError(key, r.signal, r.location, rule);
    };
    const auto [body, quantity] = Split(r.signal);
    if (body.empty() && In(kRunTotals, quantity)) {
      if (!r.stat.empty() || r.from || r.to || r.settled) {
        fail(
            "is a total of the whole run (sim_node's summary line): it takes no stat, from, "
            "to or settled");
      }
      continue;
    }
    if (r.stat.empty()) r.stat = "final";
    if (In(kCableSignals, quantity)) {
      // a cable's: the one named by the qualifier, else the first
      if (!body.empty() && !In(cable_names, body)) {
        fail("no cable named " + body + " in the scene (cables: " + Join(cable_names) + ")");
      }
      r.cable = !body.empty() ? body : cable_names.empty() ? "cable" : cable_names.front();
      continue;
    }
    if (body.empty()) {
      if (In(kStatusSignals, quantity)) continue;
      fail("unknown signal; the signals are <body>.<quantity> (bodies: " + Join(body_names) +
           "), [<cable>.]" + Join(kCableSignals) + " (cables: " + Join(cable_names) + "), " +
           Join(kStatusSignals) + ", and the run totals " + Join(kRunTotals));
    }
    if (!In(body_names, body)) {
      fail("no body named " + body + " in the scene (bodies: " + Join(body_names) + ")");
    }
    if (!In(kBodyColumns, quantity) && !In(kBodyDerived, quantity) &&
        !In(kForceColumns, quantity) && quantity != "cable_force") {
      fail("unknown quantity " + quantity + " of a body; one of " + Join(kBodyColumns) + ", " +
           Join(kBodyDerived) + ", " + Join(kForceColumns) + ", cable_force");
    }
  }
}

std::vector<double> ComputeSweepResults(const std::vector<SweepResult>& results,
                                        const std::string& case_dir,
                                        const std::string& sim_node_stdout,
                                        std::vector<SettledCheck>* settled) {
  CaseFiles files(case_dir);
  if (settled != nullptr) settled->assign(results.size(), SettledCheck{});
  std::optional<RunSummary> summary;
  std::vector<double> values;
  for (const SweepResult& r : results) {
    const auto [body, quantity] = Split(r.signal);
    if (body.empty() && In(kRunTotals, quantity)) {
      if (!summary) summary = ParseSummaryLine(sim_node_stdout);
      if (!summary) {
        throw std::runtime_error("results." + r.name + ": no sim_node summary line in " + case_dir +
                                 "/sim_node.out");
      }
      values.push_back(RunTotal(quantity, *summary));
      continue;
    }
    Series s = SignalSeries(r, &files);
    // the window [from, to], with the CSV's 9-digit times
    const double from = r.from.value_or(-INFINITY), to = r.to.value_or(INFINITY);
    s.erase(std::remove_if(s.begin(), s.end(),
                           [&](const auto& p) {
                             return p.first < from - 1e-9 * std::max(1.0, std::abs(from)) ||
                                    p.first > to + 1e-9 * std::max(1.0, std::abs(to));
                           }),
            s.end());
    if (s.empty()) {
      throw std::runtime_error("results." + r.name + ": " + r.signal + " has no rows" +
                               (r.from || r.to ? " in the window" : "") + " in " + case_dir);
    }
    values.push_back(Statistic(s, r.stat));
    if (r.settled && settled != nullptr) {
      try {
        (*settled)[values.size() - 1] = CheckSettled(s, *r.settled);
      } catch (const std::runtime_error& e) {
        throw std::runtime_error("results." + r.name + ": " + e.what());
      }
    }
  }
  return values;
}

}  // namespace towsim::app
