#pragma once
// The generalized-alpha method (Chung & Hulbert 1993, in the Arnold & Bruls 2007 form with
// pseudo-accelerations a^ that the core uses) applied to the undamped linear oscillator
// x'' + omega^2 x = 0: what the scheme itself does to the energy E = (v^2 + omega^2 x^2) / 2.
//
//   x_{n+1} = x_n + h v_n + h^2 (1/2 - beta) a^_n + h^2 beta a^_{n+1}
//   v_{n+1} = v_n + h (1 - gamma) a^_n + h gamma a^_{n+1}
//   (1 - alpha_m) a^_{n+1} + alpha_m a^_n = (1 - alpha_f) a_{n+1} + alpha_f a_n
//   a_{n+1} = -omega^2 x_{n+1}
// alpha_m = (2 rho - 1) / (rho + 1), alpha_f = rho / (rho + 1), gamma = 1/2 + alpha_f - alpha_m,
// beta = (gamma + 1/2)^2 / 4; rho_inf = 1 is the trapezoidal rule.
//
// The point: for rho_inf < 1 the scheme dissipates over time, but the physical energy is NOT
// monotone from step to step: it rises in some steps by a relative amount that grows like
// (omega h)^3 (about 1.4e-5 at omega h = 0.1 for rho_inf = 0.6).

namespace towsim::reference {

struct OscillatorEnergy {
  double max_step_rise = 0.0;  // max_n (E_{n+1} - E_n) / E_0
  double final_ratio = 0.0;    // E_N / E_0
};

// starts at x = 1, v = 0 with a_0 = a^_0 = -omega^2, runs `steps` steps of size omega_h / omega
OscillatorEnergy GeneralizedAlphaOscillator(double rho_inf, double omega_h, int steps);

// spectral radius of the one-step amplification matrix on (x, v, a^)
double GeneralizedAlphaSpectralRadius(double rho_inf, double omega_h);

}  // namespace towsim::reference
