#pragma once
// The value lists of a sweep parameter that are not written out (docs/sweeps.md): ranges, evenly
// spaced points and seeded random draws. Pure functions, reproducible on every platform: the
// draws use std::mt19937_64, whose output sequence the C++ standard fixes, and transforms of
// our own (the standard's distributions are implementation-defined).

#include <cstdint>
#include <string>
#include <vector>

namespace towsim::app {

// from, from + step, ... up to `to` inclusive (an end within 1e-9 |step| of `to` counts);
// step != 0 and pointing from `from` towards `to` (the caller checks)
std::vector<double> RangeValues(double from, double to, double step);

// `count` >= 2 points evenly spaced from `from` to `to`, both included (count 1: from)
std::vector<double> LinspaceValues(double from, double to, int count);

// uniform on [low, high): low + (high - low) u, u = (x >> 11) 2^-53 for each 64-bit output x
std::vector<double> UniformDraws(double low, double high, int count, std::uint64_t seed);

// normal(mean, stddev) by Box-Muller from pairs of the uniforms above (u1 in (0, 1])
std::vector<double> NormalDraws(double mean, double stddev, int count, std::uint64_t seed);

// integers uniform on [low, high] (both included), by rejection: no modulo bias
std::vector<long long> IntegerDraws(long long low, long long high, int count, std::uint64_t seed);

// a number as a sweep value (and --set value): "%.9g", the CSV precision
std::string FormatSweepNumber(double x);

}  // namespace towsim::app
