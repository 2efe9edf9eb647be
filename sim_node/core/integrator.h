#pragma once
// Implicit time integration of the constrained system: generalized-alpha (Chung & Hulbert 1993)
// in the form of Arnold & Bruls (2007), with the equations of motion and the position-level
// constraints (paper Eq. 26) enforced at t_{n+1}:
//   (1 - alpha_m) a^_{n+1} + alpha_m a^_n = (1 - alpha_f) a_{n+1} + alpha_f a_n
//   q_{n+1} = q_n + h v_n + h^2 (1/2 - beta) a^_n + h^2 beta a^_{n+1}
//   v_{n+1} = v_n + h (1 - gamma) a^_n + h gamma a^_{n+1}
// alpha_m = (2 rho - 1)/(rho + 1), alpha_f = rho/(rho + 1), gamma = 1/2 + alpha_f - alpha_m,
// beta = (gamma + 1/2)^2 / 4. rho_inf = 1 gives the trapezoidal rule (Newmark average
// acceleration, energy-conserving for linear systems); rho_inf < 1 damps high frequencies,
// second order throughout. Newton on q_{n+1} (and lambda):
//   [ c_a M_eff + K + c_v C   Phi_q^T ] [dq     ]   [ -R   ]
//   [ Phi_q                   0       ] [dlambda] = [ -Phi ],
// c_a = (1 - alpha_m) / ((1 - alpha_f) beta h^2), c_v = gamma / (beta h),
// solved block-tridiagonally. A step whose Newton fails is halved recursively.
//
// The kept Newton matrix (below) belongs to the state: State::newton holds the point it was
// formed at (q, v, a, t, h and the waves' sampling positions), its contraction rate and age;
// the factored matrix in this class is a cache of it, rebuilt by RestoreNewtonMatrix when a
// state is set, so a restored run continues bit for bit. The Newton matrix depends on neither
// the multipliers nor the support positions (the joints are linear in q and lambda), only on
// the supports' compliances (vehicle_coupling.h), which State::newton keeps with it.
//
// Modified Newton: the factored Newton matrix is kept across iterations and steps (most steps
// converge in one iteration, and a residual alone costs a fraction of residual + tangent +
// factorization). It is refreshed when h changes (c_a, c_v depend on it) or when it contracts
// too slowly: with theta = |dq_k| / |dq_{k-1}| the contraction rate of the kept matrix, the
// error left after an increment dq is about theta / (1 - theta) |dq| (Hairer & Wanner, Solving
// ODEs II, IV.8), so an iterate x + dq is accepted when that estimate is within the tolerance,
// with theta taken at least kMaxContraction (the rates measured on a step's large first
// increments understate those of the smaller ones after them), i.e. |dq| <= 2.3 tol; a fresh
// matrix is accepted by the same test (its rate ~ 0, taken as kMaxContraction). A matrix with
// theta > kMaxContraction is replaced at the current iterate, and one whose last measured rate
// exceeds kRefreshRate at the next step's first evaluation (the matrix is formed with the
// residual that step evaluates anyway: a refresh there costs the tangent but no evaluation).
// A kept matrix whose first increment fails the test and whose rate was measured more than
// kMaxKeepAge steps ago is replaced for the second evaluation (its rate grows with its age: it
// would be replaced within the step anyway, and replacing it now saves the third evaluation).
// A first iteration is accepted on a rate measured at most kMaxThetaAge steps ago, or
// kMaxThetaAgeSteady after a re-measurement found it below kSteadyRate.
// Where the residual changes sharply between iterates (a contact switching on), a kept matrix
// can lead away: a matrix formed at the previous iterate whose first reuse shows theta >
// kMaxContraction is replaced at every iterate for the rest of the step (formed again where its
// increment led, it would send the iterate back where it was: a cycle), and an older one whose
// increment is no smaller than the last (theta >= 1) after an increment that raised |r|_inf
// has both increments taken back and a fresh matrix formed where the last one started
// (docs/physics.md, "Newton convergence").
// A step that fails with a kept matrix is retried with full Newton (a fresh matrix at every
// iteration) before it is halved.
// The measurements behind each rule and constant, and what was tried instead:
// docs/benchmarks.md#the-integrators-newton-rules-the-evidence.
//
// Predictor: a^_{n+1} = a^_n. Extrapolating a^ from the steps before is closer in the smooth
// phases, but at the shipped tolerance it amplifies the accepted iterates' errors (their
// high-frequency part, which generalized-alpha reverses and damps by rho_inf every step while
// the predictor extrapolates it) and costs more evaluations (docs/benchmarks.md, the same
// section).
//
// Waves (environment_field.h): their kinematics are sampled once per (sub)step at t_{n+1} at
// the predictor's node positions and held through the Newton iterations (the Newton matrix is
// then exact for the residual it solves); IntegratorSettings::waves_per_iteration resamples
// them at every iteration instead, to measure what holding them costs in accuracy.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/network_matrix.h"
#include "core/simulation.h"
#include "core/state.h"
#include "core/step_inputs.h"
#include "core/step_sampler.h"
#include "core/system.h"

namespace towsim::core {

struct AlphaParameters {
  double alpha_m, alpha_f, gamma, beta;
  static AlphaParameters FromSettings(const IntegratorSettings& s);
};

class Integrator {
 public:
  // reads the sea and the supports from *inputs, which it sizes (StepSampler::Resize) and
  // fills with the waves and the State's motions (step_inputs.h); *inputs outlives it
  Integrator(const System& system, StepInputs* inputs);

  // advance *state by h (sub-stepping on Newton failure). `guess`, if given, is a solution of
  // a nearby problem over the same step (the previous vehicle-coupling pass, whose supports
  // moved slightly): Newton starts from its a^_{n+1} and lambda instead of the predictor.
  StepStatus Step(State* state, double h, const State* guess = nullptr);
  // consistent a and lambda at the current q, v: [M_eff Phi_q^T; Phi_q 0] [a; lambda] = [Q - F; 0]
  bool InitializeAcceleration(State* state);
  // rebuilds the kept Newton matrix of `state` (State::newton) into this integrator's cache;
  // false if it cannot be factored
  bool RestoreNewtonMatrix(const State& state);
  // Newton matrices factored so far (full evaluations of the tangent), for profiling and tests
  long tangent_refreshes() const { return tangent_refreshes_; }

  // a kept Newton matrix is replaced once its contraction rate exceeds this: the remaining
  // error is then at most theta / (1 - theta) = 0.43 of the last increment, and a fresh matrix
  // (quadratic convergence) is cheaper than the extra iterations a slower rate would cost
  static constexpr double kMaxContraction = 0.3;
  // a first iteration with a kept matrix is accepted on the rate measured at most this many
  // steps ago; otherwise one more iteration measures it (an increment alone does not bound the
  // error of an inexact matrix: it may be stiffer than the true one in some direction). A
  // refreshed matrix counts as measured (theta ~ 0 where it was formed, taken as
  // kMaxContraction)
  static constexpr int kMaxThetaAge = 16;
  // ... and at most this many steps ago after a re-measurement (one due by kMaxThetaAge) found
  // the rate below kSteadyRate; any measured rate at or above it, and a refresh, return to
  // kMaxThetaAge. Longer saves evaluations but leaves a run at a small h more solver error
  static constexpr int kMaxThetaAgeSteady = 32;
  // half kRefreshRate: re-measured rates fall mostly well below it or above kMaxContraction
  static constexpr double kSteadyRate = 0.1;
  // a kept matrix whose first increment fails the test is kept for the second evaluation only
  // if its rate was measured at most this many steps ago, else replaced (see above): older
  // ones are almost always replaced within the step anyway
  static constexpr int kMaxKeepAge = 7;
  // a kept matrix whose last measured rate exceeds this is replaced at the first evaluation of
  // the next step (its Newton matrix is formed with that residual: no extra evaluation), not
  // after a first iteration has shown the rate above kMaxContraction (one evaluation more).
  // Lower thresholds leave more steps converged to just within the tolerance, and the swinging
  // cable's fitted order (tests/reference/swinging_cable_core_test.cc, >= 1.8) near its bound
  static constexpr double kRefreshRate = 0.2;

 private:
  struct Attempt {
    bool ok = false;
    bool non_finite = false;
    bool reused = false;  // a kept (not freshly computed) Newton matrix was used
    int iterations = 0;
    double residual = 0.0;
    int worst_dof = 0;
    // the last force test (newton_convergence.h): theta |r_k| in force units, its bound and
    // where it was largest; 0 when no increment met its bound
    double force_residual = 0.0, force_bound = 0.0;
    int worst_force_dof = 0;
  };
  // full: a fresh Newton matrix at every iteration (classic Newton); else modified Newton
  Attempt Newton(State* state, double h, bool full, const State* guess);
  StepStatus Advance(State* state, double h, int level, const State* guess);

  const System& system_;
  StepSampler sampler_;
  StepInputs* inputs_;  // the step's inputs (step_inputs.h), shared with the vehicle coupling
  AlphaParameters ap_;
  double q_scale_;
  double weight_scale_;  // W of the force bound (newton_convergence.h)
  // every element at least 1 m long: the force norm is at most |r|_inf (newton_convergence.h)
  bool slopes_at_most_inf_;
  NetworkMatrix jac_;
  Eigen::VectorXd r_, phi_, rhs_, dq_, dl_;
  Eigen::VectorXd dq_last_, dl_last_;  // Newton: the increment last taken (swapped with dq_, dl_)
  Eigen::VectorXd q_star_, v_star_, a_const_, a_hat_;  // Newton: predictor parts
  std::vector<State> backup_;                          // one saved state per sub-stepping level
  // the waves in inputs_, sampled once per (sub)step at t_{n+1} at the predicted positions (and
  // kept for the later vehicle-coupling passes over the same step); calm water: never sampled
  bool waves_ = false;
  double wave_time_ = -1.0;  // t of the waves in inputs_ (< 0: none yet)
  Attempt last_failure_;
  Eigen::VectorXd wave_q_;  // positions the waves in inputs_ were sampled at
  long tangent_refreshes_ = 0;
};

}  // namespace towsim::core
