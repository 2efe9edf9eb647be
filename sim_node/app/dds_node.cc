#include "app/dds_node.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "app/dds_pacer.h"
#include "app/dds_publisher.h"
#include "app/dds_uri.h"
#include "app/foxglove_server.h"
#include "app/mcap_recording.h"
#include "app/peer_nodes.h"
#include "app/stop_signal.h"
#include "app/strain_watch.h"
#include "app/unknown_commands.h"
#include "core/script.h"
#include "dds/command_arbiter.h"
#include "dds/entities.h"
#include "dds/port_mapping.h"
#include "dds/ros_graph.h"
#include "dds/topic_names.h"
#include "dds/translators.h"
#include "io/output_error.h"

namespace towsim::app {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kExitOk = 0;
constexpr int kExitError = 1;  // an output (CSV, recording) could not be written: disk full
constexpr int kExitBadInput = 2;
constexpr int kExitSolver = 3;
constexpr int kExitStoppedInSetup = -1;  // Setup(): a signal stopped it (Run() exits 0)

constexpr double kWaitSlice = 0.02;         // longest wait between polls of the stop signal [s]
constexpr double kIdleStatusPeriod = 0.5;   // state and status repeated while paused / waiting [s]
constexpr double kLockstepHintAfter = 5.0;  // say what lockstep waits for after [s]
// lockstep: a vehicle never heard from is waited for this long, then failsafe (README "DDS
// node"; --wait-for-controllers waits without limit before the first step) [s]
constexpr double kLockstepStartTimeout = 30.0;
constexpr double kRtfWindow = 1.0;          // achieved real-time factor over [s]
constexpr double kExitFlushTimeout = 0.02;  // for the last status to be acked [s]
// On exit, Cyclone keeps each writer with unacknowledged samples alive for WriterLingerDuration
// (default 1 s): with a subscriber that vanished without a goodbye (killed; its lease has not
// expired), stopping would take a second per writer. The node's exit waits 10 ms per writer.
constexpr const char* kLingerConfig =
    "<Internal><WriterLingerDuration>10ms</WriterLingerDuration></Internal>";
constexpr int kMaxCommandNotes = 5;            // rejected / clamped commands told on stderr
constexpr const char* kNodeName = "sim_node";  // its ROS 2 node name (dds/ros_graph.h)

constexpr uint8_t kRunning = towsim_msgs_msg_dds__SimStatus_Constants_STATE_RUNNING;
constexpr uint8_t kPaused = towsim_msgs_msg_dds__SimStatus_Constants_STATE_PAUSED;
constexpr uint8_t kWaiting = towsim_msgs_msg_dds__SimStatus_Constants_STATE_WAITING;
constexpr uint8_t kFinished = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED;
constexpr uint8_t kFailed = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;
constexpr uint8_t kStopped = towsim_msgs_msg_dds__SimStatus_Constants_STATE_STOPPED;
constexpr uint8_t kHealthOk = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_OK;
constexpr uint8_t kHealthFailsafe = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_FAILSAFE;
constexpr uint8_t kHealthError = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_ERROR;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// steps per publication of a topic at rate_hz [Hz] (<= 0: every step)
long Stride(double rate_hz, double h) {
  if (!(rate_hz > 0.0)) return 1;
  return std::max(1L, std::lround(1.0 / (rate_hz * h)));
}

std::string NewRunId(const std::string& scene) {
  std::random_device device;
  const unsigned long long bits =
      (static_cast<unsigned long long>(device()) << 32) ^ static_cast<unsigned long long>(device());
  char id[64];
  std::snprintf(id, sizeof id, "%016llx", bits);
  return scene + "-" + id;
}

class DdsNode {
 public:
  DdsNode(const core::Model& model, const DdsNodeOptions& options)
      : model_(model), opt_(options), h_(model.time.step), rate_(options.rate) {}

  int Run();

 private:
  int Setup();
  // steps until the end, a signal or a failure; returns the exit code, sets the final state.
  // Throws io::OutputError when an output cannot be written.
  int Loop(uint8_t* end_state);
  bool lockstep() const { return opt_.mode == Mode::kLockstep; }
  bool realtime() const { return opt_.mode == Mode::kRealtime; }
  bool finished() const { return steps_to_run_ >= 0 && static_cast<long>(step_) >= steps_to_run_; }
  double period() const { return h_ / rate_; }

  // takes every SimControl request and acts on it; true if the schedule changed (pause,
  // reset, rate, resume), so that a wait must end
  bool HandleControl();
  void TakeCommands();
  // lockstep: waits for the commands of step_; false if a signal or a control request
  // interrupted the wait
  bool WaitLockstep();
  // paused: status now and then, and wait for control requests
  void Idle();
  bool AllCommanded() const;  // every vehicle that takes commands has received one
  // one step with the commands held; false on solver failure
  bool DoStep();
  // back to the scene's initial state; false on solver failure
  bool DoReset();
  void PublishInitial();
  void PublishStatus(uint8_t state);
  uint8_t RunningState() const;
  void Output(const core::StepStatus& status, long wall_us);
  void Summary(double wall) const;
  // a rejected or clamped command on stderr (dds::CheckedCommand, dds::CheckedWinchCommand)
  template <class Checked>
  void NoteCommand(const Checked& c, int i);
  // arbiter entries 0 .. num_command_vehicles() - 1 are the vehicles, then the winch's
  int num_command_vehicles() const { return static_cast<int>(command_vehicles_.size()); }

  const core::Model& model_;
  DdsNodeOptions opt_;
  double h_;
  double rate_;

  std::vector<int> command_vehicles_;  // vehicle index of arbiter entry i
  int winch_entry_ = -1;               // the winch's arbiter entry; < 0: no winch
  std::optional<dds::CommandArbiter> arbiter_;
  std::optional<core::Simulation> sim_;
  std::optional<core::ScriptRunner> script_;
  std::unique_ptr<dds::Participant> participant_;
  std::unique_ptr<McapRecording> recording_;  // declared first: outlives the endpoints
  std::unique_ptr<NodeEndpoints> endpoints_;
  std::unique_ptr<dds::RosGraphNode> graph_;  // the ROS 2 node /<ns>/sim_node
  std::unique_ptr<FoxgloveServer> foxglove_;  // after endpoints_: stops before them
  std::unique_ptr<PeerNodes> peers_;          // other nodes in the namespace
  std::unique_ptr<UnknownCommands> unknown_;  // commands on topics of no commandable body
  std::string peer_note_;                     // the warning about them, for the status
  StrainWatch strain_;                        // the largest cable strain, at the output times
  PublishStrides strides_;
  long output_stride_ = 1;
  bool has_lockstep_vehicles_ = false;

  // the run (from the start or the last reset)
  std::string run_id_;
  uint64_t step_ = 0;
  long steps_to_run_ = -1;  // < 0: no end
  bool paused_ = false;
  bool waiting_for_controllers_ = false;  // --wait-for-controllers, before the first command
  long step_budget_ = 0;                  // STEP n while paused: steps left
  core::StepStatus last_status_;
  double step_wall_ = 0.0;  // [s]
  long last_output_ = -1;
  std::string control_note_;  // the last refused control request

  // the process
  Pacer pacer_;
  Clock::time_point start_wall_;
  Clock::time_point last_status_wall_;
  Clock::time_point rtf_wall_;
  double rtf_sim_ = 0.0, rtf_ = 0.0;
  long total_steps_ = 0;
  double total_sim_time_ = 0.0;  // of the runs before the last reset [s]
  int resets_ = 0;
  uint64_t prior_received_ = 0, prior_rejected_ = 0, prior_clamped_ = 0, prior_failsafes_ = 0,
           prior_timeouts_ = 0;
  int command_notes_ = 0;
  std::string failure_;
  bool output_failed_ = false;  // opt_.output threw io::OutputError
  dds::StatusSample status_;    // reused: no allocation per step
};

int DdsNode::Setup() {
  auto bad = [](const std::string& message) {
    std::fprintf(stderr, "sim_node: error: %s\n", message.c_str());
    return kExitBadInput;
  };
  if (opt_.mode == Mode::kOffline) return bad("RunDdsNode: --mode offline has no DDS");
  if (!(std::isfinite(rate_) && rate_ > 0.0)) return bad("--rate must be a number > 0");
  if (const std::string e = dds::CheckNamespace(opt_.ns); !e.empty()) {
    return bad("--namespace " + opt_.ns + ": " + e);
  }
  if (!(opt_.command_timeout > 0.0)) return bad("command_timeout must be > 0 s");
  if (!(opt_.lockstep_timeout > 0.0)) return bad("lockstep timeout must be > 0 s");
  for (const core::SphereBody& b : model_.bodies) {
    if (const std::string e = dds::CheckBodyName(b.name); !e.empty()) {
      return bad("body " + b.name + ": " + e + " (it names DDS topics)");
    }
  }
  for (const core::Vehicle& v : model_.vehicles) {
    if (const std::string e = dds::CheckBodyName(v.name); !e.empty()) {
      return bad("body " + v.name + ": " + e + " (it names DDS topics)");
    }
  }

  // the vehicles that take commands, and those lockstep waits for
  std::vector<dds::CommandArbiter::Vehicle> vehicles;
  for (size_t v = 0; v < model_.vehicles.size(); ++v) {
    const core::Vehicle& vehicle = model_.vehicles[v];
    if (!dds::IsCommandable(vehicle.params)) continue;
    command_vehicles_.push_back(static_cast<int>(v));
    const bool waited = opt_.lockstep_bodies.empty() ||
                        std::find(opt_.lockstep_bodies.begin(), opt_.lockstep_bodies.end(),
                                  vehicle.name) != opt_.lockstep_bodies.end();
    vehicles.push_back({vehicle.name, dds::LimitsOf(vehicle.params), lockstep() && waited});
    has_lockstep_vehicles_ = has_lockstep_vehicles_ || (lockstep() && waited);
  }
  // the winch: one more entry, after the vehicles (docs/winch_dds.md)
  if (model_.cable.winch) {
    for (const auto& v : vehicles) {
      if (v.name == dds::kWinchName) {
        return bad("body winch: the name is taken by the winch's topic rt/<ns>/winch/command "
                   "(rename the vehicle)");
      }
    }
    const bool waited = opt_.lockstep_bodies.empty() ||
                        std::find(opt_.lockstep_bodies.begin(), opt_.lockstep_bodies.end(),
                                  dds::kWinchName) != opt_.lockstep_bodies.end();
    winch_entry_ = static_cast<int>(vehicles.size());
    vehicles.push_back(
        dds::CommandArbiter::Vehicle::Winch(*model_.cable.winch, lockstep() && waited));
    has_lockstep_vehicles_ = has_lockstep_vehicles_ || (lockstep() && waited);
  }
  for (const std::string& name : opt_.lockstep_bodies) {
    bool found = false;
    for (const auto& v : vehicles) found = found || v.name == name;
    if (!found) {
      return bad("lockstep body " + name + ": not a vehicle of the scene that takes commands" +
                 (model_.cable.winch ? " nor the winch" : ""));
    }
  }
  arbiter_.emplace(std::move(vehicles), opt_.command_timeout);

  // the initial state (may solve statics)
  try {
    sim_.emplace(model_, [] { return StopRequested() != 0; });  // Ctrl-C in the static solve
  } catch (const core::StopRequestedError& e) {
    std::fprintf(stderr, "sim_node: %s (no DDS participant yet)\n", e.what());
    return kExitStoppedInSetup;
  } catch (const core::SolverError& e) {
    std::fprintf(stderr, "sim_node: solver failure while building the initial state: %s\n",
                 e.what());
    return kExitSolver;
  }
  script_.emplace(model_);

  // DDS: the configuration given, else $CYCLONEDDS_URI, plus the node's exit behaviour
  std::string config = opt_.dds_config;
  if (config.empty()) config = DdsUriFromEnvironment("sim_node");
  config += config.empty() ? kLingerConfig : std::string(",") + kLingerConfig;
  if (const std::string e = dds::CheckDomainPorts(opt_.domain, config); !e.empty()) {
    return bad("DDS setup failed: " + e);
  }
  try {
    participant_ = std::make_unique<dds::Participant>(
        opt_.domain, config, opt_.security,
        opt_.open_outputs ? dds::Admit::kOpenOutputs : dds::Admit::kAuthenticated);
    endpoints_ = std::make_unique<NodeEndpoints>(*participant_, dds::TopicNames(opt_.ns), *sim_,
                                                 command_vehicles_);
    std::vector<std::string> commanded;
    for (int i = 0; i < num_command_vehicles(); ++i) {
      commanded.push_back(arbiter_->vehicle(i).name);
    }
    unknown_ = std::make_unique<UnknownCommands>(*participant_, opt_.ns, commanded);
    // another node in this domain and namespace: refused (README "DDS node"); nothing of
    // this node is published yet
    peers_ = std::make_unique<PeerNodes>(*participant_, dds::TopicNames(opt_.ns));
    if (peers_->WaitForAny(PeerNodes::kStartWindow, [] { return StopRequested() != 0; })) {
      const std::string where = "DDS domain " + std::to_string(opt_.domain) + ", namespace " +
                                opt_.ns + " (" + peers_->Names() + ")";
      if (!opt_.allow_another_node) {
        return bad("another sim_node runs on " + where +
                   ": controllers would drive both; stop it, pick another --domain or "
                   "--namespace, or pass --allow-another-node");
      }
      peer_note_ = "warning: another node runs on " + where;
      std::fprintf(stderr, "sim_node: %s\n", peer_note_.c_str());
    }
    // every reader and writer the node has now (the readers UnknownCommands makes later for
    // commands on topics of no commandable body are not listed)
    std::vector<dds_entity_t> readers = endpoints_->readers();
    readers.push_back(peers_->reader());
    graph_ = std::make_unique<dds::RosGraphNode>(participant_->get(), opt_.ns, kNodeName, readers,
                                                 endpoints_->writers());
  } catch (const dds::SecurityError& e) {
    return bad(e.what());
  } catch (const std::runtime_error& e) {  // dds::DdsError, the ROS 2 graph entry
    std::fprintf(stderr, "sim_node: error: DDS setup failed: %s\n", e.what());
    return kExitBadInput;
  }
  if (!opt_.record_file.empty()) {
    try {
      recording_ = std::make_unique<McapRecording>(opt_.record_file, opt_.overwrite);
      endpoints_->StartRecording(*participant_, recording_.get());
    } catch (const io::OutputError& e) {  // created, not written: disk full
      std::fprintf(stderr, "sim_node: error: --record %s: %s\n", opt_.record_file.c_str(),
                   e.what());
      return kExitError;
    } catch (const std::exception& e) {
      return bad("--record " + opt_.record_file + ": " + e.what());
    }
  }

  // after the recording: its channels are the recording's too
  if (opt_.foxglove_port >= 0) {
    try {
      foxglove_ = std::make_unique<FoxgloveServer>(FoxgloveServer::Options{
          "127.0.0.1", static_cast<uint16_t>(opt_.foxglove_port), "sim_node " + opt_.ns});
      endpoints_->StartFoxglove(*participant_, foxglove_.get());
      foxglove_->Start();
    } catch (const std::exception& e) {
      return bad("--foxglove " + std::to_string(opt_.foxglove_port) + ": " + e.what());
    }
    std::printf("sim_node: Foxglove at ws://127.0.0.1:%u\n",
                static_cast<unsigned>(foxglove_->port()));
    std::fflush(stdout);
  }

  strides_.clock = Stride(opt_.rates.clock, h_);
  strides_.odom = Stride(opt_.rates.odom, h_);
  strides_.cable_force = Stride(opt_.rates.cable_force, h_);
  strides_.sensors = Stride(opt_.rates.sensors, h_);
  strides_.status = lockstep() ? 1 : Stride(opt_.rates.status, h_);  // lockstep: every step
  strides_.cable_state =
      Stride(opt_.rates.cable_state < 0.0 ? model_.time.output_rate : opt_.rates.cable_state, h_);
  strides_.markers =
      Stride(opt_.rates.markers < 0.0 ? model_.time.output_rate : opt_.rates.markers, h_);
  output_stride_ = Stride(model_.time.output_rate, h_);
  if (std::isfinite(opt_.duration)) steps_to_run_ = std::max(0L, std::lround(opt_.duration / h_));
  paused_ = opt_.start_paused;
  waiting_for_controllers_ = opt_.wait_for_controllers && num_command_vehicles() > 0;
  run_id_ = NewRunId(model_.name);
  return kExitOk;
}

int DdsNode::Run() {
  InstallStopHandlers();
  if (const int rc = Setup(); rc != kExitOk) return rc == kExitStoppedInSetup ? kExitOk : rc;

  int exit_code = kExitOk;
  uint8_t end_state = kFinished;
  start_wall_ = rtf_wall_ = last_status_wall_ = Clock::now();
  try {
    PublishInitial();
    if (realtime()) pacer_.Start(period());
    exit_code = Loop(&end_state);
  } catch (const io::OutputError& e) {
    // an output failed (README "Exit codes"): the run ends, FAILED with the reason, and what
    // still works (DDS, the other output) ends cleanly
    exit_code = kExitError;
    end_state = kFailed;
    failure_ = std::string("output failed: ") + e.what();
    std::fprintf(stderr, "sim_node: %s\n", failure_.c_str());
    if (recording_ && recording_->failed()) endpoints_->StopRecording();
    if (output_failed_) opt_.output = nullptr;
  }

  PublishStatus(end_state);
  endpoints_->Flush(kExitFlushTimeout);
  if (last_output_ != static_cast<long>(step_) && end_state != kFailed) {
    Output(last_status_, std::lround(step_wall_ * 1e6));
  }
  Summary(Seconds(Clock::now() - start_wall_));
  if (recording_) {
    try {
      recording_->Close();
      std::fprintf(stderr, "sim_node: recorded %llu messages on %zu topics to %s\n",
                   static_cast<unsigned long long>(recording_->message_count()),
                   recording_->topic_count(), recording_->path().c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr,
                   "sim_node: error: the recording %s is incomplete (%s); towsim_export "
                   "--recover reads what it holds\n",
                   recording_->path().c_str(), e.what());
      exit_code = kExitError;
    }
  }
  return exit_code;
}

int DdsNode::Loop(uint8_t* end_state) {
  for (;;) {
    if (StopRequested()) {
      *end_state = kStopped;
      return kExitOk;
    }
    HandleControl();
    if (!failure_.empty()) {
      *end_state = kFailed;
      return kExitSolver;
    }
    if (finished()) return kExitOk;
    if (paused_ && step_budget_ == 0) {
      Idle();
      continue;
    }
    TakeCommands();
    if (waiting_for_controllers_) {
      if (!AllCommanded()) {
        Idle();
        continue;
      }
      waiting_for_controllers_ = false;
      if (realtime()) pacer_.Start(period());  // the pacing starts with the first step
    }
    if (lockstep() && !WaitLockstep()) continue;
    if (realtime()) {
      const bool on_time = pacer_.WaitForDeadline(
          [this] { return !StopRequested() && !HandleControl(); }, kWaitSlice);
      if (!on_time) continue;
      TakeCommands();  // the freshest
    }
    if (!DoStep()) {
      *end_state = kFailed;
      return kExitSolver;
    }
  }
}

void DdsNode::PublishInitial() {
  dds::SceneInfoSample info;
  info.run_id = run_id_;
  info.scene = model_.name;
  info.mode = ModeName(opt_.mode);
  info.time = sim_->time();
  info.step_size = h_;
  info.duration = steps_to_run_ < 0 ? -1.0 : static_cast<double>(steps_to_run_) * h_;
  info.command_timeout = opt_.command_timeout;
  for (int b = 0; b < sim_->num_bodies(); ++b) info.bodies.push_back(sim_->body_name(b));
  for (int i = 0; i < num_command_vehicles(); ++i) {
    info.commanded_bodies.push_back(arbiter_->vehicle(i).name);
  }
  info.cable_nodes = sim_->num_nodes();
  if (const std::optional<core::WinchParams>& w = model_.cable.winch) {
    info.has_winch = true;
    info.winch_min_length = w->min_length;
    info.winch_max_length = w->max_length;
    info.winch_max_speed = w->max_speed;
    info.winch_max_acceleration = w->max_acceleration;
  }
  endpoints_->PublishSceneInfo(info);

  last_status_ = core::StepStatus{};
  endpoints_->PublishState(*sim_, step_, strides_, /*all=*/true);
  PublishStatus(RunningState());
  Output(last_status_, 0);
}

uint8_t DdsNode::RunningState() const {
  if (paused_ && step_budget_ == 0) return kPaused;
  if (waiting_for_controllers_) return kWaiting;
  if (has_lockstep_vehicles_ && !arbiter_->ReadyFor(step_)) return kWaiting;
  return kRunning;
}

void DdsNode::PublishStatus(uint8_t state) {
  last_status_wall_ = Clock::now();
  dds::StatusSample& s = status_;
  if (s.run_id != run_id_) s.run_id = run_id_;
  if (s.mode.empty()) s.mode = ModeName(opt_.mode);
  s.state = state;
  s.step = step_;
  s.sim_time = sim_->time();
  s.rate = realtime() ? rate_ : 0.0;
  s.real_time_factor = rtf_;
  s.step_wall_time = step_wall_;
  s.lateness = pacer_.stats().last();
  s.lateness_max = pacer_.stats().max();
  s.overruns = pacer_.overruns();
  s.newton_iterations = last_status_.iterations;
  s.residual = last_status_.residual;
  s.coupling_iterations = sim_->coupling_iterations();
  s.substeps = last_status_.substeps;
  s.failsafe_count = arbiter_->failsafe_count();
  s.failsafe_bodies.clear();
  for (int i = 0; i < arbiter_->size(); ++i) {
    if (arbiter_->failsafe(i)) s.failsafe_bodies.push_back(arbiter_->vehicle(i).name);
  }
  s.commands_received = arbiter_->received() + unknown_->count();
  s.commands_rejected = arbiter_->rejected() + unknown_->count();
  s.commands_clamped = arbiter_->clamped();
  s.lockstep_timeouts = arbiter_->lockstep_timeouts();
  if (peers_ && peers_->Poll()) {
    // one that appeared while this node runs: both go on, warned (README "DDS node")
    peer_note_ = "warning: another node runs on DDS domain " + std::to_string(opt_.domain) +
                 ", namespace " + opt_.ns + " (" + peers_->Names() + ")";
    std::fprintf(stderr, "sim_node: %s\n", peer_note_.c_str());
  }
  if (state == kFailed) {
    s.health = kHealthError;
    s.message = failure_;
  } else if (!s.failsafe_bodies.empty()) {
    s.health = kHealthFailsafe;
    s.message = arbiter_->last_event();
  } else {
    s.health = kHealthOk;
    if (!peer_note_.empty()) {
      s.message = peer_note_;
    } else if (strain_.extreme()) {
      s.message = strain_.Warning();
    } else if (!control_note_.empty()) {
      s.message = control_note_;
    } else if (!unknown_->last_event().empty() && arbiter_->last_event().empty()) {
      s.message = unknown_->last_event();
    } else if (s.message != arbiter_->last_event()) {
      s.message = arbiter_->last_event();
    }
  }
  endpoints_->PublishStatus(s);
}

bool DdsNode::HandleControl() {
  bool changed = false;
  endpoints_->control_reader().TakeEach([&](const dds::SimControlMsg& msg, const auto&) {
    const dds::ControlRequest r = dds::FromSimControl(msg);
    if (r.kind != dds::ControlRequest::kInvalid) control_note_.clear();
    switch (r.kind) {
      case dds::ControlRequest::kPause:
        changed = changed || !paused_ || step_budget_ > 0;
        paused_ = true;
        step_budget_ = 0;
        break;
      case dds::ControlRequest::kResume:
        changed = changed || paused_;
        paused_ = false;
        step_budget_ = 0;
        break;
      case dds::ControlRequest::kStep:
        if (!paused_) {
          control_note_ = "sim_control: STEP ignored: the node is not paused";
          break;
        }
        step_budget_ += r.steps;
        changed = true;
        break;
      case dds::ControlRequest::kReset:
        DoReset();  // on failure, failure_ ends the run
        changed = true;
        break;
      case dds::ControlRequest::kSetRate:
        rate_ = r.rate;
        changed = true;
        break;
      case dds::ControlRequest::kInvalid:
        control_note_ = "sim_control: " + r.error;
        std::fprintf(stderr, "sim_node: %s\n", control_note_.c_str());
        break;
    }
  });
  if (changed && failure_.empty()) {
    if (realtime()) pacer_.Start(period());
    PublishStatus(RunningState());
  }
  return changed;
}

template <class Checked>
void DdsNode::NoteCommand(const Checked& c, int i) {
  if (c.verdict == dds::CheckedCommand::kAccepted) return;
  if (command_notes_ >= kMaxCommandNotes) return;
  ++command_notes_;
  std::fprintf(stderr, "sim_node: %s at step %llu: %s%s\n", arbiter_->vehicle(i).name.c_str(),
               static_cast<unsigned long long>(step_),
               c.verdict == dds::CheckedCommand::kRejected ? "command rejected: " : "",
               c.reason.c_str());
  if (command_notes_ == kMaxCommandNotes) {
    std::fprintf(stderr, "sim_node: (further rejected or clamped commands: see the status)\n");
  }
}

void DdsNode::TakeCommands() {
  if (unknown_->Poll() > 0 && command_notes_ < kMaxCommandNotes) {
    ++command_notes_;
    std::fprintf(stderr, "sim_node: %s\n", unknown_->last_event().c_str());
  }
  const double t = sim_->time();
  for (int i = 0; i < endpoints_->num_command_readers(); ++i) {
    endpoints_->command_reader(i).TakeEach(
        [&](const dds::ActuatorCommandMsg& msg, const dds_sample_info_t&) {
          NoteCommand(arbiter_->Receive(i, msg, t), i);
        });
  }
  if (winch_entry_ >= 0) {
    endpoints_->winch_reader()->TakeEach(
        [&](const dds::WinchCommandMsg& msg, const dds_sample_info_t&) {
          NoteCommand(arbiter_->Receive(winch_entry_, msg, t), winch_entry_);
        });
  }
}

bool DdsNode::WaitLockstep() {
  if (arbiter_->ReadyFor(step_)) return true;
  const Clock::time_point begin = Clock::now();
  bool timed_out = false, start_timed_out = false, hinted = false;
  for (;;) {
    if (StopRequested()) return false;
    if (HandleControl()) return false;
    TakeCommands();
    if (arbiter_->ReadyFor(step_)) return true;
    const Clock::time_point now = Clock::now();
    const double waited = Seconds(now - begin);
    // a vehicle heard from (even a rejected command) after lockstep_timeout, one never heard
    // from after kLockstepStartTimeout: failsafe, no longer waited for
    const bool start_over = waited >= kLockstepStartTimeout;
    if ((!timed_out && waited >= opt_.lockstep_timeout) || (start_over && !start_timed_out)) {
      timed_out = true;
      start_timed_out = start_over;
      if (arbiter_->TimeOut(step_, start_over) > 0) {
        std::fprintf(stderr, "sim_node: %s\n", arbiter_->last_event().c_str());
        PublishStatus(RunningState());
        if (arbiter_->ReadyFor(step_)) return true;
      }
    }
    if (!hinted && waited >= kLockstepHintAfter) {
      hinted = true;
      std::string names;
      for (int i : arbiter_->Missing(step_)) {
        names += (names.empty() ? "" : ", ") + arbiter_->vehicle(i).name;
      }
      std::fprintf(stderr,
                   "sim_node: lockstep: waiting for the commands of step %llu (%s) on "
                   "rt%s/<body>/command\n",
                   static_cast<unsigned long long>(step_), names.c_str(),
                   opt_.ns == "/" ? "" : opt_.ns.c_str());
    }
    if (Seconds(now - last_status_wall_) >= kIdleStatusPeriod) {
      // again, for late joiners (volatile topics): the state, then the status
      endpoints_->PublishState(*sim_, step_, strides_, /*all=*/true);
      PublishStatus(kWaiting);
    }
    double slice = kWaitSlice;
    if (!timed_out) slice = std::min(slice, std::max(1e-4, opt_.lockstep_timeout - waited));
    endpoints_->WaitForInput(slice);
  }
}

void DdsNode::Idle() {
  if (Seconds(Clock::now() - last_status_wall_) >= kIdleStatusPeriod) {
    endpoints_->PublishState(*sim_, step_, strides_, /*all=*/true);
    PublishStatus(RunningState());
  }
  endpoints_->WaitForInput(kWaitSlice);
}

bool DdsNode::AllCommanded() const {
  for (int i = 0; i < num_command_vehicles(); ++i) {
    if (!arbiter_->commanded(i)) return false;
  }
  return true;
}

bool DdsNode::DoStep() {
  core::Simulation& sim = *sim_;
  arbiter_->CheckTimeouts(sim.time());
  // the script entries due first, then the controllers' commands (and failsafes) over them
  if (opt_.use_script) script_->Apply(&sim);
  for (int i = 0; i < num_command_vehicles(); ++i) {
    core::VehicleCommand command;
    if (arbiter_->Take(i, &command)) sim.SetVehicleCommand(command_vehicles_[i], command);
  }
  if (core::WinchCommand winch; winch_entry_ >= 0 && arbiter_->Take(winch_entry_, &winch)) {
    sim.SetWinchCommand(winch);
  }

  const Clock::time_point t0 = Clock::now();
  const double t_before = sim.time();
  const core::StepStatus status = sim.Step();
  if (!status.ok()) {
    char text[160];
    std::snprintf(text, sizeof text, "solver failure at t = %.9g s (step %llu): ", t_before,
                  static_cast<unsigned long long>(step_ + 1));
    failure_ = text + status.message;
    std::fprintf(stderr, "sim_node: %s\n", failure_.c_str());
    last_status_ = status;
    return false;
  }
  last_status_ = status;
  ++step_;
  ++total_steps_;
  if (step_budget_ > 0) --step_budget_;

  endpoints_->PublishState(sim, step_, strides_, /*all=*/false);
  const Clock::time_point t1 = Clock::now();
  step_wall_ = Seconds(t1 - t0);

  // achieved real-time factor over the last window
  const double window = Seconds(t1 - rtf_wall_);
  if (window >= kRtfWindow || total_steps_ == 1) {
    rtf_ = window > 0.0 ? (sim.time() - rtf_sim_) / window : 0.0;
    if (window >= kRtfWindow) {
      rtf_wall_ = t1;
      rtf_sim_ = sim.time();
    }
  }
  if (step_ % static_cast<uint64_t>(strides_.status) == 0 || (paused_ && step_budget_ == 0)) {
    PublishStatus(RunningState());
  }
  if (static_cast<long>(step_) % output_stride_ == 0) {
    if (strain_.Observe(sim)) std::fprintf(stderr, "sim_node: %s\n", strain_.Warning().c_str());
    Output(status, std::lround(step_wall_ * 1e6));
  }
  if (realtime()) pacer_.EndStep();
  return true;
}

bool DdsNode::DoReset() {
  std::optional<core::Simulation> fresh;  // the old run stays as it is if this throws
  try {
    fresh.emplace(model_, [] { return StopRequested() != 0; });
  } catch (const core::StopRequestedError&) {
    return true;  // the run loop ends on the stop request, with the old run's state
  } catch (const core::SolverError& e) {
    failure_ = std::string("reset: the initial state could not be built: ") + e.what();
    std::fprintf(stderr, "sim_node: solver failure: %s\n", failure_.c_str());
    return false;
  }
  total_sim_time_ += sim_->time();
  prior_received_ += arbiter_->received();
  prior_rejected_ += arbiter_->rejected();
  prior_clamped_ += arbiter_->clamped();
  prior_failsafes_ += arbiter_->failsafe_count();
  prior_timeouts_ += arbiter_->lockstep_timeouts();
  *sim_ = std::move(*fresh);
  script_.emplace(model_);
  arbiter_->Reset();
  step_ = 0;
  step_budget_ = 0;
  last_status_ = core::StepStatus{};
  step_wall_ = 0.0;
  last_output_ = -1;
  control_note_.clear();
  run_id_ = NewRunId(model_.name);
  ++resets_;
  rtf_wall_ = Clock::now();
  rtf_sim_ = sim_->time();
  PublishInitial();
  return true;
}

void DdsNode::Output(const core::StepStatus& status, long wall_us) {
  if (!opt_.output) return;
  try {
    opt_.output(*sim_, status, wall_us);
  } catch (const io::OutputError&) {
    output_failed_ = true;
    throw;
  }
  last_output_ = static_cast<long>(step_);
}

void DdsNode::Summary(double wall) const {
  const double sim_time = total_sim_time_ + sim_->time();
  const double rtf = wall > 0.0 ? sim_time / wall : 0.0;
  char line[640];
  int n = std::snprintf(
      line, sizeof line,
      "sim_node: %s: %s, %ld steps, %.6g s simulated in %.3f s (RTF %.*f), overruns %llu, "
      "failsafes %llu, commands %llu (rejected %llu, clamped %llu), lockstep timeouts %llu, "
      "resets %d",
      model_.name.c_str(), ModeName(opt_.mode), total_steps_, sim_time, wall, rtf < 10.0 ? 2 : 0,
      rtf, static_cast<unsigned long long>(pacer_.overruns()),
      static_cast<unsigned long long>(prior_failsafes_ + arbiter_->failsafe_count()),
      static_cast<unsigned long long>(prior_received_ + arbiter_->received() + unknown_->count()),
      static_cast<unsigned long long>(prior_rejected_ + arbiter_->rejected() + unknown_->count()),
      static_cast<unsigned long long>(prior_clamped_ + arbiter_->clamped()),
      static_cast<unsigned long long>(prior_timeouts_ + arbiter_->lockstep_timeouts()), resets_);
  if (strain_.extreme() && n > 0 && n < static_cast<int>(sizeof line)) {
    n += std::snprintf(line + n, sizeof line - n, "%s", strain_.SummaryPart().c_str());
  }
  if (peers_ && !peers_->run_ids().empty() && n > 0 && n < static_cast<int>(sizeof line)) {
    n += std::snprintf(line + n, sizeof line - n, ", other nodes in the namespace: %s",
                       peers_->Names().c_str());
  }
  if (realtime() && pacer_.stats().count() > 0 && n > 0 && n < static_cast<int>(sizeof line)) {
    const LatenessStats& l = pacer_.stats();
    std::snprintf(line + n, sizeof line - n, ", lateness p50 %.0f us p99 %.0f us max %.0f us",
                  1e6 * l.Quantile(0.50), 1e6 * l.Quantile(0.99), 1e6 * l.max());
  }
  std::printf("%s\n", line);
  std::fflush(stdout);
}

}  // namespace

int RunDdsNode(const core::Model& model, const DdsNodeOptions& options) {
  DdsNode node(model, options);
  return node.Run();
}

}  // namespace towsim::app
