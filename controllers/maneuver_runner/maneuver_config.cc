#include "maneuver_runner/maneuver_config.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "common/config_file.h"
#include "installed/installed_data.h"

namespace towsim::controllers {
namespace {

const std::vector<std::string> kFileKeys = {
    "maneuver",    "body",          "thrust",         "start",     "rudder_deg",
    "heading_deg", "until_yaw_deg", "until_turn_deg", "reversals", "port_first",
    "tow_speed",   "from_length",   "to_length",      "payout_rate", "hold",
    "towfish",     "sample_period"};

constexpr const char* kKinds = "must be one of case1, uturn, zigzag, turning_circle, payout";

ManeuverKind KindOf(const std::string& name, const std::string& where) {
  for (ManeuverKind k : {ManeuverKind::kCase1, ManeuverKind::kUTurn, ManeuverKind::kZigZag,
                         ManeuverKind::kTurningCircle, ManeuverKind::kPayout}) {
    if (name == ManeuverName(k)) return k;
  }
  throw ConfigError(where + ": " + kKinds);
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
    case ManeuverKind::kPayout:
      c.rudder_deg = 0.0;
      c.start = 100.0;
      break;
  }
}

}  // namespace

std::vector<std::string> ManeuverFlagNames() {
  return {"maneuver",   "config",      "body",          "thrust",         "start",
          "rudder-deg", "heading-deg", "until-yaw-deg", "until-turn-deg", "reversals",
          "results",    "domain",      "namespace",     "timeout",
          "security",   "tow-speed",   "from-length",   "to-length",      "payout-rate",
          "hold",       "towfish",     "sample-period", "plot",           "cable"};
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
    case ManeuverKind::kPayout:
      return "payout";
  }
  return "?";
}

ManeuverConfig ResolveManeuver(const Flags& f) {
  ManeuverConfig c;
  std::unique_ptr<ConfigFile> file;
  if (f.Has("config")) {
    file = std::make_unique<ConfigFile>(f.String("config", ""), kFileKeys, installed::kManeuvers);
  }
  // the kind first: it sets the defaults the rest overrides
  if (f.Has("maneuver")) {
    const std::string m = f.String("maneuver", "");
    c.kind = KindOf(m, "--maneuver " + m);
  } else if (file && file->Has("maneuver")) {
    const std::string m = file->String("maneuver");
    try {
      c.kind = KindOf(m, "");
    } catch (const ConfigError&) {
      throw file->Error("maneuver", kKinds);
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
  const std::string tow_speed = number("tow_speed", "tow-speed", &c.tow_speed);
  const std::string from_length = number("from_length", "from-length", &c.from_length);
  const std::string to_length = number("to_length", "to-length", &c.to_length);
  const std::string payout_rate = number("payout_rate", "payout-rate", &c.payout_rate);
  const std::string hold = number("hold", "hold", &c.hold);
  const std::string sample_period = number("sample_period", "sample-period", &c.sample_period);
  if (f.Has("towfish")) {
    c.towfish = f.String("towfish", c.towfish);
  } else if (file && file->Has("towfish")) {
    c.towfish = file->String("towfish");
  }
  c.results = f.String("results", "");
  c.plot = f.String("plot", "");
  if (!c.plot.empty() && c.kind != ManeuverKind::kPayout) {
    throw ConfigError("--plot " + c.plot + ": only the payout manoeuvre draws a plot");
  }

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
    case ManeuverKind::kPayout:
      if (c.rudder_deg != 0.0) fail("rudder_deg", rudder, "must be 0 for payout (no rudder)");
      if (!(c.thrust > 0.0)) fail("thrust", thrust, "must be > 0 [N] (the speed hold's limit)");
      if (!(c.tow_speed > 0.0 && std::isfinite(c.tow_speed))) {
        fail("tow_speed", tow_speed, "must be a number > 0 [m/s]");
      }
      if (!(c.from_length > 0.0 && std::isfinite(c.from_length))) {
        fail("from_length", from_length, "must be a number > 0 [m]");
      }
      if (!(c.to_length > 0.0 && std::isfinite(c.to_length)) || c.to_length == c.from_length) {
        fail("to_length", to_length, "must be a number > 0 [m], not from_length");
      }
      if (!(c.payout_rate > 0.0 && std::isfinite(c.payout_rate))) {
        fail("payout_rate", payout_rate, "must be a number > 0 [m/s]");
      }
      if (!(c.hold >= 0.0 && std::isfinite(c.hold))) fail("hold", hold, "must be >= 0 [s]");
      if (!(c.sample_period > 0.0 && std::isfinite(c.sample_period))) {
        fail("sample_period", sample_period, "must be a number > 0 [s]");
      }
      if (c.towfish.empty() || c.towfish == c.body) {
        throw ConfigError("towfish " + c.towfish + ": must name the towed body (not " + c.body +
                          ")");
      }
      break;
  }
  return c;
}

}  // namespace towsim::controllers
