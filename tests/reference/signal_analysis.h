#pragma once
// Small signal-analysis helpers for the reference tests: the period of an oscillation from
// its zero crossings, and the order of convergence from errors at several step sizes.

#include <vector>

namespace towsim::reference {

// times of the sign changes of y(t) (samples (t[i], y[i]), t increasing), located by linear
// interpolation between the samples; a sample exactly 0 counts once
std::vector<double> ZeroCrossings(const std::vector<double>& t, const std::vector<double>& y);

// frequency [Hz] from crossing times: crossings are half a period apart, so
// f = (n - 1) / (2 (t_last - t_first)); needs at least 2 crossings (returns 0 otherwise)
double FrequencyFromCrossings(const std::vector<double>& crossings);

// least-squares slope p of log(error) = log(C) + p log(h)
double FitConvergenceOrder(const std::vector<double>& h, const std::vector<double>& error);

}  // namespace towsim::reference
