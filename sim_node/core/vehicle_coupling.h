#pragma once
// Coupling of the 6-DOF vehicles with the cable within one fixed step (paper Fig. 7, Eq. 29-30).
//
// The vehicles advance with their own explicit RK4 (vehicle_model.h) under the cable's joint
// force lambda, applied at the attachment point; the cable then advances implicitly with the
// attachment points as driven supports, moving linearly from their positions at t_n to those
// at t_{n+1}, which gives the new joint force.
//   staggered (the paper's scheme): one pass, the vehicles see lambda_n (constant);
//   strong: the pass is repeated with the vehicles seeing lambda varying linearly from lambda_n
//   to the latest lambda_{n+1}, with Aitken's dynamic relaxation (Kuettler & Wall 2008) on
//   lambda_{n+1}, until the attachment points move by less than the Newton tolerance.
// The iteration converges when (stiffness of the cable end + its inertia / h^2) h^2 / (2 m_veh)
// < 1, i.e. for any step at which the cable's own integration is meaningful.

#include <vector>

#include "core/integrator.h"
#include "core/simulation.h"
#include "core/state.h"
#include "core/system.h"

namespace towsim::core {

class VehicleCoupling {
 public:
  VehicleCoupling(System* system, Integrator* integrator);

  // sets the attachment points of the current state as the (static) supports
  void HoldSupports(const State& state);
  // one step of length h of cable and vehicles with the given vehicle commands
  StepStatus Step(State* state, const std::vector<VehicleCommand>& commands, double h);
  int last_iterations() const { return last_iterations_; }

  // the force the cable exerts on vehicle v (world frame) in `state`, zero if not attached
  Vec3 JointForce(const State& state, int v) const;
  // attachment point of the cable end on vehicle v in the world frame
  Vec3 AttachmentPoint(const VehicleState& vs, int end) const;

 private:
  System* system_;
  Integrator* integrator_;
  int vehicle_end_[2] = {-1, -1};  // vehicle index holding each cable end, or -1
  int last_iterations_ = 0;
  // per-step work space, sized once: Step does not allocate
  State start_;
  std::vector<VehicleState> vehicles_;
  std::vector<Vec3> f0_, f1_, residual_, residual_prev_;
};

}  // namespace towsim::core
