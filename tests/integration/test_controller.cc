// test_controller: a lockstep controller for the integration tests. It uses msgs/ (the
// generated C types and the Cyclone C API) and the wire library (wire/: topic names, QoS,
// Security, decoders), as an external controller that links towsim::wire would.
//
//   test_controller --domain N [--namespace /towsim] [--until-step K] [--log FILE]
//                   [--command BODY@T=THRUST,RUDDER,ELEVATOR ...] [--timeout S] [--stats]
//                   [--security DIR/NAME] [--body NAME ...]
//                   [--winch [W@]T=speed:V | [W@]T=length:L | [W@]T=mode:M:V ...]
//                   [--winch-until T] [--pause STEP=S]
//
// It learns the bodies from rt/<ns>/scene_info, then answers every SimStatus of a new step k
// with one ActuatorCommand stamped k per commanded body: zeros, or the latest --command of
// that body whose time T has come (t >= T, the script's rule); with --body (repeatable) only
// the bodies named (and their odometry only), so that several controller processes share a
// run. With --log it writes, for every step answered, one line per body of the odometry of
// that step (matched by stamp):
//   step body x y z qx qy qz qw u v w p q r      (%.17g: the doubles exactly)
// It exits 0 once the node reports step K (--until-step) or the end of its run, 1 when
// nothing has happened for --timeout seconds (default 30) or on a DDS error. A scene with
// winches (SceneInfo.winches; has_winch alone: the one winch `winch`): every step answered
// also gets one WinchCommand stamped k per winch on rt/<ns>/<winch>/command, speed 0 or the
// latest --winch of that winch (W@: the winch named W, else the first) whose time has come
// (mode:M:V sends the
// raw mode number M, and V may be nan or inf, for the tests of rejected commands), until the
// simulation time --winch-until (then the winch is no longer answered). Needs
// CYCLONEDDS_URI (the loopback configuration). --security: DDS Security with the identity
// DIR/NAME (wire/security.h, exit 2 if refused). --pause STEP=S: before answering step STEP,
// sleep S wall seconds (a slow controller, for the tests of --lockstep-timeout). --stats
// prints the lockstep rate on stdout, the mean and the median wall time between consecutive
// answers:
//   test_controller: 1999 steps in 0.701 s: 2852 steps/s, 350.6 us/step (median 301.2 us)

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "dds/dds.h"
#include "nav_msgs.h"
#include "towsim_msgs.h"
#include "wire/decoders.h"
#include "wire/qos.h"
#include "wire/security.h"
#include "wire/topic_names.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace wire = towsim::wire;

struct ScheduledCommand {
  std::string body;
  double at = 0.0;  // [s]
  double thrust = 0.0, rudder = 0.0, elevator = 0.0;
  bool fired = false;
};

struct ScheduledWinch {
  std::string winch;  // W@ (empty: the scene's first winch)
  double at = 0.0;    // [s]
  uint8_t mode = 0;
  double value = 0.0;
  bool fired = false;
};

struct Args {
  uint32_t domain = 0;
  std::string ns = "/towsim";
  long long until_step = -1;
  std::string log;
  std::vector<ScheduledCommand> commands;
  double timeout = 30.0;
  bool stats = false;
  std::string security;
  std::vector<std::string> only;  // --body: the commanded bodies answered; empty: all
  std::vector<ScheduledWinch> winch;
  double winch_until = HUGE_VAL;  // [s]
  long long pause_step = -1;      // --pause: the step answered late
  double pause = 0.0;             // [s]
};

[[noreturn]] void Fail(const std::string& message) {
  std::fprintf(stderr, "test_controller: error: %s\n", message.c_str());
  std::exit(1);
}

dds_entity_t Check(dds_entity_t e, const std::string& what) {
  if (e < 0) Fail(what + ": " + dds_strretcode(e));
  return e;
}

// the topic `topic` of `owner` (wire/topic_names.h)
dds_entity_t CreateTopic(dds_entity_t participant, const wire::TopicNames& names, wire::Topic topic,
                         const std::string& owner = "") {
  const std::string name = names.Name(topic, owner);
  return Check(
      dds_create_topic(participant, wire::SpecOf(topic).type, name.c_str(), nullptr, nullptr),
      name + " topic");
}

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

Args Parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) Fail(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--domain") {
      a.domain = static_cast<uint32_t>(std::strtoul(value().c_str(), nullptr, 10));
    } else if (arg == "--namespace") {
      a.ns = value();
    } else if (arg == "--until-step") {
      a.until_step = std::strtoll(value().c_str(), nullptr, 10);
    } else if (arg == "--log") {
      a.log = value();
    } else if (arg == "--security") {
      a.security = value();
    } else if (arg == "--body") {
      a.only.push_back(value());
    } else if (arg == "--stats") {
      a.stats = true;
    } else if (arg == "--timeout") {
      a.timeout = std::strtod(value().c_str(), nullptr);
    } else if (arg == "--winch") {
      // [W@]T=speed:V, [W@]T=length:L or [W@]T=mode:M:V
      std::string v = value();
      ScheduledWinch w;
      if (const auto at = v.find('@'); at != std::string::npos) {
        w.winch = v.substr(0, at);
        v = v.substr(at + 1);
      }
      const auto eq = v.find('=');
      const std::string usage = "--winch " + v + ": must be T=speed:V, T=length:L or T=mode:M:V";
      if (eq == std::string::npos) Fail(usage);
      w.at = std::strtod(v.substr(0, eq).c_str(), nullptr);
      const std::string rest = v.substr(eq + 1);
      if (rest.rfind("speed:", 0) == 0) {
        w.mode = towsim_msgs_msg_dds__WinchCommand_Constants_SPEED;
        w.value = std::strtod(rest.c_str() + 6, nullptr);
      } else if (rest.rfind("length:", 0) == 0) {
        w.mode = towsim_msgs_msg_dds__WinchCommand_Constants_LENGTH;
        w.value = std::strtod(rest.c_str() + 7, nullptr);
      } else if (rest.rfind("mode:", 0) == 0) {
        char* end = nullptr;
        w.mode = static_cast<uint8_t>(std::strtoul(rest.c_str() + 5, &end, 10));
        if (end == nullptr || *end != ':') Fail(usage);
        w.value = std::strtod(end + 1, nullptr);
      } else {
        Fail(usage);
      }
      a.winch.push_back(w);
    } else if (arg == "--pause") {
      const std::string v = value();
      const auto eq = v.find('=');
      if (eq == std::string::npos) Fail("--pause " + v + ": must be STEP=SECONDS");
      a.pause_step = std::strtoll(v.substr(0, eq).c_str(), nullptr, 10);
      a.pause = std::strtod(v.c_str() + eq + 1, nullptr);
    } else if (arg == "--winch-until") {
      a.winch_until = std::strtod(value().c_str(), nullptr);
    } else if (arg == "--command") {
      // BODY@T=THRUST,RUDDER,ELEVATOR
      const std::string v = value();
      ScheduledCommand c;
      const auto at = v.find('@'), eq = v.find('=');
      if (at == std::string::npos || eq == std::string::npos || eq < at) {
        Fail("--command " + v + ": must be BODY@T=THRUST,RUDDER,ELEVATOR");
      }
      c.body = v.substr(0, at);
      c.at = std::strtod(v.substr(at + 1, eq - at - 1).c_str(), nullptr);
      if (std::sscanf(v.c_str() + eq + 1, "%lf,%lf,%lf", &c.thrust, &c.rudder, &c.elevator) != 3) {
        Fail("--command " + v + ": must be BODY@T=THRUST,RUDDER,ELEVATOR");
      }
      a.commands.push_back(c);
    } else {
      Fail("unknown option " + arg);
    }
  }
  return a;
}

struct Body {
  std::string name;
  dds_entity_t odom_reader = 0;
  dds_entity_t odom_waitset = 0;  // --log: the odometry of the step, when not there yet
  std::map<std::pair<int32_t, uint32_t>, wire::Odometry> odoms;  // by stamp
};

}  // namespace

int main(int argc, char** argv) {
  const Args args = Parse(argc, argv);
  const char* uri = std::getenv("CYCLONEDDS_URI");
  if (uri == nullptr || *uri == '\0') Fail("CYCLONEDDS_URI is not set (use config/cyclonedds.xml)");
  const wire::TopicNames names(args.ns);

  dds_entity_t participant = 0;
  try {
    participant = wire::CreateSecureParticipant(args.domain, args.security);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "test_controller: error: %s\n", e.what());
    return 2;
  }
  dds_qos_t* state_qos = wire::ProfileQos(wire::QosProfile::kState, 256);
  dds_qos_t* command_qos = wire::ProfileQos(wire::QosProfile::kCommand);
  dds_qos_t* scene_qos = wire::ProfileQos(wire::QosProfile::kLatched);

  // what the node simulates
  const dds_entity_t scene_topic = CreateTopic(participant, names, wire::Topic::kSceneInfo);
  const dds_entity_t scene_reader =
      Check(dds_create_reader(participant, scene_topic, scene_qos, nullptr), "scene_info reader");
  const dds_entity_t status_topic = CreateTopic(participant, names, wire::Topic::kStatus);
  const dds_entity_t status_reader =
      Check(dds_create_reader(participant, status_topic, state_qos, nullptr), "status reader");

  std::vector<Body> bodies;
  std::vector<std::string> commanded;
  std::vector<std::string> winches;  // by name, SceneInfo order
  const Clock::time_point t_begin = Clock::now();
  while (bodies.empty()) {
    void* samples[1] = {nullptr};
    dds_sample_info_t info;
    const dds_return_t n = dds_take(scene_reader, samples, &info, 1, 1);
    if (n > 0 && info.valid_data) {
      const wire::SceneInfo s =
          wire::DecodeSceneInfo(*static_cast<const towsim_msgs_msg_dds__SceneInfo_*>(samples[0]));
      for (const std::string& name : s.bodies) {
        Body b;
        b.name = name;
        // --body: the odometry of those bodies only
        if (args.only.empty() ||
            std::find(args.only.begin(), args.only.end(), b.name) != args.only.end()) {
          bodies.push_back(b);
        }
      }
      for (const std::string& name : s.commanded_bodies) {
        if (args.only.empty() ||
            std::find(args.only.begin(), args.only.end(), name) != args.only.end()) {
          commanded.push_back(name);
        }
      }
      for (const std::string& name : args.only) {
        if (std::find(commanded.begin(), commanded.end(), name) == commanded.end()) {
          Fail("--body " + name + ": not a commanded body of the node's scene");
        }
      }
      winches = s.winches;
      if (s.has_winch && winches.empty()) winches.push_back(wire::kOneWinch);  // an older node
    }
    if (n > 0) dds_return_loan(scene_reader, samples, n);
    if (bodies.empty()) {
      if (Seconds(Clock::now() - t_begin) > args.timeout) Fail("no scene_info from the node");
      dds_sleepfor(DDS_MSECS(10));
    }
  }

  // odometry of every body, a command writer per commanded body
  for (Body& b : bodies) {
    const dds_entity_t t = CreateTopic(participant, names, wire::Topic::kOdom, b.name);
    b.odom_reader = Check(dds_create_reader(participant, t, state_qos, nullptr), "odom reader");
    if (!args.log.empty()) {  // only --log waits for the odometry (a condition costs per sample)
      b.odom_waitset = Check(dds_create_waitset(participant), "waitset");
      Check(dds_waitset_attach(
                b.odom_waitset,
                Check(dds_create_readcondition(b.odom_reader, DDS_ANY_STATE), "read condition"), 0),
            "waitset attach");
    }
  }
  std::vector<dds_entity_t> writers;
  for (const std::string& name : commanded) {
    const dds_entity_t t = CreateTopic(participant, names, wire::Topic::kCommand, name);
    writers.push_back(
        Check(dds_create_writer(participant, t, command_qos, nullptr), "command writer"));
  }
  std::vector<dds_entity_t> winch_writers;  // one per winch
  for (const std::string& name : winches) {
    const dds_entity_t t = CreateTopic(participant, names, wire::Topic::kWinchCommand, name);
    winch_writers.push_back(
        Check(dds_create_writer(participant, t, command_qos, nullptr), "winch writer"));
  }
  for (const ScheduledWinch& c : args.winch) {
    if (!c.winch.empty() && std::find(winches.begin(), winches.end(), c.winch) == winches.end())
      Fail("--winch " + c.winch + "@...: not a winch of the node's scene");
  }
  // the node must hear the first command: wait until every writer and reader matched
  for (;;) {
    bool all = true;
    std::vector<dds_entity_t> all_writers = writers;
    all_writers.insert(all_writers.end(), winch_writers.begin(), winch_writers.end());
    for (dds_entity_t w : all_writers) {
      dds_publication_matched_status_t m;
      dds_get_publication_matched_status(w, &m);
      all = all && m.current_count > 0;
    }
    for (const Body& b : bodies) {
      dds_subscription_matched_status_t m;
      dds_get_subscription_matched_status(b.odom_reader, &m);
      all = all && m.current_count > 0;
    }
    if (all) break;
    if (Seconds(Clock::now() - t_begin) > args.timeout) Fail("the node's endpoints did not match");
    dds_sleepfor(DDS_MSECS(5));
  }

  std::FILE* log = nullptr;
  if (!args.log.empty()) {
    log = std::fopen(args.log.c_str(), "w");
    if (log == nullptr) Fail("cannot write " + args.log + ": " + std::strerror(errno));
  }

  const dds_entity_t waitset = dds_create_waitset(participant);
  const dds_entity_t status_cond = dds_create_readcondition(status_reader, DDS_ANY_STATE);
  dds_waitset_attach(waitset, status_cond, 0);

  std::vector<ScheduledCommand> schedule = args.commands;
  std::map<std::string, towsim_msgs_msg_dds__ActuatorCommand_> held;
  for (const std::string& name : commanded) held[name] = towsim_msgs_msg_dds__ActuatorCommand_{};
  std::vector<ScheduledWinch> winch_schedule = args.winch;
  // per winch, speed 0 until its schedule says otherwise
  std::vector<towsim_msgs_msg_dds__WinchCommand_> winch_held(winches.size(),
                                                              towsim_msgs_msg_dds__WinchCommand_{});

  std::string run_id;
  unsigned long long answered = ~0ULL;
  Clock::time_point last_progress = Clock::now();
  Clock::time_point first_answer;
  long answers = 0;
  std::vector<double> intervals;  // --stats: between consecutive answers [us]
  if (args.stats) intervals.reserve(1 << 16);
  int exit_code = -1;
  while (exit_code < 0) {
    dds_waitset_wait(waitset, nullptr, 0, DDS_MSECS(100));
    void* samples[16] = {};
    dds_sample_info_t infos[16];
    const dds_return_t n = dds_take(status_reader, samples, infos, 16, 16);
    for (int i = 0; i < n && exit_code < 0; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* raw = static_cast<const towsim_msgs_msg_dds__SimStatus_*>(samples[i]);
      const wire::SimStatus s = wire::DecodeStatus(*raw);
      const bool terminal = s.terminal();
      const bool fresh = run_id != s.run_id || answered != s.step;
      if (!fresh) {
        if (terminal) exit_code = 0;  // the last status of a step already answered
        continue;
      }
      run_id = s.run_id;
      answered = s.step;
      const Clock::time_point previous = last_progress;
      last_progress = Clock::now();
      if (answers++ == 0) first_answer = last_progress;
      if (args.stats && answers > 1) intervals.push_back(1e6 * Seconds(last_progress - previous));

      // the odometry of this step, matched by stamp
      if (log != nullptr) {
        for (Body& b : bodies) {
          const Clock::time_point wait_begin = Clock::now();
          const std::pair<int32_t, uint32_t> key{raw->header.stamp.sec, raw->header.stamp.nanosec};
          for (;;) {
            void* os[32] = {};
            dds_sample_info_t oi[32];
            const dds_return_t k = dds_take(b.odom_reader, os, oi, 32, 32);
            for (int j = 0; j < k; ++j) {
              if (!oi[j].valid_data) continue;
              const auto* o = static_cast<const nav_msgs_msg_dds__Odometry_*>(os[j]);
              b.odoms[{o->header.stamp.sec, o->header.stamp.nanosec}] = wire::DecodeOdometry(*o);
            }
            if (k > 0) dds_return_loan(b.odom_reader, os, k);
            if (b.odoms.count(key) > 0) break;
            if (Seconds(Clock::now() - wait_begin) > 2.0) {
              Fail("no odometry of " + b.name + " for step " + std::to_string(s.step));
            }
            dds_waitset_wait(b.odom_waitset, nullptr, 0, DDS_MSECS(100));  // no polling
          }
          const wire::Odometry& o = b.odoms[key];
          std::fprintf(log,
                       "%llu %s %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
                       "%.17g %.17g %.17g\n",
                       static_cast<unsigned long long>(s.step), b.name.c_str(), o.x, o.y, o.z, o.qx,
                       o.qy, o.qz, o.qw, o.u, o.v, o.w, o.p, o.q, o.r);
          // older stamps are done with
          b.odoms.erase(b.odoms.begin(), b.odoms.find(key));
        }
      }
      if (terminal || (args.until_step >= 0 && static_cast<long long>(s.step) >= args.until_step)) {
        exit_code = 0;
        break;
      }
      if (static_cast<long long>(s.step) == args.pause_step) {
        std::fprintf(stderr, "test_controller: pausing %g s before answering step %llu\n",
                     args.pause, static_cast<unsigned long long>(s.step));
        dds_sleepfor(static_cast<dds_duration_t>(args.pause * 1e9));
        last_progress = Clock::now();
      }
      // the script's rule: entries whose time has come fire, in order
      for (ScheduledCommand& c : schedule) {
        if (c.fired || s.t < c.at - 1e-9) continue;
        c.fired = true;
        if (held.count(c.body) == 0) Fail("--command for " + c.body + ": not a commanded body");
        held[c.body].thrust = c.thrust;
        held[c.body].rudder = c.rudder;
        held[c.body].elevator = c.elevator;
      }
      for (size_t w = 0; w < writers.size(); ++w) {
        towsim_msgs_msg_dds__ActuatorCommand_ cmd = held[commanded[w]];
        cmd.header.stamp = raw->header.stamp;
        cmd.header.frame_id = const_cast<char*>(commanded[w].c_str());
        cmd.step = s.step;
        const dds_return_t rc = dds_write(writers[w], &cmd);
        if (rc < 0) Fail(std::string("writing a command: ") + dds_strretcode(rc));
      }
      for (ScheduledWinch& c : winch_schedule) {
        if (c.fired || s.t < c.at - 1e-9 || winches.empty()) continue;
        c.fired = true;
        const size_t w = c.winch.empty() ? 0
                                         : std::find(winches.begin(), winches.end(), c.winch) -
                                               winches.begin();
        winch_held[w].mode = c.mode;
        winch_held[w].value = c.value;
      }
      if (!winch_writers.empty() && s.t < args.winch_until - 1e-9) {
        for (size_t w = 0; w < winch_writers.size(); ++w) {
          towsim_msgs_msg_dds__WinchCommand_ cmd = winch_held[w];
          cmd.header.stamp = raw->header.stamp;
          cmd.header.frame_id = const_cast<char*>("");
          cmd.step = s.step;
          const dds_return_t rc = dds_write(winch_writers[w], &cmd);
          if (rc < 0) Fail(std::string("writing a winch command: ") + dds_strretcode(rc));
        }
      } else if (winch_writers.empty() && !winch_schedule.empty()) {
        Fail("--winch: the node's scene has no winch");
      }
    }
    if (n > 0) dds_return_loan(status_reader, samples, n);
    if (exit_code < 0 && Seconds(Clock::now() - last_progress) > args.timeout) {
      Fail("no new status from the node for " + std::to_string(args.timeout) + " s");
    }
  }
  if (log != nullptr) std::fclose(log);
  if (args.stats && answers > 1) {
    const double wall = Seconds(last_progress - first_answer);
    std::sort(intervals.begin(), intervals.end());
    std::printf(
        "test_controller: %ld steps in %.3f s: %.0f steps/s, %.1f us/step (median %.1f us)\n",
        answers - 1, wall, (answers - 1) / wall, 1e6 * wall / (answers - 1),
        intervals[(intervals.size() - 1) / 2]);
  }
  dds_delete_qos(state_qos);
  dds_delete_qos(command_qos);
  dds_delete_qos(scene_qos);
  dds_delete(participant);
  return exit_code;
}
