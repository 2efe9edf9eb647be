#pragma once
// The DDS modes of sim_node (docs/contract.md §3-4): realtime, fast and lockstep. The node
// steps a core::Simulation and publishes on the ROS-2-compatible topics of docs/contract.md §3; external
// controllers drive the vehicles over rt/<ns>/<body>/command, run control comes over
// rt/<ns>/sim_control.
//
//   realtime  step k starts at its wall-clock deadline k * h / rate after the start (or the
//             last resume / reset / rate change); lateness measured, overruns counted
//   fast      as fast as it goes, still publishing and taking commands
//   lockstep  step k (state k -> k + 1) waits until every commanded vehicle holds a command
//             answering step k; after `lockstep_timeout` of wall time a vehicle that has sent
//             a command before (valid or rejected) goes to failsafe and is no longer waited
//             for until valid commands resume; a vehicle never heard from is given 30 s (or
//             `lockstep_timeout` if longer; the controller may start after the node), then
//             the same. `lockstep_timeout` 0: no limit at all. Same commands, bit-identical
//             states.
//
// Commands: dds/command_arbiter.h (last writer wins, NaN rejected, out of range clamped,
// failsafe after `command_timeout` of simulation time). Each step: the scene's script entries
// due fire first, then the commands taken: the vehicles', then the winch's (a scene with
// cable.winch: rt/<ns>/winch/command, an arbiter entry named "winch", waited for in lockstep
// like a vehicle; docs/winch_dds.md). SimControl (app/node/run_control.h): PAUSE, RESUME,
// STEP n (while paused), RESET (a new core::Simulation from the same Model, a new run id),
// SET_RATE. The pieces (docs/app_layer.md): app/node/node_setup.h builds the node,
// app/node/run_control.h decides, app/node/dds_publisher.h publishes the topics of
// app/common/node_topics.h.
//
// --fail-on-failsafe (`fail_on_failsafe`): the first failsafe (command_timeout) or lockstep
// timeout ends the run after the step it happened in (app/node/failsafe_failure.h): outputs
// written to that step, a final status FAILED naming the body, the step and the reason, the
// summary, exit code 5. Ending at once keeps a CI log short and its last state the one that
// failed; the rest of the run would follow uncontrolled bodies.
//
// Exit: at the end of `duration`, or on SIGINT / SIGTERM (app/common/stop_signal.h) at the next
// step boundary or within 20 ms of waiting (writers linger 10 ms each for unacknowledged samples;
// the node adds <Internal><WriterLingerDuration>10ms</...> to the DDS configuration); a
// summary line on stdout, of the counters through every RESET (app/node/run_counters.h):
//   sim_node: <scene>: lockstep, 2000 steps, 100 s simulated in 1.520 s (RTF 66), overruns 0,
//   failsafes 0, commands 4000 (rejected 0, clamped 0), lockstep timeouts 0, resets 0

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "app/node/command_line.h"
#include "core/model.h"
#include "core/publish_rates.h"
#include "core/simulation.h"

namespace towsim::app {

struct DdsNodeOptions {
  Mode mode = Mode::kRealtime;  // kRealtime, kFast or kLockstep (kOffline: exit 2)
  // simulated time to run [s]: round(duration / h) steps, then exit 0; infinity: until stopped
  double duration = std::numeric_limits<double>::infinity();
  double rate = 1.0;             // realtime pacing factor (2: twice real time), > 0
  uint32_t domain = 0;           // DDS domain id
  std::string ns = "/towsim";    // ROS 2 namespace of the topics (/clock stays at the root)
  std::string dds_config;        // CYCLONEDDS_URI-style config; empty: $CYCLONEDDS_URI
  std::string security;          // DDS Security identity DIR/NAME (wire/security.h); "": none
  bool open_outputs = false;     // with security: readers without a certificate see the outputs
  double command_timeout = 0.5;  // failsafe after this much simulation time without command [s]
  // lockstep: wall time to wait for a step's commands [s], >= 0; 0: wait forever
  double lockstep_timeout = 1.0;
  // end with exit code 5 at the first failsafe or lockstep timeout (after its step)
  bool fail_on_failsafe = false;
  // lockstep: the vehicles (and "winch") waited for; empty: every vehicle that takes commands
  // and the winch
  std::vector<std::string> lockstep_bodies;
  core::PublishRates rates;   // the scene's publish.* (core/publish_rates.h)
  bool use_script = true;     // the scene's script drives the vehicles between commands
  bool start_paused = false;  // wait for SimControl RESUME / STEP before the first step
  // MCAP recording of every message the node publishes (sim_node --record); empty: none.
  // Each message is serialized once and the same bytes are published and recorded (see
  // app/node/dds_publisher.h); the file is completed at the end of the run and on SIGINT / SIGTERM.
  std::string record_file;
  // a Foxglove WebSocket server on 127.0.0.1:foxglove_port serving every topic the node
  // publishes (docs/foxglove.md; 0: a free port); < 0: none
  int foxglove_port = -1;
  bool overwrite = false;  // record_file may replace an existing file (else exit 2)
  // record_file's log time = the wall clock (else the simulation time, docs/recording.md)
  bool record_wall_time = false;
  // run although another node publishes in this domain and namespace (else exit 2; the
  // status warns either way, app/node/peer_nodes.h)
  bool allow_another_node = false;
  // wait before the first step until every vehicle that takes commands has received one (so
  // controllers started beside the node miss no step, in every mode; the status says waiting)
  bool wait_for_controllers = false;
  // the winch (cable.winch) follows the scene's script: not waited for in lockstep, no
  // failsafe, its commands on rt/<ns>/winch/command rejected and counted (sim_node --winch
  // script, docs/winch_dds.md); false: commanded over DDS like a vehicle
  bool winch_script = false;
  // called with the state at t = 0, every k = max(1, round(1 / (output_rate h))) steps and at
  // the last state (e.g. CsvWriter::Write), and failsafe[v]: whether vehicle v (Model::vehicles)
  // was in failsafe during the step that led there (dds/command_arbiter.h), winch_failsafe[w]
  // the same for winch w; may throw (then RunDdsNode throws)
  std::function<void(const core::Simulation&, const core::StepStatus&, long wall_us,
                     const std::vector<bool>& failsafe, const std::vector<bool>& winch_failsafe)>
      output;
};

// Runs the node until the duration is reached or SIGINT / SIGTERM. Returns the exit code:
// 0 done or stopped by a signal, 2 bad options or DDS setup failure (Cyclone's message on
// stderr), 3 solver failure (initial state or a step), 5 a failsafe or lockstep timeout under
// `fail_on_failsafe`. Call InstallStopHandlers() first (it
// is called again here, harmlessly).
int RunDdsNode(const core::Model& model, const DdsNodeOptions& options);

}  // namespace towsim::app
