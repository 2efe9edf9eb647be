// towsim_replay: republishes an MCAP recording on DDS with its recorded timing.
//
//   towsim_replay FILE.mcap [--rate X | --fast] [--topics T ...] [--start S] [--loop]
//                 [--delay S] [--domain N] [--namespace NS] [--recover] [--quiet]
//                 [--security DIR/NAME]
//
// Every message of the chosen channels is written raw (the recorded CDR bytes, dds/raw_cdr;
// Cyclone validates them against the type) on a writer of the channel's type (the schema name,
// "nav_msgs/msg/Odometry", mapped to the generated descriptor of msgs/) with the QoS of the
// towsim topics (docs/contract.md §3: reliable keep-last 1; scene_info transient local). Timing: message
// i is written at t0 + (log_time_i - log_time_first) / rate of wall time, on the recording's
// own clock: the simulation time for sim_node --record and towsim_record --use-sim-time (so
// --rate 1 plays a lockstep run at real time), the wall clock for sim_node --record-wall-time
// and towsim_record (receive time), docs/recording.md; --rate 0 or --fast: as fast as
// possible. /clock is replayed like any topic, so nodes with use_sim_time follow it.
//
// Discovery: the first scene_info message (if replayed) is written first, then the replay
// waits --delay S (default 1 s) so that subscribers started beside it (towsim_record, which
// learns the bodies from scene_info) match the writers, then the timeline starts (without
// that message). --start S skips the first S seconds of the recording; --loop starts again
// at the end. --namespace NS republishes the recording's namespace (the prefix of its
// scene_info or status topic) under NS; /clock stays at the root.
//
// Progress line on stderr (`[towsim_replay] 12.3/60.0 s  20%  4567/23000 messages`), summary on
// stdout. SIGINT / SIGTERM stop it at once (exit 0). Exit 2: bad options, an unknown topic in
// --topics (the message lists the recorded topics), a file that is not a complete, valid
// MCAP file (the reader's message, naming the byte offset), a channel of a type outside the
// contract, a DDS setup failure. --recover reads a damaged or cut-off file as towsim_export
// --recover does (every intact chunk; the skipped byte ranges on stderr) and exits 4 after
// the replay if anything was skipped.

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/common/dds_tool_options.h"
#include "app/common/dds_uri.h"
#include "app/common/exit_codes.h"
#include "app/common/mcap_recording.h"
#include "app/common/stop_signal.h"
#include "app/common/tool_command_line.h"
#include "app/common/tool_flags.h"
#include "app/common/topic_types.h"
#include "dds/entities.h"
#include "dds/messages.h"
#include "dds/qos.h"
#include "dds/raw_cdr.h"
#include "io/mcap_reader.h"
#include "wire/topic_names.h"

namespace {

using towsim::app::kExitBadInput;
using towsim::app::kExitError;
using towsim::app::kExitIncomplete;  // --recover skipped damaged byte ranges
using towsim::app::kExitOk;
constexpr double kMaxSleepSlice = 0.05;   // wake at least this often for signals [s]
constexpr double kProgressPeriod = 0.25;  // progress line redraw [s]
constexpr double kAckTimeout = 1.0;       // at the end, for subscribers to acknowledge [s]

namespace dds = towsim::dds;
namespace wire = towsim::wire;
namespace io = towsim::io;

const char* kUsage =
    "usage: towsim_replay FILE.mcap [--rate X | --fast] [--topics T ...] [--start S] [--loop]\n"
    "                     [--delay S] [--domain N] [--namespace NS] [--recover] [--quiet]\n"
    "                     [--security DIR/NAME]\n"
    "  --rate X        playback speed factor (default 1; 0: as fast as possible)\n"
    "  --fast          the same as --rate 0\n"
    "  --topics T ...  only these recorded topics (ROS names, /towsim/towfish/odom ...)\n"
    "  --start S       skip the first S seconds of the recording (>= 0)\n"
    "  --loop          start again at the end, until stopped\n"
    "  --delay S       wait S seconds after creating the writers (discovery; default 1)\n"
    "  --domain N      DDS domain id (default 0)\n"
    "  --namespace NS  republish the recorded namespace under NS (/clock stays)\n"
    "  --recover       replay every intact chunk of a damaged or cut-off file (exit 4 if\n"
    "                  anything was skipped; the byte ranges on stderr)\n"
    "  --quiet         no progress line\n"
    "  --security DIR/NAME  DDS Security with the identity DIR/NAME (scripts/security.sh;\n"
    "                  the node's, DIR/sim_node, to republish its outputs; docs/security.md)\n";

struct Options {
  std::string file;
  double rate = 1.0;
  std::vector<std::string> topics;
  double start = 0.0;
  bool loop = false;
  double delay = 1.0;
  uint32_t domain = 0;
  std::string ns;  // empty: as recorded
  bool quiet = false;
  bool recover = false;
  std::string security;  // --security DIR/NAME (wire/security.h); empty: none
};

int Bad(const std::string& message) {
  std::fprintf(stderr, "towsim_replay: error: %s\n", message.c_str());
  return kExitBadInput;
}

bool Number(const std::string& v, double* out) {
  char* end = nullptr;
  *out = std::strtod(v.c_str(), &end);
  return !v.empty() && *end == '\0' && std::isfinite(*out);
}

// the options, read into `o`
towsim::app::ToolCommandLine CommandLine(Options* o) {
  // "--name V": V a number >= 0, `unit` after the rule in the error
  auto at_least_zero = [](const char* name, double* out, const char* unit) {
    return [=](const std::string& v) -> std::string {
      if (Number(v, out) && *out >= 0.0) return "";
      return std::string(name) + " " + v + ": must be a number >= 0" + unit;
    };
  };
  towsim::app::ToolCommandLine line("towsim_replay", kUsage);
  line.Shared(towsim::app::DdsToolOptions({&o->domain, &o->ns, &o->security, &o->quiet}))
      .Flag("--loop", &o->loop)
      .Flag("--recover", &o->recover)
      .Flag("--fast", [o] { o->rate = 0.0; })
      .Value("--rate", at_least_zero("--rate", &o->rate, ""))
      .Value("--start", at_least_zero("--start", &o->start, " [s]"))
      .Value("--delay", at_least_zero("--delay", &o->delay, " [s]"))
      .Option(
          "--topics",
          [o](towsim::app::ToolFlags& flags) { return towsim::app::ReadTopics(flags, &o->topics); })
      .Others([o](const towsim::app::ToolFlags& flags) -> std::string {
        if (flags.arg().rfind("--", 0) == 0 || !o->file.empty()) {
          return towsim::app::UnknownOption(flags);
        }
        o->file = flags.arg();
        return "";
      })
      .Require([o]() -> std::string { return o->file.empty() ? "missing FILE.mcap" : ""; });
  return line;
}

// the recorded namespace: the prefix of a channel ending in /scene_info or /status
std::string RecordedNamespace(const std::map<uint16_t, io::McapChannel>& channels) {
  for (const char* suffix : {"/scene_info", "/status"}) {
    const std::string s = suffix;
    for (const auto& [id, c] : channels) {
      if (c.topic.size() > s.size() &&
          c.topic.compare(c.topic.size() - s.size(), s.size(), s) == 0) {
        return c.topic.substr(0, c.topic.size() - s.size());
      }
    }
  }
  return "";
}

struct Output {
  std::string ros_topic;  // as recorded
  std::string dds_topic;  // as republished
  const dds_topic_descriptor_t* descriptor = nullptr;
  dds::RawType* type = nullptr;
  dds::Entity topic, writer;
  bool scene_info = false;
};

void SleepUntil(double wall_target) {
  // absolute sleeps on CLOCK_REALTIME (dds_time's clock), in slices so that signals are seen
  for (;;) {
    if (towsim::app::StopRequested()) return;
    const double now = static_cast<double>(dds_time()) * 1e-9;
    const double left = wall_target - now;
    if (left <= 0.0) return;
    const double until = left > kMaxSleepSlice ? now + kMaxSleepSlice : wall_target;
    timespec ts;
    ts.tv_sec = static_cast<time_t>(std::floor(until));
    ts.tv_nsec = static_cast<long>((until - std::floor(until)) * 1e9);
    clock_nanosleep(CLOCK_REALTIME, TIMER_ABSTIME, &ts, nullptr);
  }
}

int Replay(const Options& opt) {
  // throws McapError naming the offset
  io::McapReader reader =
      opt.recover ? io::McapReader::Recover(opt.file) : io::McapReader::Open(opt.file);
  for (const io::McapSkipped& skipped : reader.skipped()) {
    std::fprintf(stderr, "towsim_replay: %s: skipped %s\n", opt.file.c_str(),
                 io::DescribeSkipped(skipped).c_str());
  }
  if (const std::string nothing = io::NothingRecovered(reader); !nothing.empty()) {
    return Bad(opt.file + ": " + nothing);
  }
  const int done = reader.skipped().empty() ? kExitOk : kExitIncomplete;

  // channels -> outputs
  std::set<std::string> available;
  for (const auto& [id, c] : reader.channels()) available.insert(c.topic);
  for (const std::string& t : opt.topics) {
    if (!available.count(t)) {
      std::string list;
      for (const std::string& a : available) list += (list.empty() ? "" : ", ") + a;
      return Bad("--topics " + t + ": not in " + opt.file + " (recorded topics: " + list + ")");
    }
  }
  const std::string recorded_ns = RecordedNamespace(reader.channels());
  const std::string uri = towsim::app::DdsUriFromEnvironment("towsim_replay");
  std::unique_ptr<dds::Participant> participant;
  try {
    participant = std::make_unique<dds::Participant>(opt.domain, uri, opt.security);
  } catch (const wire::SecurityError& e) {
    return Bad(e.what());
  } catch (const dds::DdsError& e) {
    return Bad(std::string("DDS setup failed: ") + e.what());
  }
  std::vector<std::unique_ptr<dds::RawType>> types;
  std::map<uint16_t, std::unique_ptr<Output>> outputs;
  for (const auto& [id, c] : reader.channels()) {
    if (!opt.topics.empty() &&
        std::find(opt.topics.begin(), opt.topics.end(), c.topic) == opt.topics.end()) {
      continue;
    }
    const auto schema = reader.schemas().find(c.schema_id);
    const std::string type_name = schema == reader.schemas().end() ? "" : schema->second.name;
    if (c.message_encoding != "cdr") {
      return Bad(opt.file + ": channel " + c.topic + ": message encoding '" + c.message_encoding +
                 "', expected cdr");
    }
    const dds_topic_descriptor_t* d = towsim::app::DescriptorOfRos2Type(type_name);
    if (d == nullptr) {
      return Bad(opt.file + ": channel " + c.topic + ": type '" + type_name +
                 "' is not a towsim type (msgs/)");
    }
    auto out = std::make_unique<Output>();
    out->ros_topic = c.topic;
    std::string topic = c.topic;
    if (!opt.ns.empty() && !recorded_ns.empty() && topic.rfind(recorded_ns + "/", 0) == 0) {
      topic = (opt.ns == "/" ? "" : opt.ns) + topic.substr(recorded_ns.size());
    }
    out->dds_topic = wire::DdsTopicName(topic);
    out->descriptor = d;
    out->scene_info = d == &towsim_msgs_msg_dds__SceneInfo__desc;
    for (const auto& t : types) {
      if (t->descriptor() == d) out->type = t.get();
    }
    try {
      if (out->type == nullptr) {
        types.push_back(std::make_unique<dds::RawType>(*participant, d));
        out->type = types.back().get();
      }
      const dds_entity_t t =
          dds_create_topic(participant->get(), d, out->dds_topic.c_str(), nullptr, nullptr);
      if (t < 0) throw dds::DdsError("creating topic " + out->dds_topic, t);
      out->topic = dds::Entity(t);
      // scene_info and /tf_static are transient local (late joiners get them)
      const bool latched = out->scene_info || out->ros_topic == "/tf_static";
      dds::Qos qos = latched                                       ? dds::SceneInfoQos()
                     : d == &towsim_msgs_msg_dds__SimControl__desc ? dds::ControlQos()
                                                                   : dds::StateQos(1);
      const dds_entity_t w = dds_create_writer(participant->get(), t, qos.get(), nullptr);
      if (w < 0) throw dds::DdsError("creating a writer for " + out->dds_topic, w);
      out->writer = dds::Entity(w);
    } catch (const dds::DdsError& e) {
      return Bad(std::string("DDS setup failed: ") + e.what());
    }
    outputs[id] = std::move(out);
  }

  // the timeline (log-time order, chunk CRCs checked here)
  std::vector<io::McapMessage> messages;
  reader.ForEachMessage([&](const io::McapMessage& m) {
    if (outputs.count(m.channel_id)) messages.push_back(m);
  });
  if (messages.empty()) {
    std::printf("towsim_replay: no messages to replay in %s\n", opt.file.c_str());
    return done;
  }
  const uint64_t first_time = messages.front().log_time;
  const uint64_t skip_before = first_time + static_cast<uint64_t>(std::llround(opt.start * 1e9));
  size_t begin = 0;
  while (begin < messages.size() && messages[begin].log_time < skip_before) ++begin;
  if (begin == messages.size()) {
    return Bad("--start " + std::to_string(opt.start) + ": the recording lasts only " +
               std::to_string(1e-9 * static_cast<double>(messages.back().log_time - first_time)) +
               " s");
  }
  auto publish = [&](const io::McapMessage& m) {
    const Output& out = *outputs.at(m.channel_id);
    dds::CdrSample sample;
    try {
      sample = dds::CdrSample::FromBytes(*out.type, m.data.data(), m.data.size());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(opt.file + ": message " + std::to_string(m.sequence) + " of " +
                                  out.ros_topic + " (log time " + std::to_string(m.log_time) +
                                  " ns): " + e.what());
    }
    const dds_return_t rc = sample.Write(out.writer.get(), dds_time());
    if (rc < 0) throw dds::DdsError("writing to " + out.dds_topic, rc);
  };

  // scene_info first, then the discovery delay
  size_t scene_index = messages.size();
  for (size_t i = begin; i < messages.size(); ++i) {
    if (outputs.at(messages[i].channel_id)->scene_info) {
      scene_index = i;
      break;
    }
  }
  try {
    if (scene_index < messages.size()) publish(messages[scene_index]);
  } catch (const std::invalid_argument& e) {
    return Bad(e.what());
  }
  SleepUntil(static_cast<double>(dds_time()) * 1e-9 + opt.delay);

  const double span =
      1e-9 * static_cast<double>(messages.back().log_time - messages[begin].log_time);
  uint64_t sent = scene_index < messages.size() ? 1 : 0;
  double last_progress = -1.0;
  bool drawn = false;
  const double replay_start = static_cast<double>(dds_time()) * 1e-9;
  for (int pass = 0; !towsim::app::StopRequested(); ++pass) {
    const double t0 = static_cast<double>(dds_time()) * 1e-9;
    for (size_t i = begin; i < messages.size() && !towsim::app::StopRequested(); ++i) {
      if (pass == 0 && i == scene_index) continue;  // sent before the delay
      const io::McapMessage& m = messages[i];
      const double offset = 1e-9 * static_cast<double>(m.log_time - messages[begin].log_time);
      if (opt.rate > 0.0) SleepUntil(t0 + offset / opt.rate);
      if (towsim::app::StopRequested()) break;
      try {
        publish(m);
      } catch (const std::invalid_argument& e) {
        return Bad(e.what());
      }
      ++sent;
      const double now = static_cast<double>(dds_time()) * 1e-9;
      if (!opt.quiet && (last_progress < 0.0 || now - last_progress >= kProgressPeriod)) {
        last_progress = now;
        drawn = true;
        std::fprintf(stderr, "\r[towsim_replay] %.1f/%.1f s  %3.0f%%  %zu/%zu messages   ", offset,
                     span, span > 0.0 ? 100.0 * offset / span : 100.0, i - begin + 1,
                     messages.size() - begin);
        std::fflush(stderr);
      }
    }
    if (!opt.loop) break;
  }
  if (drawn) std::fputc('\n', stderr);
  // let reliable subscribers acknowledge the last messages before the writers go
  for (const auto& [id, out] : outputs) {
    dds_wait_for_acks(out->writer.get(), static_cast<dds_duration_t>(kAckTimeout * 1e9));
  }
  std::printf("towsim_replay: %llu messages on %zu topics in %.1f s from %s\n",
              static_cast<unsigned long long>(sent), outputs.size(),
              static_cast<double>(dds_time()) * 1e-9 - replay_start, opt.file.c_str());
  std::fflush(stdout);
  return done;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const std::optional<int> exit = CommandLine(&options).Read(argc, argv)) return *exit;
  towsim::app::InstallStopHandlers();
  try {
    return Replay(options);
  } catch (const io::mcap::McapError& e) {
    return Bad(options.file + ": " + e.what());
  } catch (const dds::DdsError& e) {
    return Bad(std::string("DDS: ") + e.what());
  } catch (const std::exception& e) {
    // a file that cannot be opened is bad input too
    const std::string what = e.what();
    if (what.find(options.file) != std::string::npos) return Bad(what);
    std::fprintf(stderr, "towsim_replay: error: %s\n", what.c_str());
    return kExitError;
  }
}
