// test_controller: a lockstep controller for the integration tests. It uses msgs/ only (the
// generated C types and the Cyclone C API), as any external controller would.
//
//   test_controller --domain N [--namespace /towsim] [--until-step K] [--log FILE]
//                   [--command BODY@T=THRUST,RUDDER,ELEVATOR ...] [--timeout S] [--stats]
//                   [--security DIR/NAME]
//
// It learns the bodies from rt/<ns>/scene_info, then answers every SimStatus of a new step k
// with one ActuatorCommand stamped k per commanded body: zeros, or the latest --command of
// that body whose time T has come (t >= T, the script's rule). With --log it writes, for every
// step answered, one line per body of the odometry of that step (matched by stamp):
//   step body x y z qx qy qz qw u v w p q r      (%.17g: the doubles exactly)
// It exits 0 once the node reports step K (--until-step) or the end of its run, 1 when
// nothing has happened for --timeout seconds (default 30) or on a DDS error. Needs
// CYCLONEDDS_URI (the loopback configuration). --security: DDS Security with the identity
// DIR/NAME (dds/security.h, exit 2 if refused). --stats prints the lockstep rate on stdout:
//   test_controller: 1999 steps in 0.701 s: 2852 steps/s, 350.6 us/step

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "common/dds_qos.h"
#include "dds/dds.h"
#include "dds/security.h"
#include "nav_msgs.h"
#include "towsim_msgs.h"

namespace {

using Clock = std::chrono::steady_clock;

struct ScheduledCommand {
  std::string body;
  double at = 0.0;  // [s]
  double thrust = 0.0, rudder = 0.0, elevator = 0.0;
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
};

[[noreturn]] void Fail(const std::string& message) {
  std::fprintf(stderr, "test_controller: error: %s\n", message.c_str());
  std::exit(1);
}

dds_entity_t Check(dds_entity_t e, const std::string& what) {
  if (e < 0) Fail(what + ": " + dds_strretcode(e));
  return e;
}

std::string Prefix(const std::string& ns) { return ns == "/" ? "rt/" : "rt" + ns + "/"; }

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
    } else if (arg == "--stats") {
      a.stats = true;
    } else if (arg == "--timeout") {
      a.timeout = std::strtod(value().c_str(), nullptr);
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
  std::map<std::pair<int32_t, uint32_t>, nav_msgs_msg_dds__Odometry_> odoms;  // by stamp
};

}  // namespace

int main(int argc, char** argv) {
  const Args args = Parse(argc, argv);
  const char* uri = std::getenv("CYCLONEDDS_URI");
  if (uri == nullptr || *uri == '\0') Fail("CYCLONEDDS_URI is not set (use config/cyclonedds.xml)");
  const std::string prefix = Prefix(args.ns);

  dds_entity_t participant = 0;
  try {
    participant = towsim::dds::CreateSecureParticipant(args.domain, args.security);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "test_controller: error: %s\n", e.what());
    return 2;
  }
  using towsim::controllers::ReliableQos;
  dds_qos_t* state_qos = ReliableQos(256, false);
  dds_qos_t* command_qos = ReliableQos(towsim::controllers::kCommandDepth, false);
  dds_qos_t* scene_qos = ReliableQos(1, true);

  // what the node simulates
  const dds_entity_t scene_topic =
      Check(dds_create_topic(participant, &towsim_msgs_msg_dds__SceneInfo__desc,
                             (prefix + "scene_info").c_str(), nullptr, nullptr),
            "scene_info topic");
  const dds_entity_t scene_reader =
      Check(dds_create_reader(participant, scene_topic, scene_qos, nullptr), "scene_info reader");
  const dds_entity_t status_topic =
      Check(dds_create_topic(participant, &towsim_msgs_msg_dds__SimStatus__desc,
                             (prefix + "status").c_str(), nullptr, nullptr),
            "status topic");
  const dds_entity_t status_reader =
      Check(dds_create_reader(participant, status_topic, state_qos, nullptr), "status reader");

  std::vector<Body> bodies;
  std::vector<std::string> commanded;
  const Clock::time_point t_begin = Clock::now();
  while (bodies.empty()) {
    void* samples[1] = {nullptr};
    dds_sample_info_t info;
    const dds_return_t n = dds_take(scene_reader, samples, &info, 1, 1);
    if (n > 0 && info.valid_data) {
      const auto* s = static_cast<const towsim_msgs_msg_dds__SceneInfo_*>(samples[0]);
      for (uint32_t i = 0; i < s->bodies._length; ++i) {
        Body b;
        b.name = s->bodies._buffer[i];
        bodies.push_back(b);
      }
      for (uint32_t i = 0; i < s->commanded_bodies._length; ++i) {
        commanded.push_back(s->commanded_bodies._buffer[i]);
      }
    }
    if (n > 0) dds_return_loan(scene_reader, samples, n);
    if (bodies.empty()) {
      if (Seconds(Clock::now() - t_begin) > args.timeout) Fail("no scene_info from the node");
      dds_sleepfor(DDS_MSECS(10));
    }
  }

  // odometry of every body, a command writer per commanded body
  for (Body& b : bodies) {
    const dds_entity_t t =
        Check(dds_create_topic(participant, &nav_msgs_msg_dds__Odometry__desc,
                               (prefix + b.name + "/odom").c_str(), nullptr, nullptr),
              "odom topic");
    b.odom_reader = Check(dds_create_reader(participant, t, state_qos, nullptr), "odom reader");
  }
  std::vector<dds_entity_t> writers;
  for (const std::string& name : commanded) {
    const dds_entity_t t =
        Check(dds_create_topic(participant, &towsim_msgs_msg_dds__ActuatorCommand__desc,
                               (prefix + name + "/command").c_str(), nullptr, nullptr),
              "command topic");
    writers.push_back(
        Check(dds_create_writer(participant, t, command_qos, nullptr), "command writer"));
  }
  // the node must hear the first command: wait until every writer and reader matched
  for (;;) {
    bool all = true;
    for (dds_entity_t w : writers) {
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

  std::string run_id;
  unsigned long long answered = ~0ULL;
  Clock::time_point last_progress = Clock::now();
  Clock::time_point first_answer;
  long answers = 0;
  int exit_code = -1;
  while (exit_code < 0) {
    dds_waitset_wait(waitset, nullptr, 0, DDS_MSECS(100));
    void* samples[16] = {};
    dds_sample_info_t infos[16];
    const dds_return_t n = dds_take(status_reader, samples, infos, 16, 16);
    for (int i = 0; i < n && exit_code < 0; ++i) {
      if (!infos[i].valid_data) continue;
      const auto* s = static_cast<const towsim_msgs_msg_dds__SimStatus_*>(samples[i]);
      const bool terminal = s->state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED ||
                            s->state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED ||
                            s->state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_STOPPED;
      const bool fresh = run_id != s->run_id || answered != s->step;
      if (!fresh) {
        if (terminal) exit_code = 0;  // the last status of a step already answered
        continue;
      }
      run_id = s->run_id;
      answered = s->step;
      last_progress = Clock::now();
      if (answers++ == 0) first_answer = last_progress;

      // the odometry of this step, matched by stamp
      if (log != nullptr) {
        for (Body& b : bodies) {
          const Clock::time_point wait_begin = Clock::now();
          const std::pair<int32_t, uint32_t> key{s->header.stamp.sec, s->header.stamp.nanosec};
          for (;;) {
            void* os[32] = {};
            dds_sample_info_t oi[32];
            const dds_return_t k = dds_take(b.odom_reader, os, oi, 32, 32);
            for (int j = 0; j < k; ++j) {
              if (!oi[j].valid_data) continue;
              const auto* o = static_cast<const nav_msgs_msg_dds__Odometry_*>(os[j]);
              nav_msgs_msg_dds__Odometry_ copy = *o;
              copy.header.frame_id = nullptr;
              copy.child_frame_id = nullptr;
              b.odoms[{o->header.stamp.sec, o->header.stamp.nanosec}] = copy;
            }
            if (k > 0) dds_return_loan(b.odom_reader, os, k);
            if (b.odoms.count(key) > 0) break;
            if (Seconds(Clock::now() - wait_begin) > 2.0) {
              Fail("no odometry of " + b.name + " for step " + std::to_string(s->step));
            }
            dds_sleepfor(DDS_USECS(50));
          }
          const nav_msgs_msg_dds__Odometry_& o = b.odoms[key];
          std::fprintf(log,
                       "%llu %s %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
                       "%.17g %.17g %.17g\n",
                       static_cast<unsigned long long>(s->step), b.name.c_str(),
                       o.pose.pose.position.x, o.pose.pose.position.y, o.pose.pose.position.z,
                       o.pose.pose.orientation.x, o.pose.pose.orientation.y,
                       o.pose.pose.orientation.z, o.pose.pose.orientation.w, o.twist.twist.linear.x,
                       o.twist.twist.linear.y, o.twist.twist.linear.z, o.twist.twist.angular.x,
                       o.twist.twist.angular.y, o.twist.twist.angular.z);
          // older stamps are done with
          b.odoms.erase(b.odoms.begin(), b.odoms.find(key));
        }
      }
      if (terminal ||
          (args.until_step >= 0 && static_cast<long long>(s->step) >= args.until_step)) {
        exit_code = 0;
        break;
      }
      // the script's rule: entries whose time has come fire, in order
      for (ScheduledCommand& c : schedule) {
        if (c.fired || s->sim_time < c.at - 1e-9) continue;
        c.fired = true;
        if (held.count(c.body) == 0) Fail("--command for " + c.body + ": not a commanded body");
        held[c.body].thrust = c.thrust;
        held[c.body].rudder = c.rudder;
        held[c.body].elevator = c.elevator;
      }
      for (size_t w = 0; w < writers.size(); ++w) {
        towsim_msgs_msg_dds__ActuatorCommand_ cmd = held[commanded[w]];
        cmd.header.stamp = s->header.stamp;
        cmd.header.frame_id = const_cast<char*>(commanded[w].c_str());
        cmd.step = s->step;
        const dds_return_t rc = dds_write(writers[w], &cmd);
        if (rc < 0) Fail(std::string("writing a command: ") + dds_strretcode(rc));
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
    std::printf("test_controller: %ld steps in %.3f s: %.0f steps/s, %.1f us/step\n", answers - 1,
                wall, (answers - 1) / wall, 1e6 * wall / (answers - 1));
  }
  dds_delete_qos(state_qos);
  dds_delete_qos(command_qos);
  dds_delete_qos(scene_qos);
  dds_delete(participant);
  return exit_code;
}
