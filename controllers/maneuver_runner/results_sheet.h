#pragma once
// The manoeuvre runner's results sheet: the trials-sheet numbers of a zig-zag or a turning
// circle as text (stdout) and as YAML (--results FILE). Pure formatting, no DDS.

#include <string>

#include "maneuver_runner/maneuver_config.h"
#include "maneuver_runner/turning_circle.h"
#include "maneuver_runner/zigzag.h"

namespace towsim::controllers {

struct RunSummary {
  double approach_speed = 0.0;  // horizontal speed at execute [m/s]
  double approach_yaw = 0.0;    // heading at execute [rad]
  double t_end = 0.0;           // last answered step's time [s]
};

std::string ZigZagText(const ManeuverConfig& c, const RunSummary& s, const ZigZagResults& r);
std::string ZigZagYaml(const ManeuverConfig& c, const RunSummary& s, const ZigZagResults& r);
std::string TurningCircleText(const ManeuverConfig& c, const RunSummary& s,
                              const TurningCircleResults& r);
std::string TurningCircleYaml(const ManeuverConfig& c, const RunSummary& s,
                              const TurningCircleResults& r);

}  // namespace towsim::controllers
