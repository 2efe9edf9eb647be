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

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/block_tridiagonal.h"
#include "core/simulation.h"
#include "core/state.h"
#include "core/system.h"

namespace towsim::core {

struct AlphaParameters {
  double alpha_m, alpha_f, gamma, beta;
  static AlphaParameters FromSettings(const IntegratorSettings& s);
};

class Integrator {
 public:
  explicit Integrator(const System& system);

  // advance *state by h (sub-stepping on Newton failure)
  StepStatus Step(State* state, double h);
  // consistent a and lambda at the current q, v: [M_eff Phi_q^T; Phi_q 0] [a; lambda] = [Q - F; 0]
  bool InitializeAcceleration(State* state);

 private:
  struct Attempt {
    bool ok = false;
    bool non_finite = false;
    int iterations = 0;
    double residual = 0.0;
    int worst_dof = 0;
  };
  Attempt Newton(State* state, double h);
  StepStatus Advance(State* state, double h, int level);

  const System& system_;
  AlphaParameters ap_;
  double q_scale_;
  BlockTridiagonal jac_;
  Eigen::VectorXd r_, phi_, rhs_, dq_, dl_;
  Eigen::VectorXd q_star_, v_star_, a_const_, a_hat_;  // Newton: predictor parts
  std::vector<State> backup_;  // one saved state per sub-stepping level
  Attempt last_failure_;
};

}  // namespace towsim::core
