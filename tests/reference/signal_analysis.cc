#include "signal_analysis.h"

#include <cmath>
#include <cstddef>
#include <utility>

namespace towsim::reference {

std::vector<double> ZeroCrossings(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> out;
  for (std::size_t i = 0; i + 1 < t.size() && i + 1 < y.size(); ++i) {
    const double y0 = y[i];
    const double y1 = y[i + 1];
    if (y0 == 0.0) {
      // count an exact zero once, where the signal actually changes side
      if (i > 0 && y[i - 1] * y1 < 0.0) out.push_back(t[i]);
      continue;
    }
    if (y0 * y1 < 0.0) out.push_back(t[i] - y0 * (t[i + 1] - t[i]) / (y1 - y0));
  }
  return out;
}

double FrequencyFromCrossings(const std::vector<double>& crossings) {
  if (crossings.size() < 2) return 0.0;
  const double span = crossings.back() - crossings.front();
  return static_cast<double>(crossings.size() - 1) / (2.0 * span);
}

double FitConvergenceOrder(const std::vector<double>& h, const std::vector<double>& error) {
  // slope = cov(x, y) / var(x) with x = log h, y = log e
  const std::size_t n = h.size();
  double mx = 0.0;
  double my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += std::log(h[i]);
    my += std::log(error[i]);
  }
  mx /= n;
  my /= n;
  double sxy = 0.0;
  double sxx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = std::log(h[i]) - mx;
    sxy += dx * (std::log(error[i]) - my);
    sxx += dx * dx;
  }
  return sxy / sxx;
}

void Fft(std::vector<std::complex<double>>* x) {
  constexpr double kPi = 3.14159265358979323846;
  std::vector<std::complex<double>>& a = *x;
  const std::size_t n = a.size();
  // bit-reversal permutation
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  // butterflies of length 2, 4, ..., n with w = exp(-2 pi i / len)
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const std::complex<double> w_len = std::polar(1.0, -2.0 * kPi / static_cast<double>(len));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> w = 1.0;
      for (std::size_t k = 0; k < len / 2; ++k) {
        const std::complex<double> u = a[i + k], v = a[i + k + len / 2] * w;
        a[i + k] = u + v;
        a[i + k + len / 2] = u - v;
        w *= w_len;
      }
    }
  }
}

Spectrum WelchSpectrum(const std::vector<double>& record, double dt, int segment) {
  constexpr double kPi = 3.14159265358979323846;
  const std::size_t m = static_cast<std::size_t>(segment);
  // Hann window and its power sum U = sum w_n^2
  std::vector<double> window(m);
  double u = 0.0;
  for (std::size_t n = 0; n < m; ++n) {
    window[n] = 0.5 * (1.0 - std::cos(2.0 * kPi * static_cast<double>(n) / m));
    u += window[n] * window[n];
  }
  double mean = 0.0;
  for (double v : record) mean += v;
  mean /= static_cast<double>(record.size());
  Spectrum out;
  out.omega.resize(m / 2 + 1);
  out.density.assign(m / 2 + 1, 0.0);
  for (std::size_t k = 0; k <= m / 2; ++k) out.omega[k] = 2.0 * kPi * k / (m * dt);
  std::vector<std::complex<double>> x(m);
  for (std::size_t start = 0; start + m <= record.size(); start += m / 2) {
    for (std::size_t n = 0; n < m; ++n) x[n] = window[n] * (record[start + n] - mean);
    Fft(&x);
    // one-sided: S(w_k) = 2 |X_k|^2 dt / (2 pi U), the ends k = 0, m/2 not doubled
    for (std::size_t k = 0; k <= m / 2; ++k) {
      const double factor = (k == 0 || k == m / 2) ? 1.0 : 2.0;
      out.density[k] += factor * std::norm(x[k]) * dt / (2.0 * kPi * u);
    }
    ++out.segments;
  }
  for (double& s : out.density) s /= out.segments;
  return out;
}

std::vector<double> Autocorrelation(const std::vector<double>& record, int max_lag) {
  std::size_t n = 1;
  while (n < 2 * record.size()) n <<= 1;
  double mean = 0.0;
  for (double v : record) mean += v;
  mean /= static_cast<double>(record.size());
  std::vector<std::complex<double>> x(n, 0.0);
  for (std::size_t i = 0; i < record.size(); ++i) x[i] = record[i] - mean;
  Fft(&x);
  // Wiener-Khinchin: r = IFFT(|X|^2); the inverse by conj(FFT(conj(.))) / n
  for (auto& c : x) c = std::conj(c * std::conj(c));
  Fft(&x);
  std::vector<double> rho(static_cast<std::size_t>(max_lag) + 1);
  for (std::size_t k = 0; k < rho.size(); ++k) rho[k] = x[k].real() / x[0].real();
  return rho;
}

}  // namespace towsim::reference
