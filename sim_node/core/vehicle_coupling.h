#pragma once
// Coupling of the 6-DOF vehicles with the cable within one fixed step (paper Fig. 7, Eq. 29-30).
//
// The vehicles advance with their own explicit RK4 (vehicle_model.h) under the cable's joint
// force lambda, applied at the attachment point; the cable then advances implicitly with the
// attachment points as driven supports, moving linearly from their positions at t_n to those
// at t_{n+1}, which gives the new joint force.
//   staggered (the paper's scheme): one pass, the vehicles see lambda_n (constant);
//   strong: the pass is repeated with the vehicles seeing the mean (lambda_n + lambda_{n+1}) / 2
//   of the joint force, constant over the step, with Aitken's dynamic relaxation (Kuettler &
//   Wall 2008) on lambda_{n+1}, until the attachment points move by less than the Newton
//   tolerance.
// Why the mean: the joint impulse is h (lambda_n + lambda_{n+1}) / 2 either way, but the
// attachment point's displacement weights the two forces as the Newmark average-acceleration
// rule (beta = 1/4: h^2/4 each), which is unconditionally stable against the stiff cable end
// (k = EA / l_e). A force linear in time gives the linear-acceleration weights (h^2/3 on
// lambda_n, h^2/6 on lambda_{n+1}; beta = 1/6), stable only for omega h < sqrt(12) with
// omega^2 = k / m_vehicle: with the shipped cable that failed above h = 0.13 s, with E x10 at
// h = 0.05 s (tests/stress). Both are second order.
// The iteration converges when (stiffness of the cable end + its inertia / h^2) h^2 / (2 m_veh)
// < 1, i.e. for any step at which the cable's own integration is meaningful.
//
// Cost (docs/benchmarks.md): each pass is a full cable solve, so the strong scheme starts from
// a predictor, lambda_{n+1} ~ lambda_n + (h / h_prev)(lambda_n - lambda_{n-1}) (linear
// extrapolation of the last two steps), and stops as soon as the joint-force residual
// r = lambda_{n+1} - guess cannot move an attachment point by more than the tolerance: the
// vehicles see the mean (lambda_n + guess) / 2, constant over the step, so the error r in the
// guess is an error r / 2 in that force and moves the point by at most (h^2 / 2) g |r| / 2
// = (h^2 / 4) g |r|, g the largest eigenvalue of the point's compliance G = J M^-1 J^T
// (M = M_RB + M_A, J = [I, -S(at_B)]: point velocity from nu). In a steady tow most steps then
// need one pass, like the staggered scheme, and still satisfy the strong scheme's tolerance.
// Aitken's factor adapts within a step from the second update on; the first update takes the
// factor the previous step ended with (State::coupling.relaxation; kFirstRelaxation at the
// start of a run): the coupling's contraction rate changes little from one step to the next,
// and a fixed first factor of 1/2 would leave half of the first residual for the next pass
// whatever the rate (in waves, where every step needs a second pass, it made one step in five
// take a third).

#include <vector>

#include "core/integrator.h"
#include "core/simulation.h"
#include "core/state.h"
#include "core/system.h"

namespace towsim::core {

class VehicleCoupling {
 public:
  VehicleCoupling(System* system, Integrator* integrator);

  // sets the attachment points of *state as its (static) supports and clears its coupling
  // history (State::coupling): a state that starts a run
  void HoldSupports(State* state);
  // sizes the per-step work space like `state` (Step then does not allocate)
  void SizeWorkSpace(const State& state);
  // one step of length h of cable and vehicles with the given vehicle commands
  StepStatus Step(State* state, const std::vector<VehicleCommand>& commands, double h);
  int last_iterations() const { return last_iterations_; }

  // the force the cable exerts on vehicle v (world frame) in `state`, zero if not attached
  Vec3 JointForce(const State& state, int v) const;
  // attachment point of the cable end on vehicle v in the world frame
  Vec3 AttachmentPoint(const VehicleState& vs, int end) const;

 private:
  // a converged step: keeps lambda_n (of `start`), h and the water at the step's end in
  // state->coupling for the next step
  StepStatus Accept(const State& start, double h, State* state, StepStatus* status);

  System* system_;
  Integrator* integrator_;
  int vehicle_end_[2] = {-1, -1};      // vehicle index holding each cable end, or -1
  double compliance_[2] = {0.0, 0.0};  // largest eigenvalue of G at each vehicle end [1/kg]
  int last_iterations_ = 0;
  // the relaxation factor a run starts with (Kuettler & Wall 2008 start Aitken at 0.5 or less)
  static constexpr double kFirstRelaxation = 0.5;
  double relaxation_ = kFirstRelaxation;  // this step's last Aitken factor
  // per-step work space, sized once: Step does not allocate
  State start_;
  State previous_pass_;  // the cable's solution of the previous strong-coupling pass
  NewtonPoint newton_;   // the kept Newton matrix carried from pass to pass
  int previous_pass_substeps_ = 0;
  std::vector<VehicleState> vehicles_;
  std::vector<Vec3> f0_, f1_, residual_, residual_prev_;
  // the water at each vehicle at the start and the end of the step (vehicle_model.h): sampled
  // once per step, the end at the pose predicted from the start (p + h R_WB nu_1); the end of
  // one step is the start of the next (State::coupling.flow_end)
  std::vector<VehicleFlow> flow0_, flow1_;
};

}  // namespace towsim::core
