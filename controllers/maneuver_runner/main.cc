// maneuver_runner: plays a manoeuvre on a vehicle of a running sim_node, against its live
// state, and prints the trials sheet at the end.
// The command line, its parameters and exit codes: kUsage below (`maneuver_runner --help`).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/client.h"
#include "common/config_file.h"
#include "common/flags.h"
#include "common/laws.h"
#include "maneuver_runner/maneuver_config.h"
#include "maneuver_runner/payout.h"
#include "maneuver_runner/results_sheet.h"
#include "maneuver_runner/turning_circle.h"
#include "maneuver_runner/uturn.h"
#include "maneuver_runner/zigzag.h"

using namespace towsim::controllers;

namespace {
constexpr char kUsage[] =
    "usage: maneuver_runner [--maneuver case1|uturn|zigzag|turning_circle|payout]\n"
    "                       [--config FILE|NAME] [--body tow_vehicle] [--thrust 4165]\n"
    "                       [--start 55] [--rudder-deg D] [--heading-deg P] [--reversals 4]\n"
    "                       [--port-first] [--until-yaw-deg 170] [--until-turn-deg 0]\n"
    "                       [--tow-speed 3] [--from-length 150] [--to-length 250]\n"
    "                       [--payout-rate 1] [--hold 100] [--towfish towfish]\n"
    "                       [--sample-period 10] [--results FILE.yaml] [--plot FILE.svg]\n"
    "                       [--domain 0] [--namespace /towsim] [--timeout 30]\n"
    "                       [--security DIR/NAME] [--cable NAME]\n"
    "  case1           thrust T, rudder 0 (the paper's Case 1)\n"
    "  uturn           from `start` the rudder at D until the yaw reaches --until-yaw-deg, then 0\n"
    "                  (the paper's Case 2; the default manoeuvre)\n"
    "  zigzag          the IMO / ITTC D/P zig-zag (maneuver_runner/zigzag.h): sheet with the\n"
    "                  overshoot angles, initial turning time and period\n"
    "  turning_circle  rudder D held from `start` (maneuver_runner/turning_circle.h): advance,\n"
    "                  transfer, tactical and steady turning diameters\n"
    "  payout          towing at --tow-speed (thrust: a PI on the surge, up to --thrust), the\n"
    "                  winch pays out from --from-length to --to-length at --payout-rate from\n"
    "                  `start`, holds --hold s, reels back in (maneuver_runner/payout.h): sheet\n"
    "                  with the towfish's depth against the paid-out length and time, --plot\n"
    "                  draws it (the scene needs cable.winch; commands on <ns>/winch/command)\n"
    "  --cable NAME    the cable whose state <ns>/NAME/state the manoeuvre reads (payout: the\n"
    "                  sheet's paid-out length; default the one cable, `cable`; a network's\n"
    "                  cables by name, the winch's cable); a name the node's scene has no\n"
    "                  cable of is refused, naming its cables (exit 1)\n"
    "Parameters from --config (config/maneuvers/*.yaml; a bare NAME: the installed\n"
    "P/share/towsim/maneuvers/NAME.yaml) and flags (flags win), see\n"
    "maneuver_runner/maneuver_config.h. Needs CYCLONEDDS_URI. Exit 0 at the end of the node's\n"
    "run or on SIGINT/SIGTERM (the sheet printed either way), 1 on an error or a timeout, 2 on a\n"
    "bad command line or file (the message names the flag or key, its value and the rule).\n";
}  // namespace

int main(int argc, char** argv) {
  ClientOptions opt;
  opt.name = "maneuver_runner";
  ManeuverConfig c;
  try {
    const Flags f(argc, argv, ManeuverFlagNames(), ManeuverSwitchNames());
    if (f.Help()) {
      std::printf("%s", kUsage);
      return 0;
    }
    c = ResolveManeuver(f);
    opt.body = c.body;
    opt.domain = f.Domain();
    opt.ns = f.String("namespace", "/towsim");
    opt.timeout = f.Number("timeout", 30.0);
    opt.security = f.String(kSecurityFlag, "");
    if (c.kind == ManeuverKind::kPayout) {
      opt.winch = true;         // the drum's commands with each answer
      opt.cable = true;         // the paid-out length, for the sheet
      opt.observe = c.towfish;  // its depth, for the sheet
    }
    // the cable read (docs/controllers.md "Cables"): checked against the scene's cables
    opt.cable = opt.cable || f.Has("cable");
    opt.cable_name = f.String("cable", opt.cable_name);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "maneuver_runner: error: %s\n", e.what());
    return 2;
  }
  const double sign = c.port_first ? -1.0 : 1.0;
  UTurnParams uturn;
  uturn.thrust = c.thrust;
  uturn.rudder = c.kind == ManeuverKind::kCase1 ? 0.0 : Rad(c.rudder_deg);
  uturn.start = c.start;
  uturn.until_yaw = Rad(c.until_yaw_deg);
  ZigZagParams zigzag;
  zigzag.thrust = c.thrust;
  zigzag.rudder = Rad(c.rudder_deg);
  zigzag.switch_angle = Rad(c.heading_deg);
  zigzag.start = c.start;
  zigzag.reversals = c.reversals;
  zigzag.port_first = c.port_first;
  TurningCircleParams circle;
  circle.thrust = c.thrust;
  circle.rudder = sign * Rad(c.rudder_deg);
  circle.start = c.start;
  circle.until_turn = Rad(c.until_turn_deg);
  PayoutParams payout;
  payout.tow_speed = c.tow_speed;
  payout.max_thrust = c.thrust;
  payout.start = c.start;
  payout.from_length = c.from_length;
  payout.to_length = c.to_length;
  payout.rate = c.payout_rate;
  payout.hold = c.hold;

  try {
    RequireDdsUri();
    InstallStopHandlers();
    LockstepClient client(opt);
    UTurnState uturn_state;
    ZigZagState zigzag_state;
    TurningCircleState circle_state;
    PayoutState payout_state;
    PayoutSheet payout_sheet(payout, c.sample_period);
    std::vector<TrackSample> track;
    RunSummary summary;
    bool executed = false;
    double turn_end = -1.0;
    const int rc = client.Run([&](const BodyState& b) {
      const double speed = std::hypot(b.x_dot, b.y_dot);
      if (!executed && b.t >= c.start - 1e-9) {
        executed = true;
        summary.approach_speed = speed;
        summary.approach_yaw = b.yaw;
      }
      summary.t_end = b.t;
      if (executed) track.push_back({b.t, b.x, b.y, b.yaw, speed, b.r});
      ManeuverCommand m;
      switch (c.kind) {
        case ManeuverKind::kCase1:
        case ManeuverKind::kUTurn: {
          const bool before = uturn_state.turned;
          m = UTurnStep(uturn, uturn_state, b.t, b.yaw);
          if (!before && uturn_state.turned) turn_end = b.t;
          break;
        }
        case ManeuverKind::kZigZag:
          m = ZigZagStep(zigzag, zigzag_state, b.t, b.yaw);
          break;
        case ManeuverKind::kTurningCircle:
          m = TurningCircleStep(circle, circle_state, b.t, b.yaw);
          break;
        case ManeuverKind::kPayout: {
          const PayoutCommand p = PayoutStep(payout, payout_state, b.t, b.u, b.dt);
          // the sheet: the steps whose cable state came (the node's cable/state rate)
          if (b.observed.valid && std::abs(b.cable.t - b.t) < 1e-9) {
            payout_sheet.Add({b.t, b.cable.paid_out_length, b.observed.z, b.z, b.u});
          }
          Actuation a{p.vehicle.thrust, p.vehicle.rudder, p.vehicle.elevator};
          a.winch.mode =
              p.winch_length_mode ? WinchDemand::Mode::kLength : WinchDemand::Mode::kSpeed;
          a.winch.value = p.winch_value;
          return a;
        }
      }
      return Actuation{m.thrust, m.rudder, m.elevator};
    });
    std::printf("maneuver_runner: %s, %llu steps answered", ManeuverName(c.kind),
                static_cast<unsigned long long>(client.steps_answered()));
    std::string text, yaml;
    switch (c.kind) {
      case ManeuverKind::kCase1:
      case ManeuverKind::kUTurn:
        std::printf(", turn ended at t = %g s\n", turn_end);
        yaml = "maneuver: " + std::string(ManeuverName(c.kind)) +
               "\nturn_end: " + std::to_string(turn_end) + "\n";
        break;
      case ManeuverKind::kZigZag: {
        const ZigZagResults r = ZigZagSheet(zigzag_state);
        std::printf("\n");
        text = ZigZagText(c, summary, r);
        yaml = ZigZagYaml(c, summary, r);
        break;
      }
      case ManeuverKind::kTurningCircle: {
        const TurningCircleResults r = TurningCircleSheet(track);
        std::printf("\n");
        text = TurningCircleText(c, summary, r);
        yaml = TurningCircleYaml(c, summary, r);
        break;
      }
      case ManeuverKind::kPayout:
        std::printf(", %zu sheet samples\n", payout_sheet.results().samples.size());
        text = PayoutText(c, payout_sheet.results());
        yaml = PayoutYaml(c, payout_sheet.results());
        break;
    }
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
    if (!c.plot.empty()) {
      const std::string svg = PayoutPlotSvg(c, payout_sheet.results());
      std::FILE* out = std::fopen(c.plot.c_str(), "w");
      if (out == nullptr || std::fputs(svg.c_str(), out) < 0 || std::fclose(out) != 0) {
        std::fprintf(stderr, "maneuver_runner: error: cannot write --plot %s\n", c.plot.c_str());
        return 1;
      }
    }
    if (!c.results.empty()) {
      std::FILE* out = std::fopen(c.results.c_str(), "w");
      if (out == nullptr || std::fputs(yaml.c_str(), out) < 0 || std::fclose(out) != 0) {
        std::fprintf(stderr, "maneuver_runner: error: cannot write --results %s\n",
                     c.results.c_str());
        return 1;
      }
    }
    return rc;
  } catch (const SecurityError& e) {
    std::fprintf(stderr, "maneuver_runner: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "maneuver_runner: error: %s\n", e.what());
    return 1;
  }
}
