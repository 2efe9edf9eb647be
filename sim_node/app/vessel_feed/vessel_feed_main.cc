// towsim_vessel_feed: a ship simulator's stand-in. Publishes an external vessel's pose
// (docs/vessels.md "External vessels") from a time-history file, step by step, beside a
// running sim_node.
//
//   towsim_vessel_feed --vessel NAME --history FILE.csv [--domain N] [--namespace NS]
//                      [--security DIR/NAME] [--quiet]
//
// The file is a vessel time history (t,x,y,z,roll,pitch,yaw: world NED [m], ZYX Euler angles
// [rad]; scene/time_history_file.h), read and interpolated exactly as a scene's `time_history:`
// is (the same reader, core/pose_spline.h through core::VesselMotion), so that the node fed by
// this program runs the same, bit for bit, as the node given the file in its scene
// (tests/integration/vessel_feed_integration_test.cc).
//
// Protocol, on rt/<ns>/<vessel>/pose_command (nav_msgs/Odometry in the frames of the node's
// odometry, dds/vessel_pose_translator.h):
//   - a new run (scene_info with a new run id): the pose at the run's start time (its stamp,
//     t_0 = 0), which lockstep waits for before it publishes the initial state;
//   - each new status (step n at sim_time t_n, exact in the message): the pose of t_n + h (h the
//     scene's step), stamped t_n + h, which lockstep waits for before step n (none past the
//     run's duration).
// In realtime and fast modes the node does not wait: a pose that comes after its step is
// counted missing there (the node's summary line). The program ends when the node's run ends
// (a final status: finished, failed or stopped; exit 0), or on SIGINT / SIGTERM (exit 0).
// Exit 2: bad options, a bad history file (naming file, line and rule), a vessel the node's
// scene does not have, a DDS setup failure.

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "app/common/dds_tool_options.h"
#include "app/common/dds_uri.h"
#include "app/common/exit_codes.h"
#include "app/common/stop_signal.h"
#include "app/common/tool_command_line.h"
#include "core/vessel.h"
#include "core/vessel_motion.h"
#include "core/wave_field.h"
#include "dds/entities.h"
#include "dds/messages.h"
#include "dds/qos.h"
#include "dds/translators.h"
#include "dds/vessel_pose_translator.h"
#include "scene/time_history_file.h"
#include "wire/decoders.h"
#include "wire/topic_names.h"

namespace {

namespace app = towsim::app;
namespace core = towsim::core;
namespace dds = towsim::dds;
namespace wire = towsim::wire;

constexpr double kWaitSlice = 0.02;     // longest wait between polls of the stop signal [s]
constexpr double kMatchTimeout = 10.0;  // for the node's pose reader to match [s]
constexpr double kAckTimeout = 1.0;     // at the end, for the node to acknowledge [s]
constexpr int kStatusDepth = 16;        // status history: no step lost in a burst

const char* kUsage =
    "usage: towsim_vessel_feed --vessel NAME --history FILE.csv [--domain N] [--namespace NS]\n"
    "                          [--security DIR/NAME] [--quiet]\n"
    "Publishes the pose of the external vessel NAME (a scene body with `type: vessel,\n"
    "external: true`) on rt/<ns>/NAME/pose_command from a time history, step by step beside a\n"
    "running sim_node: the pose of t_0 for each new run, then for each state n the node reports\n"
    "the pose of t_n + h. Ends when the node's run ends. docs/vessels.md \"External vessels\".\n"
    "  --vessel NAME       the vessel (a body of the node's scene)\n"
    "  --history FILE.csv  t,x,y,z,roll,pitch,yaw (world NED [m], ZYX Euler angles [rad]), as a\n"
    "                      scene's time_history: (docs/vessels.md \"Time history files\")\n"
    "  --domain N          DDS domain id (default 0)\n"
    "  --namespace NS      the node's namespace (default /towsim)\n"
    "  --quiet             no summary line\n"
    "  --security DIR/NAME DDS Security with the identity DIR/NAME (docs/security.md)\n";

struct Options {
  std::string vessel;
  std::string history;
  uint32_t domain = 0;
  std::string ns = "/towsim";
  std::string security;
  bool quiet = false;
};

app::ToolCommandLine CommandLine(Options* o) {
  app::ToolCommandLine line("towsim_vessel_feed", kUsage);
  line.Shared(app::DdsToolOptions({&o->domain, &o->ns, &o->security, &o->quiet}))
      .Value("--vessel", &o->vessel)
      .Value("--history", &o->history)
      .Require([o]() -> std::string {
        if (o->vessel.empty()) return "missing --vessel NAME";
        if (const std::string e = wire::CheckBodyName(o->vessel); !e.empty()) {
          return "--vessel " + o->vessel + ": " + e;
        }
        return o->history.empty() ? "missing --history FILE.csv" : "";
      });
  return line;
}

int64_t Nanoseconds(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

class Feeder {
 public:
  Feeder(const Options& options, const std::string& dds_uri)
      : opt_(options),
        names_(options.ns),
        participant_(options.domain, dds_uri, options.security),
        scene_topic_(participant_, &towsim_msgs_msg_dds__SceneInfo__desc,
                     names_.Name(wire::Topic::kSceneInfo)),
        status_topic_(participant_, &towsim_msgs_msg_dds__SimStatus__desc,
                      names_.Name(wire::Topic::kStatus)),
        pose_topic_(participant_, &nav_msgs_msg_dds__Odometry__desc,
                    names_.Name(wire::Topic::kPoseCommand, options.vessel)),
        scene_reader_(participant_, scene_topic_, dds::SceneInfoQos()),
        status_reader_(participant_, status_topic_, dds::StateQos(kStatusDepth)),
        pose_writer_(participant_, pose_topic_, dds::CommandQos()),
        waitset_(participant_),
        message_(dds::kWorldFrame, options.vessel + "_frd") {
    waitset_.Attach(scene_reader_.condition());
    waitset_.Attach(status_reader_.condition());
  }

  // `vessel` holds the history; its motion evaluates the spline as the node's would
  void SetHistory(core::Vessel vessel) {
    vessel_ = std::move(vessel);
    motion_.emplace(vessel_, calm_);
  }

  int Run();

 private:
  // the pose of time t, stamped t
  void Publish(double t);
  // waits until the node's pose reader matches (a pose written before would be lost)
  bool WaitForMatch();

  Options opt_;
  wire::TopicNames names_;
  dds::Participant participant_;
  dds::Topic scene_topic_, status_topic_, pose_topic_;
  dds::Reader<dds::SceneInfoMsg> scene_reader_;
  dds::Reader<dds::SimStatusMsg> status_reader_;
  dds::Writer<dds::OdometryMsg> pose_writer_;
  dds::WaitSet waitset_;
  dds::OdometryMessage message_;
  core::Vessel vessel_;
  core::WaveField calm_;
  std::optional<core::VesselMotion> motion_;

  std::string run_id_;  // the node's run being fed
  double h_ = 0.0;      // its step [s]
  double end_ = -1.0;   // its duration [s]; < 0: no end
  bool have_step_ = false;
  uint64_t last_step_ = 0;  // the last status step answered
  long published_ = 0;
  bool warned_end_ = false;
};

bool Feeder::WaitForMatch() {
  const double start = static_cast<double>(dds_time()) * 1e-9;
  while (pose_writer_.matched() == 0) {
    if (app::StopRequested()) return false;
    if (static_cast<double>(dds_time()) * 1e-9 - start > kMatchTimeout) return false;
    waitset_.Wait(Nanoseconds(kWaitSlice));
  }
  return true;
}

void Feeder::Publish(double t) {
  const core::VesselPose pose = motion_->At(t);
  if (!warned_end_ && t > vessel_.time_history->t.back()) {
    warned_end_ = true;
    std::fprintf(stderr,
                 "towsim_vessel_feed: warning: t = %.9g s is past the end of %s (%.9g s): the "
                 "pose continues on a straight line at the last rate\n",
                 t, opt_.history.c_str(), vessel_.time_history->t.back());
  }
  dds::ToPoseCommand(pose, t, &message_.msg);
  pose_writer_.Write(message_.msg);
  ++published_;
}

int Feeder::Run() {
  bool ended = false;
  while (!ended && !app::StopRequested()) {
    waitset_.Wait(Nanoseconds(kWaitSlice));
    int bad = 0;
    scene_reader_.TakeEach([&](const dds::SceneInfoMsg& m, const dds_sample_info_t&) {
      const wire::SceneInfo info = wire::DecodeSceneInfo(m);
      if (info.run_id == run_id_) return;
      bool found = false;
      for (const std::string& b : info.bodies) found = found || b == opt_.vessel;
      if (!found) {
        std::string list;
        for (const std::string& b : info.bodies) list += (list.empty() ? "" : ", ") + b;
        std::fprintf(stderr,
                     "towsim_vessel_feed: error: --vessel %s: not a body of the node's scene %s "
                     "(bodies: %s)\n",
                     opt_.vessel.c_str(), info.scene.c_str(), list.c_str());
        bad = 1;
        return;
      }
      // a new run: its initial pose (lockstep waits for it before the initial state)
      run_id_ = info.run_id;
      h_ = info.step_size;
      end_ = info.duration;
      have_step_ = false;
      if (!WaitForMatch()) return;
      Publish(wire::StampSeconds(m.header.stamp));
    });
    if (bad) return app::kExitBadInput;
    status_reader_.TakeEach([&](const dds::SimStatusMsg& m, const dds_sample_info_t&) {
      const wire::SimStatus s = wire::DecodeStatus(m);
      if (s.terminal()) ended = ended || s.run_id == run_id_ || run_id_.empty();
      if (s.run_id != run_id_ || run_id_.empty() || s.terminal()) return;
      if (have_step_ && s.step <= last_step_) return;  // answered (or older)
      have_step_ = true;
      last_step_ = s.step;
      // the pose of the node's next state, at t_n + h as the node's step computes it (none
      // past the run's end: the last state's status asks for no step)
      if (end_ >= 0.0 && s.t + h_ > end_ + 0.5 * h_) return;
      Publish(s.t + h_);
    });
  }
  dds_wait_for_acks(pose_writer_.get(), Nanoseconds(kAckTimeout));
  if (!opt_.quiet) {
    std::printf("towsim_vessel_feed: %s: %ld poses from %s\n", opt_.vessel.c_str(), published_,
                opt_.history.c_str());
    std::fflush(stdout);
  }
  return app::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  const app::ToolCommandLine line = CommandLine(&options);
  if (const std::optional<int> exit = line.Read(argc, argv)) return *exit;
  core::Vessel vessel;
  vessel.name = options.vessel;
  try {
    vessel.time_history = towsim::scene::ReadTimeHistoryFile(options.history, "--history");
  } catch (const std::exception& e) {  // scene::ConfigError: file, line and rule
    return line.Fail(e.what());
  }
  vessel.position = vessel.time_history->pose.front().head<3>();
  vessel.euler = vessel.time_history->pose.front().tail<3>();
  app::InstallStopHandlers();
  const std::string uri = app::DdsUriFromEnvironment("towsim_vessel_feed");
  std::unique_ptr<Feeder> feeder;
  try {
    feeder = std::make_unique<Feeder>(options, uri);
  } catch (const std::exception& e) {  // dds::DdsError, wire::SecurityError
    return line.Fail(std::string("DDS setup failed: ") + e.what());
  }
  feeder->SetHistory(std::move(vessel));
  try {
    return feeder->Run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "towsim_vessel_feed: error: %s\n", e.what());
    return app::kExitError;
  }
}
