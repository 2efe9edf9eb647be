#include "maneuver_runner/results_sheet.h"

#include <algorithm>
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

namespace {

struct NamedEnd {
  const char* name;
  const PayoutResults::PhaseEnd* end;
};

std::vector<NamedEnd> PhaseEnds(const PayoutResults& r) {
  return {{"approach", &r.approach},
          {"payout", &r.payout},
          {"hold", &r.hold},
          {"reel_in", &r.reel_in},
          {"final", &r.final}};
}

// an SVG panel at (x0, y0), w x h: the series (x, y) pairs scaled to the data's range; depth
// axes point down (NED), as the towfish hangs
struct Series {
  std::vector<double> x, y;
  const char* colour;
  const char* label;
};

std::string Panel(double x0, double y0, double w, double h, const char* title,
                  const char* x_label, const char* y_label, const std::vector<Series>& series,
                  bool y_down) {
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  for (const Series& s : series) {
    for (double v : s.x) xmin = std::min(xmin, v), xmax = std::max(xmax, v);
    for (double v : s.y) ymin = std::min(ymin, v), ymax = std::max(ymax, v);
  }
  if (!(xmax > xmin)) xmax = xmin + 1.0;
  if (!(ymax > ymin)) ymax = ymin + 1.0;
  const double pad = 0.05 * (ymax - ymin);
  ymin -= pad;
  ymax += pad;
  const double left = x0 + 60, right = x0 + w - 20, top = y0 + 30, bottom = y0 + h - 40;
  auto px = [&](double v) { return left + (v - xmin) / (xmax - xmin) * (right - left); };
  auto py = [&](double v) {
    const double f = (v - ymin) / (ymax - ymin);
    return y_down ? top + f * (bottom - top) : bottom - f * (bottom - top);
  };
  std::string out = Format(
      "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
      "stroke=\"#444\"/>\n<text x=\"%.1f\" y=\"%.1f\" font-size=\"14\">%s</text>\n"
      "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" text-anchor=\"middle\">%s</text>\n"
      "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" transform=\"rotate(-90 %.1f %.1f)\" "
      "text-anchor=\"middle\">%s</text>\n",
      left, top, right - left, bottom - top, left, y0 + 20, title, 0.5 * (left + right),
      bottom + 32, x_label, x0 + 15, 0.5 * (top + bottom), x0 + 15, 0.5 * (top + bottom),
      y_label);
  for (int k = 0; k <= 4; ++k) {  // ticks
    const double xv = xmin + k * (xmax - xmin) / 4, yv = ymin + k * (ymax - ymin) / 4;
    out += Format("<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" text-anchor=\"middle\">%.4g</text>\n",
                  px(xv), bottom + 14, xv);
    out += Format("<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" text-anchor=\"end\">%.4g</text>\n",
                  left - 4, py(yv) + 3, yv);
  }
  int row = 0;
  for (const Series& s : series) {
    std::string points;
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      points += Format("%.1f,%.1f ", px(s.x[i]), py(s.y[i]));
    }
    // (points may be longer than Format's buffer)
    out += Format("<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.5\" points=\"", s.colour) +
           points + "\"/>\n";
    out += Format("<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" fill=\"%s\">%s</text>\n",
                  right - 150, top + 16 + 14 * row++, s.colour, s.label);
  }
  return out;
}

}  // namespace

std::string PayoutText(const ManeuverConfig& c, const PayoutResults& r) {
  std::string out = Format(
      "payout %g m -> %g m at %g m/s, hold %g s, back to %g m; %s towing at %g m/s (thrust <= "
      "%g N), payout from t = %.2f s; depth of %s\n",
      c.from_length, c.to_length, c.payout_rate, c.hold, c.from_length, c.body.c_str(),
      c.tow_speed, c.thrust, c.start, c.towfish.c_str());
  out += "  end of      t [s]   length [m]   depth [m]   tow depth [m]   speed [m/s]\n";
  for (const NamedEnd& e : PhaseEnds(r)) {
    if (!e.end->valid) {
      out += Format("  %-9s  (not reached)\n", e.name);
      continue;
    }
    const PayoutSample& a = e.end->at;
    out += Format("  %-9s %8.2f %12.3f %11.3f %15.3f %13.3f\n", e.name, a.t, a.length, a.depth,
                  a.tow_depth, a.speed);
  }
  out += Format("  largest length %.3f m, largest depth %.3f m\n", r.max_length, r.max_depth);
  out += "  t [s]   length [m]   depth [m]\n";
  for (const PayoutSample& a : r.samples) {
    out += Format("  %7.2f %12.3f %11.3f\n", a.t, a.length, a.depth);
  }
  return out;
}

std::string PayoutYaml(const ManeuverConfig& c, const PayoutResults& r) {
  std::string out = Format(
      "maneuver: payout\nbody: %s\ntowfish: %s\nthrust: %.6g\nt_execute: %.6g\n"
      "tow_speed: %.6g\nfrom_length: %.6g\nto_length: %.6g\npayout_rate: %.6g\nhold: %.6g\n",
      c.body.c_str(), c.towfish.c_str(), c.thrust, c.start, c.tow_speed, c.from_length,
      c.to_length, c.payout_rate, c.hold);
  for (const NamedEnd& e : PhaseEnds(r)) {
    if (!e.end->valid) continue;
    const PayoutSample& a = e.end->at;
    out += Format("%s_t: %.6f\n%s_length: %.6f\n%s_depth: %.6f\n%s_tow_depth: %.6f\n%s_speed: %.6f\n",
                  e.name, a.t, e.name, a.length, e.name, a.depth, e.name, a.tow_depth, e.name,
                  a.speed);
  }
  out += Format("max_length: %.6f\nmax_depth: %.6f\nsamples: [", r.max_length, r.max_depth);
  // one sample at a time (the list is longer than Format's buffer)
  for (size_t i = 0; i < r.samples.size(); ++i) {
    const PayoutSample& a = r.samples[i];
    out += Format("%s[%.4f, %.4f, %.4f]", i ? ", " : "", a.t, a.length, a.depth);
  }
  return out + "]\n";
}

std::string PayoutPlotSvg(const ManeuverConfig& c, const PayoutResults& r) {
  Series depth_t{{}, {}, "#1f77b4", "towfish depth z [m]"};
  Series length_t{{}, {}, "#d62728", "paid-out length [m]"};
  Series depth_l{{}, {}, "#1f77b4", "towfish depth z [m]"};
  for (const PayoutSample& a : r.samples) {
    depth_t.x.push_back(a.t);
    depth_t.y.push_back(a.depth);
    length_t.x.push_back(a.t);
    length_t.y.push_back(a.length);
    depth_l.x.push_back(a.length);
    depth_l.y.push_back(a.depth);
  }
  const std::string title = Format("payout %g -> %g m at %g m/s, towing at %g m/s",
                                   c.from_length, c.to_length, c.payout_rate, c.tow_speed);
  std::string out =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"1100\" height=\"720\">\n"
      "<rect width=\"1100\" height=\"720\" fill=\"white\"/>\n";
  out += Format("<text x=\"20\" y=\"24\" font-size=\"16\">%s</text>\n", title.c_str());
  out += Panel(0, 30, 1100, 230, "depth against time (down)", "t [s]", "z [m]", {depth_t}, true);
  out += Panel(0, 260, 1100, 230, "paid-out length against time", "t [s]", "length [m]",
               {length_t}, false);
  out += Panel(0, 490, 1100, 230, "depth against length (down)", "length [m]", "z [m]",
               {depth_l}, true);
  return out + "</svg>\n";
}

}  // namespace towsim::controllers
