#pragma once
// Static equilibrium before t = 0 (cable.initial = static): solve
//   F_int(q) - Q_ext(q, V_f) + Phi_q^T lambda = 0,  Phi(q, 0) = 0
// in the frame moving with the uniform velocity V_f (cable.initial_velocity): with a driven end
// this is the steady towed configuration, with fixed ends the classic mooring statics. Newton
// with pseudo-transient continuation (Kelley & Keyes 1998): the iteration matrix is
// K + M_eff / delta, delta grown by switched evolution relaxation (delta_{k+1} = delta_k
// |R_{k-1}| / |R_k|), so far from equilibrium it is damped implicit dynamics and near it plain
// Newton with quadratic convergence. Exact to the solver tolerance, no dynamic relaxation.

#include <functional>
#include <string>

#include "core/state.h"
#include "core/system.h"

namespace towsim::core {

struct StaticResult {
  bool ok = false;
  bool stopped = false;  // `stop` asked for it: no equilibrium, *state the last iterate
  int iterations = 0;
  double residual = 0.0;  // inf-norm of R [N]
  std::string message;
};

// *state holds the initial guess (q) and is overwritten with the equilibrium, v = V_f on every
// node position and body, lambda the support reactions. `stop` (if set) is asked before every
// iteration; true ends the solve (the caller's stop request: the core has no signals).
StaticResult SolveStatic(const System& system, const Eigen::Vector3d& frame_velocity, State* state,
                         const std::function<bool()>& stop = {});

}  // namespace towsim::core
