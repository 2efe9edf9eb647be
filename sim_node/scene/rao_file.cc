#include "scene/rao_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include "core/constants.h"
#include "scene/config_error.h"
#include "scene/csv_data_file.h"
#include "scene/yaml_reader.h"

namespace towsim::scene {
namespace {

using internal::CsvDataFile;
using internal::CsvDataRow;
using internal::FileLocation;
using internal::FormatNumber;
using internal::kDegToRad;

// the file's columns
enum Column { kPeriod = 0, kDirection, kDof, kAmplitude, kPhase };
const std::vector<std::string> kHeader = {"period", "direction_deg", "dof", "amplitude",
                                          "phase_deg"};
const std::array<const char*, core::kVesselDofs> kDofNames = {"surge", "sway",  "heave",
                                                              "roll",  "pitch", "yaw"};
// the full circle and the agreement of its end columns [deg, m/m or deg/m]
constexpr double kCircleTol = 1e-9;

struct Row {
  int line = 0;
  double period = 0.0;     // [s]
  double direction = 0.0;  // [deg]
  int dof = 0;
  double amplitude = 0.0;  // as in the file
  double phase = 0.0;      // [deg]
};

// the phase difference a - b wrapped into (-180, 180] [deg]
double PhaseDifferenceDeg(double a, double b) {
  double d = std::fmod(a - b, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

Row ParseRow(const CsvDataFile& file, const CsvDataRow& r, const std::string& key) {
  const auto fail = [&](Column c, const std::string& rule) {
    throw ConfigError(key, r.fields[c], FileLocation(file, r.line), rule);
  };
  Row row;
  row.line = r.line;
  if (!internal::ParseFiniteNumber(r.fields[kPeriod], &row.period) || row.period <= 0.0) {
    fail(kPeriod, "period must be a finite number > 0 [s]");
  }
  if (!internal::ParseFiniteNumber(r.fields[kDirection], &row.direction) ||
      row.direction < -180.0 || row.direction > 360.0) {
    fail(kDirection,
         "direction_deg must be a finite number within [-180, 360] (the direction the waves "
         "travel toward, relative to the heading)");
  }
  const auto dof = std::find(kDofNames.begin(), kDofNames.end(), r.fields[kDof]);
  if (dof == kDofNames.end()) fail(kDof, "dof must be one of surge, sway, heave, roll, pitch, yaw");
  row.dof = static_cast<int>(dof - kDofNames.begin());
  if (!internal::ParseFiniteNumber(r.fields[kAmplitude], &row.amplitude) || row.amplitude < 0.0) {
    fail(kAmplitude,
         "amplitude must be a finite number >= 0 (m/m for surge, sway and heave, deg/m for "
         "roll, pitch and yaw)");
  }
  if (!internal::ParseFiniteNumber(r.fields[kPhase], &row.phase)) {
    fail(kPhase, "phase_deg must be a finite number (the lag behind the wave crest)");
  }
  return row;
}

size_t IndexOf(const std::vector<double>& sorted, double x) {
  return static_cast<size_t>(std::lower_bound(sorted.begin(), sorted.end(), x) - sorted.begin());
}

}  // namespace

core::RaoTable ReadRaoFile(const std::string& path, const std::string& key) {
  const CsvDataFile file = internal::ReadCsvDataFile(path, key, kHeader);
  const auto fail_file = [&](const std::string& value, const std::string& rule) {
    throw ConfigError(key, value, file.name, rule);
  };
  if (file.rows.empty()) fail_file(path, "holds no RAO rows after its header");

  std::vector<Row> rows;
  rows.reserve(file.rows.size());
  for (const CsvDataRow& r : file.rows) rows.push_back(ParseRow(file, r, key));

  // the grid: the union of the periods and of the directions (exact values as written)
  std::vector<double> periods, directions;
  for (const Row& r : rows) {
    periods.push_back(r.period);
    directions.push_back(r.direction);
  }
  for (std::vector<double>* v : {&periods, &directions}) {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  const size_t np = periods.size(), nd = directions.size();
  const double span = directions.back() - directions.front();
  if (span > 360.0 + kCircleTol) {
    fail_file("directions " + FormatNumber(directions.front()) + " to " +
                  FormatNumber(directions.back()) + " deg",
              "the directions span " + FormatNumber(span) +
                  " deg; at most 360 (a direction and the same plus 360 would be given twice)");
  }
  const bool periodic = nd >= 2 && std::abs(span - 360.0) <= kCircleTol;

  // each (period, direction, dof) once: the line that gave it (0: not given)
  std::array<std::vector<int>, core::kVesselDofs> given;
  std::array<std::vector<const Row*>, core::kVesselDofs> at;
  for (const Row& r : rows) {
    std::vector<int>& g = given[r.dof];
    if (g.empty()) {
      g.assign(np * nd, 0);
      at[r.dof].assign(np * nd, nullptr);
    }
    const size_t k = IndexOf(periods, r.period) * nd + IndexOf(directions, r.direction);
    if (g[k] != 0) {
      throw ConfigError(key,
                        file.rows[&r - rows.data()].fields[kPeriod] + "," +
                            file.rows[&r - rows.data()].fields[kDirection] + "," + kDofNames[r.dof],
                        FileLocation(file, r.line),
                        "duplicate of line " + std::to_string(g[k]) +
                            " (the same period, direction_deg and dof)");
    }
    g[k] = r.line;
    at[r.dof][k] = &r;
  }
  for (int j = 0; j < core::kVesselDofs; ++j) {
    if (given[j].empty()) continue;
    for (size_t i = 0; i < np; ++i) {
      for (size_t d = 0; d < nd; ++d) {
        if (given[j][i * nd + d] != 0) continue;
        fail_file(kDofNames[j],
                  std::string(kDofNames[j]) + " has no row for period " + FormatNumber(periods[i]) +
                      " s, direction_deg " + FormatNumber(directions[d]) +
                      " (each dof given must give every period and "
                      "direction of the table: " +
                      std::to_string(np) + " periods x " + std::to_string(nd) + " directions)");
      }
    }
  }
  // full circle: the first and the last column are one direction
  if (periodic) {
    for (int j = 0; j < core::kVesselDofs; ++j) {
      if (given[j].empty()) continue;
      for (size_t i = 0; i < np; ++i) {
        const Row& first = *at[j][i * nd];
        const Row& last = *at[j][i * nd + nd - 1];
        const bool both_zero = first.amplitude <= kCircleTol && last.amplitude <= kCircleTol;
        if (std::abs(first.amplitude - last.amplitude) <= kCircleTol &&
            (both_zero || std::abs(PhaseDifferenceDeg(first.phase, last.phase)) <= kCircleTol)) {
          continue;
        }
        const CsvDataRow& raw = file.rows[&last - rows.data()];
        throw ConfigError(
            key, raw.fields[kAmplitude] + "," + raw.fields[kPhase], FileLocation(file, last.line),
            "the directions span the full circle (" + FormatNumber(directions.front()) + " to " +
                FormatNumber(directions.back()) +
                " deg), so the rows of both ends are the same "
                "direction and must agree: " +
                std::string(kDofNames[j]) + " at period " + FormatNumber(periods[i]) +
                " s has amplitude,phase_deg " + FormatNumber(last.amplitude) + "," +
                FormatNumber(last.phase) + " here and " + FormatNumber(first.amplitude) + "," +
                FormatNumber(first.phase) + " at line " + std::to_string(first.line));
      }
    }
  }

  core::RaoTable table;
  table.source = path;
  table.periodic_directions = periodic;
  table.extrapolate = false;
  table.periods = periods;
  const size_t nd_kept = periodic ? nd - 1 : nd;  // the full circle's last column dropped
  for (size_t d = 0; d < nd_kept; ++d) table.directions.push_back(directions[d] * kDegToRad);
  for (int j = 0; j < core::kVesselDofs; ++j) {
    if (given[j].empty()) continue;
    // rotations: deg/m -> rad/m
    const double scale = j >= static_cast<int>(core::VesselDof::kRoll) ? kDegToRad : 1.0;
    table.amplitude[j].resize(np * nd_kept);
    table.phase[j].resize(np * nd_kept);
    for (size_t i = 0; i < np; ++i) {
      for (size_t d = 0; d < nd_kept; ++d) {
        const Row& r = *at[j][i * nd + d];
        table.amplitude[j][i * nd_kept + d] = r.amplitude * scale;
        table.phase[j][i * nd_kept + d] = r.phase * kDegToRad;
      }
    }
  }
  return table;
}

}  // namespace towsim::scene
