#pragma once
// The realtime pacing factor (sim_node --rate, SimControl SET_RATE; docs/contract.md §4): one rule for
// the command line and the wire. Header only and free of DDS, so the offline sim_node, which
// links no DDS (docs/benchmarks.md, "Start-up"), checks --rate by the same rule.

#include <cmath>
#include <string>

namespace towsim::dds {

// kMinRate <= rate <= kMaxRate. Below, a step period is more than 1000 steps of simulated time
// (and the wall-clock deadlines overflow); above, the period is below the clock's resolution
// (--mode fast runs unpaced).
inline constexpr double kMinRate = 1e-3;
inline constexpr double kMaxRate = 1e6;

// the rule broken by `rate`, or empty
inline std::string CheckRate(double rate) {
  if (std::isfinite(rate) && rate >= kMinRate && rate <= kMaxRate) return {};
  return "the rate must be a number >= 1e-3 and <= 1e6 (--mode fast runs unpaced)";
}

}  // namespace towsim::dds
