// towsim_foxglove: a live Foxglove WebSocket connection to a towsim node (docs/foxglove.md).
//
//   towsim_foxglove --domain N [--namespace NS] --port PORT [--address ADDR] [--quiet]
//                   [--security DIR/NAME]
//   towsim_foxglove --layout SCENE [--namespace NS] [--output FILE]
//
// --layout writes a Foxglove layout for the scene (app/foxglove/foxglove_layout.h) to FILE or
// stdout and exits, without DDS.
//
// A bridge process: it subscribes over DDS like towsim_record does (so it shows a node and
// towsim_replay alike), learning the bodies and cables from rt/<ns>/scene_info, and serves every
// towsim topic of the namespace (app/common/topic_types.h NodeTopics: odometry, cable force and
// command per body, the state of each cable, status, scene info, sim_control, markers, /clock,
// /tf, /tf_static) as a
// Foxglove channel (encoding cdr, schema encoding ros2msg, the schemas of the MCAP recordings),
// the payloads as received. A DDS reader exists only while a client subscribes to its
// channel, so a bridge without clients costs the node nothing (the node serializes a topic
// only for a matched reader). Message log times and the `time` capability are the simulation
// time: the header stamp of each message, /clock for the time messages.
//
// clientPublish: a client may advertise rt/<ns>/<body>/command (towsim_msgs/msg/
// ActuatorCommand), rt/<ns>/<winch>/command (towsim_msgs/msg/WinchCommand, per winch the scene info
// lists; docs/winch_dds.md) and rt/<ns>/sim_control (towsim_msgs/msg/
// SimControl) with encoding cdr.
// Each message is checked to be a valid CDR sample of its type (Cyclone's deserializer) and
// written on DDS as it is; the node validates it exactly like any DDS command (NaN rejected,
// out of range clamped, counted in its status). A malformed message is rejected here: an error
// status to the client, and counted. Other topics or encodings are refused at advertise, but
// for the topics Foxglove's 3D panel advertises when it opens (/move_base_simple/goal,
// /clicked_point, /initialpose: FoxgloveCommands' kPanelTopics), taken and their messages
// ignored.
// Foxglove's Teleop panel publishes geometry_msgs/msg/Twist: on a command topic it becomes an
// ActuatorCommand answering the step of the newest status seen, then goes the same way
// (TwistToCommand): thrust = linear.x [N] when non-zero, else the thrust the panel set last
// (so the rudder buttons keep the speed); rudder = -angular.z [rad] (the panel's "left" is a
// positive angular.z, a positive rudder turns to starboard); elevator = linear.z [rad]; an
// all-zero Twist stops (thrust 0, fins centred).
//
// With --security DIR/NAME its participant runs DDS Security with that identity (wire/security.h,
// docs/security.md); clientPublish then needs an identity allowed to command
// (scripts/security.sh NAME:BODY,...,sim_control).
// Binds 127.0.0.1 unless --address says otherwise, at start-up (a bad address or a busy port
// exits 2 at once); accepts connections once the node's scene info has come. Prints on
// stdout, once listening:
//   towsim_foxglove: serving ws://127.0.0.1:8765 (domain 0, namespace /towsim)
// Ends on SIGINT / SIGTERM with a summary line (FoxgloveServer::SummaryText):
//   towsim_foxglove: 1234 messages sent (dropped 0), client messages 10 (rejected 1,
//   malformed 1), requests 4 (refused 1, malformed 0), error replies 2 (suppressed 0), time
//   messages dropped 0, clients 1 (closed at the bound 0)
// Each client's send queue is bounded (app/foxglove/client_queue.h, docs/foxglove.md "Bounds").
// Exit codes: 0 done, 1 unexpected error, 2 bad input, DDS setup failure, a bad address or the
// port in use.

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/common/dds_tool_options.h"
#include "app/common/dds_tool_run.h"
#include "app/common/dds_uri.h"
#include "app/common/exit_codes.h"
#include "app/common/mcap_recording.h"
#include "app/common/stop_signal.h"
#include "app/common/tool_command_line.h"
#include "app/common/topic_types.h"
#include "app/foxglove/foxglove_commands.h"
#include "app/foxglove/foxglove_layout.h"
#include "installed/installed_data.h"
#include "app/foxglove/foxglove_server.h"
#include "dds/entities.h"
#include "dds/messages.h"
#include "dds/qos.h"
#include "dds/raw_cdr.h"
#include "io/ros2_schemas.h"
#include "scene/scene_loader.h"
#include "wire/topic_names.h"

namespace {

using towsim::app::kExitBadInput;
using towsim::app::kExitError;
using towsim::app::kExitOk;
constexpr double kWaitSlice = 0.02;      // longest wait between checks [s]
constexpr double kSceneHintAfter = 3.0;  // say what it waits for after [s]
constexpr int kReaderDepth = 16;         // keep-last history of a bridge reader

namespace dds = towsim::dds;
namespace wire = towsim::wire;
using towsim::app::FoxgloveServer;

const char* kUsage =
    "usage: towsim_foxglove --domain N [--namespace NS] --port PORT [--address ADDR] [--quiet]\n"
    "                       [--security DIR/NAME]\n"
    "       towsim_foxglove --layout SCENE [--namespace NS] [--output FILE]\n"
    "  --domain N        DDS domain id of the node (0 to 232)\n"
    "  --namespace NS    ROS 2 namespace of the node's topics (default /towsim)\n"
    "  --port PORT       WebSocket port (Foxglove's default 8765; 0: any free port)\n"
    "  --address ADDR    interface to listen on (default 127.0.0.1; 0.0.0.0: every one)\n"
    "  --quiet           no progress notes on stderr\n"
    "  --security DIR/NAME DDS Security with the identity DIR/NAME (scripts/security.sh;\n"
    "                    docs/security.md)\n"
    "  --layout SCENE    write a Foxglove layout for the scene file and exit (no DDS)\n"
    "  --output FILE     where --layout writes it (default: stdout)\n"
    "Connect Foxglove to ws://ADDR:PORT; ends on SIGINT / SIGTERM.\n";

struct Options {
  uint32_t domain = 0;
  bool has_domain = false;
  std::string ns = wire::kDefaultNamespace;
  int port = -1;
  std::string address = "127.0.0.1";
  bool quiet = false;
  std::string security;  // --security DIR/NAME (wire/security.h); empty: none
  std::string layout;    // --layout SCENE: write its layout and exit
  std::string output;    // --output FILE of --layout; empty: stdout
};

// the options, read into `o`
towsim::app::ToolCommandLine CommandLine(Options* o) {
  towsim::app::ToolCommandLine line("towsim_foxglove", kUsage);
  line.Shared(towsim::app::DdsToolOptions(
                  {&o->domain, &o->ns, &o->security, &o->quiet, &o->has_domain}))
      .Value("--port",
             [o](const std::string& v) -> std::string {
               char* end = nullptr;
               const long port = std::strtol(v.c_str(), &end, 10);
               if (v.empty() || *end != '\0' || port < 0 || port > 65535) {
                 return "--port " + v + ": must be an integer from 0 to 65535";
               }
               o->port = static_cast<int>(port);
               return "";
             })
      .Value("--address",
             [o](const std::string& v) -> std::string {
               o->address = v;
               return v.empty() ? "--address needs a value" : "";
             })
      .Value("--layout",
             [o](const std::string& v) -> std::string {
               o->layout = v;
               return v.empty() ? "--layout needs a scene file" : "";
             })
      .Value("--output",
             [o](const std::string& v) -> std::string {
               o->output = v;
               return v.empty() ? "--output needs a file" : "";
             })
      .Require([o]() -> std::string {
        if (o->layout.empty()) return o->output.empty() ? "" : "--output needs --layout SCENE";
        // --layout writes a file: no DDS, no server
        if (o->has_domain || o->port >= 0 || !o->security.empty()) {
          return "--layout SCENE takes no --domain, --port or --security (it writes a layout "
                 "and exits)";
        }
        return "";
      })
      .Require([o]() -> std::string {
        return o->has_domain || !o->layout.empty() ? "" : "missing --domain N";
      })
      .Require([o]() -> std::string {
        return o->port < 0 && o->layout.empty() ? "missing --port PORT" : "";
      });
  return line;
}

// the simulation time of a sample [ns]: the stamp of its header (every towsim type starts
// with a std_msgs/Header or a builtin_interfaces/Time, after the 4-byte encapsulation), or of
// the first element of a leading sequence (TFMessage, MarkerArray); `fallback` if none
uint64_t StampNs(bool sequence_first, const uint8_t* p, size_t size, uint64_t fallback) {
  size_t at = 4;
  if (sequence_first) {
    uint32_t n = 0;
    if (size < 8) return fallback;
    std::memcpy(&n, p + 4, 4);
    if (n == 0) return fallback;
    at = 8;
  }
  if (size < at + 8 || p[1] != 0x01) return fallback;  // little-endian CDR only
  int32_t sec = 0;
  uint32_t nanosec = 0;
  std::memcpy(&sec, p + at, 4);
  std::memcpy(&nanosec, p + at + 4, 4);
  if (sec < 0) return 0;
  return static_cast<uint64_t>(sec) * 1000000000ull + nanosec;
}

FoxgloveServer::Options ServerOptions(const Options& o) {
  FoxgloveServer::Options s;
  s.address = o.address;
  s.port = static_cast<uint16_t>(o.port);
  s.name = "towsim_foxglove " + o.ns;
  s.program = "towsim_foxglove";
  s.quiet = o.quiet;
  return s;
}

// one towsim topic served as a channel; its reader exists while a client subscribes
struct Served {
  towsim::app::NodeTopic topic;
  uint32_t channel = 0;
  bool sequence_first = false;
  bool is_clock = false;
  bool is_status = false;
  dds::Entity topic_entity, reader, condition;
};

class Bridge {
 public:
  Bridge(const Options& o, const std::string& config)
      : opt_(o),
        names_(o.ns),
        participant_(o.domain, config, o.security),
        waitset_(participant_),
        server_(ServerOptions(o)) {}

  int Run();

 private:
  // winches: SceneInfo.winches (the one winch "winch" when an earlier towsim sent only
  // has_winch), so clients may command each
  // cables: SceneInfo.cables (empty from an earlier towsim: the one cable)
  void Serve(const std::vector<std::string>& bodies, const std::vector<std::string>& cables,
             const std::vector<std::string>& winches);
  // readers for the channels with subscribers (and /clock while a client is connected)
  void UpdateReaders();
  void TakeAll();

  Options opt_;
  wire::TopicNames names_;
  dds::Participant participant_;
  dds::WaitSet waitset_;
  FoxgloveServer server_;
  std::vector<std::unique_ptr<Served>> served_;
  uint64_t clock_ns_ = 0;
  dds::RawType status_type_{participant_, &towsim_msgs_msg_dds__SimStatus__desc};
  std::unique_ptr<towsim::app::FoxgloveCommands> commands_;  // clientPublish, after Serve()
};

void Bridge::Serve(const std::vector<std::string>& bodies, const std::vector<std::string>& cables,
                   const std::vector<std::string>& winches) {
  for (const towsim::app::NodeTopic& t :
       towsim::app::NodeTopics(names_, bodies, true, cables, winches)) {
    auto s = std::make_unique<Served>();
    s->topic = t;
    const std::string type = towsim::io::Ros2TypeName(t.descriptor->m_typename);
    // transient local (scene info, /tf_static): latched, so that a client subscribing while
    // another one is (the reader exists, its sample was taken) gets the last one too
    s->channel = server_.AddChannel(wire::RosTopicName(t.dds_name), type,
                                    towsim::io::Ros2MsgSchema(type), t.transient_local);
    s->sequence_first = t.descriptor == &tf2_msgs_msg_dds__TFMessage__desc ||
                        t.descriptor == &visualization_msgs_msg_dds__MarkerArray__desc;
    s->is_clock = t.descriptor == &rosgraph_msgs_msg_dds__Clock__desc;
    s->is_status = t.descriptor == &towsim_msgs_msg_dds__SimStatus__desc;
    const dds_entity_t e =
        dds_create_topic(participant_.get(), t.descriptor, t.dds_name.c_str(), nullptr, nullptr);
    if (e < 0) throw dds::DdsError("creating topic " + t.dds_name, e);
    s->topic_entity = dds::Entity(e);
    served_.push_back(std::move(s));
  }
  commands_ =
      std::make_unique<towsim::app::FoxgloveCommands>(participant_, names_, bodies, winches);
  commands_->Attach(&server_);
}

void Bridge::UpdateReaders() {
  const bool connected = server_.clients() > 0;
  for (auto& s : served_) {
    // /clock for the time messages and the status for Teleop's step while a client is there
    const bool want =
        server_.HasSubscribers(s->channel) || ((s->is_clock || s->is_status) && connected);
    if (want == s->reader.valid()) continue;
    if (!want) {
      s->condition = dds::Entity();
      s->reader = dds::Entity();  // its read condition with it
      continue;
    }
    dds::Qos qos = dds::StateQos(kReaderDepth);
    if (s->topic.transient_local) {
      dds_qset_durability(qos.get(), DDS_DURABILITY_TRANSIENT_LOCAL);
    }
    const dds_entity_t r =
        dds_create_reader(participant_.get(), s->topic_entity.get(), qos.get(), nullptr);
    if (r < 0) throw dds::DdsError("creating a reader for " + s->topic.dds_name, r);
    s->reader = dds::Entity(r);
    const dds_entity_t c = dds_create_readcondition(r, DDS_ANY_STATE);
    if (c < 0) throw dds::DdsError("creating a read condition for " + s->topic.dds_name, c);
    s->condition = dds::Entity(c);
    waitset_.Attach(c);
  }
}

void Bridge::TakeAll() {
  for (auto& s : served_) {
    if (!s->reader.valid()) continue;
    const int n =
        dds::TakeRaw(s->reader.get(), [&](const uint8_t* p, size_t size, const dds_sample_info_t&) {
          const uint64_t t = StampNs(s->sequence_first, p, size, clock_ns_);
          if (s->is_clock) {
            clock_ns_ = t;
            server_.BroadcastTime(t);
          }
          if (s->is_status) {
            dds::SimStatusMsg m{};
            if (status_type_.Deserialize(p, size, &m)) commands_->SetStatusStep(m.step);
            dds_sample_free(&m, &towsim_msgs_msg_dds__SimStatus__desc, DDS_FREE_CONTENTS);
          }
          server_.Publish(s->channel, t, p, size);
        });
    if (n < 0) throw dds::DdsError("taking from " + s->topic.dds_name, n);
  }
}

int Bridge::Run() {
  // the address and port at once (bad or busy: exit 2 before any wait); connections are
  // accepted once the node's channels are known
  try {
    server_.Listen();
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "towsim_foxglove: error: --address %s --port %d: %s\n",
                 opt_.address.c_str(), opt_.port, e.what());
    return kExitBadInput;
  }
  std::printf("towsim_foxglove: serving ws://%s:%u (domain %u, namespace %s)\n",
              opt_.address.c_str(), static_cast<unsigned>(server_.port()), opt_.domain,
              opt_.ns.c_str());
  std::fflush(stdout);

  // the bodies (scene_info is transient local: also when the node started first)
  dds::Topic scene_topic(participant_, &towsim_msgs_msg_dds__SceneInfo__desc,
                         names_.Name(wire::Topic::kSceneInfo));
  dds::Reader<dds::SceneInfoMsg> scene(participant_, scene_topic, dds::SceneInfoQos());
  std::vector<std::string> bodies, cables, winches;
  bool have_scene = false, hinted = false;
  const double start = static_cast<double>(dds_time()) * 1e-9;
  while (!have_scene && !towsim::app::StopRequested()) {
    scene.TakeEach([&](const dds::SceneInfoMsg& m, const dds_sample_info_t&) {
      if (have_scene) return;
      for (uint32_t i = 0; i < m.bodies._length; ++i) bodies.push_back(m.bodies._buffer[i]);
      for (uint32_t i = 0; i < m.cables._length; ++i) cables.push_back(m.cables._buffer[i]);
      for (uint32_t i = 0; i < m.winches._length; ++i) winches.push_back(m.winches._buffer[i]);
      if (m.has_winch && winches.empty()) winches.push_back(wire::kOneWinch);
      have_scene = true;
    });
    if (!have_scene) dds_sleepfor(DDS_MSECS(10));
    if (!hinted && static_cast<double>(dds_time()) * 1e-9 - start > kSceneHintAfter) {
      hinted = true;
      std::fprintf(stderr, "towsim_foxglove: waiting for a node's %s (domain %u)\n",
                   wire::RosTopicName(names_.Name(wire::Topic::kSceneInfo)).c_str(), opt_.domain);
    }
  }
  if (!have_scene) {  // stopped while waiting
    server_.Stop();
    return kExitOk;
  }
  Serve(bodies, cables, winches);
  server_.Start();

  // the waitset wakes on data; it holds this guard condition so that a wait without readers
  // (no client subscribed) still blocks for its slice instead of returning at once
  const dds_entity_t idle = dds_create_guardcondition(participant_.get());
  if (idle < 0) throw dds::DdsError("creating a guard condition", idle);
  const dds::Entity idle_entity(idle);
  waitset_.Attach(idle);
  while (!towsim::app::StopRequested()) {
    UpdateReaders();
    waitset_.Wait(static_cast<int64_t>(kWaitSlice * 1e9));
    TakeAll();
  }
  server_.Stop();
  std::printf("towsim_foxglove: %s\n", FoxgloveServer::SummaryText(server_.totals()).c_str());
  std::fflush(stdout);
  return kExitOk;
}

}  // namespace

namespace {

// --layout SCENE: the scene's Foxglove layout to --output (or stdout)
int WriteLayout(const Options& o, const towsim::app::ToolCommandLine& line) {
  std::string json;
  try {
    // a bare scene name also finds the scenes of an installed towsim, as sim_node's --scene
    const std::string scene =
        towsim::installed::ResolveInstalled(o.layout, towsim::installed::kScenes);
    json = towsim::app::FoxgloveLayoutJson(towsim::scene::LoadScene(scene),
                                           wire::TopicNames(o.ns));
  } catch (const std::exception& e) {  // scene::ConfigError: file, line and rule
    return line.Fail(std::string("--layout ") + o.layout + ": " + e.what());
  }
  if (o.output.empty()) {
    std::fwrite(json.data(), 1, json.size(), stdout);
    return std::fflush(stdout) == 0 ? kExitOk : kExitError;
  }
  std::ofstream out(o.output, std::ios::binary);
  out << json;
  out.close();
  if (!out) {
    return line.Fail("--output " + o.output + ": cannot write: " + std::strerror(errno));
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  const towsim::app::ToolCommandLine line = CommandLine(&options);
  if (const std::optional<int> exit = line.Read(argc, argv)) return *exit;
  if (!options.layout.empty()) return WriteLayout(options, line);
  return towsim::app::RunDdsTool<Bridge>("towsim_foxglove", options, false);
}
