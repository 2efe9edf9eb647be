#pragma once
// The dynamic state: a copyable value (DESIGN §1: Model / State / Workspace kept apart).
//
// Generalized coordinates q (n x 1), ordered
//   [ body 0 (3) ... body B-1 (3) | cable node 0 (6) ... cable node N (6) ]
// where a cable node holds e = [r (3), r' = dr/dx (3)] (paper Eq. 1) and a sphere body holds
// its position p_WB (3). Offsets come from Simulation::body_dof / cable_dof.

#include <vector>

#include <Eigen/Core>

#include "core/vehicle_model.h"

namespace towsim::core {

struct State {
  double t = 0.0;           // [s]
  Eigen::VectorXd q;        // generalized positions
  Eigen::VectorXd v;        // generalized velocities
  Eigen::VectorXd a;        // generalized accelerations
  Eigen::VectorXd a_alpha;  // generalized-alpha pseudo acceleration (equals a for trapezoidal)
  Eigen::VectorXd lambda;   // constraint multipliers: start end, then end end [N]
  std::vector<VehicleState> vehicles;  // 6-DOF vehicles (Model::vehicles order)
};

}  // namespace towsim::core
