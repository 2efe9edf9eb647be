#include "generalized_alpha_oscillator.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace towsim::reference {

namespace {

// one step on the state (x, v, a^) of x'' = -x (omega = 1, h = omega h), a_n = -x_n
struct Step {
  double am, af, gamma, beta, h;
  Step(double rho_inf, double omega_h)
      : am((2.0 * rho_inf - 1.0) / (rho_inf + 1.0)),
        af(rho_inf / (rho_inf + 1.0)),
        gamma(0.5 + af - am),
        beta(0.25 * (gamma + 0.5) * (gamma + 0.5)),
        h(omega_h) {}
  void operator()(double* x, double* v, double* a_hat) const {
    const double a = -*x;
    // x_{n+1} = c0 + k ((1 - af) a_{n+1} + af a_n - am a^_n), a_{n+1} = -x_{n+1}
    const double c0 = *x + h * *v + h * h * (0.5 - beta) * *a_hat;
    const double k = h * h * beta / (1.0 - am);
    const double x1 = (c0 + k * (af * a - am * *a_hat)) / (1.0 + k * (1.0 - af));
    const double a_hat1 = ((1.0 - af) * -x1 + af * a - am * *a_hat) / (1.0 - am);
    *v += h * ((1.0 - gamma) * *a_hat + gamma * a_hat1);
    *x = x1;
    *a_hat = a_hat1;
  }
};

}  // namespace

OscillatorEnergy GeneralizedAlphaOscillator(double rho_inf, double omega_h, int steps) {
  const Step step(rho_inf, omega_h);
  double x = 1.0, v = 0.0, a_hat = -1.0;
  auto energy = [&] { return 0.5 * (v * v + x * x); };
  const double e0 = energy();
  double e_prev = e0;
  OscillatorEnergy out;
  for (int n = 0; n < steps; ++n) {
    step(&x, &v, &a_hat);
    const double e = energy();
    out.max_step_rise = std::max(out.max_step_rise, (e - e_prev) / e0);
    e_prev = e;
  }
  out.final_ratio = e_prev / e0;
  return out;
}

double GeneralizedAlphaSpectralRadius(double rho_inf, double omega_h) {
  // the step is linear in (x, v, a^): its matrix column by column
  const Step step(rho_inf, omega_h);
  Eigen::Matrix3d amp;
  for (int j = 0; j < 3; ++j) {
    double y[3] = {0.0, 0.0, 0.0};
    y[j] = 1.0;
    step(&y[0], &y[1], &y[2]);
    amp.col(j) << y[0], y[1], y[2];
  }
  return amp.eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace towsim::reference
