#pragma once
// sim_node beside a controller under test (docs/testing_controllers.md): a SimNode starts the
// installed sim_node (lockstep by default) on a DDS domain id of its own, with the project's
// loopback configuration (cyclonedds.xml of the installation, CYCLONEDDS_URI set for the
// child), a scene and --set overrides; it is itself a DDS participant that keeps what the node
// publishes (odometry, the state of every cable (SceneInfo.cables), cable forces, status) and
// sends SimControl requests.
//
// Start-up: the node starts paused (--paused); once scene_info has come and the step-0 state
// of every body has been received (the node repeats it while paused), the node is resumed
// (unless SimNodeOptions::start_paused). In lockstep the first step then waits for the
// controllers' first commands, so controllers may be started afterwards.
//
// Samples are kept in arrival order, per topic; `run` counts the RESETs seen on that topic
// (the sim time going back), so run 0 is before the first RESET. Thread-safe: the samples
// are taken by a DDS listener and copied out under a lock.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "testing/dds_domain.h"
#include "testing/process.h"
#include "wire/decoders.h"

#ifndef TOWSIM_TESTING_SIM_NODE
#error "TOWSIM_TESTING_SIM_NODE is not defined: link towsim::testing (find_package(towsim))"
#endif
#ifndef TOWSIM_TESTING_DATA_DIR
#error "TOWSIM_TESTING_DATA_DIR is not defined: link towsim::testing (find_package(towsim))"
#endif

namespace towsim::testing {

struct SimNodeOptions {
  // a scene file, or the name of an installed scene ("case1_forward": data_dir/scenes/NAME.yaml)
  std::string scene;
  std::string mode = "lockstep";        // lockstep, fast or realtime
  double duration = 10.0;               // --duration [s] of simulated time
  double rate = 1.0;                    // --rate (realtime)
  std::vector<std::string> set;         // --set KEY.PATH=VALUE each
  std::vector<std::string> extra_args;  // further sim_node flags, e.g. --wait-for-controllers
  std::string ns = "/towsim";           // --namespace
  int domain = -1;                      // -1: a free one (DomainLease), else exactly this id
  bool csv = true;                      // --csv <log dir>/csv (bodies.csv, ... of docs/contract.md §5)
  bool start_paused = false;            // stay paused after start-up (Resume() starts)
  // --fail-on-failsafe: the first failsafe or lockstep timeout ends the run with exit code 5,
  // the body, step and reason in the log and the final status (FAILED); false: the node runs on
  // with the body in failsafe (for tests of the failsafe itself)
  bool fail_on_failsafe = true;
  // --lockstep-timeout [s] (lockstep only): wall time a step waits for its commands; 0: wait
  // forever (debugging); < 0: sim_node's default (1 s)
  double lockstep_timeout = -1.0;
  double startup_timeout = 30.0;        // [s] for scene_info and the first state
  // where the installation is: the defaults come from find_package(towsim)
  std::string sim_node = TOWSIM_TESTING_SIM_NODE;  // the sim_node executable
  std::string data_dir = TOWSIM_TESTING_DATA_DIR;  // share/towsim: scenes/, cyclonedds.xml
  // the log directory; empty: <gtest TempDir>/towsim_<suite>_<test>_d<domain>, removed at the
  // end of a passing test and kept (its path printed) after a failing one; a directory given
  // here is always kept
  std::string log_dir;
};

// the node's messages as the wire library decodes them (wire/decoders.h); `run` counts the
// RESETs seen on that topic
using SceneInfo = wire::SceneInfo;

struct OdometrySample : wire::Odometry {  // t, x, y, z, qx..qw, u, v, w, p, q, r
  int run = 0;
  double roll = 0, pitch = 0, yaw = 0;  // ZYX [rad]
};

struct CableSample : wire::CableState {  // step, t, x, y, z, tension, paid_out_length, ...
  int run = 0;
};

struct WrenchSample : wire::Wrench {  // t, fx, fy, fz, mx, my, mz: on a body, body frame
  int run = 0;
};

// run_id, mode, message, state, health, step, t, the counters; running(), terminal(), ...
using StatusSample = wire::SimStatus;

// how the node ended
struct NodeResult {
  // 128 + signal if a signal ended it; -1 if it did not end in time; 5: a failsafe or
  // lockstep timeout ended it (SimNodeOptions::fail_on_failsafe)
  int exit_code = -1;
  std::string summary;  // the summary line "sim_node: <scene>: <mode>, N steps, ..."
};

class SimNode {
 public:
  // starts the node and waits for scene_info and the first state; throws std::runtime_error
  // with the node's log if it exits or does not come up within startup_timeout
  explicit SimNode(SimNodeOptions options);
  ~SimNode();  // stops the node (SIGINT, then SIGKILL) if it still runs
  SimNode(const SimNode&) = delete;
  SimNode& operator=(const SimNode&) = delete;

  int domain() const;
  const std::string& ns() const;
  const SceneInfo& scene_info() const;
  // CYCLONEDDS_URI=file://<data_dir>/cyclonedds.xml: the environment a controller needs
  std::string dds_uri() const;
  const std::string& log_dir() const;
  std::string csv_dir() const;  // <log dir>/csv (bodies.csv, cable.csv, forces.csv, status.csv)
  std::string command_line() const;
  std::string log() const;  // the node's stdout and stderr so far

  // the latest sample, if any
  std::optional<OdometrySample> odometry(const std::string& body) const;
  // cable: a name of SceneInfo.cables; the one cable of a scene is "cable"; nullopt for a
  // cable the scene does not have
  std::optional<CableSample> cable_state(const std::string& cable = "cable") const;
  std::optional<WrenchSample> cable_force(const std::string& body) const;
  std::optional<StatusSample> status() const;
  // every sample so far, oldest first (cable states: the max tension of each only)
  std::vector<OdometrySample> odometry_history(const std::string& body) const;
  std::vector<WrenchSample> cable_force_history(const std::string& body) const;
  std::vector<StatusSample> status_history() const;
  struct TensionSample {
    int run = 0;
    double t = 0.0;
    double max = 0.0;  // [N] over the nodes
    int node = 0;      // where
  };
  std::vector<TensionSample> max_tension_history(const std::string& cable = "cable") const;

  // waits up to `timeout` [s] for a status (among those received, oldest first) for which
  // `pred` holds; returns it
  std::optional<StatusSample> WaitForStatus(const std::function<bool(const StatusSample&)>& pred,
                                            double timeout = 30.0);

  // SimControl requests (towsim_msgs/SimControl)
  void Pause();
  void Resume();
  void Step(uint32_t steps);
  void Reset();
  void SetRate(double rate);

  // waits up to `timeout` [s] for the node to end by itself (--duration reached)
  NodeResult Wait(double timeout = 60.0);
  // SIGINT now, then waits up to `timeout` [s] (SIGKILL after that)
  NodeResult Stop(double timeout = 10.0);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace towsim::testing
