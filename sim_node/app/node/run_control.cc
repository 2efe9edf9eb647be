#include "app/node/run_control.h"

#include <utility>

#include "dds/messages.h"

namespace towsim::app {

RunControl::RunControl(const Options& options)
    : paused_(options.start_paused),
      waiting_for_controllers_(options.wait_for_controllers),
      steps_to_run_(options.steps_to_run),
      rate_(options.rate) {}

RunControl::Effect RunControl::Apply(const dds::ControlRequest& r) {
  Effect e;
  if (r.kind != dds::ControlRequest::kInvalid) note_.clear();
  switch (r.kind) {
    case dds::ControlRequest::kPause:
      e.changed = !paused_ || step_budget_ > 0;
      paused_ = true;
      step_budget_ = 0;
      break;
    case dds::ControlRequest::kResume:
      e.changed = paused_;
      paused_ = false;
      step_budget_ = 0;
      break;
    case dds::ControlRequest::kStep:
      if (!paused_) {
        note_ = "sim_control: STEP ignored: the node is not paused";
        break;
      }
      step_budget_ += r.steps;
      e.changed = true;
      break;
    case dds::ControlRequest::kReset:
      e.reset = true;
      e.changed = true;
      break;
    case dds::ControlRequest::kSetRate:
      rate_ = r.rate;
      e.changed = true;
      break;
    case dds::ControlRequest::kInvalid:
      note_ = "sim_control: " + r.error;
      e.invalid = true;
      break;
  }
  return e;
}

void RunControl::Reset() {
  step_budget_ = 0;
  note_.clear();
}

void RunControl::Stepped() {
  if (step_budget_ > 0) --step_budget_;
}

uint8_t RunControl::State(bool lockstep_waiting) const {
  if (holding()) return towsim_msgs_msg_dds__SimStatus_Constants_STATE_PAUSED;
  if (waiting_for_controllers_ || lockstep_waiting) {
    return towsim_msgs_msg_dds__SimStatus_Constants_STATE_WAITING;
  }
  return towsim_msgs_msg_dds__SimStatus_Constants_STATE_RUNNING;
}

uint8_t RunControl::EndState() const {
  if (!failure_.empty()) return towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;
  if (stopped_) return towsim_msgs_msg_dds__SimStatus_Constants_STATE_STOPPED;
  return towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED;
}

}  // namespace towsim::app
