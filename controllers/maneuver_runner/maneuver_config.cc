#include "maneuver_runner/maneuver_config.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "common/config_file.h"

namespace towsim::controllers {
namespace {

const std::vector<std::string> kFileKeys = {
    "maneuver",    "body",          "thrust",         "start",     "rudder_deg",
    "heading_deg", "until_yaw_deg", "until_turn_deg", "reversals", "port_first"};

ManeuverKind KindOf(const std::string& name, const std::string& where) {
  for (ManeuverKind k : {ManeuverKind::kCase1, ManeuverKind::kUTurn, ManeuverKind::kZigZag,
                         ManeuverKind::kTurningCircle}) {
    if (name == ManeuverName(k)) return k;
  }
  throw ConfigError(where + ": must be one of case1, uturn, zigzag, turning_circle");
}

void SetDefaults(ManeuverConfig& c) {
  switch (c.kind) {
    case ManeuverKind::kCase1:
      c.rudder_deg = 0.0;
      break;
    case ManeuverKind::kUTurn:
      c.rudder_deg = 20.0;
      break;
    case ManeuverKind::kZigZag:
      c.rudder_deg = 10.0;
      c.heading_deg = 10.0;
      break;
    case ManeuverKind::kTurningCircle:
      c.rudder_deg = 20.0;
      break;
  }
}

}  // namespace

std::vector<std::string> ManeuverFlagNames() {
  return {"maneuver",   "config",      "body",          "thrust",         "start",
          "rudder-deg", "heading-deg", "until-yaw-deg", "until-turn-deg", "reversals",
          "results",    "domain",      "namespace",     "timeout",
          "security"};
}
std::vector<std::string> ManeuverSwitchNames() { return {"port-first"}; }

const char* ManeuverName(ManeuverKind kind) {
  switch (kind) {
    case ManeuverKind::kCase1:
      return "case1";
    case ManeuverKind::kUTurn:
      return "uturn";
    case ManeuverKind::kZigZag:
      return "zigzag";
    case ManeuverKind::kTurningCircle:
      return "turning_circle";
  }
  return "?";
}

ManeuverConfig ResolveManeuver(const Flags& f) {
  ManeuverConfig c;
  std::unique_ptr<ConfigFile> file;
  if (f.Has("config")) file = std::make_unique<ConfigFile>(f.String("config", ""), kFileKeys);
  // the kind first: it sets the defaults the rest overrides
  if (f.Has("maneuver")) {
    const std::string m = f.String("maneuver", "");
    c.kind = KindOf(m, "--maneuver " + m);
  } else if (file && file->Has("maneuver")) {
    const std::string m = file->String("maneuver");
    try {
      c.kind = KindOf(m, "");
    } catch (const ConfigError&) {
      throw file->Error("maneuver", "must be one of case1, uturn, zigzag, turning_circle");
    }
  }
  SetDefaults(c);
  // where each number came from, for the error messages
  auto number = [&](const std::string& key, const std::string& flag, double* out) -> std::string {
    if (f.Has(flag)) {
      *out = f.Number(flag, *out);
      return "--" + flag + " " + f.String(flag, "");
    }
    if (file && file->Has(key)) {
      *out = file->Number(key);
      return "";  // a file value: file->Error names it
    }
    return "default";
  };
  auto fail = [&](const std::string& key, const std::string& flag_src, const std::string& rule) {
    if (!flag_src.empty() && flag_src != "default") throw ConfigError(flag_src + ": " + rule);
    if (flag_src.empty()) throw file->Error(key, rule);
    throw ConfigError(key + ": " + rule);
  };
  if (f.Has("body")) {
    c.body = f.String("body", c.body);
  } else if (file && file->Has("body")) {
    c.body = file->String("body");
  }
  const std::string thrust = number("thrust", "thrust", &c.thrust);
  if (!std::isfinite(c.thrust)) fail("thrust", thrust, "must be a finite number [N]");
  const std::string start = number("start", "start", &c.start);
  if (!(c.start >= 0.0)) fail("start", start, "must be >= 0 [s]");
  const std::string rudder = number("rudder_deg", "rudder-deg", &c.rudder_deg);
  const std::string heading = number("heading_deg", "heading-deg", &c.heading_deg);
  const std::string until_yaw = number("until_yaw_deg", "until-yaw-deg", &c.until_yaw_deg);
  const std::string until_turn = number("until_turn_deg", "until-turn-deg", &c.until_turn_deg);
  double reversals = c.reversals;
  const std::string rev = number("reversals", "reversals", &reversals);
  if (f.Has("port-first")) {
    c.port_first = true;
  } else if (file && file->Has("port_first")) {
    c.port_first = file->Bool("port_first");
  }
  c.results = f.String("results", "");

  switch (c.kind) {
    case ManeuverKind::kCase1:
      if (c.rudder_deg != 0.0) fail("rudder_deg", rudder, "must be 0 for case1 (no rudder)");
      break;
    case ManeuverKind::kUTurn:
      if (!(std::abs(c.rudder_deg) <= 90.0)) fail("rudder_deg", rudder, "must be in [-90, 90]");
      if (!(std::abs(c.until_yaw_deg) <= 180.0)) {
        fail("until_yaw_deg", until_yaw, "must be in [-180, 180] (a yaw)");
      }
      break;
    case ManeuverKind::kZigZag:
      if (!(c.rudder_deg > 0.0 && c.rudder_deg <= 90.0)) {
        fail("rudder_deg", rudder, "must be in (0, 90] for a zig-zag (its sign: port_first)");
      }
      if (!(c.heading_deg > 0.0 && c.heading_deg < 180.0)) {
        fail("heading_deg", heading, "must be in (0, 180) (the zig-zag's switch angle)");
      }
      if (!(reversals >= 1 && reversals <= 100 && reversals == std::floor(reversals))) {
        fail("reversals", rev, "must be an integer from 1 to 100");
      }
      c.reversals = static_cast<int>(reversals);
      break;
    case ManeuverKind::kTurningCircle:
      if (!(c.rudder_deg > 0.0 && c.rudder_deg <= 90.0)) {
        fail("rudder_deg", rudder,
             "must be in (0, 90] for a turning circle (its sign: port_first)");
      }
      if (!(c.until_turn_deg >= 0.0)) {
        fail("until_turn_deg", until_turn, "must be >= 0 (0: rudder held to the end)");
      }
      break;
  }
  return c;
}

}  // namespace towsim::controllers
