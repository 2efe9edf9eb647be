#include "scene/time_history_file.h"

#include <array>
#include <cmath>
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

constexpr double kPi = core::kPi;
const std::vector<std::string> kHeader = {"t", "x", "y", "z", "roll", "pitch", "yaw"};
const std::array<const char*, 7> kUnits = {"s", "m", "m", "m", "rad", "rad", "rad"};

}  // namespace

core::TimeHistory ReadTimeHistoryFile(const std::string& path, const std::string& key) {
  const CsvDataFile file = internal::ReadCsvDataFile(path, key, kHeader);
  if (file.rows.size() < 2) {
    throw ConfigError(key, path, file.name,
                      "holds " + std::to_string(file.rows.size()) +
                          " sample(s); a time history needs at least 2");
  }
  core::TimeHistory history;
  history.source = path;
  history.t.reserve(file.rows.size());
  history.pose.reserve(file.rows.size());
  const CsvDataRow* previous = nullptr;
  for (const CsvDataRow& r : file.rows) {
    const auto fail = [&](int c, const std::string& rule) {
      throw ConfigError(key, r.fields[c], FileLocation(file, r.line), rule);
    };
    std::array<double, 7> v{};
    for (int c = 0; c < 7; ++c) {
      if (!internal::ParseFiniteNumber(r.fields[c], &v[c])) {
        fail(c, kHeader[c] + " must be a finite number [" + kUnits[c] + "]");
      }
    }
    if (!(v[4] > -kPi && v[4] <= kPi)) {
      fail(4, "roll must lie within (-pi, pi] rad (ZYX Euler angles)");
    }
    if (!(v[5] > -0.5 * kPi && v[5] < 0.5 * kPi)) {
      fail(5, "pitch must lie within (-pi/2, pi/2) rad (ZYX Euler angles)");
    }
    if (!history.t.empty() && !(v[0] > history.t.back())) {
      fail(0, "t must increase strictly: " + r.fields[0] + " after " + previous->fields[0] +
                  " at line " + std::to_string(previous->line));
    }
    Eigen::Matrix<double, 6, 1> pose;
    pose << v[1], v[2], v[3], v[4], v[5], v[6];
    if (!history.pose.empty()) {
      // unwrap: yaw + 2 pi n with n bringing the step from the previous yaw within [-pi, pi]
      const double yaw_before = history.pose.back()(5);
      pose(5) += 2.0 * kPi * std::round((yaw_before - pose(5)) / (2.0 * kPi));
    }
    history.t.push_back(v[0]);
    history.pose.push_back(pose);
    previous = &r;
  }
  return history;
}

std::string TimeHistoryCoverageProblem(const core::TimeHistory& history, double duration) {
  if (history.t.empty()) return "the time history holds no samples";
  const double start = history.t.front(), end = history.t.back();
  if (start <= 0.0 && end >= duration) return {};
  return "the time history spans t = " + FormatNumber(start) + " to " + FormatNumber(end) +
         " s, but the run needs t = 0 to " + FormatNumber(duration) +
         " s (the history must start at t <= 0 and end at t >= the duration)";
}

}  // namespace towsim::scene
