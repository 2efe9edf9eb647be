#pragma once
// Small signal-analysis helpers for the reference tests: the period of an oscillation from
// its zero crossings, the order of convergence from errors at several step sizes, and
// spectral estimates of sampled records (FFT, Welch's averaged periodogram, autocorrelation).

#include <complex>
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

// in-place radix-2 FFT, X_k = sum_n x_n exp(-2 pi i k n / N); N a power of 2
void Fft(std::vector<std::complex<double>>* x);

// One-sided spectral density estimate of a record sampled every dt [s], by Welch's method:
// segments of `segment` samples (a power of 2) overlapping by half, each with a Hann window,
// their periodograms averaged. Returns S at w_k = 2 pi k / (segment dt), k = 0..segment/2, in
// [unit^2 s / rad] (so that sum S dw ~ the record's variance).
struct Spectrum {
  std::vector<double> omega;    // [rad/s]
  std::vector<double> density;  // [unit^2 s / rad]
  int segments = 0;             // number averaged
};
Spectrum WelchSpectrum(const std::vector<double>& record, double dt, int segment);

// Normalised autocorrelation rho(k dt) = sum_n x_n x_{n+k} / sum_n x_n^2 of the mean-free record
// for lags k = 0 .. max_lag (by FFT of the zero-padded record).
std::vector<double> Autocorrelation(const std::vector<double>& record, int max_lag);

}  // namespace towsim::reference
