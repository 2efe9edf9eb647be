#pragma once
// Does an RAO table cover the sea a vessel will meet? (docs/vessels.md "RAO files")
//
// A wave component of angular frequency w covers when its period 2 pi / w lies within
// [periods.front(), periods.back()] and its direction relative to the heading,
// beta = direction - heading, lies within the table's directions once wrapped into
// [d0, d0 + 2 pi) (core/rao_table.h). A periodic table covers every direction. When the
// heading changes during the run (a course with turns, or a time history) every relative
// direction may occur, so only a periodic table covers the sea's directions then.
// Tolerances: 1e-9 relative on the period, 1e-9 rad on the direction (a sea built from the
// table's own numbers covers).
//
// The check is for a table that does not extrapolate: with extrapolate: true the caller skips
// it (core/rao_table.h holds the nearest entry outside the table).

#include <string>
#include <vector>

#include "core/vessel.h"
#include "core/wave_field.h"

namespace towsim::scene {

// Empty when `table` covers every component of `sea`; else one sentence naming the first
// component that it does not cover (its number, period [s] and direction relative to the
// heading [deg]) and the table's range, for the caller to put into a ConfigError, e.g.
//   wave component 3 of 100 (period 2.1 s, direction 45 deg relative to the heading) lies
//   outside the RAO table (periods 3 to 30 s, directions -90 to 90 deg)
// `initial_heading` [rad] is the heading the relative directions are taken from when
// `heading_changes` is false.
std::string RaoCoverageProblem(const core::RaoTable& table,
                               const std::vector<core::WaveComponent>& sea, bool heading_changes,
                               double initial_heading);

}  // namespace towsim::scene
