#include "core/winch_drive.h"

#include <algorithm>
#include <cmath>

#include "core/drum_element.h"
#include "core/model.h"
#include "core/system.h"

namespace towsim::core {

WinchDrive::WinchDrive(System* system) : system_(system) {
  const int nw = system->num_winches();
  commands_.resize(nw);
  steps_.resize(nw);
  braking_.assign(nw, 0);
  slips_.assign(nw, 0.0);
  next_slips_.assign(nw, 0.0);
  brakes_.resize(nw);
}

const WinchParams& WinchDrive::params(int w) const { return *system_->model().cables[w].winch; }

void WinchDrive::Initialize(State* state) {
  const int nc = system_->num_cables();
  state->winches.assign(nc, WinchState());
  for (int c = 0; c < nc; ++c) {
    const CableParams& cable = system_->model().cables[c];
    WinchState& w = state->winches[c];
    w.length = cable.length;
    w.speed = 0.0;
    w.nodes = system_->num_nodes(c);
    w.drum.length = system_->drum_length(c);
    if (cable.winch && std::isfinite(cable.winch->brake_tension)) any_brake_ = true;
  }
  if (any_brake_) brake_start_ = *state;
}

void WinchDrive::SetCommand(const WinchCommand& command, int w) {
  if (w < 0 || w >= num_winches() || !system_->has_winch(w) || !std::isfinite(command.value))
    return;
  WinchCommand c = command;
  ClampWinchCommand(params(w), &c);
  commands_[w] = c;
}

double WinchDrive::MaxSlip(double h, int w) const {
  return (kSplitLength - 1.0 - kMergeLength) * system_->element_length(w) / h;
}

void WinchDrive::MoveDrum(double h, double slip, State* state, int w) {
  WinchState& ws = state->winches[w];
  WinchStep& step = steps_[w];
  step = AdvanceWinch(params(w), commands_[w], ws.length, ws.drive_speed, slip, h);
  // l_0(t) over the step: from l_0 at rate V_n, reaching l_0 + dL at t + h
  const double dl = step.length - ws.length;
  ws.drum.t0 = state->t;
  ws.drum.length = system_->drum_length(w);
  ws.drum.rate = ws.speed;
  ws.drum.accel = 2.0 * (dl - ws.speed * h) / (h * h);
}

void WinchDrive::Prepare(double h, double slip, State* state, int w) {
  const double l0 = system_->drum_length(w);
  MoveDrum(h, slip, state, w);
  const double dl = steps_[w].length - state->winches[w].length;
  // keep l_0 at the step's end within [kMergeLength, kSplitLength] l_e (drum_element.h)
  const double le = system_->element_length(w);
  bool changed = false;
  if (l0 + dl > kSplitLength * le) {
    changed = SplitDrumElement(system_, state, w);
  } else if (l0 + dl < kMergeLength * le) {
    changed = MergeDrumElement(system_, state, w);
  }
  if (changed) MoveDrum(h, slip, state, w);  // from the new drum element's l_0
}

void WinchDrive::SolveBrakeSlip(double h, State* state,
                                const std::function<StepStatus(double)>& step_system,
                                StepStatus* s) {
  const int nw = num_winches();
  for (int w = 0; w < nw; ++w) {
    if (!braking_[w]) continue;
    const CableParams& c = system_->model().cables[w];
    const double stiffness_h = c.axial_stiffness * h / system_->drum_length(w);
    const double slope = state->winches[w].slip_slope;
    brakes_[w].emplace(c.winch->brake_tension, MaxSlip(h, w), slope < 0.0 ? slope : -stiffness_h);
  }
  int iterations = s->iterations;
  while (s->ok()) {
    // each braking drum's next slip from its own tension (the drums' cables are coupled only
    // through the bodies, so each secant sees mostly its own slip)
    bool again = false;
    for (int w = 0; w < nw; ++w) {
      if (!braking_[w]) continue;
      next_slips_[w] = slips_[w];
      const double tension = state->lambda.segment<3>(system_->EndLambda(0, w)).norm();
      if (steps_[w].length < params(w).max_length &&
          brakes_[w]->Next(slips_[w], tension, &next_slips_[w]))
        again = true;
    }
    if (!again) break;
    // again from the step's start, keeping the kept Newton matrix the attempt left (the
    // integrator's cache of it, integrator.h)
    brake_start_.newton = state->newton;
    *state = brake_start_;
    for (int w = 0; w < nw; ++w) {
      if (!braking_[w]) continue;
      slips_[w] = next_slips_[w];
      MoveDrum(h, slips_[w], state, w);
    }
    *s = step_system(h);
    iterations += s->iterations;
  }
  s->iterations = iterations;
  for (int w = 0; w < nw; ++w) {
    if (braking_[w] && brakes_[w]->attempts() > 1)
      state->winches[w].slip_slope = brakes_[w]->slope();
  }
}

StepStatus WinchDrive::Step(double h, State* state,
                            const std::function<StepStatus(double)>& step_system) {
  const int nw = num_winches();
  // a brake (winch.h): the first attempt slips as the last step did
  bool brake = false;
  for (int w = 0; w < nw; ++w) {
    braking_[w] = system_->has_winch(w) && std::isfinite(params(w).brake_tension) &&
                  system_->end_lambda_count(0, w) > 0;
    slips_[w] = braking_[w] ? std::clamp(state->winches[w].slip_speed, 0.0, MaxSlip(h, w)) : 0.0;
    brake = brake || braking_[w];
  }
  for (int w = 0; w < nw; ++w)
    if (system_->has_winch(w)) Prepare(h, slips_[w], state, w);
  if (brake) brake_start_ = *state;
  StepStatus s = step_system(h);
  if (brake) SolveBrakeSlip(h, state, step_system, &s);
  if (s.ok()) {
    for (int w = 0; w < nw; ++w) {
      if (!system_->has_winch(w)) continue;
      WinchState& ws = state->winches[w];
      const WinchStep& step = steps_[w];
      ws.length = step.length;
      ws.speed = step.speed;
      ws.drive_speed = step.drive_speed;
      ws.slip_speed = step.slip_speed;
      ws.slipping = step.slipping;
      system_->SetLayout(ws.nodes, ws.length, w);
    }
  }
  return s;
}

}  // namespace towsim::core
