#include "app/sweep/sweep_values.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace towsim::app {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;  // 2^-53

// u in [0, 1) with 53 random bits
double Unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * kTwoToMinus53; }

}  // namespace

std::vector<double> RangeValues(double from, double to, double step) {
  std::vector<double> values;
  // n = floor((to - from) / step) with a tolerance, then from + i step (no accumulated sum)
  const double span = (to - from) / step;
  const long n = static_cast<long>(std::floor(span + 1e-9));
  for (long i = 0; i <= n; ++i) values.push_back(from + static_cast<double>(i) * step);
  return values;
}

std::vector<double> LinspaceValues(double from, double to, int count) {
  std::vector<double> values;
  if (count == 1) return {from};
  for (int i = 0; i < count; ++i) {
    // the last point exactly `to`
    values.push_back(i + 1 == count ? to : from + (to - from) * i / (count - 1));
  }
  return values;
}

std::vector<double> UniformDraws(double low, double high, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> values;
  for (int i = 0; i < count; ++i) values.push_back(low + (high - low) * Unit(rng));
  return values;
}

std::vector<double> NormalDraws(double mean, double stddev, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> values;
  while (static_cast<int>(values.size()) < count) {
    // Box-Muller: z0 = sqrt(-2 ln u1) cos(2 pi u2), z1 = ... sin(2 pi u2)
    const double u1 = 1.0 - Unit(rng);  // (0, 1]: ln u1 finite
    const double u2 = Unit(rng);
    const double radius = std::sqrt(-2.0 * std::log(u1));
    values.push_back(mean + stddev * radius * std::cos(kTwoPi * u2));
    if (static_cast<int>(values.size()) < count) {
      values.push_back(mean + stddev * radius * std::sin(kTwoPi * u2));
    }
  }
  return values;
}

std::vector<long long> IntegerDraws(long long low, long long high, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::uint64_t span = static_cast<std::uint64_t>(high - low) + 1;  // 0: all 2^64
  // accept x < limit, the largest multiple of span that fits, then x mod span is uniform
  const std::uint64_t limit = span == 0 ? 0 : UINT64_MAX - (UINT64_MAX % span + 1) % span;
  std::vector<long long> values;
  while (static_cast<int>(values.size()) < count) {
    const std::uint64_t x = rng();
    if (span == 0) {
      values.push_back(static_cast<long long>(x));
    } else if (x <= limit) {
      values.push_back(low + static_cast<long long>(x % span));
    }
  }
  return values;
}

std::string FormatSweepNumber(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.9g", x);
  return buffer;
}

}  // namespace towsim::app
