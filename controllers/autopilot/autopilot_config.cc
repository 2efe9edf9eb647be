#include "autopilot/autopilot_config.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "common/config_file.h"
#include "installed/installed_data.h"

namespace towsim::controllers {
namespace {

const std::vector<std::string> kFileKeys = {"body",
                                            "speed",
                                            "heading_deg",
                                            "depth",
                                            "schedule",
                                            "waypoints",
                                            "survey_origin",
                                            "survey_heading_deg",
                                            "survey_leg_length",
                                            "survey_spacing",
                                            "survey_legs",
                                            "survey_turn",
                                            "lookahead",
                                            "acceptance_radius",
                                            "speed_kp",
                                            "speed_ki",
                                            "thrust_ff",
                                            "thrust_rate",
                                            "max_thrust",
                                            "min_thrust",
                                            "heading_kp",
                                            "heading_ki",
                                            "heading_kd",
                                            "max_rudder_deg",
                                            "rudder_rate_deg",
                                            "depth_kp",
                                            "depth_ki",
                                            "depth_kd",
                                            "max_elevator_deg",
                                            "elevator_rate_deg",
                                            "elevator_sign"};

// a parameter: file key, flag (may be ""), rule check
struct Number {
  const ConfigFile* file;
  const Flags* flags;
  // reads key / flag into *out if given; checks `ok`; errors name the source
  void operator()(const std::string& key, const std::string& flag, double* out, bool (*ok)(double),
                  const std::string& rule) const {
    if (!flag.empty() && flags->Has(flag)) {
      *out = flags->Number(flag, *out);
      if (!ok(*out)) throw ConfigError("--" + flag + " " + flags->String(flag, "") + ": " + rule);
    } else if (file != nullptr && file->Has(key)) {
      *out = file->Number(key);
      if (!ok(*out)) throw file->Error(key, rule);
    }
  }
};

bool Positive(double v) { return v > 0.0; }
bool NonNegative(double v) { return v >= 0.0; }
bool Finite(double v) { return std::isfinite(v); }
bool Degrees90(double v) { return v > 0.0 && v <= 90.0; }

}  // namespace

std::vector<std::string> AutopilotFlagNames() {
  return {"config",
          "body",
          "speed",
          "heading-deg",
          "depth",
          "survey-origin",
          "survey-heading-deg",
          "leg-length",
          "spacing",
          "legs",
          "turn",
          "lookahead",
          "acceptance-radius",
          "heading-kp",
          "heading-ki",
          "heading-kd",
          "speed-kp",
          "speed-ki",
          "log",
          "domain",
          "namespace",
          "timeout",
          "security",
          "cable"};
}
std::vector<std::string> AutopilotSwitchNames() { return {}; }

AutopilotConfig ResolveAutopilot(const Flags& f) {
  AutopilotConfig c;
  std::unique_ptr<ConfigFile> file;
  if (f.Has("config")) {
    file = std::make_unique<ConfigFile>(f.String("config", ""), kFileKeys, installed::kAutopilot);
  }
  const Number number{file.get(), &f};
  AutopilotGains& g = c.gains;

  if (f.Has("body")) {
    c.body = f.String("body", c.body);
  } else if (file && file->Has("body")) {
    c.body = file->String("body");
  }
  number("speed", "speed", &c.initial.speed, Finite, "must be a finite speed [m/s]");
  double heading_deg = 0.0;
  number("heading_deg", "heading-deg", &heading_deg, Finite, "must be a finite angle [deg]");
  c.initial.heading = WrapPi(Rad(heading_deg));
  if (f.Has("depth") || (file && file->Has("depth"))) {
    number("depth", "depth", &c.initial.depth, NonNegative, "must be >= 0 [m] (z down)");
    g.depth_enabled = true;
  }
  // gains and limits
  number("speed_kp", "speed-kp", &g.speed.kp, NonNegative, "must be >= 0");
  number("speed_ki", "speed-ki", &g.speed.ki, NonNegative, "must be >= 0");
  number("thrust_ff", "", &g.thrust_ff, NonNegative, "must be >= 0 [N/(m/s)^2]");
  number("thrust_rate", "", &g.thrust_rate, NonNegative, "must be >= 0 [N/s] (0: none)");
  number("max_thrust", "", &g.speed.out_max, Positive, "must be > 0 [N]");
  number("min_thrust", "", &g.speed.out_min, Finite, "must be a number [N]");
  if (!(g.speed.out_min < g.speed.out_max)) {
    throw file->Error("min_thrust", "must be < max_thrust");
  }
  number("heading_kp", "heading-kp", &g.heading.kp, NonNegative, "must be >= 0");
  number("heading_ki", "heading-ki", &g.heading.ki, NonNegative, "must be >= 0");
  number("heading_kd", "heading-kd", &g.heading.kd, NonNegative, "must be >= 0");
  double max_rudder = Deg(g.heading.out_max), rudder_rate = Deg(g.heading.rate_limit);
  number("max_rudder_deg", "", &max_rudder, Degrees90, "must be in (0, 90] [deg]");
  number("rudder_rate_deg", "", &rudder_rate, NonNegative, "must be >= 0 [deg/s] (0: none)");
  g.heading.out_max = Rad(max_rudder);
  g.heading.out_min = -g.heading.out_max;
  g.heading.rate_limit = Rad(rudder_rate);
  number("depth_kp", "", &g.depth.kp, NonNegative, "must be >= 0");
  number("depth_ki", "", &g.depth.ki, NonNegative, "must be >= 0");
  number("depth_kd", "", &g.depth.kd, NonNegative, "must be >= 0");
  double max_elevator = Deg(g.depth.out_max), elevator_rate = Deg(g.depth.rate_limit);
  number("max_elevator_deg", "", &max_elevator, Degrees90, "must be in (0, 90] [deg]");
  number("elevator_rate_deg", "", &elevator_rate, NonNegative, "must be >= 0 [deg/s]");
  g.depth.out_max = Rad(max_elevator);
  g.depth.out_min = -g.depth.out_max;
  g.depth.rate_limit = Rad(elevator_rate);
  number(
      "elevator_sign", "", &g.depth_sign, [](double v) { return v == 1.0 || v == -1.0; },
      "must be 1 or -1");

  // setpoint changes
  if (file && file->Has("schedule")) {
    file->List("schedule", {"at", "speed", "heading_deg", "depth"},
               [&](size_t, const ConfigFile::Entry& e) {
                 SetpointChange s;
                 if (!e.Has("at")) throw e.Error("at", "required (the time of the change [s])");
                 s.at = e.Number("at");
                 if (!(s.at >= 0.0)) throw e.Error("at", "must be >= 0 [s]");
                 if (!c.schedule.empty() && s.at < c.schedule.back().at) {
                   throw e.Error("at", "must not be earlier than the previous entry's");
                 }
                 if (e.Has("speed")) s.has_speed = true, s.speed = e.Number("speed");
                 if (e.Has("heading_deg")) {
                   s.has_heading = true;
                   s.heading = WrapPi(Rad(e.Number("heading_deg")));
                 }
                 if (e.Has("depth")) {
                   s.has_depth = true;
                   s.depth = e.Number("depth");
                   if (!g.depth_enabled) {
                     throw e.Error("depth", "a depth change needs the depth loop: set depth");
                   }
                 }
                 if (!s.has_speed && !s.has_heading && !s.has_depth) {
                   throw e.Error("at",
                                 "the entry changes nothing (give speed, heading_deg or depth)");
                 }
                 c.schedule.push_back(s);
               });
  }

  // waypoints: an explicit list, or a lawn-mower survey
  if (file && file->Has("waypoints")) {
    file->List("waypoints", {"x", "y"}, [&](size_t, const ConfigFile::Entry& e) {
      if (!e.Has("x") || !e.Has("y")) throw e.Error("x", "each waypoint needs x and y [m]");
      c.waypoints.push_back({e.Number("x"), e.Number("y")});
    });
    if (c.waypoints.empty()) throw file->Error("waypoints", "must list at least one waypoint");
    c.follow_waypoints = true;
  }
  const bool survey_flag = f.Has("legs") || f.Has("leg-length") || f.Has("spacing") ||
                           f.Has("survey-origin") || f.Has("survey-heading-deg") || f.Has("turn");
  const bool survey_file = file && (file->Has("survey_legs") || file->Has("survey_leg_length") ||
                                    file->Has("survey_spacing") || file->Has("survey_origin"));
  if (survey_flag || survey_file) {
    if (c.follow_waypoints) {
      throw ConfigError("survey: give either waypoints or a lawn-mower survey, not both");
    }
    LawnMowerParams p;
    double legs = p.legs, survey_heading = 0.0;
    number(
        "survey_legs", "legs", &legs,
        [](double v) { return v >= 1 && v <= 1000 && v == std::floor(v); },
        "must be an integer from 1 to 1000");
    p.legs = static_cast<int>(legs);
    number("survey_leg_length", "leg-length", &p.leg_length, Positive, "must be > 0 [m]");
    number("survey_spacing", "spacing", &p.spacing, Positive, "must be > 0 [m]");
    number("survey_heading_deg", "survey-heading-deg", &survey_heading, Finite,
           "must be a finite angle [deg]");
    p.heading = Rad(survey_heading);
    if (f.Has("survey-origin")) {
      const std::string s = f.String("survey-origin", "");
      double x = 0, y = 0;
      char tail = 0;
      if (std::sscanf(s.c_str(), "%lf,%lf%c", &x, &y, &tail) != 2) {
        throw ConfigError("--survey-origin " + s + ": must be X,Y [m] (world NED)");
      }
      p.origin = {x, y};
    } else if (file && file->Has("survey_origin")) {
      const std::vector<double> o = file->Numbers("survey_origin", 2);
      p.origin = {o[0], o[1]};
    }
    std::string turn = "starboard";
    if (f.Has("turn")) {
      turn = f.String("turn", turn);
      if (turn != "starboard" && turn != "port") {
        throw ConfigError("--turn " + turn + ": must be starboard or port");
      }
    } else if (file && file->Has("survey_turn")) {
      turn = file->String("survey_turn");
      if (turn != "starboard" && turn != "port") {
        throw file->Error("survey_turn", "must be starboard or port");
      }
    }
    p.turn = turn == "port" ? -1 : 1;
    c.waypoints = LawnMower(p);
    c.follow_waypoints = true;
  }
  number("lookahead", "lookahead", &c.lookahead, Positive, "must be > 0 [m]");
  number("acceptance_radius", "acceptance-radius", &c.acceptance_radius, Positive,
         "must be > 0 [m]");
  c.log = f.String("log", "");
  return c;
}

AutopilotSetpoint SetpointAt(const AutopilotConfig& c, double t) {
  AutopilotSetpoint s = c.initial;
  for (const SetpointChange& x : c.schedule) {
    if (t < x.at - 1e-9) break;
    if (x.has_speed) s.speed = x.speed;
    if (x.has_heading) s.heading = x.heading;
    if (x.has_depth) s.depth = x.depth;
  }
  return s;
}

}  // namespace towsim::controllers
