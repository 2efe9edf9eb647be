#include "maneuver_runner/results_sheet.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <vector>

#include "common/laws.h"

namespace towsim::controllers {
namespace {

std::string Format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string Format(const char* fmt, ...) {
  char buf[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  return buf;
}

const char* Ordinal(size_t k) {
  static const char* const kNames[] = {"1st", "2nd", "3rd", "4th", "5th", "6th", "7th", "8th"};
  return k < 8 ? kNames[k] : "next";
}

std::string List(const std::vector<double>& v, double scale) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += Format("%s%.4g", i ? ", " : "", v[i] * scale);
  return s + "]";
}

std::string Header(const ManeuverConfig& c, const RunSummary& s) {
  return Format(
      "body: %s\nthrust: %.6g\nt_execute: %.6g\napproach_speed: %.4f\n"
      "approach_heading_deg: %.3f\nt_end: %.6g\n",
      c.body.c_str(), c.thrust, c.start, s.approach_speed, Deg(s.approach_yaw), s.t_end);
}

}  // namespace

std::string ZigZagText(const ManeuverConfig& c, const RunSummary& s, const ZigZagResults& r) {
  std::string out = Format(
      "zig-zag %g/%g (%s first), %s, thrust %g N, executed at t = %.2f s, approach speed "
      "%.3f m/s, heading %.2f deg\n",
      c.rudder_deg, c.heading_deg, c.port_first ? "port" : "starboard", c.body.c_str(), c.thrust,
      r.t_execute, s.approach_speed, Deg(s.approach_yaw));
  if (r.initial_turning_time >= 0.0) {
    out += Format("  initial turning time (to %g deg)   %8.2f s\n", c.heading_deg,
                  r.initial_turning_time);
  }
  for (size_t k = 0; k < r.overshoots.size(); ++k) {
    out += Format("  %s overshoot angle                %8.2f deg   time to check yaw %6.2f s\n",
                  Ordinal(k), Deg(r.overshoots[k]), r.times_to_check_yaw[k]);
  }
  for (size_t k = 0; k < r.periods.size(); ++k) {
    out += Format("  period (reversal %zu -> %zu)          %8.2f s\n", k + 1, k + 3, r.periods[k]);
  }
  out += Format("  completed                          %8s (%zu overshoots measured, t = %.2f s)\n",
                r.finished ? "yes" : "no", r.overshoots.size(), s.t_end);
  return out;
}

std::string ZigZagYaml(const ManeuverConfig& c, const RunSummary& s, const ZigZagResults& r) {
  return Format("maneuver: zigzag\nrudder_deg: %g\nheading_deg: %g\nport_first: %s\n", c.rudder_deg,
                c.heading_deg, c.port_first ? "true" : "false") +
         Header(c, s) +
         Format(
             "initial_turning_time: %.4f\novershoot_deg: %s\ntime_to_check_yaw: %s\n"
             "period: %s\ncompleted: %s\n",
             r.initial_turning_time, List(r.overshoots, 180.0 / kPi).c_str(),
             List(r.times_to_check_yaw, 1.0).c_str(), List(r.periods, 1.0).c_str(),
             r.finished ? "true" : "false");
}

std::string TurningCircleText(const ManeuverConfig& c, const RunSummary& s,
                              const TurningCircleResults& r) {
  std::string out = Format(
      "turning circle, rudder %g deg to %s, %s, thrust %g N, executed at t = %.2f s, approach "
      "speed %.3f m/s, heading %.2f deg\n",
      c.rudder_deg, c.port_first ? "port" : "starboard", c.body.c_str(), c.thrust, r.t_execute,
      s.approach_speed, Deg(s.approach_yaw));
  if (r.has_90) {
    out += Format("  advance (at 90 deg)               %8.2f m    (%.2f s after execute)\n",
                  r.advance, r.time_90);
    out += Format("  transfer (at 90 deg)              %8.2f m\n", std::abs(r.transfer));
  }
  if (r.has_180) {
    out += Format("  tactical diameter (at 180 deg)    %8.2f m    (%.2f s after execute)\n",
                  std::abs(r.tactical_diameter), r.time_180);
  }
  if (r.has_steady) {
    out += Format("  steady turning diameter           %8.2f m    (circle fit; 2U/r = %.2f m)\n",
                  r.steady_diameter, r.kinematic_diameter);
    out += Format("  steady speed, yaw rate            %8.3f m/s  %.3f deg/s\n", r.steady_speed,
                  Deg(r.steady_yaw_rate));
  }
  out +=
      Format("  heading change reached            %8.1f deg  (t = %.2f s)%s\n", Deg(r.total_turn),
             s.t_end, r.has_steady ? "" : "; steady circle needs 540 deg: run longer");
  return out;
}

std::string TurningCircleYaml(const ManeuverConfig& c, const RunSummary& s,
                              const TurningCircleResults& r) {
  std::string out = Format("maneuver: turning_circle\nrudder_deg: %g\nport_first: %s\n",
                           c.rudder_deg, c.port_first ? "true" : "false") +
                    Header(c, s);
  if (r.has_90) {
    out += Format("advance: %.4f\ntransfer: %.4f\ntime_90: %.4f\n", r.advance, std::abs(r.transfer),
                  r.time_90);
  }
  if (r.has_180) {
    out += Format("tactical_diameter: %.4f\ntime_180: %.4f\n", std::abs(r.tactical_diameter),
                  r.time_180);
  }
  if (r.has_steady) {
    out += Format(
        "steady_diameter: %.4f\nkinematic_diameter: %.4f\nsteady_speed: %.4f\n"
        "steady_yaw_rate_deg: %.4f\n",
        r.steady_diameter, r.kinematic_diameter, r.steady_speed, Deg(r.steady_yaw_rate));
  }
  out += Format("total_turn_deg: %.3f\n", Deg(r.total_turn));
  return out;
}

}  // namespace towsim::controllers
