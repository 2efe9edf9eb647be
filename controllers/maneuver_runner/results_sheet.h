#pragma once
// The manoeuvre runner's results sheet: the trials-sheet numbers of a zig-zag, a turning
// circle or a payout as text (stdout) and as YAML (--results FILE), and the payout's plot
// (--plot FILE.svg). Pure formatting, no DDS.

#include <string>

#include "maneuver_runner/maneuver_config.h"
#include "maneuver_runner/payout.h"
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

// the payout: phase ends (t, length, towfish depth, tow depth and speed) and the table of
// samples; YAML keys <phase>_t, <phase>_length, <phase>_depth, <phase>_tow_depth,
// <phase>_speed for approach, payout, hold, reel_in and final, max_length, max_depth, and
// samples: [[t, length, depth], ...]
std::string PayoutText(const ManeuverConfig& c, const PayoutResults& r);
std::string PayoutYaml(const ManeuverConfig& c, const PayoutResults& r);
// SVG 1.1: the towfish's depth and the paid-out length against time, and the depth against the
// length (the samples)
std::string PayoutPlotSvg(const ManeuverConfig& c, const PayoutResults& r);

}  // namespace towsim::controllers
