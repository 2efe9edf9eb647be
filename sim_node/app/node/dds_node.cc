#include "app/node/dds_node.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/common/exit_codes.h"
#include "app/common/stop_signal.h"
#include "app/node/dds_pacer.h"
#include "app/node/failsafe_failure.h"
#include "app/node/node_setup.h"
#include "app/node/run_control.h"
#include "app/node/run_counters.h"
#include "app/node/fold_watch.h"
#include "app/node/strain_watch.h"
#include "dds/actuator_state_translator.h"
#include "dds/command_arbiter.h"
#include "dds/translators.h"
#include "io/output_error.h"
#include "wire/topic_names.h"

namespace towsim::app {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kWaitSlice = 0.02;         // longest wait between polls of the stop signal [s]
constexpr double kIdleStatusPeriod = 0.5;   // state and status repeated while paused / waiting [s]
constexpr double kLockstepHintAfter = 5.0;  // say what lockstep waits for after [s]
// lockstep: a vehicle never heard from is waited for this long (or --lockstep-timeout if
// longer), then failsafe (docs/topics.md, "Commands and lockstep"; --wait-for-controllers
// waits without limit before the first step) [s]
constexpr double kLockstepStartTimeout = 30.0;
constexpr double kRtfWindow = 1.0;          // achieved real-time factor over [s]
constexpr double kExitFlushTimeout = 0.02;  // for the last status to be acked [s]
constexpr int kMaxCommandNotes = 5;         // rejected / clamped commands told on stderr

// a command on the winch's topic while the winch follows the script (--winch script)
constexpr const char* kWinchScriptRejected =
    "winch: command rejected (the winch follows the scene's script: --winch script)";

constexpr uint8_t kWaiting = towsim_msgs_msg_dds__SimStatus_Constants_STATE_WAITING;
constexpr uint8_t kFailed = towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

std::string NewRunId(const std::string& scene) {
  std::random_device device;
  const unsigned long long bits =
      (static_cast<unsigned long long>(device()) << 32) ^ static_cast<unsigned long long>(device());
  char id[64];
  std::snprintf(id, sizeof id, "%016llx", bits);
  return scene + "-" + id;
}

// the run: steps, run control (app/node/run_control.h), commands, status and outputs
class DdsNode {
 public:
  DdsNode(const core::Model& model, const DdsNodeOptions& options)
      : model_(model),
        opt_(options),
        h_(model.time.step),
        control_(RunControl::Options{options.start_paused, false, -1, options.rate}) {}

  int Run();

 private:
  // steps until the end, a signal or a failure; returns the exit code (the end state in
  // control_). Throws io::OutputError when an output cannot be written.
  int Loop();
  // --fail-on-failsafe: notes the first failsafe or lockstep timeout (failsafe_failure_); the
  // loop ends the run before its next step
  void NoteFailsafe(std::string failure);
  bool lockstep() const { return opt_.mode == Mode::kLockstep; }
  bool realtime() const { return opt_.mode == Mode::kRealtime; }
  double period() const { return h_ / control_.rate(); }

  // takes every SimControl request and acts on it; true if the schedule changed (pause,
  // reset, rate, resume), so that a wait must end
  bool HandleControl();
  void TakeCommands();
  // lockstep: waits for the commands of `step` (call it right after HandleControl and
  // TakeCommands); false if a signal or a control request interrupted the wait. step -1: the
  // external vessels' poses of the initial state (docs/vessels.md "External vessels"), before
  // it is published; control requests then wait until it ends (a RESET publishes the initial
  // state from within HandleControl)
  bool WaitLockstep(int64_t step);
  // the external vessels' newly received poses given to the simulation: a pose of the state
  // now or of the next one at the simulation's own time of that state (its stamp carries
  // whole nanoseconds), any other at its stamp
  void ApplyPoses();
  // before a step: the external vessels without a pose for its end, counted; the start of a
  // run of them said on stderr
  void CountMissingPoses();
  // paused: status now and then, and wait for control requests
  void Idle();
  // the arbiter entries --wait-for-controllers waits for: every vehicle that takes commands,
  // and the winch where lockstep waits for it (docs/winch_dds.md)
  std::vector<int> Awaited() const;
  bool AllCommanded() const;  // every entry of Awaited() has received a valid command
  // "tow_vehicle (rt/towsim/tow_vehicle/command), winch (rt/towsim/winch/command)"
  std::string Describe(const std::vector<int>& entries) const;
  // --wait-for-controllers: says on stderr whom the first step waits for, when that changes
  void NoteAwaited();
  // one step with the commands held; false on solver failure
  bool DoStep();
  // back to the scene's initial state; false on solver failure
  bool DoReset();
  void PublishInitial();
  // the state of step_ on the state topics (NodeEndpoints::PublishState), the vehicles'
  // actuator flags first: the arbiter's failsafe flags and command_source_
  void PublishState(bool all);
  void PublishStatus(uint8_t state);
  uint8_t RunningState() const;
  void Output(const core::StepStatus& status, long wall_us);
  void Summary(double wall) const;
  // the counters of this run (since the start or the last RESET)
  RunCounters ThisRun() const;
  // the process's: the runs before the last RESET, this one, and what no RESET clears
  RunCounters Totals() const;
  // a rejected or clamped command on stderr (dds::CheckedCommand, dds::CheckedWinchCommand)
  template <class Checked>
  void NoteCommand(const Checked& c, int i);
  // arbiter entries 0 .. num_command_vehicles() - 1 are the vehicles, then the winch's
  int num_command_vehicles() const { return static_cast<int>(n_.command_vehicles.size()); }
  // the arbiter entry of an external vessel, of a winch
  bool is_vessel_entry(int i) const { return n_.arbiter->vehicle(i).vessel; }
  bool is_winch_entry(int i) const { return n_.arbiter->vehicle(i).winch; }

  const core::Model& model_;
  DdsNodeOptions opt_;
  double h_;
  NodeParts n_;  // app/node/node_setup.h
  RunControl control_;
  StrainWatch strain_;  // the largest cable strain, at the output times
  FoldWatch fold_{model_.time.step};  // folded elements, every FoldWatch::kCheckInterval

  // the run (from the start or the last reset)
  std::string run_id_;
  uint64_t step_ = 0;
  core::StepStatus last_status_;
  double step_wall_ = 0.0;  // [s]
  long last_output_ = -1;

  // the process
  Pacer pacer_;
  Clock::time_point start_wall_;
  Clock::time_point last_status_wall_;
  Clock::time_point rtf_wall_;
  double rtf_sim_ = 0.0, rtf_ = 0.0;
  RunCounters before_reset_;  // the runs before the last RESET, and the RESETs
  int command_notes_ = 0;
  std::vector<int> late_notes_;  // by external vessel: runs of missing poses said on stderr
  std::string awaited_note_;  // the last NoteAwaited() line
  // --winch script: commands on the winch's topic, rejected (received and rejected in the
  // status, with the commands on topics of no commandable body)
  uint64_t winch_script_rejected_ = 0;
  bool output_failed_ = false;  // opt_.output threw io::OutputError
  std::vector<bool> failsafe_;  // by vehicle, for opt_.output (reused: no allocation per output)
  // by vehicle: who set the command it holds (dds::kSource*, docs/topics.md "Actuator state"),
  // and the vehicles a script entry set in this step (reused)
  std::vector<uint8_t> command_source_;
  std::vector<bool> script_set_;
  std::vector<bool> winch_failsafe_;  // by winch, the same
  // --fail-on-failsafe: why the run ends (app/node/failsafe_failure.h); empty: no failsafe yet
  std::string failsafe_failure_;
  dds::StatusSample status_;  // reused: no allocation per step
};

int DdsNode::Run() {
  InstallStopHandlers();
  if (const int rc = SetUpNode(model_, opt_, &n_); rc != kExitOk) {
    return rc == kExitStoppedInSetup ? kExitOk : rc;
  }
  control_ = RunControl(RunControl::Options{opt_.start_paused,
                                            opt_.wait_for_controllers && !Awaited().empty(),
                                            n_.steps_to_run, opt_.rate});
  run_id_ = NewRunId(model_.name);
  command_source_.assign(model_.vehicles.size(), dds::kSourceNone);

  int exit_code = kExitOk;
  start_wall_ = rtf_wall_ = last_status_wall_ = Clock::now();
  try {
    PublishInitial();
    if (realtime()) pacer_.Start(period());
    exit_code = Loop();
  } catch (const io::OutputError& e) {
    // an output failed (docs/command_line.md "Exit codes"): the run ends, FAILED with the reason,
    // and what still works (DDS, the other output) ends cleanly
    exit_code = kExitError;
    control_.Fail(std::string("output failed: ") + e.what());
    std::fprintf(stderr, "sim_node: %s\n", control_.failure().c_str());
    if (n_.recording && n_.recording->failed()) n_.endpoints->StopRecording();
    if (output_failed_) opt_.output = nullptr;
  }

  const uint8_t end_state = control_.EndState();
  PublishStatus(end_state);
  n_.endpoints->Flush(kExitFlushTimeout);
  // the last state is written unless a step or an output failed (a failsafe leaves a good state)
  if (last_output_ != static_cast<long>(step_) &&
      (end_state != kFailed || exit_code == kExitFailsafe)) {
    Output(last_status_, std::lround(step_wall_ * 1e6));
  }
  Summary(Seconds(Clock::now() - start_wall_));
  if (n_.foxglove) {  // its clients closed first: the counts are final
    n_.foxglove->Stop();
    std::fprintf(stderr, "sim_node: Foxglove: %s\n",
                 FoxgloveServer::SummaryText(n_.foxglove->totals()).c_str());
  }
  if (n_.recording) {
    try {
      n_.recording->Close();
      std::fprintf(stderr, "sim_node: recorded %llu messages on %zu topics to %s\n",
                   static_cast<unsigned long long>(n_.recording->message_count()),
                   n_.recording->topic_count(), n_.recording->path().c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr,
                   "sim_node: error: the recording %s is incomplete (%s); towsim_export "
                   "--recover reads what it holds\n",
                   n_.recording->path().c_str(), e.what());
      exit_code = kExitError;
    }
  }
  return exit_code;
}

int DdsNode::Loop() {
  for (;;) {
    // --fail-on-failsafe: the step in which the first failsafe or lockstep timeout happened is
    // done (or a signal or a control request ended the wait for it): the run ends here
    if (!failsafe_failure_.empty()) {
      control_.Fail(failsafe_failure_);
      std::fprintf(stderr, "sim_node: error: %s (--fail-on-failsafe)\n", failsafe_failure_.c_str());
      return kExitFailsafe;
    }
    if (StopRequested()) {
      control_.Stop();
      return kExitOk;
    }
    HandleControl();
    if (control_.failed()) return kExitSolver;
    if (control_.finished(step_)) return kExitOk;
    if (control_.holding()) {
      Idle();
      continue;
    }
    TakeCommands();
    if (control_.waiting_for_controllers()) {
      if (!AllCommanded()) {
        NoteAwaited();
        Idle();
        continue;
      }
      control_.ControllersReady();
      if (realtime()) pacer_.Start(period());  // the pacing starts with the first step
    }
    if (lockstep() && !WaitLockstep(static_cast<int64_t>(step_))) continue;
    if (realtime()) {
      const bool on_time = pacer_.WaitForDeadline(
          [this] { return !StopRequested() && !HandleControl(); }, kWaitSlice);
      if (!on_time) continue;
      TakeCommands();  // the freshest
    }
    if (!DoStep()) return kExitSolver;
  }
}

void DdsNode::PublishInitial() {
  dds::SceneInfoSample info;
  info.run_id = run_id_;
  info.scene = model_.name;
  info.mode = ModeName(opt_.mode);
  info.time = n_.sim->time();
  info.step_size = h_;
  info.duration =
      control_.steps_to_run() < 0 ? -1.0 : static_cast<double>(control_.steps_to_run()) * h_;
  info.command_timeout = opt_.command_timeout;
  dds::SceneOf(*n_.sim, &info);  // bodies, cables, winch
  for (int i = 0; i < num_command_vehicles(); ++i) {
    info.commanded_bodies.push_back(n_.arbiter->vehicle(i).name);
  }
  n_.endpoints->PublishSceneInfo(info);

  // lockstep: the external vessels' poses of the initial state before it is published
  // (docs/vessels.md "External vessels"); elsewhere the scene's pose until one comes
  if (lockstep() && !n_.vessel_entries.empty()) {
    TakeCommands();
    WaitLockstep(-1);
  }
  ApplyPoses();
  last_status_ = core::StepStatus{};
  PublishState(/*all=*/true);
  PublishStatus(RunningState());
  Output(last_status_, 0);
}

void DdsNode::PublishState(bool all) {
  for (int i = 0; i < num_command_vehicles(); ++i) {
    const int v = n_.command_vehicles[i];
    n_.endpoints->SetActuatorFlags(v,
                                   dds::ActuatorFlags{n_.arbiter->failsafe(i), command_source_[v]});
  }
  n_.endpoints->PublishState(*n_.sim, step_, n_.strides, all);
}

uint8_t DdsNode::RunningState() const {
  return control_.State(n_.has_lockstep_vehicles && !n_.arbiter->ReadyFor(step_));
}

void DdsNode::PublishStatus(uint8_t state) {
  last_status_wall_ = Clock::now();
  dds::StatusSample& s = status_;
  if (s.run_id != run_id_) s.run_id = run_id_;
  if (s.mode.empty()) s.mode = ModeName(opt_.mode);
  s.state = state;
  s.step = step_;
  s.sim_time = n_.sim->time();
  s.rate = realtime() ? control_.rate() : 0.0;
  s.real_time_factor = rtf_;
  s.step_wall_time = step_wall_;
  s.lateness = pacer_.stats().last();
  s.lateness_max = pacer_.stats().max();
  s.overruns = pacer_.overruns();
  s.newton_iterations = last_status_.iterations;
  s.residual = last_status_.residual;
  s.coupling_iterations = n_.sim->coupling_iterations();
  s.substeps = last_status_.substeps;
  if (n_.peers && n_.peers->Poll()) {
    // one that appeared while this node runs: both go on, warned (docs/topics.md)
    n_.peer_note = "warning: another node runs on DDS domain " + std::to_string(opt_.domain) +
                   ", namespace " + opt_.ns + " (" + n_.peers->Names() + ")";
    std::fprintf(stderr, "sim_node: %s\n", n_.peer_note.c_str());
  }
  std::string strain;  // empty unless the strain is extreme: no allocation
  if (strain_.extreme()) strain = strain_.Warning();
  dds::StatusNotes notes;
  notes.failure = control_.failure();
  notes.peer = n_.peer_note;
  notes.strain = strain;
  notes.control = control_.note();
  notes.unknown_commands = n_.unknown->count() + winch_script_rejected_;
  notes.unknown_event = winch_script_rejected_ > 0 ? std::string_view(kWinchScriptRejected)
                                                   : std::string_view(n_.unknown->last_event());
  dds::ToStatusCommands(*n_.arbiter, notes, &s);
  n_.endpoints->PublishStatus(s);
}

bool DdsNode::HandleControl() {
  bool changed = false;
  n_.endpoints->control_reader().TakeEach([&](const dds::SimControlMsg& msg, const auto&) {
    const RunControl::Effect e = control_.Apply(dds::FromSimControl(msg));
    if (e.invalid) std::fprintf(stderr, "sim_node: %s\n", control_.note().c_str());
    if (e.reset) DoReset();  // on failure, control_.failed() ends the run
    changed = changed || e.changed;
  });
  if (changed && !control_.failed()) {
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
  std::fprintf(stderr, "sim_node: %s at step %llu: %s%s\n", n_.arbiter->vehicle(i).name.c_str(),
               static_cast<unsigned long long>(step_),
               c.verdict == dds::CheckedCommand::kRejected ? "command rejected: " : "",
               c.reason.c_str());
  if (command_notes_ == kMaxCommandNotes) {
    std::fprintf(stderr, "sim_node: (further rejected or clamped commands: see the status)\n");
  }
}

void DdsNode::TakeCommands() {
  if (n_.unknown->Poll() > 0 && command_notes_ < kMaxCommandNotes) {
    ++command_notes_;
    std::fprintf(stderr, "sim_node: %s\n", n_.unknown->last_event().c_str());
  }
  const double t = n_.sim->time();
  for (int i = 0; i < n_.endpoints->num_pose_readers(); ++i) {
    const int e = n_.vessel_entries[i];
    n_.endpoints->pose_reader(i).TakeEach([&](const dds::OdometryMsg& msg, const auto&) {
      NoteCommand(n_.arbiter->Receive(e, msg, t, step_, h_), e);
    });
  }
  for (int i = 0; i < n_.endpoints->num_command_readers(); ++i) {
    n_.endpoints->command_reader(i).TakeEach(
        [&](const dds::ActuatorCommandMsg& msg, const dds_sample_info_t&) {
          NoteCommand(n_.arbiter->Receive(i, msg, t), i);
        });
  }
  // winch w's reader feeds its entry winch_entry + w (winch w on cable w)
  for (int w = 0; w < n_.endpoints->num_winch_readers(); ++w) {
    if (const int e = n_.winch_entry + w; n_.winch_entry >= 0) {
      n_.endpoints->winch_reader(w).TakeEach(
          [&](const dds::WinchCommandMsg& msg, const dds_sample_info_t&) {
            NoteCommand(n_.arbiter->Receive(e, msg, t), e);
          });
    } else if (n_.winch_script) {
      n_.endpoints->winch_reader(w).TakeEach([&](const dds::WinchCommandMsg&, const auto&) {
        if (++winch_script_rejected_ == 1) {
          std::fprintf(stderr, "sim_node: %s\n", kWinchScriptRejected);
        }
      });
    }
  }
}

void DdsNode::NoteFailsafe(std::string failure) {
  if (opt_.fail_on_failsafe && failsafe_failure_.empty()) failsafe_failure_ = std::move(failure);
}

bool DdsNode::WaitLockstep(int64_t step) {
  dds::CommandArbiter& arbiter = *n_.arbiter;
  const bool initial = step < 0;
  if (arbiter.ReadyFor(step)) return true;
  // --lockstep-timeout 0: no limit, not even for a vehicle never heard from
  const double limit = opt_.lockstep_timeout;
  const bool forever = limit == 0.0;
  const double start_limit = std::max(kLockstepStartTimeout, limit);
  const Clock::time_point begin = Clock::now();
  bool timed_out = false, start_timed_out = false, hinted = false;
  // the run loop has just taken the commands and the control requests: wait first, then take,
  // so that each reader is taken once per wake-up (docs/benchmarks.md, "Lockstep at the speed
  // of the wire")
  for (;;) {
    const Clock::time_point now = Clock::now();
    const double waited = Seconds(now - begin);
    // a vehicle heard from (even a rejected command) after the limit, one never heard from
    // after start_limit: failsafe, no longer waited for
    const bool start_over = !forever && waited >= start_limit;
    if ((!forever && !timed_out && waited >= limit) || (start_over && !start_timed_out)) {
      timed_out = true;
      start_timed_out = start_over;
      if (arbiter.TimeOut(step, start_over) > 0) {
        std::fprintf(stderr, "sim_node: %s\n", arbiter.last_event().c_str());
        bool never_heard = start_over;
        for (int v = 0; v < arbiter.size(); ++v) {
          never_heard = never_heard && !(arbiter.failsafe(v) && arbiter.commanded(v));
        }
        // the bound waited out, not the clock's reading just past it (which a late wake-up
        // makes 0.501 s for a 0.5 s limit): the message is the rule that was broken
        NoteFailsafe(LockstepTimeoutFailure(FailsafeEntries(arbiter), n_.sim->time(), step_,
                                            start_over ? start_limit : limit, limit, never_heard));
        PublishStatus(RunningState());
        if (arbiter.ReadyFor(step)) return true;
      }
    }
    if (!hinted && waited >= kLockstepHintAfter) {
      hinted = true;
      // secured: a controller whose identity may not command is refused in its own process;
      // nothing of it reaches the node (docs/security.md, "A refused command")
      std::string what = "the commands of step " + std::to_string(step_);
      if (initial) what = "the initial poses";
      std::fprintf(stderr, "sim_node: lockstep: waiting for %s: %s%s\n", what.c_str(),
                   Describe(arbiter.Missing(step)).c_str(),
                   opt_.security.empty()
                       ? ""
                       : " (secured: a controller whose identity may not command one of them is "
                         "refused in its own process, which the node cannot see; check the "
                         "controller's output)");
    }
    if (!initial && Seconds(now - last_status_wall_) >= kIdleStatusPeriod) {
      // again, for late joiners (volatile topics): the state, then the status (not before the
      // initial state: a status asks the vessels' feeders for the pose of the next state)
      PublishState(/*all=*/true);
      PublishStatus(kWaiting);
    }
    double slice = kWaitSlice;
    if (!timed_out && !forever) slice = std::min(slice, std::max(1e-4, limit - waited));
    n_.endpoints->WaitForInput(slice);
    if (StopRequested()) return false;
    if (!initial && HandleControl()) return false;
    TakeCommands();
    if (arbiter.ReadyFor(step)) return true;
  }
}

void DdsNode::ApplyPoses() {
  core::Simulation& sim = *n_.sim;
  const int64_t now = static_cast<int64_t>(step_);
  for (size_t i = 0; i < n_.vessel_entries.size(); ++i) {
    core::VesselPose pose;
    double stamp = 0.0;
    int64_t state = -1;
    if (!n_.arbiter->Take(n_.vessel_entries[i], &pose, &stamp, &state)) continue;
    // t_n + h as the step computes it (core/simulation.cc), so that the pose is met exactly
    const double t = state == now ? sim.time() : state == now + 1 ? sim.time() + h_ : stamp;
    sim.SetVesselPose(n_.external_vessels[i], t, pose);
  }
}

void DdsNode::CountMissingPoses() {
  if (n_.vessel_entries.empty()) return;
  if (n_.arbiter->CountMissingPoses(step_) == 0) return;
  late_notes_.resize(n_.vessel_entries.size(), 0);
  for (size_t i = 0; i < n_.vessel_entries.size(); ++i) {
    const int e = n_.vessel_entries[i];
    if (!n_.arbiter->late(e) || late_notes_[i] > kMaxCommandNotes) continue;
    // said once per run of missing poses, at most kMaxCommandNotes times per vessel
    if (++late_notes_[i] > kMaxCommandNotes) {
      std::fprintf(stderr, "sim_node: %s: (further missing poses: see the summary)\n",
                   n_.arbiter->vehicle(e).name.c_str());
      continue;
    }
    std::fprintf(stderr,
                 "sim_node: warning: %s: no pose for t = %.9g s (the end of step %llu): its last "
                 "motion carried on\n",
                 n_.arbiter->vehicle(e).name.c_str(), n_.sim->time() + h_,
                 static_cast<unsigned long long>(step_));
  }
}

void DdsNode::Idle() {
  if (Seconds(Clock::now() - last_status_wall_) >= kIdleStatusPeriod) {
    PublishState(/*all=*/true);
    PublishStatus(RunningState());
  }
  n_.endpoints->WaitForInput(kWaitSlice);
}

std::vector<int> DdsNode::Awaited() const {
  std::vector<int> entries;
  for (int i = 0; i < num_command_vehicles(); ++i) entries.push_back(i);
  for (int w = 0; w < n_.num_winch_entries; ++w) {
    if (n_.arbiter->vehicle(n_.winch_entry + w).lockstep) entries.push_back(n_.winch_entry + w);
  }
  for (int e : n_.vessel_entries) entries.push_back(e);
  return entries;
}

bool DdsNode::AllCommanded() const {
  for (int i : Awaited()) {
    if (!n_.arbiter->commanded(i)) return false;
  }
  return true;
}

std::string DdsNode::Describe(const std::vector<int>& entries) const {
  const wire::TopicNames names(opt_.ns);
  std::string text;
  for (int i : entries) {
    const std::string& name = n_.arbiter->vehicle(i).name;
    const std::string topic = is_winch_entry(i)    ? names.Name(wire::Topic::kWinchCommand, name)
                              : is_vessel_entry(i) ? names.Name(wire::Topic::kPoseCommand, name)
                                                   : names.Name(wire::Topic::kCommand, name);
    text += (text.empty() ? "" : ", ") + name + " (" + topic + ")";
  }
  return text;
}

void DdsNode::NoteAwaited() {
  std::vector<int> missing;
  for (int i : Awaited()) {
    if (!n_.arbiter->commanded(i)) missing.push_back(i);
  }
  const std::string note = Describe(missing);
  if (note == awaited_note_) return;
  awaited_note_ = note;
  std::fprintf(stderr, "sim_node: --wait-for-controllers: waiting for the first command of %s\n",
               note.c_str());
}

bool DdsNode::DoStep() {
  core::Simulation& sim = *n_.sim;
  if (n_.arbiter->CheckTimeouts(sim.time()) > 0) {
    NoteFailsafe(FailsafeFailure(FailsafeEntries(*n_.arbiter), sim.time(), step_,
                                 n_.arbiter->last_failsafe_reason()));
  }
  // the script entries due first, then the controllers' commands (and failsafes) over them:
  // the vehicles', then the winch's (docs/winch_dds.md)
  // (the source of each vehicle's command: the last of them that set it)
  if (opt_.use_script) {
    script_set_.assign(model_.vehicles.size(), false);
    n_.script->Apply(&sim, &script_set_);
    for (std::size_t v = 0; v < script_set_.size(); ++v) {
      if (script_set_[v]) command_source_[v] = dds::kSourceScript;
    }
  }
  for (int i = 0; i < num_command_vehicles(); ++i) {
    core::VehicleCommand command;
    if (n_.arbiter->Take(i, &command)) {
      sim.SetVehicleCommand(n_.command_vehicles[i], command);
      command_source_[n_.command_vehicles[i]] =
          n_.arbiter->failsafe(i) ? dds::kSourceFailsafe : dds::kSourceDds;
    }
  }
  for (int w = 0; w < n_.num_winch_entries; ++w) {
    if (core::WinchCommand winch; n_.arbiter->Take(n_.winch_entry + w, &winch))
      sim.SetWinchCommand(winch, w);
  }
  // the external vessels' poses (docs/vessels.md "External vessels")
  ApplyPoses();
  CountMissingPoses();

  const Clock::time_point t0 = Clock::now();
  const double t_before = sim.time();
  const core::StepStatus status = sim.Step();
  if (!status.ok()) {
    char text[160];
    std::snprintf(text, sizeof text, "solver failure at t = %.9g s (step %llu): ", t_before,
                  static_cast<unsigned long long>(step_ + 1));
    control_.Fail(text + status.message);
    std::fprintf(stderr, "sim_node: %s\n", control_.failure().c_str());
    last_status_ = status;
    return false;
  }
  last_status_ = status;
  ++step_;
  control_.Stepped();
  const FoldWatch::Event folded = fold_.Observe(sim, static_cast<long>(step_));
  if (folded == FoldWatch::Event::kFolded) {
    std::fprintf(stderr, "sim_node: %s\n", fold_.Warning().c_str());
  } else if (folded == FoldWatch::Event::kFailed) {
    char text[160];
    std::snprintf(text, sizeof text, "solver failure at t = %.9g s (step %llu): ", sim.time(),
                  static_cast<unsigned long long>(step_));
    control_.Fail(text + fold_.Failure());
    std::fprintf(stderr, "sim_node: %s\n", control_.failure().c_str());
    return false;
  }

  PublishState(/*all=*/false);
  const Clock::time_point t1 = Clock::now();
  step_wall_ = Seconds(t1 - t0);

  // achieved real-time factor over the last window
  const double window = Seconds(t1 - rtf_wall_);
  if (window >= kRtfWindow || before_reset_.steps + static_cast<long>(step_) == 1) {
    rtf_ = window > 0.0 ? (sim.time() - rtf_sim_) / window : 0.0;
    if (window >= kRtfWindow) {
      rtf_wall_ = t1;
      rtf_sim_ = sim.time();
    }
  }
  if (n_.strides.Due(core::PublishRate::kStatus, step_, false) || control_.holding()) {
    PublishStatus(RunningState());
  }
  if (static_cast<long>(step_) % n_.output_stride == 0) {
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
    control_.Fail(std::string("reset: the initial state could not be built: ") + e.what());
    std::fprintf(stderr, "sim_node: solver failure: %s\n", control_.failure().c_str());
    return false;
  }
  before_reset_ += ThisRun();
  ++before_reset_.resets;
  *n_.sim = std::move(*fresh);
  fold_ = FoldWatch(model_.time.step);  // the new run's folds only
  n_.script.emplace(model_);
  // the poses of the old run that came in the meantime are not the new run's
  for (int i = 0; i < n_.endpoints->num_pose_readers(); ++i) {
    n_.endpoints->pose_reader(i).TakeEach([](const dds::OdometryMsg&, const auto&) {});
  }
  n_.arbiter->Reset();
  command_source_.assign(model_.vehicles.size(), dds::kSourceNone);
  step_ = 0;
  last_status_ = core::StepStatus{};
  step_wall_ = 0.0;
  last_output_ = -1;
  control_.Reset();
  run_id_ = NewRunId(model_.name);
  rtf_wall_ = Clock::now();
  rtf_sim_ = n_.sim->time();
  PublishInitial();
  return true;
}

void DdsNode::Output(const core::StepStatus& status, long wall_us) {
  if (!opt_.output) return;
  // the arbiter's failsafe flags by vehicle: entry i is vehicle command_vehicles[i]
  failsafe_.assign(model_.vehicles.size(), false);
  for (int i = 0; i < num_command_vehicles(); ++i) {
    failsafe_[n_.command_vehicles[i]] = n_.arbiter->failsafe(i);
  }
  // the winches': entry winch_entry + w is winch w (none with --winch script: never failsafe)
  winch_failsafe_.assign(n_.sim->num_winches(), false);
  for (int w = 0; w < n_.num_winch_entries; ++w)
    winch_failsafe_[w] = n_.arbiter->failsafe(n_.winch_entry + w);
  try {
    opt_.output(*n_.sim, status, wall_us, failsafe_, winch_failsafe_);
  } catch (const io::OutputError&) {
    output_failed_ = true;
    throw;
  }
  last_output_ = static_cast<long>(step_);
}

RunCounters DdsNode::ThisRun() const {
  RunCounters c;
  c.steps = static_cast<long>(step_);
  c.sim_time = n_.sim->time();
  c.received = n_.arbiter->received();
  c.rejected = n_.arbiter->rejected();
  c.clamped = n_.arbiter->clamped();
  c.failsafes = n_.arbiter->failsafe_count();
  c.lockstep_timeouts = n_.arbiter->lockstep_timeouts();
  c.poses_missing = n_.arbiter->poses_missing();
  return c;
}

RunCounters DdsNode::Totals() const {
  RunCounters c = before_reset_;
  c += ThisRun();
  c.overruns = pacer_.overruns();
  c.unknown_commands = n_.unknown->count() + winch_script_rejected_;
  c.external_vessels = static_cast<int>(n_.vessel_entries.size());
  return c;
}

void DdsNode::Summary(double wall) const {
  std::optional<std::string> other_nodes;
  if (n_.peers && !n_.peers->run_ids().empty()) other_nodes = n_.peers->Names();
  std::optional<SummaryLateness> lateness;
  if (realtime() && pacer_.stats().count() > 0) {
    const LatenessStats& l = pacer_.stats();
    lateness = SummaryLateness{l.Quantile(0.50), l.Quantile(0.99), l.max()};
  }
  const std::string line = NodeSummaryLine(model_.name, ModeName(opt_.mode), Totals(), wall,
                                           strain_.SummaryPart(), other_nodes, lateness);
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

}  // namespace

int RunDdsNode(const core::Model& model, const DdsNodeOptions& options) {
  DdsNode node(model, options);
  return node.Run();
}

}  // namespace towsim::app
