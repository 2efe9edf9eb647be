// lockstep_pingpong: the bare DDS round trip of one lockstep step (docs/benchmarks.md,
// "Lockstep at the speed of the wire"), between two processes over loopback, with the node's
// QoS and the messages one step exchanges:
//   ping (the node's side):        writes the odometry of every body, then the SimStatus of step
//                                  k (the message a controller waits on), and waits (waitset)
//                                  until every body's ActuatorCommand stamped k has come back;
//   pong (a controller's side):    waits (waitset) for a SimStatus of a new step, takes the
//                                  odometry of its bodies, writes one ActuatorCommand per body
//                                  stamped with that step.
// No physics, no sleeps, no polling: what is left is what the wire and Cyclone cost.
//
//   lockstep_pingpong ping --domain N --bodies A[,B...] [--pongs P] [--rounds R] [--warmup W]
//   lockstep_pingpong pong --domain N --bodies A[,B...]
//
// ping prints the sizes and the round trip (from the first write of step k to the last
// command of step k taken) of the R measured rounds after W warm-up rounds:
//   ping-pong: 1 pong, bodies tow_vehicle,towfish: out 2 x odom 760 B + status 212 B,
//   back 2 x command 64 B; 5000 rounds: round trip p50 31.2 us p99 58.0 us
// and ends the pongs with a status FINISHED. Needs CYCLONEDDS_URI (config/cyclonedds.xml).
// Exit 0, 1 on a DDS error or a pong silent for 10 s, 2 on bad flags.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "dds/entities.h"
#include "dds/frames.h"
#include "dds/messages.h"
#include "dds/qos.h"
#include "dds/raw_cdr.h"
#include "dds/translators.h"
#include "wire/topic_names.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace tdds = towsim::dds;

constexpr double kSilence = 10.0;            // a pong that answers nothing for this long: error [s]
constexpr int64_t kResend = DDS_MSECS(200);  // warm-up: the status again (discovery races)
constexpr uint8_t kRunning = towsim_msgs_msg_dds__SimStatus_Constants_STATE_RUNNING;
constexpr uint8_t kFinished = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED;

struct Args {
  std::string role;
  uint32_t domain = 0;
  std::vector<std::string> bodies;
  int pongs = 1;
  long rounds = 5000;
  long warmup = 200;
};

[[noreturn]] void Usage(const std::string& message) {
  std::fprintf(stderr,
               "lockstep_pingpong: error: %s\n"
               "usage: lockstep_pingpong ping|pong --domain N --bodies A[,B...] [--pongs P] "
               "[--rounds R] [--warmup W]\n",
               message.c_str());
  std::exit(2);
}

long Integer(const std::string& flag, const std::string& v, long lo, long hi) {
  char* end = nullptr;
  const long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || x < lo || x > hi) {
    Usage(flag + " = " + v + ": must be an integer from " + std::to_string(lo) + " to " +
          std::to_string(hi));
  }
  return x;
}

Args Parse(int argc, char** argv) {
  Args a;
  if (argc < 2) Usage("ping or pong first");
  a.role = argv[1];
  if (a.role != "ping" && a.role != "pong") Usage("role = " + a.role + ": must be ping or pong");
  for (int i = 2; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) Usage(flag + " needs a value");
    const std::string v = argv[++i];
    if (flag == "--domain") {
      a.domain = static_cast<uint32_t>(Integer(flag, v, 0, 232));
    } else if (flag == "--bodies") {
      std::stringstream s(v);
      for (std::string b; std::getline(s, b, ',');) {
        if (const std::string e = towsim::wire::CheckBodyName(b); !e.empty()) {
          Usage("--bodies = " + v + ": " + e);
        }
        a.bodies.push_back(b);
      }
    } else if (flag == "--pongs") {
      a.pongs = static_cast<int>(Integer(flag, v, 1, 16));
    } else if (flag == "--rounds") {
      a.rounds = Integer(flag, v, 1, 100000000);
    } else if (flag == "--warmup") {
      a.warmup = Integer(flag, v, 1, 100000000);
    } else {
      Usage("unknown flag " + flag);
    }
  }
  if (a.bodies.empty()) Usage("--bodies: at least one body");
  return a;
}

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

double Quantile(std::vector<double> x, double p) {  // nearest rank
  std::sort(x.begin(), x.end());
  const size_t rank = static_cast<size_t>(std::ceil(p * static_cast<double>(x.size())));
  return x[std::max<size_t>(rank, 1) - 1];
}

// a status as the node fills it in lockstep (dds_node.cc PublishStatus): the run id, the mode,
// the counters
tdds::StatusSample StepStatus(uint64_t step, double h) {
  tdds::StatusSample s;
  s.run_id = "case1_forward-0123456789abcdef";
  s.mode = "lockstep";
  s.state = kRunning;
  s.step = step;
  s.sim_time = static_cast<double>(step) * h;
  s.newton_iterations = 2;
  s.coupling_iterations = 1;
  s.substeps = 1;
  s.commands_received = 2 * step;
  return s;
}

struct PingBody {
  std::unique_ptr<tdds::Topic> odom_topic, command_topic;
  std::unique_ptr<tdds::Writer<tdds::OdometryMsg>> odom;
  std::unique_ptr<tdds::Reader<tdds::ActuatorCommandMsg>> command;
  std::unique_ptr<tdds::OdometryMessage> odom_msg;
  uint64_t answered = ~0ULL;  // step of the last command taken
};

int Ping(const Args& a) {
  constexpr double kStep = 0.05;  // Case 1's step [s]: the stamps only
  const towsim::wire::TopicNames names(towsim::wire::kDefaultNamespace);
  tdds::Participant participant(a.domain, "");
  tdds::Topic status_topic(participant, &towsim_msgs_msg_dds__SimStatus__desc,
                           names.Name(towsim::wire::Topic::kStatus));
  tdds::Writer<tdds::SimStatusMsg> status(participant, status_topic, tdds::StateQos());
  tdds::WaitSet waitset(participant);
  std::vector<PingBody> bodies(a.bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    PingBody& p = bodies[b];
    const std::string& name = a.bodies[b];
    p.odom_topic = std::make_unique<tdds::Topic>(participant, &nav_msgs_msg_dds__Odometry__desc,
                                                 names.Name(towsim::wire::Topic::kOdom, name));
    p.command_topic =
        std::make_unique<tdds::Topic>(participant, &towsim_msgs_msg_dds__ActuatorCommand__desc,
                                      names.Name(towsim::wire::Topic::kCommand, name));
    p.odom = std::make_unique<tdds::Writer<tdds::OdometryMsg>>(participant, *p.odom_topic,
                                                               tdds::StateQos());
    p.command = std::make_unique<tdds::Reader<tdds::ActuatorCommandMsg>>(
        participant, *p.command_topic, tdds::CommandQos());
    p.odom_msg = std::make_unique<tdds::OdometryMessage>(tdds::kWorldFrame, tdds::FrdFrame(name));
    p.odom_msg->msg.pose.pose.orientation.w = 1.0;
    waitset.Attach(p.command->condition());
  }
  tdds::SimStatusMessage status_msg;

  // every pong matched: its status reader, its odometry readers and its command writers
  const Clock::time_point begin = Clock::now();
  for (;;) {
    bool all = status.matched_count() >= a.pongs;
    for (const PingBody& p : bodies) all = all && p.odom->matched() && p.command->matched_count();
    if (all) break;
    if (Seconds(Clock::now() - begin) > kSilence) {
      std::fprintf(stderr, "lockstep_pingpong: error: no pong matched in %g s\n", kSilence);
      return 1;
    }
    dds_sleepfor(DDS_MSECS(5));
  }

  // the sizes on the wire (serialized once by Cyclone, with the 4-byte encapsulation header;
  // 0 if the serializer probe of dds/raw_cdr.h fails, as it does over shared memory)
  auto size_of = [&participant](const dds_topic_descriptor_t* type, const void* sample) {
    try {
      return tdds::CdrSample::FromSample(tdds::RawType(participant, type), sample).size();
    } catch (const tdds::DdsError&) {
      return size_t{0};
    }
  };
  tdds::ToSimStatus(StepStatus(1, kStep), &status_msg);
  const size_t status_bytes = size_of(&towsim_msgs_msg_dds__SimStatus__desc, &status_msg.msg);
  const size_t odom_bytes = size_of(&nav_msgs_msg_dds__Odometry__desc, &bodies[0].odom_msg->msg);
  tdds::ActuatorCommandMsg command_sample{};
  command_sample.header.frame_id = const_cast<char*>(a.bodies[0].c_str());
  const size_t command_bytes =
      size_of(&towsim_msgs_msg_dds__ActuatorCommand__desc, &command_sample);

  std::vector<double> rtt;
  rtt.reserve(static_cast<size_t>(a.rounds));
  const long total = a.warmup + a.rounds;
  for (long k = 1; k <= total; ++k) {
    const uint64_t step = static_cast<uint64_t>(k);
    const Clock::time_point t0 = Clock::now();
    const tdds::TimeMsg stamp = tdds::ToTimeMsg(static_cast<double>(k) * kStep);
    for (PingBody& p : bodies) {
      p.odom_msg->msg.header.stamp = stamp;
      p.odom_msg->msg.pose.pose.position.x = static_cast<double>(k) * 0.3;
      p.odom->Write(p.odom_msg->msg);
    }
    tdds::ToSimStatus(StepStatus(step, kStep), &status_msg);
    status.Write(status_msg.msg);
    Clock::time_point last = Clock::now();
    for (;;) {
      int missing = 0;
      for (PingBody& p : bodies) {
        p.command->TakeEach([&](const tdds::ActuatorCommandMsg& c, const dds_sample_info_t&) {
          if (c.step == step) p.answered = step;
        });
        missing += p.answered != step;
      }
      if (missing == 0) break;
      const int64_t wait = k <= a.warmup ? kResend : DDS_SECS(1);
      if (waitset.Wait(wait) == 0) {
        if (Seconds(Clock::now() - last) > kSilence) {
          std::fprintf(stderr, "lockstep_pingpong: error: no answer to step %ld in %g s\n", k,
                       kSilence);
          return 1;
        }
        if (k <= a.warmup) status.Write(status_msg.msg);  // a pong that matched late
      }
    }
    if (k > a.warmup) rtt.push_back(1e6 * Seconds(Clock::now() - t0));
    (void)last;
  }
  tdds::StatusSample end = StepStatus(static_cast<uint64_t>(total + 1), kStep);
  end.state = kFinished;
  tdds::ToSimStatus(end, &status_msg);
  status.Write(status_msg.msg);
  dds_wait_for_acks(status.get(), DDS_SECS(1));

  std::string list;
  for (const std::string& b : a.bodies) list += (list.empty() ? "" : ",") + b;
  const size_t n = a.bodies.size();
  std::printf(
      "ping-pong: %d pong%s, bodies %s: out %zu x odom %zu B + status %zu B, back %zu x command "
      "%zu B; %ld rounds: round trip p50 %.1f us p99 %.1f us\n",
      a.pongs, a.pongs == 1 ? "" : "s", list.c_str(), n, odom_bytes, status_bytes, n, command_bytes,
      a.rounds, Quantile(rtt, 0.50), Quantile(rtt, 0.99));
  return 0;
}

int Pong(const Args& a) {
  const towsim::wire::TopicNames names(towsim::wire::kDefaultNamespace);
  tdds::Participant participant(a.domain, "");
  tdds::Topic status_topic(participant, &towsim_msgs_msg_dds__SimStatus__desc,
                           names.Name(towsim::wire::Topic::kStatus));
  tdds::Reader<tdds::SimStatusMsg> status(participant, status_topic, tdds::StateQos(16));
  tdds::WaitSet waitset(participant);
  waitset.Attach(status.condition());
  struct PongBody {
    std::unique_ptr<tdds::Topic> odom_topic, command_topic;
    std::unique_ptr<tdds::Reader<tdds::OdometryMsg>> odom;
    std::unique_ptr<tdds::Writer<tdds::ActuatorCommandMsg>> command;
    double x = 0.0;
  };
  std::vector<PongBody> bodies(a.bodies.size());
  for (size_t b = 0; b < bodies.size(); ++b) {
    PongBody& p = bodies[b];
    p.odom_topic =
        std::make_unique<tdds::Topic>(participant, &nav_msgs_msg_dds__Odometry__desc,
                                      names.Name(towsim::wire::Topic::kOdom, a.bodies[b]));
    p.command_topic =
        std::make_unique<tdds::Topic>(participant, &towsim_msgs_msg_dds__ActuatorCommand__desc,
                                      names.Name(towsim::wire::Topic::kCommand, a.bodies[b]));
    p.odom = std::make_unique<tdds::Reader<tdds::OdometryMsg>>(participant, *p.odom_topic,
                                                               tdds::StateQos(16));
    p.command = std::make_unique<tdds::Writer<tdds::ActuatorCommandMsg>>(
        participant, *p.command_topic, tdds::CommandQos());
  }
  uint64_t answered = ~0ULL;
  Clock::time_point last = Clock::now();
  for (;;) {
    bool finished = false;
    uint64_t step = answered;
    tdds::TimeMsg stamp{};
    status.TakeEach([&](const tdds::SimStatusMsg& s, const dds_sample_info_t&) {
      finished = finished || s.state == kFinished;
      step = s.step;
      stamp = s.header.stamp;
    });
    if (finished) return 0;
    if (step != answered) {
      for (size_t b = 0; b < bodies.size(); ++b) {
        PongBody& p = bodies[b];
        p.odom->TakeEach([&](const tdds::OdometryMsg& o, const dds_sample_info_t&) {
          p.x = o.pose.pose.position.x;
        });
        tdds::ActuatorCommandMsg c{};
        c.header.stamp = stamp;
        c.header.frame_id = const_cast<char*>(a.bodies[b].c_str());
        c.step = step;
        c.thrust = 4165.0 + 1e-3 * p.x;  // uses the odometry it took
        p.command->Write(c);
      }
      answered = step;
      last = Clock::now();
    }
    if (waitset.Wait(DDS_SECS(1)) == 0 && Seconds(Clock::now() - last) > kSilence) {
      std::fprintf(stderr, "lockstep_pingpong: error: pong: no status for %g s\n", kSilence);
      return 1;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = Parse(argc, argv);
  if (std::getenv("CYCLONEDDS_URI") == nullptr) {
    std::fprintf(stderr,
                 "lockstep_pingpong: error: CYCLONEDDS_URI is not set (use "
                 "config/cyclonedds.xml)\n");
    return 2;
  }
  try {
    return a.role == "ping" ? Ping(a) : Pong(a);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lockstep_pingpong: error: %s\n", e.what());
    return 1;
  }
}
