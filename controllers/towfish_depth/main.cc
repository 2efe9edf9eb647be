// towfish_depth: holds a towed body at a commanded depth, or at a commanded altitude above
// the seabed, with its elevators (PID with anti-windup and rate limit,
// towfish_depth/depth_law.h; altitude: towfish_depth/seabed.h):
//   towfish_depth [--body towfish] (--depth D | --altitude A [--seabed-depth B |
//                 --seabed-profile s0:d0,s1:d1,...] | --hold) [--kp 0.15] [--ki 0.01]
//                 [--kd 0.5] [--max-elevator-deg 25] [--rate-deg 20] [--max-pitch-deg 30]
//                 [--elevator-sign -1] [--domain 0] [--namespace /towsim] [--timeout 30]
//                 [--security DIR/NAME] [--winch [--winch-gain 0.1] [--winch-deadband 0.5]
//                 [--winch-filter 10] [--winch-elevator-depth 25] [--winch-max-speed V]
//                 [--winch-max-acceleration A]]
//                 [--log FILE] [--cable NAME]
// Altitude mode: the commanded depth is z + range cos(roll) cos(pitch) - A, range the sim's own
// altimeter (<ns>/<body>/altitude, sensor_msgs/Range, docs/sensors.md: along the body's z axis,
// so its vertical part is the depth of the echo below the body) of the step answered; while it
// reports no seabed (+inf: none in the scene or out of range) the last target (at first the
// current depth) is held. Fallback for a scene without a seabed: --seabed-depth B or
// --seabed-profile give the seabed instead (no altimeter read): the commanded depth is
// seabed(s) - A, s the horizontal distance the body has run since the first step (flat at B, or
// piecewise linear through the profile).
// --elevator-sign 1 for a body that dives on positive elevator (-1: it rises, the towfish);
// --hold commands zero elevator (the uncontrolled reference).
// Winch mode (--winch; towfish_depth/winch_law.h): the commanded depth (or altitude) is held
// with the winch at the cable's start for the slow part (the depth error the elevators leave
// and their steady deflection) and the elevators for the fast part:
// each step also publishes a WinchCommand (SPEED) on <ns>/winch/command, within the winch's
// max_speed and max_acceleration (from the node's scene_info, or less with --winch-max-speed,
// --winch-max-acceleration); the node clamps the length to [min_length, max_length].
// --log writes "t z elevator target_depth" per step (winch mode: and the drum speed commanded;
// --cable NAME: and the cable's "t_c top end", common/client.h CableLogColumns). Needs CYCLONEDDS_URI. Exit 0 at the end of the node's run
// or on SIGINT/SIGTERM, 1 on an error or a timeout, 2 on a bad command line.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/client.h"
#include "common/flags.h"
#include "common/laws.h"
#include "towfish_depth/depth_law.h"
#include "towfish_depth/seabed.h"
#include "towfish_depth/winch_law.h"

using namespace towsim::controllers;

namespace {
constexpr char kUsage[] =
    "usage: towfish_depth [--body towfish] (--depth D | --altitude A [--seabed-depth B |\n"
    "                     --seabed-profile s0:d0,s1:d1,...] | --hold) [--kp 0.15] [--ki 0.01]\n"
    "                     [--kd 0.5] [--max-elevator-deg 25] [--rate-deg 20]\n"
    "                     [--max-pitch-deg 30] [--elevator-sign -1] [--domain 0]\n"
    "                     [--namespace /towsim] [--timeout 30] [--security DIR/NAME] [--log FILE]\n"
    "                     [--winch [--winch-gain 0.1] [--winch-deadband 0.5] [--winch-filter 10]\n"
    "                     [--winch-elevator-depth 25] [--winch-max-speed V]\n"
    "                     [--winch-max-acceleration A]] [--cable NAME]\n"
    "  --depth D          hold the depth D [m] below the surface\n"
    "  --altitude A       hold A [m] above the seabed, measured by the sim's own altimeter\n"
    "                     (<ns>/<body>/altitude, sensor_msgs/Range); while it sees no seabed\n"
    "                     the depth is held\n"
    "  --seabed-depth B   fallback for a scene without a seabed: a flat seabed at B [m]\n"
    "                     (the altimeter is not read)\n"
    "  --seabed-profile s0:d0,...  fallback for a scene without a seabed: piecewise-linear\n"
    "                     seabed depth d [m] against the distance run s [m]\n"
    "  --hold             zero elevator (the uncontrolled reference)\n"
    "  --winch            also drive the winch (<ns>/winch/command): the slow part of the\n"
    "                     depth change and the elevators' steady demand, within the winch's\n"
    "                     limits; --winch-gain K [1/s], --winch-elevator-depth G [m/rad],\n"
    "                     --winch-deadband D [m], --winch-filter T [s], --winch-max-speed V\n"
    "                     [m/s], --winch-max-acceleration A [m/s^2] (towfish_depth/winch_law.h)\n"
    "  --log FILE         writes \"t z elevator target_depth\" per step (--winch: and the\n"
    "                     drum speed; --cable: and \"t_c top end\")\n"
    "  --cable NAME       also read the state of cable NAME (<ns>/NAME/state; the one cable:\n"
    "                     cable, a network's by name) and log the newest sample's stamp t_c\n"
    "                     and its tension at node 0 and at the last node [N]; a name the\n"
    "                     node's scene has no cable of is refused, naming its cables (exit 1)\n"
    "Exit 0 at the end of the node's run or on SIGINT/SIGTERM, 1 error or timeout, 2 bad "
    "command line.\n";
}  // namespace

int main(int argc, char** argv) {
  ClientOptions opt;
  opt.name = "towfish_depth";
  DepthParams p;
  std::string log_path;
  bool altitude_mode = false;
  double altitude = 0.0;
  SeabedProfile seabed;
  WinchDepthParams winch;
  double winch_max_speed = 0.0, winch_max_acceleration = 0.0;  // <= 0: the winch's own
  try {
    const Flags f(argc, argv,
                  {"body", "depth", "kp", "ki", "kd", "max-elevator-deg", "rate-deg",
                   "max-pitch-deg", "elevator-sign", "domain", "namespace", "timeout", "log",
                   "altitude", "seabed-depth", "seabed-profile", "winch-gain", "winch-deadband",
                   "winch-filter", "winch-max-speed", "winch-max-acceleration", "winch-elevator-depth",
                   kSecurityFlag, "cable"},
                  {"hold", "winch"});
    if (f.Help()) {
      std::printf("%s", kUsage);
      return 0;
    }
    altitude_mode = f.Has("altitude");
    if (!f.Has("depth") && !f.Has("hold") && !altitude_mode) {
      throw std::runtime_error("--depth D (or --altitude A with a seabed, or --hold) is required");
    }
    if (altitude_mode && f.Has("depth")) {
      throw std::runtime_error("--depth and --altitude: give one of them");
    }
    if (altitude_mode) {
      altitude = f.Number("altitude", 0.0);
      if (!(altitude > 0.0)) {
        throw std::runtime_error("--altitude " + f.String("altitude", "") + ": must be > 0 [m]");
      }
      if (f.Has("seabed-depth") && f.Has("seabed-profile")) {
        throw std::runtime_error("--seabed-depth and --seabed-profile: give one of them");
      }
      opt.altitude = !f.Has("seabed-depth") && !f.Has("seabed-profile");  // the altimeter
      if (f.Has("seabed-depth")) {
        const double b = f.Number("seabed-depth", 0.0);
        if (!(b > altitude)) {
          throw std::runtime_error("--seabed-depth " + f.String("seabed-depth", "") +
                                   ": must be > --altitude (the target depth seabed - altitude "
                                   "must be below the surface)");
        }
        seabed = FlatSeabed(b);
      } else if (f.Has("seabed-profile")) {
        seabed = ParseSeabedProfile(f.String("seabed-profile", ""), "--seabed-profile");
        for (double d : seabed.depth) {
          if (!(d > altitude)) {
            throw std::runtime_error("--seabed-profile " + f.String("seabed-profile", "") +
                                     ": every depth must be > --altitude");
          }
        }
      }
    } else if (f.Has("seabed-depth") || f.Has("seabed-profile")) {
      throw std::runtime_error("--seabed-depth / --seabed-profile need --altitude A");
    }
    opt.body = f.String("body", "towfish");
    constexpr double kNoLimit = std::numeric_limits<double>::max();
    opt.domain = f.Domain();
    opt.ns = f.String("namespace", "/towsim");
    opt.timeout = f.Number("timeout", 30.0, 0.0, kNoLimit, /*lo_open=*/true);
    opt.security = f.String(kSecurityFlag, "");
    p.depth = f.Number("depth", 0.0, 0.0, kNoLimit);  // [m] below the surface (NED z)
    p.kp = f.Number("kp", p.kp, 0.0, kNoLimit);
    p.ki = f.Number("ki", p.ki, 0.0, kNoLimit);
    p.kd = f.Number("kd", p.kd, 0.0, kNoLimit);
    p.max_elevator =
        Rad(f.Number("max-elevator-deg", Deg(p.max_elevator), 0.0, 90.0, /*lo_open=*/true));
    p.rate_limit = Rad(f.Number("rate-deg", Deg(p.rate_limit), 0.0, kNoLimit, /*lo_open=*/true));
    p.sign = f.Number("elevator-sign", -1.0) >= 0.0 ? 1.0 : -1.0;
    p.max_pitch = Rad(f.Number("max-pitch-deg", Deg(p.max_pitch), 0.0, 90.0, /*lo_open=*/true));
    p.hold = f.Has("hold");
    log_path = f.String("log", "");
    opt.cable = f.Has("cable");  // docs/controllers.md "Cables"
    opt.cable_name = f.String("cable", opt.cable_name);
    opt.winch = f.Has("winch");
    for (const char* w : {"winch-gain", "winch-deadband", "winch-filter", "winch-max-speed",
                          "winch-max-acceleration", "winch-elevator-depth"}) {
      if (!opt.winch && f.Has(w)) throw std::runtime_error(std::string("--") + w + " needs --winch");
    }
    if (opt.winch && p.hold) throw std::runtime_error("--winch and --hold: give one of them");
    winch.gain = f.Number("winch-gain", winch.gain, 0.0, kNoLimit, /*lo_open=*/true);
    winch.deadband = f.Number("winch-deadband", winch.deadband, 0.0, kNoLimit);
    winch.filter = f.Number("winch-filter", winch.filter, 0.0, kNoLimit, /*lo_open=*/true);
    winch.elevator_depth = f.Number("winch-elevator-depth", winch.elevator_depth, 0.0, kNoLimit);
    winch_max_speed = f.Number("winch-max-speed", 0.0, 0.0, kNoLimit, /*lo_open=*/true);
    winch_max_acceleration =
        f.Number("winch-max-acceleration", 0.0, 0.0, kNoLimit, /*lo_open=*/true);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "towfish_depth: error: %s\n", e.what());
    return 2;
  }
  std::FILE* log = nullptr;
  try {
    RequireDdsUri();
    InstallStopHandlers();
    if (!log_path.empty()) {
      log = std::fopen(log_path.c_str(), "w");
      if (log == nullptr) throw std::runtime_error("cannot write " + log_path);
    }
    LockstepClient client(opt);
    if (opt.winch) {
      // within the winch's limits (SceneInfo), or the tighter ones asked for
      const WinchInfo& w = client.winch();
      winch.max_speed = winch_max_speed > 0.0 ? std::min(winch_max_speed, w.max_speed)
                                              : w.max_speed;
      winch.max_acceleration = winch_max_acceleration > 0.0
                                   ? std::min(winch_max_acceleration, w.max_acceleration)
                                   : w.max_acceleration;
    }
    WinchDepthState winch_state;
    PidState state;
    AlongTrack track;
    bool have_target = false, warned = false;
    const int rc = client.Run([&](const BodyState& b) {
      if (altitude_mode && opt.altitude) {
        if (std::isfinite(b.altitude)) {
          // the beam runs along the body's z axis: its echo comes from the depth z + r cos(roll)
          // cos(pitch) (docs/sensors.md); the seabed there, less the altitude
          p.depth = b.z + b.altitude * std::cos(b.roll) * std::cos(b.pitch) - altitude;
          have_target = true;
        } else {
          if (!have_target) p.depth = b.z;  // nothing measured yet: hold the depth
          have_target = true;
          if (!warned) {
            std::fprintf(stderr,
                         "towfish_depth: warning: t = %g s: the altimeter sees no seabed "
                         "(range %g); holding the depth %g m (a scene without a seabed needs "
                         "--seabed-depth B or --seabed-profile)\n",
                         b.t, b.altitude, p.depth);
            warned = true;
          }
        }
      } else if (altitude_mode) {
        p.depth = AltitudeTargetDepth(seabed, track.Update(b.x, b.y), altitude);
      }
      const double elevator = DepthStep(p, state, b.z, b.z_dot, b.pitch, b.dt);
      Actuation a{0.0, 0.0, elevator};
      if (opt.winch) {
        // the elevators' "deeper" demand: sign * elevator (towfish_depth/depth_law.h)
        const double deeper = p.sign >= 0.0 ? elevator : -elevator;
        a.winch.value = WinchDepthStep(winch, winch_state, p.depth, b.z, deeper, b.dt);
      }
      if (log != nullptr) {
        std::fprintf(log, "%.6f %.6f %.6f %.6f", b.t, b.z, elevator, p.depth);
        if (opt.winch) std::fprintf(log, " %.6f", a.winch.value);
        if (opt.cable) std::fputs(CableLogColumns(b.cable).c_str(), log);
        std::fputc('\n', log);
      }
      return a;
    });
    if (log != nullptr) std::fclose(log);
    std::printf("towfish_depth: %llu steps answered\n",
                static_cast<unsigned long long>(client.steps_answered()));
    return rc;
  } catch (const SecurityError& e) {
    if (log != nullptr) std::fclose(log);
    std::fprintf(stderr, "towfish_depth: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    if (log != nullptr) std::fclose(log);
    std::fprintf(stderr, "towfish_depth: error: %s\n", e.what());
    return 1;
  }
}
