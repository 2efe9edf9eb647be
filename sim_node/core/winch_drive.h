#pragma once
// The winch's part of a Simulation step (winch.h, docs/winch.md): the drum's motion over the
// step, the split or merge of the drum element it needs, the brake's slip solved by repeating
// the step, and the winch's state and the cable's layout at the step's end.
//
//   Step(h):  slip s = clamp(s_n, 0, s_max) with a brake that holds the cable, else 0
//             L(t) over the step: AdvanceWinch, l_0(t) = l_0 + V_n (t - t_n) + 1/2 c (t - t_n)^2
//             with l_0(t_n + h) = l_0 + dL; split / merge the drum element if l_0 + dL leaves
//             [kMergeLength, kSplitLength] l_e (drum_element.h), then the motion again
//             the cable (and the vehicles) over h (the caller's step)
//             a brake: the step again from its start with each slip of BrakeSlipIteration
//             converged: (L, V, drive speed, slip) of the step's end into State::winch, and
//             the system's layout for them
//
// Without a winch Step is the caller's step alone.

#include <functional>

#include "core/simulation.h"
#include "core/state.h"
#include "core/winch.h"

namespace towsim::core {

class System;  // system.h

class WinchDrive {
 public:
  // the winch of system->model().cables[0] (none: Step only takes the caller's step); `system`
  // must outlive this
  explicit WinchDrive(System* system);

  // the winch's part of the initial state: the scene's cable length at rest, the nodes and
  // the drum element's length of the system's layout; sizes the brake's restart copy once (its
  // copies in Step do not allocate)
  void Initialize(State* state);

  bool has_winch() const { return has_winch_; }
  // the command held from now on, clamped into the limits (WinchCommandRange); a non-finite
  // value is ignored (the command held so far stays). Without a winch: ignored.
  void SetCommand(const WinchCommand& command);
  const WinchCommand& command() const { return command_; }

  // one step h of *state (above); step_system(h) takes the cable and the vehicles over h from
  // *state (the same object), and may be called again after *state is reset to the step's
  // start
  StepStatus Step(double h, State* state, const std::function<StepStatus(double)>& step_system);

 private:
  // the drum's motion for the step h from *state with the brake's slip `slip`, with the split
  // or merge of the drum element it needs (winch.h, drum_element.h)
  void Prepare(double h, double slip, State* state);
  // step_ and the drum element's motion over the step h with the slip `slip`
  void MoveDrum(double h, double slip, State* state);
  // the brake's tension band (winch.h): the step repeated from brake_start_ with the slips of
  // BrakeSlipIteration, *s the last attempt's status, its iterations summed over the attempts
  void SolveBrakeSlip(double h, double slip, State* state,
                      const std::function<StepStatus(double)>& step_system, StepStatus* s);
  // the largest slip the scene's step rule allows (winch.h): (kSplitLength - 1 - kMergeLength)
  // l_e a step
  double MaxSlip(double h) const;

  System* system_;
  bool has_winch_;
  WinchCommand command_;
  WinchStep step_;     // the drum's motion over the step being taken
  State brake_start_;  // a slipping brake's step start, for its repeated attempts (winch.h)
};

}  // namespace towsim::core
