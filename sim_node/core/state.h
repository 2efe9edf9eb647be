#pragma once
// The dynamic state: a copyable value (docs/contract.md §1: Model / State / Workspace kept apart), and
// complete: everything a step reads from the steps before it is here, so that a State taken
// with Simulation::GetState and given back with Simulation::SetState continues bit for bit as
// if the run had never stopped (tests/unit/simulation_state_test.cc).
//
// Generalized coordinates q (n x 1), ordered
//   [ sphere 0 (3) ... sphere S-1 (3) | cable node 0 (6) ... cable node N (6) ]
// where a cable node holds e = [r (3), r' = dr/dx (3)] (paper Eq. 1) and a sphere holds its
// position p_WB (3). Offsets come from Simulation::sphere_dof / cable_dof.
//
// Besides t, q, v, a and the multipliers, a step depends on
//   - the motion of the vehicle attachment points over the step (`supports`): the vehicles are
//     driven supports of the cable's Newton solve (vehicle_coupling.h);
//   - the coupling's history (`coupling`): the joint forces of the previous step for the
//     predictor and the water sampled at the end of the previous step;
//   - the integrator's kept Newton matrix (`newton`, integrator.h): not stored itself (it is a
//     cache), but the point it was linearized at, its step size and contraction rate, from
//     which Simulation::SetState rebuilds it exactly.

#include <vector>

#include <Eigen/Core>

#include "core/vehicle_model.h"

namespace towsim::core {

// a vehicle attachment point moving linearly from p0 at t0 to p1 at t1 (t1 <= t0: held at p1).
// With the strong coupling (vehicle_coupling.h) the end point answers the joint force: p1 is
// where the vehicle reaches under the force lambda1, and a force lambda moves it to
//   p1(lambda) = p1 + compliance (lambda - lambda1)   (compliance = (h^2 / 4) G, 3 x 3 [m/N])
struct SupportMotion {
  Vec3 p0 = Vec3::Zero(), p1 = Vec3::Zero();
  double t0 = 0.0, t1 = 0.0;
  Eigen::Matrix3d compliance = Eigen::Matrix3d::Zero();
  Vec3 lambda1 = Vec3::Zero();
};

// what the vehicle coupling carries from one step to the next (vehicle_coupling.h)
struct CouplingHistory {
  bool have_previous = false;    // the predictor has a previous step
  double h_previous = 0.0;       // its length [s]
  std::vector<Vec3> f_previous;  // joint force on each vehicle at its start, world frame [N]
  // the step before that had the same length: f_second, the joint forces at its start, make
  // the quadratic predictor possible
  bool have_second = false;
  std::vector<Vec3> f_second;
  // each predictor's recent error on the joint forces (halved each step, plus the newest) [N]
  double error_linear = 0.0, error_quadratic = 0.0;
  // the water at each vehicle sampled at the end of the previous step (at the predicted pose)
  // and its time (< 0: none; the next step then samples its start itself)
  double flow_time = -1.0;
  std::vector<VehicleFlow> flow_end;
};

// the linearization point of the integrator's kept Newton matrix (integrator.h)
struct NewtonPoint {
  bool valid = false;       // a kept matrix exists
  double h = 0.0;           // step size it was formed for [s]
  double t = 0.0;           // time it was evaluated at [s]
  Eigen::VectorXd q, v, a;  // the iterate it was evaluated at
  // the waves it was evaluated with: sampled at wave_q at t (only with waves)
  Eigen::VectorXd wave_q;
  // each winch's drum element's l_0 and dl_0/dt then (State::winches order, one per winch)
  std::vector<double> drum_length, drum_rate;
  // the support compliances it holds in its multiplier blocks (SupportMotion::compliance), one
  // per cable end (2 c + end)
  std::vector<Eigen::Matrix3d> support_compliance;
  double theta = 0.0;  // its measured contraction rate
  int theta_age = 0;   // steps since theta was measured
  // the last re-measurement of theta (core/integrator.h, kMaxThetaAge) found it small: the
  // next one is due after kMaxThetaAgeSteady steps instead
  bool theta_steady = false;
};

// the rest length of the cable's element 0 at the drum over a step (system.h): from `length`
// at t0, its rate and a constant second derivative (the winch's motion, winch.h)
struct DrumMotion {
  double t0 = 0.0;      // [s]
  double length = 0.0;  // l_0(t0) [m]
  double rate = 0.0;    // dl_0/dt at t0 [m/s]
  double accel = 0.0;   // d2l_0/dt2 [m/s^2]
  double LengthAt(double t) const {
    const double s = t - t0;
    return length + s * (rate + 0.5 * accel * s);
  }
  double RateAt(double t) const { return rate + accel * (t - t0); }
};

// a cable's winch (winch.h): the paid-out unstretched length, its rate and the nodes in use; a
// cable without a winch keeps the length cable.length, the speed 0 and cable.elements + 1 nodes
struct WinchState {
  double length = 0.0;  // L [m]
  double speed = 0.0;   // dL/dt [m/s], + pays out
  double drive_speed = 0.0;  // the drive's own speed, without the brake's slip (winch.h)
  double slip_speed = 0.0;   // the brake's slip (winch.h)
  double slip_slope = 0.0;   // dT/ds the brake's last secant measured [N s/m] (0: none yet)
  int nodes = 0;        // cable nodes in use (part of the state's shape)
  bool slipping = false;  // the brake slipped in the last step
  DrumMotion drum;        // element 0's rest length over the last (or current) step
};

struct State {
  double t = 0.0;           // [s]
  long step = 0;            // steps taken
  Eigen::VectorXd q;        // generalized positions
  Eigen::VectorXd v;        // generalized velocities
  Eigen::VectorXd a;        // generalized accelerations
  Eigen::VectorXd a_alpha;  // generalized-alpha pseudo acceleration (equals a for trapezoidal)
  Eigen::VectorXd lambda;   // constraint multipliers: start end, then end end [N]
  std::vector<VehicleState> vehicles;  // 6-DOF vehicles (Model::vehicles order)
  // vehicle attachment points, one per cable end (2 c + end: cable c's start, end)
  std::vector<SupportMotion> supports;
  CouplingHistory coupling;
  NewtonPoint newton;
  // one per cable (Model::cables order; the winched cables come first, so winch w is cable w):
  // its length, drum and nodes in use (part of the state's shape)
  std::vector<WinchState> winches;
};

}  // namespace towsim::core
