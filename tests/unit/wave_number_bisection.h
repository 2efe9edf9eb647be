#pragma once
// Test helper: the wave number of linear waves over water of depth h, by bisection on the
// dispersion relation w^2 = g k tanh(k h) (an algorithm independent of core::WaveNumber's Newton
// iteration), for closed-form references of the sea.

#include <cmath>

namespace towsim::test {

// k [1/m] with w^2 = g k tanh(k h), w > 0, h > 0, g > 0: bisection on [w^2 / g,
// w / sqrt(g h) + w^2 / g] (the deep- and the shallow-water k bracket it), to the double's
// resolution
inline double BisectWaveNumber(double omega, double depth, double gravity) {
  double lo = omega * omega / gravity, hi = omega / std::sqrt(gravity * depth) + lo;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (gravity * mid * std::tanh(mid * depth) < omega * omega ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace towsim::test
