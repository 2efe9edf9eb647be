#pragma once
// What a step reads from outside its unknowns (the cable's q, v, a and the multipliers): the
// sea sampled at the cable nodes, the spheres and the vehicles, the motion of the vehicle
// attachment points (the supports) and the drum element's rest length (the winch). One value,
// filled by one sampler (step_sampler.h) and read by System::Evaluate (the cable, sphere and
// joint assembly), the integrator and the vehicle coupling.
//
// Who fills what, and when (step_sampler.h):
//   - the waves at the nodes and spheres: the integrator, once per (sub)step at t_{n+1} at the
//     predictor's positions (integrator.h), at every Newton iteration with
//     IntegratorSettings::waves_per_iteration, at t_0 for the initial accelerations and at the
//     kept Newton matrix's point when a state is restored; never in calm water (`waves` false:
//     System::Evaluate then reads the current alone) nor in the static solve;
//   - the supports and the drum: the integrator, from the State (State::supports,
//     WinchState::drum) at the start of each Newton solve, which the vehicle coupling and the
//     winch set for the step;
//   - the water at the vehicles: the vehicle coupling, once per step, at the start (or the
//     previous step's end, CouplingHistory::flow_end) and at the predicted end pose.
// Not here: the outputs' sea at a body (Simulation::WaterVelocityAt, SurfaceElevationAt,
// BodyDepth) is at the accepted state's positions and time, which no step input holds (the
// step samples at predicted positions); the outputs query the sea there.

#include <vector>

#include "core/cable_loads.h"
#include "core/environment_field.h"
#include "core/state.h"
#include "core/vehicle_model.h"

namespace towsim::core {

// The waves at every cable node (the array nodes of every cable, System::NodeIndex; with their
// derivative along the cable, d = r' at the node) and at every sphere (d = 0).
// And at the Gauss points of every element whose rest length is the cable's nominal one (not
// a winch's drum element), element e of cable c at NodeIndex(e, c), interpolated from its nodes'
// samples once per step (cable_loads.h).
struct WaveSamples {
  std::vector<WaveSample> nodes;
  std::vector<WaveSample> spheres;
  std::vector<GaussWaves> elements;
};

struct StepInputs {
  // the waves were sampled into `waves` (false: calm water, or a solve that ignores them)
  bool has_waves = false;
  WaveSamples waves;
  // the cable ends' vehicle attachment points over the step (2 c + end; state.h)
  std::vector<SupportMotion> supports;
  // element 0's rest length over the step, one per winch (cable w for winch w; state.h)
  std::vector<DrumMotion> drums;
  // the water at each vehicle at the start and the end of the step (Model::vehicles order;
  // vehicle_model.h)
  std::vector<VehicleFlow> vehicle_flow_start, vehicle_flow_end;
};

}  // namespace towsim::core
