#include "scene/rao_coverage.h"

#include <cmath>

#include "core/constants.h"
#include "scene/yaml_reader.h"

namespace towsim::scene {
namespace {

using internal::FormatNumber;
using internal::kRadToDeg;

constexpr double kTwoPi = 2.0 * core::kPi;
constexpr double kPeriodRelTol = 1e-9;
constexpr double kDirectionTol = 1e-9;  // [rad]

// the table's range for messages
std::string TableRange(const core::RaoTable& t) {
  std::string s = "periods " + FormatNumber(t.periods.front()) + " to " +
                  FormatNumber(t.periods.back()) + " s, directions ";
  if (t.periodic_directions) return s + "the full circle";
  if (t.directions.size() == 1)
    return s + FormatNumber(t.directions.front() * kRadToDeg) + " deg only";
  return s + FormatNumber(t.directions.front() * kRadToDeg) + " to " +
         FormatNumber(t.directions.back() * kRadToDeg) + " deg";
}

// x wrapped into [d0, d0 + 2 pi), d0 the table's first direction (as the table counts them)
double WrapFrom(double x, double d0) {
  double r = std::fmod(x - d0, kTwoPi);
  if (r < 0.0) r += kTwoPi;
  if (r >= kTwoPi) r = 0.0;
  return d0 + r;
}

bool DirectionCovered(const core::RaoTable& t, double relative) {
  if (t.periodic_directions) return true;
  const double d0 = t.directions.front(), d1 = t.directions.back();
  const double b = WrapFrom(relative, d0);
  // within [d0, d1], or just below d0 (b close to d0 + 2 pi)
  return b <= d1 + kDirectionTol || b >= d0 + kTwoPi - kDirectionTol;
}

}  // namespace

std::string RaoCoverageProblem(const core::RaoTable& table,
                               const std::vector<core::WaveComponent>& sea, bool heading_changes,
                               double initial_heading) {
  if (sea.empty() || table.periods.empty() || table.directions.empty()) return {};
  if (heading_changes && !table.periodic_directions) {
    return "the vessel's heading changes during the run, so the waves may meet it from any "
           "direction, but the RAO table (" +
           TableRange(table) +
           ") does not cover the full circle (its directions must span 0 to 360 deg, or -180 "
           "to 180)";
  }
  const double p_lo = table.periods.front() * (1.0 - kPeriodRelTol);
  const double p_hi = table.periods.back() * (1.0 + kPeriodRelTol);
  for (size_t i = 0; i < sea.size(); ++i) {
    const core::WaveComponent& c = sea[i];
    const double period = 2.0 * core::kPi / c.omega;
    const double relative = c.direction - initial_heading;
    if (period >= p_lo && period <= p_hi && DirectionCovered(table, relative)) continue;
    return "wave component " + std::to_string(i + 1) + " of " + std::to_string(sea.size()) +
           " (period " + FormatNumber(period) + " s, direction " +
           FormatNumber(WrapFrom(relative, table.directions.front()) * kRadToDeg) +
           " deg relative to the heading) lies outside the RAO table (" + TableRange(table) + ")";
  }
  return {};
}

}  // namespace towsim::scene
