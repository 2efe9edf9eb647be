// towsim_record: records the topics of a towsim node from DDS into MCAP.
//
//   towsim_record --output FILE.mcap [--domain N] [--namespace NS] [--topics T ...]
//                 [--duration S] [--use-sim-time] [--overwrite] [--quiet]
//                 [--security DIR/NAME]
//
// The file is created exclusively: one that exists is refused (exit 2) unless --overwrite,
// and it is locked while written, so a second writer (towsim_record or sim_node --record) on
// the same file is refused too.
//
// It learns the bodies and cables from rt/<ns>/scene_info (transient local: also when the node
// started first), then subscribes to every towsim topic of the namespace (docs/contract.md §3:
// per body odom, cable_force and command; <cable>/state per cable, <winch>/command per winch,
// status, scene_info,
// sim_control, markers), /clock, /tf
// and /tf_static, or to the
// --topics given (ROS names, "/towsim/towfish/odom"). The payloads are stored as received
// (dds_takecdr: the CDR bytes, never deserialized and serialized again), log time = the wall
// clock when taken from the reader (receive time), publish time = the writer's source
// timestamp, as rosbag2 does. With --use-sim-time (rosbag2's option of that name) the receive
// time is read from /clock instead: log time = the last /clock value taken (0 before the
// first), so the file's timeline is the simulation time of `sim_node --record`
// (docs/recording.md). Readers are reliable with keep-all history (XCDR1), so a node in
// fast or lockstep mode loses nothing to the recorder (the reliable protocol holds the node's
// writer back instead).
//
// Ends, with a complete file, on SIGINT / SIGTERM, after --duration S of wall time from the
// first subscription, or when the node's status says its run ended (finished, failed,
// stopped; the messages arriving within kDrainAfterEnd after it are kept). A progress line on
// stderr; the summary on stdout:
//   towsim_record: 4567 messages on 11 topics, 2.1 MB, in 12.3 s -> run.mcap
// Exit codes: 0 done (also after a signal), 1 unexpected error (disk full), 2 bad input or DDS
// setup failure.

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
#include "app/common/dds_tool_run.h"
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
#include "wire/topic_names.h"

namespace {

using towsim::app::kExitBadInput;
using towsim::app::kExitError;
using towsim::app::kExitOk;
constexpr double kWaitSlice = 0.02;      // longest wait between checks of signals [s]
constexpr double kDrainAfterEnd = 0.3;   // keep taking after the node's last status [s]
constexpr double kSceneHintAfter = 3.0;  // say what it waits for after [s]
constexpr double kProgressPeriod = 0.5;  // progress line redraw [s]

using towsim::app::McapRecording;
namespace dds = towsim::dds;
namespace wire = towsim::wire;

const char* kUsage =
    "usage: towsim_record --output FILE.mcap [--domain N] [--namespace NS] [--topics T ...]\n"
    "                     [--duration S] [--use-sim-time] [--overwrite] [--quiet]\n"
    "                     [--security DIR/NAME]\n"
    "  --output FILE.mcap  the recording (created; refused if it exists)\n"
    "  --overwrite         replace FILE.mcap if it exists (never while another writer holds it)\n"
    "  --domain N          DDS domain id (default 0)\n"
    "  --namespace NS      ROS 2 namespace of the node's topics (default /towsim)\n"
    "  --topics T ...      only these topics (ROS names: /towsim/towfish/odom /clock ...);\n"
    "                      default: every towsim topic of the namespace and /clock\n"
    "  --duration S        stop after S seconds of wall time (> 0)\n"
    "  --use-sim-time      log time = the last /clock received (simulation time), not the\n"
    "                      wall clock; with --topics, /clock must be one of them\n"
    "  --quiet             no progress line\n"
    "  --security DIR/NAME DDS Security with the identity DIR/NAME (scripts/security.sh;\n"
    "                      docs/security.md)\n"
    "Ends with a complete file on SIGINT / SIGTERM or when the node's run ends.\n";

struct Options {
  std::string output;
  uint32_t domain = 0;
  std::string ns = wire::kDefaultNamespace;
  std::vector<std::string> topics;
  double duration = INFINITY;
  bool quiet = false;
  bool overwrite = false;
  bool use_sim_time = false;  // log time from /clock
  std::string security;  // --security DIR/NAME (wire/security.h); empty: none
};

int Bad(const std::string& message) {
  std::fprintf(stderr, "towsim_record: error: %s\n", message.c_str());
  return kExitBadInput;
}

// the options, read into `o`
towsim::app::ToolCommandLine CommandLine(Options* o) {
  towsim::app::ToolCommandLine line("towsim_record", kUsage);
  line.Shared(towsim::app::DdsToolOptions({&o->domain, &o->ns, &o->security, &o->quiet}))
      .Flag("--overwrite", &o->overwrite)
      .Flag("--use-sim-time", &o->use_sim_time)
      .Value("--output", &o->output)
      .Value("--duration",
             [o](const std::string& v) -> std::string {
               char* end = nullptr;
               o->duration = std::strtod(v.c_str(), &end);
               if (v.empty() || *end != '\0' || !(o->duration > 0.0)) {
                 return "--duration " + v + ": must be a number > 0 [s]";
               }
               return "";
             })
      .Option(
          "--topics",
          [o](towsim::app::ToolFlags& flags) { return towsim::app::ReadTopics(flags, &o->topics); })
      .Require(
          [o]() -> std::string { return o->output.empty() ? "missing --output FILE.mcap" : ""; })
      .Require([o]() -> std::string {
        const bool clock = o->topics.empty() || std::find(o->topics.begin(), o->topics.end(),
                                                          "/clock") != o->topics.end();
        return o->use_sim_time && !clock ? "--use-sim-time needs /clock among --topics" : "";
      });
  return line;
}

double Now() { return static_cast<double>(dds_time()) * 1e-9; }

// one subscription: a reader of raw CDR and its channel
struct Subscription {
  std::string topic;  // DDS name
  const dds_topic_descriptor_t* descriptor = nullptr;
  dds::Entity topic_entity, reader, condition;
  uint16_t channel = 0;
  uint64_t count = 0;
};

dds::Qos RecorderQos(bool transient_local) {
  dds::Qos q = dds::StateQos(1);
  dds_qset_history(q.get(), DDS_HISTORY_KEEP_ALL, 0);
  if (transient_local) dds_qset_durability(q.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
  return q;
}

class Recorder {
 public:
  Recorder(const Options& o, const std::string& config)
      : opt_(o), names_(o.ns), participant_(o.domain, config, o.security), waitset_(participant_) {}

  int Run();

 private:
  Subscription& Subscribe(const std::string& topic, const dds_topic_descriptor_t* descriptor,
                          bool transient_local);
  // takes everything available; returns true if the node's run ended
  bool TakeAll();
  void Progress(bool final);

  Options opt_;
  wire::TopicNames names_;
  dds::Participant participant_;
  dds::WaitSet waitset_;
  std::unique_ptr<McapRecording> recording_;
  std::vector<std::unique_ptr<Subscription>> subs_;
  std::unique_ptr<dds::RawType> scene_type_, status_type_, clock_type_;
  uint64_t sim_now_ = 0;  // the last /clock taken [ns] (--use-sim-time)
  std::vector<std::string> bodies_;
  std::vector<std::string> cables_;  // SceneInfo.cables (empty from an earlier towsim: one)
  std::vector<std::string> winches_;  // SceneInfo.winches (empty: the one winch's topic)
  bool have_scene_ = false;
  double start_ = 0.0, last_progress_ = -1.0;
  bool progress_drawn_ = false;
};

Subscription& Recorder::Subscribe(const std::string& topic,
                                  const dds_topic_descriptor_t* descriptor, bool transient_local) {
  auto s = std::make_unique<Subscription>();
  s->topic = topic;
  s->descriptor = descriptor;
  const dds_entity_t t =
      dds_create_topic(participant_.get(), descriptor, topic.c_str(), nullptr, nullptr);
  if (t < 0) throw dds::DdsError("creating topic " + topic, t);
  s->topic_entity = dds::Entity(t);
  dds::Qos qos = RecorderQos(transient_local);
  const dds_entity_t r = dds_create_reader(participant_.get(), t, qos.get(), nullptr);
  if (r < 0) throw dds::DdsError("creating a reader for " + topic, r);
  s->reader = dds::Entity(r);
  const dds_entity_t c = dds_create_readcondition(r, DDS_ANY_STATE);
  if (c < 0) throw dds::DdsError("creating a read condition for " + topic, c);
  s->condition = dds::Entity(c);
  waitset_.Attach(c);
  // offered_qos_profiles: the node's writers offer reliable keep-last 1
  s->channel = recording_->AddTopic(topic, descriptor->m_typename, transient_local, 1);
  subs_.push_back(std::move(s));
  return *subs_.back();
}

bool Recorder::TakeAll() {
  bool ended = false;
  for (auto& s : subs_) {
    const bool is_scene = s->descriptor == &towsim_msgs_msg_dds__SceneInfo__desc;
    const bool is_status = s->descriptor == &towsim_msgs_msg_dds__SimStatus__desc;
    const bool is_clock = s->descriptor == &rosgraph_msgs_msg_dds__Clock__desc;
    const int n = dds::TakeRaw(
        s->reader.get(), [&](const uint8_t* p, size_t size, const dds_sample_info_t& info) {
          if (is_clock && opt_.use_sim_time) {
            dds::ClockMsg msg{};
            if (clock_type_->Deserialize(p, size, &msg) && msg.clock.sec >= 0) {
              sim_now_ = static_cast<uint64_t>(msg.clock.sec) * 1'000'000'000u + msg.clock.nanosec;
            }
          }
          const uint64_t received =
              opt_.use_sim_time ? sim_now_ : static_cast<uint64_t>(dds_time());
          recording_->Write(s->channel, received, static_cast<uint64_t>(info.source_timestamp), p,
                            size);
          ++s->count;
          if (is_scene && !have_scene_) {
            towsim::dds::SceneInfoMsg msg{};
            if (scene_type_->Deserialize(p, size, &msg)) {
              for (uint32_t i = 0; i < msg.bodies._length; ++i) {
                bodies_.push_back(msg.bodies._buffer[i]);
              }
              for (uint32_t i = 0; i < msg.cables._length; ++i) {
                cables_.push_back(msg.cables._buffer[i]);
              }
              for (uint32_t i = 0; i < msg.winches._length; ++i) {
                winches_.push_back(msg.winches._buffer[i]);
              }
              have_scene_ = true;
            }
            dds_sample_free(&msg, &towsim_msgs_msg_dds__SceneInfo__desc, DDS_FREE_CONTENTS);
          }
          if (is_status) {
            towsim::dds::SimStatusMsg msg{};
            if (status_type_->Deserialize(p, size, &msg)) {
              const uint8_t st = msg.state;
              ended = ended || st == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED ||
                      st == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED ||
                      st == towsim_msgs_msg_dds__SimStatus_Constants_STATE_STOPPED;
            }
            dds_sample_free(&msg, &towsim_msgs_msg_dds__SimStatus__desc, DDS_FREE_CONTENTS);
          }
        });
    if (n < 0) throw dds::DdsError("taking from " + s->topic, n);
  }
  recording_->FlushIfDue();
  return ended;
}

void Recorder::Progress(bool final) {
  const double now = Now();
  if (final) {
    if (progress_drawn_) std::fputc('\n', stderr);
    return;
  }
  if (opt_.quiet || (last_progress_ >= 0.0 && now - last_progress_ < kProgressPeriod)) return;
  last_progress_ = now;
  progress_drawn_ = true;
  std::fprintf(stderr, "\r[towsim_record] %.1f s  %llu messages  %zu topics  %.1f MB   ",
               now - start_, static_cast<unsigned long long>(recording_->message_count()),
               subs_.size(), static_cast<double>(recording_->bytes()) / 1e6);
  std::fflush(stderr);
}

int Recorder::Run() {
  try {
    recording_ = std::make_unique<McapRecording>(opt_.output, opt_.overwrite);
  } catch (const std::exception& e) {
    return Bad("--output " + opt_.output + ": " + e.what());
  }
  scene_type_ = std::make_unique<dds::RawType>(participant_, &towsim_msgs_msg_dds__SceneInfo__desc);
  status_type_ =
      std::make_unique<dds::RawType>(participant_, &towsim_msgs_msg_dds__SimStatus__desc);
  clock_type_ = std::make_unique<dds::RawType>(participant_, &rosgraph_msgs_msg_dds__Clock__desc);

  // the explicit topic list: every one must be a towsim topic of the namespace; bodies come
  // from the names (<ns>/<body>/odom ...)
  const bool explicit_topics = !opt_.topics.empty();
  const bool want_scene =
      !explicit_topics ||
      std::find(opt_.topics.begin(), opt_.topics.end(),
                wire::RosTopicName(names_.Name(wire::Topic::kSceneInfo))) != opt_.topics.end();
  // scene_info first: it names the bodies
  Subscription* scene = nullptr;
  if (want_scene || !explicit_topics) {
    scene = &Subscribe(names_.Name(wire::Topic::kSceneInfo), &towsim_msgs_msg_dds__SceneInfo__desc,
                       true);
  }
  start_ = Now();
  double end_seen = -1.0;
  bool hinted = false, subscribed = false;
  while (!towsim::app::StopRequested()) {
    waitset_.Wait(static_cast<int64_t>(kWaitSlice * 1e9));
    const bool ended = TakeAll();
    const double now = Now();
    if (!subscribed && (have_scene_ || explicit_topics)) {
      subscribed = true;
      std::set<std::string> wanted(opt_.topics.begin(), opt_.topics.end());
      std::vector<std::string> bodies = bodies_;
      std::vector<std::string> cables = cables_;
      std::vector<std::string> winches = winches_;
      if (explicit_topics) {
        // the bodies and cables the explicit topics name (<ns>/<owner>/<topic>: the owner as
        // a body and as a cable; the topic table keeps only the names that exist)
        const std::string prefix = opt_.ns == "/" ? "/" : opt_.ns + "/";
        if (cables.empty()) cables.push_back(wire::kOneCable);
        for (const std::string& t : opt_.topics) {
          if (t.rfind(prefix, 0) != 0) continue;
          const std::string rest = t.substr(prefix.size());
          const size_t slash = rest.find('/');
          if (slash == std::string::npos) continue;
          const std::string owner = rest.substr(0, slash);
          if (std::find(cables.begin(), cables.end(), owner) == cables.end()) {
            cables.push_back(owner);
          }
          if (std::find(winches.begin(), winches.end(), owner) == winches.end()) {
            winches.push_back(owner);  // and as a winch (<w>/command)
          }
          if (owner != wire::kOneCable) bodies.push_back(owner);
        }
      }
      std::set<std::string> known;
      for (const towsim::app::NodeTopic& t :
           towsim::app::NodeTopics(names_, bodies, false, cables, winches)) {
        const std::string ros = wire::RosTopicName(t.dds_name);
        if (known.count(ros)) continue;
        known.insert(ros);
        if (explicit_topics && !wanted.count(ros)) continue;
        Subscribe(t.dds_name, t.descriptor, t.transient_local);
      }
      if (explicit_topics) {
        if (scene != nullptr)
          known.insert(wire::RosTopicName(names_.Name(wire::Topic::kSceneInfo)));
        for (const std::string& t : opt_.topics) {
          if (!known.count(t)) {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            return Bad("--topics " + t + ": not a towsim topic of namespace " + opt_.ns +
                       " (topics: " + list + ")");
          }
        }
      }
      std::fprintf(stderr, "towsim_record: recording %zu topics of %s (domain %u) to %s\n",
                   subs_.size(), opt_.ns.c_str(), opt_.domain, opt_.output.c_str());
      start_ = now;  // --duration counts from here
    }
    if (!subscribed && !hinted && now - start_ > kSceneHintAfter) {
      hinted = true;
      std::fprintf(stderr, "towsim_record: waiting for a node's %s (domain %u)\n",
                   wire::RosTopicName(names_.Name(wire::Topic::kSceneInfo)).c_str(), opt_.domain);
    }
    if (ended && end_seen < 0.0) end_seen = now;
    if (end_seen >= 0.0 && now - end_seen >= kDrainAfterEnd) break;
    if (subscribed && now - start_ >= opt_.duration) break;
    Progress(false);
  }
  TakeAll();
  Progress(true);
  recording_->Close();
  std::printf("towsim_record: %llu messages on %zu topics, %.1f MB, in %.1f s -> %s\n",
              static_cast<unsigned long long>(recording_->message_count()), subs_.size(),
              static_cast<double>(recording_->bytes()) / 1e6, Now() - start_, opt_.output.c_str());
  std::fflush(stdout);
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const std::optional<int> exit = CommandLine(&options).Read(argc, argv)) return *exit;
  return towsim::app::RunDdsTool<Recorder>("towsim_record", options, true);
}
