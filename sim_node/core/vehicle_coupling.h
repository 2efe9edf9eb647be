#pragma once
// Coupling of the 6-DOF vehicles with the cables within one fixed step (paper Fig. 7, Eq. 29-30).
// A vehicle may hold any number of cable ends (attachments): each joint force acts at its
// own point (its moment about the vehicle's origin in the vehicle's load), and each
// attachment point answers its own joint force with its own compliance C_a (below); the
// compliance between two attachments of one vehicle, (h^2 / 4) R J_a M^-1 J_b^T R^T, is
// left to the passes, whose convergence test includes it.
//
// The vehicles advance with their own explicit RK4 (vehicle_model.h) under the cable's joint
// force lambda, applied at the attachment point; the cable then advances implicitly with the
// attachment points as driven supports, moving linearly from their positions at t_n to those
// at t_{n+1}, which gives the new joint force.
//   staggered (the paper's scheme): one pass, the vehicles see lambda_n (constant);
//   strong: the vehicles see the mean (lambda_n + lambda_{n+1}) / 2 of the joint force,
//   constant over the step, converged within the cable's Newton iteration (below).
// Why the mean: the joint impulse is h (lambda_n + lambda_{n+1}) / 2 either way, but the
// attachment point's displacement weights the two forces as the Newmark average-acceleration
// rule (beta = 1/4: h^2/4 each), which is unconditionally stable against the stiff cable end
// (k = EA / l_e). A force linear in time gives the linear-acceleration weights (h^2/3 on
// lambda_n, h^2/6 on lambda_{n+1}; beta = 1/6), stable only for omega h < sqrt(12) with
// omega^2 = k / m_vehicle: with the shipped cable that failed above h = 0.13 s, with E x10 at
// h = 0.05 s (tests/stress). Both are second order.
//
// The strong coupling inside the Newton iteration (docs/benchmarks.md): the vehicles advance
// once under a predicted joint force f1 and reach p1: the linear extrapolation of the last two
// steps, lambda_n + (h / h_prev)(lambda_n - lambda_{n-1}), or at equal steps the quadratic one
// of the last three, 3 lambda_n - 3 lambda_{n-1} + lambda_{n-2}, whichever has been nearer
// the joint forces the steps found lately (each one's error, the largest over the attachments,
// averaged as e <- (e + e_new) / 2; State::coupling; the quadratic one while its error is
// below kQuadraticMargin of the linear one's). In waves the joint forces follow the sea and
// the quadratic one is the nearer (Case 3: its error 0.28 of the linear one's on average; the
// vehicles advanced twice in 5 of 2000 steps against 983 with the linear one alone); in calm
// water after a manoeuvre it amplifies the steps' small oscillations and the linear one stays
// (docs/physics.md, "Coupling"). A change of lambda_{n+1} by
// d lambda moves the attachment point by C d lambda, with
//   C = (h^2 / 4) R_WB G R_WB^T,  G = J M^-1 J^T   (3 x 3 [m/N])
// the point's compliance (M = M_RB + M_A, J = [I, -S(at_B)]: point velocity from nu; h^2 / 4
// because the vehicle sees half of the change over the whole step). The cable's constraint is
// then Phi = r_end - p1 - C (lambda - f1), with -C in the multiplier block of the Newton
// matrix (state.h, SupportMotion), so one Newton solve finds the cable and the joint force
// consistent with the vehicles' linearized response. The residual r = lambda_{n+1} - f1
// moves the point by C r: within the tolerance, the step is converged and each vehicle takes
// its linear response to r (velocity (h / 2) M^-1 J^T R_WB^T r, displacement h / 2 of that:
// exact but for the damping and rotation over the step, a few per cent of C r). Otherwise
// the vehicles advance again under lambda_{n+1} and the step is converged when they reach
// p1 + C r within the tolerance; else the cable's Newton runs again from the last pass
// against the new supports (rare: in the first seconds of Case 1, where the joint force jumps
// by 100 N in a step). Most steps need one vehicle advance and one cable solve, like the
// staggered scheme.

#include <vector>

#include "core/integrator.h"
#include "core/simulation.h"
#include "core/state.h"
#include "core/step_inputs.h"
#include "core/step_sampler.h"
#include "core/system.h"

namespace towsim::core {

class VehicleCoupling {
 public:
  // the cables' system, its integrator and the step's inputs it shares with the integrator
  // (step_inputs.h: the coupling fills the water at the vehicles); all outlive it
  VehicleCoupling(const System& system, Integrator* integrator, StepInputs* inputs);

  // sets the attachment points of *state as its (static) supports and clears its coupling
  // history (State::coupling): a state that starts a run
  void HoldSupports(State* state);
  // sizes the per-step work space like `state` (Step then does not allocate)
  void SizeWorkSpace(const State& state);
  // one step of length h of cables and vehicles with the given vehicle commands
  StepStatus Step(State* state, const std::vector<VehicleCommand>& commands, double h);
  int last_iterations() const { return last_iterations_; }
  // the cable ends held by vehicles (State::coupling.f_previous has one entry each)
  int num_attachments() const { return static_cast<int>(attachments_.size()); }

 private:
  // a cable end held by a vehicle at a body-fixed point
  struct Attachment {
    int end = 0;      // the network's cable end 2 c + k (System::num_ends)
    int vehicle = 0;  // index into Model::vehicles
    Vec3 at_B = Vec3::Zero();
    Eigen::Matrix<double, 3, 6> j;  // J = [I, -S(at_B)]: the point's velocity from nu
    Mat3 g_B = Mat3::Zero();        // G = J M^-1 J^T, body frame [1/kg]
    Eigen::Matrix<double, 6, 3> m_inv_jt;  // M^-1 J^T (body frame)
  };
  // attachment point of attachment a in the world frame: p_WB + R_WB at_B (Eq. 24)
  Vec3 AttachmentPoint(const VehicleState& vs, int a) const;
  // a converged step: keeps lambda_n (of `start`), h and the water at the step's end in
  // state->coupling for the next step
  StepStatus Accept(const State& start, double h, State* state, StepStatus* status);
  // the linear response of vehicle state *vs (advanced over h) to a change r_W of the joint
  // force at t_{n+1} at attachment a (see the header)
  void CorrectVehicle(int a, const Vec3& r_W, double h, VehicleState* vs) const;

  const System& system_;
  Integrator* integrator_;
  StepSampler sampler_;
  StepInputs* inputs_;
  // the attachments, ordered by vehicle: vehicle v holds attachments first_[v] .. first_[v+1]-1
  std::vector<Attachment> attachments_;
  std::vector<int> first_;
  int last_iterations_ = 0;
  // per-step work space, sized once: Step does not allocate
  State start_;
  State previous_pass_;  // the cables' solution of the previous strong-coupling pass
  NewtonPoint newton_;   // the kept Newton matrix carried from pass to pass
  int previous_pass_substeps_ = 0;
  std::vector<VehicleState> vehicles_;
  std::vector<Vec3> f0_, f1_, residual_;  // per attachment
  // this step's two predictions of lambda_{n+1}, and whether both were made (Accept scores
  // them)
  std::vector<Vec3> linear_, quadratic_;
  bool predicted_ = false;
  double weight_scale_;                    // W of the force bound (newton_convergence.h)
  // the last pass's largest joint-force residual and its bound [N], for the failure message
  double last_force_residual_ = 0.0, last_force_bound_ = 0.0;
  std::vector<Mat3> point_compliance_;    // per attachment
  std::vector<double> end_stiffness_;     // per attachment: its end element's EA / l_e [N/m]
  std::vector<PointLoad> loads_;          // per attachment
  std::vector<VehicleInertia> inertia_;   // each vehicle's, factored once (vehicle_model.h)
};

}  // namespace towsim::core
