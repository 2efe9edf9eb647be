// autopilot: speed, heading and (optionally) depth hold for a vehicle of a running sim_node,
// with waypoint following (LOS) and lawn-mower surveys (autopilot/autopilot_law.h,
// autopilot/guidance.h).
// The command line, its parameters and exit codes: kUsage below (`autopilot --help`).

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

#include "autopilot/autopilot_config.h"
#include "autopilot/autopilot_law.h"
#include "autopilot/guidance.h"
#include "common/client.h"
#include "common/flags.h"
#include "common/laws.h"

using namespace towsim::controllers;

namespace {
constexpr char kUsage[] =
    "usage: autopilot [--config FILE|NAME] [--body tow_vehicle] [--speed 6] [--heading-deg 0]\n"
    "                 [--depth Z] [--legs N --leg-length L --spacing S [--survey-origin X,Y]\n"
    "                  [--survey-heading-deg H] [--turn starboard|port]] [--lookahead 60]\n"
    "                 [--acceptance-radius 30] [--heading-kp ..] [--heading-ki ..]\n"
    "                 [--heading-kd ..] [--speed-kp ..] [--speed-ki ..] [--log FILE]\n"
    "                 [--domain 0] [--namespace /towsim] [--timeout 30] [--security DIR/NAME]\n"
    "                 [--cable NAME]\n"
    "--config: config/autopilot/*.yaml; a bare NAME: the installed\n"
    "P/share/towsim/autopilot/NAME.yaml.\n"
    "Setpoints from t = 0, changed by the file's `schedule`; with waypoints (file) or a survey\n"
    "(flags or file) the heading setpoint comes from the guidance. --log writes one line per\n"
    "step: \"t x y yaw u speed_d heading_d thrust rudder elevator waypoint\"; with --cable NAME\n"
    "(the state <ns>/NAME/state of that cable: the one cable, cable, a network's by name; a name\n"
    "the node's scene has no cable of is refused, naming its cables) and \"t_c top end\": the\n"
    "newest cable sample's stamp and its tension at node 0 and the last node [N]. At the end it "
    "prints\n"
    "the waypoints with the time each was reached. Needs CYCLONEDDS_URI. Exit 0 at the end of\n"
    "the node's run or on SIGINT/SIGTERM, 1 on an error or a timeout, 2 on a bad command line or\n"
    "configuration file (naming the flag or key, its value and the rule).\n";
}  // namespace

int main(int argc, char** argv) {
  ClientOptions opt;
  opt.name = "autopilot";
  AutopilotConfig c;
  try {
    const Flags f(argc, argv, AutopilotFlagNames(), AutopilotSwitchNames());
    if (f.Help()) {
      std::printf("%s", kUsage);
      return 0;
    }
    c = ResolveAutopilot(f);
    opt.body = c.body;
    opt.domain = f.Domain();
    opt.ns = f.String("namespace", "/towsim");
    opt.timeout = f.Number("timeout", 30.0);
    opt.security = f.String(kSecurityFlag, "");
    opt.cable = f.Has("cable");  // docs/controllers.md "Cables"
    opt.cable_name = f.String("cable", opt.cable_name);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "autopilot: error: %s\n", e.what());
    return 2;
  }
  if (c.gains.depth_enabled && c.body == "tow_vehicle") {
    std::fprintf(stderr,
                 "autopilot: note: depth hold on %s, a surface-piercing semi-submersible: its "
                 "waterplane (49 kN/m) dominates the elevators' lift; expect < 0.2 m of effect\n",
                 c.body.c_str());
  }
  std::FILE* log = nullptr;
  try {
    RequireDdsUri();
    InstallStopHandlers();
    if (!c.log.empty()) {
      log = std::fopen(c.log.c_str(), "w");
      if (log == nullptr) throw std::runtime_error("cannot write --log " + c.log);
    }
    LockstepClient client(opt);
    AutopilotState state;
    WaypointTracker tracker;
    tracker.waypoints = c.waypoints;
    tracker.lookahead = c.lookahead;
    tracker.acceptance_radius = c.acceptance_radius;
    const int rc = client.Run([&](const BodyState& b) {
      AutopilotSetpoint sp = SetpointAt(c, b.t);
      if (c.follow_waypoints) sp.heading = TrackWaypoints(tracker, b.t, b.x, b.y, b.yaw);
      AutopilotMeasurement m;
      m.u = b.u;
      m.yaw = b.yaw;
      m.r = b.r;
      m.z = b.z;
      m.z_dot = b.z_dot;
      const AutopilotCommand a = AutopilotStep(c.gains, state, sp, m, b.dt);
      if (log != nullptr) {
        std::fprintf(log, "%.4f %.4f %.4f %.6f %.5f %.4f %.6f %.3f %.6f %.6f %zu", b.t, b.x, b.y,
                     b.yaw, b.u, sp.speed, sp.heading, a.thrust, a.rudder, a.elevator,
                     tracker.target);
        if (opt.cable) std::fputs(CableLogColumns(b.cable).c_str(), log);
        std::fputc('\n', log);
      }
      return Actuation{a.thrust, a.rudder, a.elevator};
    });
    if (log != nullptr) std::fclose(log);
    log = nullptr;
    std::printf("autopilot: %llu steps answered\n",
                static_cast<unsigned long long>(client.steps_answered()));
    for (size_t i = 0; i < tracker.waypoints.size(); ++i) {
      const bool reached = i < tracker.reached_at.size() && tracker.reached_at[i] >= 0.0;
      std::printf("autopilot: waypoint %zu (%.1f, %.1f) %s", i + 1, tracker.waypoints[i].x,
                  tracker.waypoints[i].y, reached ? "reached at t = " : "not reached\n");
      if (reached) {
        std::printf("%.2f s, %.1f m off\n", tracker.reached_at[i], tracker.miss[i]);
      }
    }
    return rc;
  } catch (const SecurityError& e) {
    if (log != nullptr) std::fclose(log);
    std::fprintf(stderr, "autopilot: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    if (log != nullptr) std::fclose(log);
    std::fprintf(stderr, "autopilot: error: %s\n", e.what());
    return 1;
  }
}
