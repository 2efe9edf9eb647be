#pragma once
// The winches' part of a Simulation step (winch.h, docs/winch.md): each drum's motion over the
// step, the split or merge of its drum element, the brakes' slips solved by repeating the
// step, and the winches' states and their cables' layouts at the step's end. Winch w sits at
// the start of cable w (the scene puts the winched cables first, model.h); every drum moves in
// the same step.
//
//   Step(h):  for each winch w: slip s_w = clamp(s_w,n, 0, s_max) with a brake that holds the
//             cable, else 0; L_w(t) over the step: AdvanceWinch, l_0(t) = l_0 + V_n (t - t_n)
//             + 1/2 c (t - t_n)^2 with l_0(t_n + h) = l_0 + dL; split / merge the drum element
//             if l_0 + dL leaves [kMergeLength, kSplitLength] l_e (drum_element.h), then the
//             motion again
//             the cables (and the vehicles) over h (the caller's step)
//             brakes: the step again from its start with each braking winch's next slip of
//             its own BrakeSlipIteration (one secant per drum on its own tension), until none
//             asks for another attempt
//             converged: (L, V, drive speed, slip) of the step's end into State::winches, and
//             the system's layout for them
//
// Without a winch Step is the caller's step alone; with one it is the arithmetic of the one
// winch alone (the loops run once).

#include <functional>
#include <optional>
#include <vector>

#include "core/simulation.h"
#include "core/state.h"
#include "core/winch.h"

namespace towsim::core {

class System;  // system.h

class WinchDrive {
 public:
  // the winches of system->model().cables (none: Step only takes the caller's step); `system`
  // must outlive this
  explicit WinchDrive(System* system);

  // State::winches, one per cable: the scene's cable length at rest, the nodes and the drum
  // element's length of the system's layout; sizes the brakes' restart copy once (its copies
  // in Step do not allocate)
  void Initialize(State* state);

  int num_winches() const { return static_cast<int>(commands_.size()); }
  bool has_winch() const { return !commands_.empty(); }
  // winch w's command held from now on, clamped into its limits (WinchCommandRange); a
  // non-finite value is ignored (the command held so far stays). No such winch: ignored.
  void SetCommand(const WinchCommand& command, int w = 0);
  // (no such winch: the default command, speed 0)
  const WinchCommand& command(int w = 0) const {
    return w >= 0 && w < num_winches() ? commands_[w] : no_command_;
  }

  // one step h of *state (above); step_system(h) takes the cables and the vehicles over h from
  // *state (the same object), and may be called again after *state is reset to the step's
  // start
  StepStatus Step(double h, State* state, const std::function<StepStatus(double)>& step_system);

 private:
  // winch w's drum motion for the step h from *state with the brake's slip `slip`, with the
  // split or merge of the drum element it needs (winch.h, drum_element.h)
  void Prepare(double h, double slip, State* state, int w);
  // steps_[w] and the drum element's motion over the step h with the slip `slip`
  void MoveDrum(double h, double slip, State* state, int w);
  // the brakes' tension bands (winch.h): the step repeated from brake_start_ with the slips of
  // each braking winch's BrakeSlipIteration, *s the last attempt's status, its iterations
  // summed over the attempts
  void SolveBrakeSlip(double h, State* state, const std::function<StepStatus(double)>& step_system,
                      StepStatus* s);
  // the largest slip the scene's step rule allows (winch.h): (kSplitLength - 1 - kMergeLength)
  // l_e a step, on cable w
  double MaxSlip(double h, int w) const;
  const WinchParams& params(int w) const;

  System* system_;
  std::vector<WinchCommand> commands_;  // per winch
  WinchCommand no_command_;             // command() of a winch the scene does not have
  std::vector<WinchStep> steps_;        // the drums' motions over the step being taken
  // per winch: a brake that holds its cable this step, its slip and its secant iteration
  std::vector<char> braking_;
  std::vector<double> slips_, next_slips_;
  std::vector<std::optional<BrakeSlipIteration>> brakes_;
  bool any_brake_ = false;  // some winch has a brake (brake_start_ is sized)
  State brake_start_;       // a slipping brake's step start, for its repeated attempts (winch.h)
};

}  // namespace towsim::core
