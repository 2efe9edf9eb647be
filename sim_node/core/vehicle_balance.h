#pragma once
// Static equilibrium of cables and vehicles together (cable.initial = static with vehicles in
// the scene): every vehicle that holds a cable end is placed where it is in steady motion
// with the frame velocity V_f (cable.initial_velocity), so that a run starts in steady tow.
//
// For vehicle v with pose x_v = (p_W, roll, pitch, yaw), body velocity nu = [R_WB^T V_f; 0]
// and actuators at their commanded positions, the steady motion asks nu_dot = 0 in the
// vehicle's equations (vehicle_model.h, paper Eq. 27-28):
//   R_v(x) = (M_RB + M_A) nu_dot(x_v, tau_cable(x)) = 0       (6 per vehicle)
// where tau_cable is the sum of the joint forces lambda_a (Eq. 29-30) of the cable ends it
// holds, with their moments about O, from the cables' static equilibrium with the vehicles
// held where x puts them (SolveStatic, static_solver.h). A towing vehicle (one with a
// propeller, in a scene where no fixed, driven or vessel end holds the frame) has no
// horizontal position of its own in the moving frame (the whole system may translate): its x
// and y are kept and its thrust is the unknown instead, the thrust that holds the speed.
//
// Solved by Levenberg-Marquardt on the vehicles' unknowns (Marquardt's diagonal scaling,
// Nocedal & Wright 2006 §10.3), the Jacobian by forward differences of R, each column one
// static solve of the cables started from the current equilibrium; each step is limited to a
// tenth of the shortest cable in position and 0.2 rad in attitude. Converged when every
// vehicle's force residual is below kBalanceTolerance of its force scale (its weight and its
// cable force) and its moment residual below that times its length. Where no equilibrium is
// reachable (a buoyant vehicle on a slack line, a towing vehicle whose propeller cannot hold
// the speed) the result says which vehicle and which balance is left, docs/physics.md
// "Static equilibrium with vehicles".

#include <functional>
#include <string>
#include <vector>

#include "core/state.h"
#include "core/static_solver.h"
#include "core/system.h"

namespace towsim::core {

// relative residual at which the balance is converged (of the vehicle's force scale), whatever
// integrator.tolerance: a run that starts in its balance has almost no discretisation error,
// so the balance's own must be smaller still (docs/physics.md "Static equilibrium with
// vehicles")
constexpr double kBalanceTolerance = 1e-7;

struct BalanceResult {
  bool ok = false;
  bool stopped = false;  // `stop` asked for it
  int iterations = 0;    // Levenberg-Marquardt iterations
  int static_solves = 0;
  double residual = 0.0;  // largest relative residual (of the force scale)
  std::string message;  // why it failed
  // on success: "balanced 2 vehicles in 6 iterations (73 static solves); tow_vehicle's thrust
  // 4162.7 N"
  std::string report;
};

// the vehicles that hold a cable end (those the balance moves)
std::vector<int> HeldVehicles(const System& system);
// whether vehicle v tows: it has a propeller and no fixed, driven or vessel end holds the frame
bool IsTowingVehicle(const System& system, int v);

// *state holds the cables' initial guess and the vehicles' poses as their guess; on success it
// holds the equilibrium: cables (q, v = V_f, lambda), each held vehicle's pose, nu = [R^T V_f;
// 0] and actuators at their commands, the supports at the attachment points. (*commands)[v] is
// the command in force at t = 0; a towing vehicle's thrust is replaced by the balancing one.
BalanceResult SolveStaticWithVehicles(const System& system, const Eigen::Vector3d& frame_velocity,
                                      std::vector<VehicleCommand>* commands, State* state,
                                      const std::function<bool()>& stop = {});

}  // namespace towsim::core
