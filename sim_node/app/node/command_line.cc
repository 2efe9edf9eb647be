#include "app/node/command_line.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "dds/pacing_rate.h"

namespace towsim::app {
namespace {

// a finite number that uses the whole string
bool ParseNumber(const std::string& text, double* value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (errno != 0 || end != text.c_str() + text.size() || !std::isfinite(x)) return false;
  *value = x;
  return true;
}

bool ParseMode(const std::string& text, Mode* mode) {
  for (Mode m : {Mode::kRealtime, Mode::kFast, Mode::kLockstep, Mode::kOffline}) {
    if (text == ModeName(m)) {
      *mode = m;
      return true;
    }
  }
  return false;
}

}  // namespace

const char* ModeName(Mode mode) {
  switch (mode) {
    case Mode::kRealtime:
      return "realtime";
    case Mode::kFast:
      return "fast";
    case Mode::kLockstep:
      return "lockstep";
    case Mode::kOffline:
      return "offline";
  }
  return "?";
}

std::string Usage() {
  return "usage: sim_node --scene FILE [options]\n"
         "\n"
         "Simulates the towed system of a scene file.\n"
         "\n"
         "options:\n"
         "  --scene FILE          scene YAML file (required); a bare name (case1_forward)\n"
         "                        also finds the scenes of an installed towsim\n"
         "                        (<prefix>/share/towsim/scenes)\n"
         "  --mode MODE           realtime (default), fast, lockstep (DDS, paced / free /\n"
         "                        in step with the controllers) or offline (no DDS)\n"
         "  --domain N            DDS domain id (default 0)\n"
         "  --namespace NS        ROS 2 namespace of the topics (default /towsim)\n"
         "  --duration S          simulated time [s] (default offline: the scene's\n"
         "                        time.duration; DDS modes: until stopped)\n"
         "  --rate R              wall-clock pacing factor in realtime mode (default 1)\n"
         "  --set KEY.PATH=VALUE  override a scalar scene key, e.g. --set cable.elements=40\n"
         "                        (repeatable)\n"
         "  --csv DIR             write bodies.csv, cable.csv, forces.csv, status.csv to DIR\n"
         "                        at the scene's time.output_rate (and winch.csv,\n"
         "                        environment.csv, actuators.csv when the scene has them)\n"
         "  --record FILE.mcap    DDS modes: record every message published to MCAP (ros2);\n"
         "                        an existing file is refused unless --overwrite\n"
         "  --foxglove PORT       DDS modes: serve every topic to Foxglove on\n"
         "                        ws://127.0.0.1:PORT (0: a free port, printed)\n"
         "  --overwrite           --record may replace an existing file\n"
         "  --record-wall-time    --record stamps log time by the wall clock (the old\n"
         "                        behaviour), not by the simulation time\n"
         "  --allow-another-node  DDS modes: run although another node publishes in the\n"
         "                        same domain and namespace (else exit 2; status warns)\n"
         "  --paused              DDS modes: start paused; SimControl RESUME or STEP starts\n"
         "  --wait-for-controllers\n"
         "                        DDS modes: the first step waits until every vehicle that\n"
         "                        takes commands (and the winch, where lockstep waits for\n"
         "                        it) has received one (status: waiting)\n"
         "  --winch dds|script    DDS modes, a scene with cable.winch: commanded over DDS\n"
         "                        (default), or following the scene's script, neither\n"
         "                        waited for nor failsafed (docs/winch_dds.md)\n"
         "  --security DIR/NAME   DDS modes: DDS Security with the identity DIR/NAME made by\n"
         "                        scripts/security.sh (docs/security.md)\n"
         "  --lockstep-timeout S  lockstep: wall seconds a step waits for its commands before\n"
         "                        the body goes to failsafe (default 1; 0: wait forever)\n"
         "  --fail-on-failsafe    end with exit code 5 once a body enters failsafe or a\n"
         "                        lockstep step times out (after that step; outputs complete,\n"
         "                        status FAILED with the body, step and reason)\n"
         "  -h, --help            print this help and exit\n"
         "  --version             print the version and exit\n"
         "\n"
         "exit codes: 0 ok, 1 unexpected error (e.g. disk full), 2 bad input,\n"
         "            3 solver failure, 5 failsafe or lockstep timeout (--fail-on-failsafe);\n"
         "            offline: 130 / 143 stopped by SIGINT / SIGTERM, DDS modes: 0 when\n"
         "            stopped by a signal\n";
}

ParseResult ParseCommandLine(int argc, const char* const* argv) {
  ParseResult result;
  Options& o = result.options;
  auto fail = [&result](const std::string& message) {
    result.error = message;
    return result;
  };

  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      o.help = true;
      continue;
    }
    if (arg == "--version") {
      o.version = true;
      continue;
    }
    if (arg == "--paused") {
      o.paused = true;
      continue;
    }
    if (arg == "--wait-for-controllers") {
      o.wait_for_controllers = true;
      continue;
    }
    if (arg == "--overwrite") {
      o.overwrite = true;
      continue;
    }
    if (arg == "--allow-another-node") {
      o.allow_another_node = true;
      continue;
    }
    if (arg == "--record-wall-time") {
      o.record_wall_time = true;
      continue;
    }
    if (arg == "--fail-on-failsafe") {
      o.fail_on_failsafe = true;
      continue;
    }
    static const char* const kWithValue[] = {
        "--scene",    "--mode",   "--duration",        "--rate",      "--set",
        "--csv",      "--record", "--domain",          "--namespace", "--security",
        "--foxglove", "--winch",  "--lockstep-timeout"};
    // split --name=value
    std::string name = arg;
    std::optional<std::string> value;
    if (const auto eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
    }
    bool known = false;
    for (const char* option : kWithValue) known = known || name == option;
    if (!known) {
      if (arg.rfind("-", 0) == 0) return fail("unknown option '" + arg + "'");
      return fail("unexpected argument '" + arg + "'");
    }
    if (!value) {
      if (i + 1 >= argc) return fail("option " + name + " needs a value");
      value = argv[++i];
    }
    const std::string& v = *value;

    if (name == "--scene") {
      if (v.empty()) return fail("--scene needs a file name");
      o.scene = v;
    } else if (name == "--mode") {
      if (!ParseMode(v, &o.mode)) {
        return fail("--mode " + v + ": must be one of realtime, fast, lockstep, offline");
      }
    } else if (name == "--duration") {
      double s = 0.0;
      if (!ParseNumber(v, &s) || s < 0.0) {
        return fail("--duration " + v + ": must be a number of seconds >= 0");
      }
      o.duration = s;
    } else if (name == "--rate") {
      double r = 0.0;
      if (!ParseNumber(v, &r)) return fail("--rate " + v + ": must be a number");
      if (const std::string e = dds::CheckRate(r); !e.empty())
        return fail("--rate " + v + ": " + e);
      o.rate = r;
    } else if (name == "--set") {
      const auto eq = v.find('=');
      if (eq == std::string::npos || eq == 0) {
        return fail("--set " + v + ": must have the form key.path=value");
      }
      o.overrides.push_back(v);
    } else if (name == "--csv") {
      if (v.empty()) return fail("--csv needs a directory");
      o.csv_dir = v;
    } else if (name == "--record") {
      if (v.empty()) return fail("--record needs a file name");
      o.record_file = v;
    } else if (name == "--domain") {
      // Cyclone itself rejects ids beyond its range (exit 2 with its message)
      double d = 0.0;
      if (!ParseNumber(v, &d) || d < 0.0 || d != static_cast<double>(static_cast<long>(d)) ||
          d > 4294967294.0) {
        return fail("--domain " + v + ": must be an integer >= 0");
      }
      o.domain = static_cast<uint32_t>(d);
    } else if (name == "--security") {
      if (v.empty()) return fail("--security needs DIR/NAME");
      o.security = v;
    } else if (name == "--namespace") {
      if (v.empty() || v[0] != '/') return fail("--namespace " + v + ": must start with '/'");
      o.ns = v;
    } else if (name == "--foxglove") {
      double port = 0.0;
      if (!ParseNumber(v, &port) || port < 0.0 || port > 65535.0 ||
          port != static_cast<double>(static_cast<long>(port))) {
        return fail("--foxglove " + v + ": must be a port number from 0 to 65535");
      }
      o.foxglove_port = static_cast<int>(port);
    } else if (name == "--winch") {
      if (v != "dds" && v != "script") return fail("--winch " + v + ": must be dds or script");
      o.winch = v;
    } else if (name == "--lockstep-timeout") {
      double s = 0.0;
      if (!ParseNumber(v, &s) || s < 0.0) {
        return fail("--lockstep-timeout " + v +
                    ": must be a number of seconds >= 0 (0: wait forever)");
      }
      o.lockstep_timeout = s;
    }
  }
  if (!o.help && !o.version && o.scene.empty()) return fail("missing --scene FILE");
  if (o.mode == Mode::kOffline && o.foxglove_port) {
    return fail(
        "--foxglove: needs a DDS mode (realtime, fast or lockstep); offline publishes "
        "nothing");
  }
  if (o.mode == Mode::kOffline && !o.security.empty()) {
    return fail("--security " + o.security + ": needs a DDS mode (realtime, fast or lockstep)");
  }
  if (o.mode == Mode::kOffline && o.winch == "dds") {
    return fail(
        "--winch dds: needs a DDS mode (realtime, fast or lockstep); offline the winch "
        "follows the scene's script");
  }
  if (o.mode == Mode::kOffline && (o.paused || o.wait_for_controllers)) {
    return fail(std::string(o.paused ? "--paused" : "--wait-for-controllers") +
                ": needs a DDS mode (realtime, fast or lockstep); offline takes no commands");
  }
  if (o.record_wall_time && o.record_file.empty()) {
    return fail("--record-wall-time: needs --record FILE.mcap");
  }
  if (o.lockstep_timeout && o.mode != Mode::kLockstep) {
    return fail("--lockstep-timeout: needs --mode lockstep (the mode is " +
                std::string(ModeName(o.mode)) + ")");
  }
  return result;
}

}  // namespace towsim::app
