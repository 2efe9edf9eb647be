#pragma once
// The one place a step samples the sea and takes its boundary motions (step_inputs.h): it
// fills a StepInputs that System::Evaluate, the integrator and the vehicle coupling read.
//
//   waves at the cable nodes and spheres (SampleWaves):
//     nodes:   [w, dw/dx] = sea.Waves(r, r', t)   (the derivative along r' = d/dx, x the
//              unstretched arc length; environment_field.h)
//     spheres: w = sea.Waves(p_WB, 0, t)
//   water at the vehicles (SampleVehicleFlows): at the step's start (the previous step's end
//     when it was sampled at t_n, CouplingHistory::flow_end) and at the end pose predicted from
//     the start, p_1 = p_WB + h R_WB nu_1 (the attitude of t_n; vehicle_coupling.h)
//   supports and drum (TakeMotions): State::supports and WinchState::drum as the vehicle
//     coupling and the winch set them for the step
//
// Called by the integrator (the waves, once per (sub)step or per Newton iteration, integrator.h;
// the motions, at the start of each Newton solve) and by the vehicle coupling (the vehicles'
// water, once per step). Does not allocate once Resize has sized the inputs.

#include "core/state.h"
#include "core/step_inputs.h"
#include "core/system.h"

namespace towsim::core {

class StepSampler {
 public:
  explicit StepSampler(const System& system) : system_(system) {}

  // sizes *in for the system's preallocated nodes, its spheres and the scene's vehicles
  // (allocates: call once, outside Step)
  void Resize(StepInputs* in) const;
  // the waves at the nodes in use and the spheres of q at time t into in->waves; sets
  // in->has_waves
  void SampleWaves(const Eigen::VectorXd& q, double t, StepInputs* in) const;
  // the water at each vehicle over the step [t_0, t_0 + h] from `start` (the step's start
  // state) into in->vehicle_flow_start and in->vehicle_flow_end
  void SampleVehicleFlows(const State& start, double h, StepInputs* in) const;
  // the supports and the drum motion of `state` into *in
  void TakeMotions(const State& state, StepInputs* in) const;

 private:
  const System& system_;
};

}  // namespace towsim::core
