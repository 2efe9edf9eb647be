#include "core/winch_drive.h"

#include <algorithm>
#include <cmath>

#include "core/drum_element.h"
#include "core/model.h"
#include "core/system.h"

namespace towsim::core {

WinchDrive::WinchDrive(System* system)
    : system_(system), has_winch_(system->model().cables[0].winch.has_value()) {}

void WinchDrive::Initialize(State* state) {
  const CableParams& c = system_->model().cables[0];
  state->winch.length = c.length;
  state->winch.speed = 0.0;
  state->winch.nodes = system_->num_nodes();
  state->winch.drum.length = system_->drum_length();
  if (c.winch && std::isfinite(c.winch->brake_tension)) brake_start_ = *state;
}

void WinchDrive::SetCommand(const WinchCommand& command) {
  if (!has_winch_ || !std::isfinite(command.value)) return;
  WinchCommand c = command;
  ClampWinchCommand(*system_->model().cables[0].winch, &c);
  command_ = c;
}

double WinchDrive::MaxSlip(double h) const {
  return (kSplitLength - 1.0 - kMergeLength) * system_->element_length() / h;
}

void WinchDrive::MoveDrum(double h, double slip, State* state) {
  WinchState& w = state->winch;
  step_ = AdvanceWinch(*system_->model().cables[0].winch, command_, w.length, w.drive_speed, slip, h);
  // l_0(t) over the step: from l_0 at rate V_n, reaching l_0 + dL at t + h
  const double dl = step_.length - w.length;
  w.drum.t0 = state->t;
  w.drum.length = system_->drum_length();
  w.drum.rate = w.speed;
  w.drum.accel = 2.0 * (dl - w.speed * h) / (h * h);
}

void WinchDrive::Prepare(double h, double slip, State* state) {
  const double l0 = system_->drum_length();
  MoveDrum(h, slip, state);
  const double dl = step_.length - state->winch.length;
  // keep l_0 at the step's end within [kMergeLength, kSplitLength] l_e (drum_element.h)
  const double le = system_->element_length();
  bool changed = false;
  if (l0 + dl > kSplitLength * le) {
    changed = SplitDrumElement(system_, state);
  } else if (l0 + dl < kMergeLength * le) {
    changed = MergeDrumElement(system_, state);
  }
  if (changed) MoveDrum(h, slip, state);  // from the new drum element's l_0
}

void WinchDrive::SolveBrakeSlip(double h, double slip, State* state,
                                const std::function<StepStatus(double)>& step_system,
                                StepStatus* s) {
  const CableParams& c = system_->model().cables[0];
  const double stiffness_h = c.axial_stiffness * h / system_->drum_length();
  const double first = state->winch.slip_slope < 0.0 ? state->winch.slip_slope : -stiffness_h;
  BrakeSlipIteration brake(c.winch->brake_tension, MaxSlip(h), first);
  int iterations = s->iterations;
  double next = 0.0;
  while (s->ok() && step_.length < c.winch->max_length &&
         brake.Next(slip, state->lambda.segment<3>(system_->EndLambda(0)).norm(), &next)) {
    // again from the step's start, keeping the kept Newton matrix the attempt left (the
    // integrator's cache of it, integrator.h)
    brake_start_.newton = state->newton;
    *state = brake_start_;
    slip = next;
    MoveDrum(h, slip, state);
    *s = step_system(h);
    iterations += s->iterations;
  }
  s->iterations = iterations;
  if (brake.attempts() > 1) state->winch.slip_slope = brake.slope();
}

StepStatus WinchDrive::Step(double h, State* state,
                            const std::function<StepStatus(double)>& step_system) {
  // a brake (winch.h): the first attempt slips as the last step did
  const bool brake = has_winch_ && std::isfinite(system_->model().cables[0].winch->brake_tension) &&
                     system_->end_lambda_count(0) > 0;
  const double slip = brake ? std::clamp(state->winch.slip_speed, 0.0, MaxSlip(h)) : 0.0;
  if (has_winch_) Prepare(h, slip, state);
  if (brake) brake_start_ = *state;
  StepStatus s = step_system(h);
  if (brake) SolveBrakeSlip(h, slip, state, step_system, &s);
  if (s.ok() && has_winch_) {
    WinchState& w = state->winch;
    w.length = step_.length;
    w.speed = step_.speed;
    w.drive_speed = step_.drive_speed;
    w.slip_speed = step_.slip_speed;
    w.slipping = step_.slipping;
    system_->SetLayout(w.nodes, w.length);
  }
  return s;
}

}  // namespace towsim::core
