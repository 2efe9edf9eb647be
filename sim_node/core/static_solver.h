#pragma once
// Static equilibrium before t = 0 (cable.initial = static): solve
//   F_int(q) - Q_ext(q, V_f) + Phi_q^T lambda = 0,  Phi(q, 0) = 0
// in the frame moving with the uniform velocity V_f (cable.initial_velocity): with a driven end
// this is the steady towed configuration, with fixed ends the classic mooring statics. Newton
// with pseudo-transient continuation (Kelley & Keyes 1998): the iteration matrix is
// K + M_eff / delta, delta grown by switched evolution relaxation (delta_{k+1} = delta_k
// |R_{k-1}| / |R_k|, and by at least kMinGrowth while |R| does not rise: static_solver.cc), so
// far from equilibrium it is damped implicit dynamics and near it plain Newton with quadratic
// convergence. Exact to the solver tolerance, no dynamic relaxation.
//
// A converged shape is accepted only if it is a cable's (docs/physics.md "Initial shapes"): no
// folded element (fold_check.h), no loop (its tangent turns by at most kMaxStaticTurning in
// all) and no element force beyond what the loads can give, the
// largest support force plus the external loads on the whole network,
//   |T(s)| <= kTensionBoundFactor (max_ends |lambda_end| + F_ext)
// (dT/ds = -f . t along a cable, so T varies by at most the load on it). A first solve that
// converges to a shape failing this check is repeated from the slack-free catenary guess
// (initial_shape.h, LayOutCatenary) with every slope's change per iteration limited to
// kMaxSlopeStep, so that no element can turn over in one Newton step; if that shape fails
// too, the solve fails with the diagnosis (the element, its strain, its slopes).

#include <functional>
#include <string>

#include "core/network_matrix.h"
#include "core/state.h"
#include "core/system.h"

namespace towsim::core {

struct StaticResult {
  bool ok = false;
  bool stopped = false;  // `stop` asked for it: no equilibrium, *state the last iterate
  int iterations = 0;
  double residual = 0.0;  // inf-norm of R [N]
  std::string message;
  int attempts = 0;  // 1, or 2 when the first shape failed the check (restarted: guess)
  std::string rejected;  // why the first attempt's shape was rejected (empty if it was not)
};

// a converged shape's element forces may exceed the bound of the loads by this factor (the
// bending shear and the drag scale's estimate of the speeds are not in the bound) [-]
constexpr double kTensionBoundFactor = 2.0;
// a static cable's tangent turns by less than pi in all under gravity and a uniform flow
// (fold_check.h, TotalTurning); an S-shape in a current profile adds to it, a loop adds 2 pi:
// a shape whose tangent turns by more than this is rejected as looped [rad]
constexpr double kMaxStaticTurning = 1.75 * 3.14159265358979323846;
// largest change of a slope component r' per Newton iteration of the second attempt [-]
constexpr double kMaxSlopeStep = 0.2;

// where a solve starts (SolveStatic)
enum class StaticStart {
  // from the guess's positions: multipliers zero, pseudo-transient continuation from a small
  // pseudo time step (far from equilibrium it is damped implicit dynamics)
  kGuess,
  // *state is the equilibrium of supports near the new ones (its q and lambda): plain Newton
  // from it, converging quadratically in a few iterations; if its increment does not shrink
  // at every iteration, or the shape fails its check, the solve starts again as from kGuess
  // (from the same positions)
  kNearEquilibrium,
};

// the factors of the Newton matrix a solve formed at its last iterate (the equilibrium): a
// chord for solves from nearby equilibria (SolveStatic's `chord`)
struct StaticFactors {
  NetworkMatrix matrix;
  bool valid = false;
};

// *state holds the initial guess (q) and is overwritten with the equilibrium, v = V_f on every
// node position and body, lambda the support reactions. `stop` (if set) is asked before every
// iteration; true ends the solve (the caller's stop request: the core has no signals).
// `tolerance` (relative, of the force scale and the cable length) overrides
// integrator.tolerance when positive (the vehicles' balance differences solves and asks more).
// With kNearEquilibrium and valid `chord` factors (formed at that nearby equilibrium), the
// first attempt is a chord iteration with them (residuals only, 2-3 for a small move), then
// plain Newton, then the start from the guess. `factors_out` (if set) receives the factors at
// the equilibrium found (a chord's: a copy of `chord`); valid false if none.
StaticResult SolveStatic(const System& system, const Eigen::Vector3d& frame_velocity, State* state,
                         const std::function<bool()>& stop = {}, double tolerance = 0.0,
                         StaticStart start = StaticStart::kGuess, StaticFactors* chord = nullptr,
                         StaticFactors* factors_out = nullptr);

}  // namespace towsim::core
