#pragma once
// The run control of the DDS node (docs/topics.md, SimControl in msgs/towsim_msgs): what
// the node does next and the state its status reports, as a pure state machine (no DDS, no
// clocks; the node's loop in app/node/dds_node.cc asks it and acts).
//
//   request           while running                while paused
//   PAUSE             paused (changed)             stays paused; a STEP budget is dropped
//   RESUME            ignored (no change)          running (changed)
//   STEP n            refused, noted in the status budget += n (changed): n steps, then
//                     ("STEP ignored: ...")        paused again
//   RESET             a reset (the node builds a new run; then Reset()), budget dropped
//   SET_RATE r        the realtime pacing factor r (changed), in either state
//   invalid           refused, noted ("sim_control: <why>"); nothing else changes
// A valid request clears the last note. The status state: PAUSED while paused with no steps
// left, WAITING before the first command (--wait-for-controllers) or while lockstep waits for
// a step's commands, else RUNNING; at the end FAILED (Fail: a solver or output failure),
// STOPPED (Stop: SIGINT / SIGTERM) or FINISHED (the duration reached).

#include <cstdint>
#include <string>

#include "dds/translators.h"

namespace towsim::app {

class RunControl {
 public:
  struct Options {
    bool start_paused = false;          // --paused: wait for RESUME / STEP before step 1
    bool wait_for_controllers = false;  // --wait-for-controllers (and a vehicle takes commands)
    long steps_to_run = -1;             // the steps of the duration; < 0: no end
    double rate = 1.0;                  // realtime pacing factor
  };

  // what a request did
  struct Effect {
    bool changed = false;  // the schedule changed (pause, resume, step, reset, rate): a wait ends
    bool reset = false;    // RESET: the node starts a new run, then calls Reset()
    bool invalid = false;  // refused as invalid: note() says why
  };

  explicit RunControl(const Options& options);

  Effect Apply(const dds::ControlRequest& request);

  // a reset took place (the step count starts again): no steps budgeted, no note
  void Reset();
  // one step was taken: a STEP budget counts down
  void Stepped();
  // the first command of every vehicle arrived (--wait-for-controllers)
  void ControllersReady() { waiting_for_controllers_ = false; }
  void Stop() { stopped_ = true; }
  void Fail(std::string reason) { failure_ = std::move(reason); }

  // paused with no steps left: the node holds (no step)
  bool holding() const { return paused_ && step_budget_ == 0; }
  bool paused() const { return paused_; }
  long step_budget() const { return step_budget_; }
  bool waiting_for_controllers() const { return waiting_for_controllers_; }
  bool finished(uint64_t step) const {
    return steps_to_run_ >= 0 && static_cast<long>(step) >= steps_to_run_;
  }
  long steps_to_run() const { return steps_to_run_; }
  double rate() const { return rate_; }
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }
  const std::string& note() const { return note_; }  // the last refused request

  // the status state while the run goes on (SimStatus STATE_RUNNING, _PAUSED, _WAITING);
  // lockstep_waiting: lockstep waits for the commands of the next step
  uint8_t State(bool lockstep_waiting) const;
  // the status state at the end (STATE_FAILED, _STOPPED, _FINISHED)
  uint8_t EndState() const;

 private:
  bool paused_;
  bool waiting_for_controllers_;
  long steps_to_run_;
  double rate_;
  long step_budget_ = 0;  // STEP n while paused: steps left
  bool stopped_ = false;
  std::string failure_;
  std::string note_;
};

}  // namespace towsim::app
