#include "testing/golden_csv.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

#include "testing/csv_file.h"

namespace towsim::testing {
namespace {

bool Number(const std::string& text, double* x) {
  char* end = nullptr;
  *x = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}

}  // namespace

bool UpdateGoldenRequested() {
  const char* v = std::getenv("TOWSIM_UPDATE_GOLDEN");
  return v != nullptr && std::string(v) == "1";
}

::testing::AssertionResult MatchesGoldenCsv(const std::string& actual_path,
                                            const std::string& golden_path, CsvTolerance tolerance,
                                            int key_columns) {
  namespace fs = std::filesystem;
  if (!fs::is_regular_file(actual_path)) {
    return ::testing::AssertionFailure() << "no file " << actual_path;
  }
  if (UpdateGoldenRequested()) {
    if (fs::path(golden_path).has_parent_path()) {
      fs::create_directories(fs::path(golden_path).parent_path());
    }
    fs::copy_file(actual_path, golden_path, fs::copy_options::overwrite_existing);
    std::printf("[golden] TOWSIM_UPDATE_GOLDEN=1: rewrote %s from %s\n", golden_path.c_str(),
                actual_path.c_str());
    return ::testing::AssertionSuccess() << "rewrote " << golden_path;
  }
  if (!fs::is_regular_file(golden_path)) {
    return ::testing::AssertionFailure()
           << "golden file " << golden_path
           << " does not exist: run the test with TOWSIM_UPDATE_GOLDEN=1 to write it";
  }
  const CsvTable a = ReadCsv(actual_path);
  const CsvTable g = ReadCsv(golden_path);
  const std::string how = " (rewrite it on purpose with TOWSIM_UPDATE_GOLDEN=1)";
  if (a.header.empty() || a.header != g.header) {
    return ::testing::AssertionFailure()
           << golden_path << ": header '" << JoinCsvRow(g.header) << "' but " << actual_path
           << " has '" << JoinCsvRow(a.header) << "'" << how;
  }
  if (a.rows.size() != g.rows.size()) {
    return ::testing::AssertionFailure() << actual_path << " has " << a.rows.size() << " rows, "
                                         << golden_path << " " << g.rows.size() << how;
  }
  const std::vector<std::string>& header = g.header;
  int failures = 0;
  std::ostringstream first;
  double worst_excess = 0.0;
  std::string worst;
  for (size_t i = 0; i < g.rows.size(); ++i) {
    const size_t row = i + 1;  // data rows from 1
    const std::vector<std::string>& fa = a.rows[i];
    const std::vector<std::string>& fg = g.rows[i];
    if (fa.size() != fg.size() || fa.size() != header.size()) {
      return ::testing::AssertionFailure() << "row " << row << ": '" << JoinCsvRow(fa)
                                           << "' vs golden '" << JoinCsvRow(fg) << "'" << how;
    }
    for (size_t c = 0; c < fg.size(); ++c) {
      if (static_cast<int>(c) < key_columns) {
        if (fa[c] != fg[c]) {
          return ::testing::AssertionFailure() << "row " << row << ": " << header[c] << " " << fa[c]
                                               << " vs golden " << fg[c] << how;
        }
        continue;
      }
      double x = 0.0, y = 0.0;
      if (!Number(fa[c], &x) || !Number(fg[c], &y)) {
        if (fa[c] == fg[c]) continue;
        return ::testing::AssertionFailure() << "row " << row << ": " << header[c] << " '" << fa[c]
                                             << "' vs golden '" << fg[c] << "'" << how;
      }
      const double allowed = tolerance.abs + tolerance.rel * std::abs(y);
      const double error = std::abs(x - y);
      if (!(error <= allowed)) {
        if (failures++ == 0) {
          first << "row " << row << " (" << fg[0] << (key_columns > 1 ? "," + fg[1] : "")
                << "): " << header[c] << " = " << fa[c] << ", golden " << fg[c] << ", |error| "
                << error << " > " << allowed;
        }
        if (error - allowed > worst_excess || worst.empty()) {
          worst_excess = error - allowed;
          std::ostringstream w;
          w << header[c] << " at row " << row << ": |error| " << error << " > " << allowed;
          worst = w.str();
        }
      }
    }
  }
  if (failures > 0) {
    return ::testing::AssertionFailure()
           << actual_path << " vs " << golden_path << ": " << failures
           << " values beyond |error| <= " << tolerance.abs << " + " << tolerance.rel
           << " |golden|; first " << first.str() << "; worst " << worst << how;
  }
  return ::testing::AssertionSuccess() << a.rows.size() << " rows within tolerance";
}

}  // namespace towsim::testing
