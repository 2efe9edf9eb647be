#include "maneuver_runner/payout.h"

#include <algorithm>
#include <cmath>

#include "common/laws.h"

namespace towsim::controllers {
namespace {
constexpr double kTimeTolerance = 1e-9;  // [s], the script's rule
}  // namespace

const char* PayoutPhaseName(PayoutPhase phase) {
  switch (phase) {
    case PayoutPhase::kApproach:
      return "approach";
    case PayoutPhase::kPayout:
      return "payout";
    case PayoutPhase::kHold:
      return "hold";
    case PayoutPhase::kReelIn:
      return "reel_in";
    case PayoutPhase::kDone:
      return "done";
  }
  return "?";
}

PayoutTimes PayoutSchedule(const PayoutParams& p) {
  const double run = std::abs(p.to_length - p.from_length) / p.rate;
  PayoutTimes t;
  t.payout = p.start;
  t.hold = p.start + run;
  t.reel_in = t.hold + p.hold;
  t.done = t.reel_in + run;
  return t;
}

PayoutPhase PayoutPhaseAt(const PayoutParams& p, double t) {
  const PayoutTimes s = PayoutSchedule(p);
  if (t < s.payout - kTimeTolerance) return PayoutPhase::kApproach;
  if (t < s.hold - kTimeTolerance) return PayoutPhase::kPayout;
  if (t < s.reel_in - kTimeTolerance) return PayoutPhase::kHold;
  if (t < s.done - kTimeTolerance) return PayoutPhase::kReelIn;
  return PayoutPhase::kDone;
}

PayoutCommand PayoutStep(const PayoutParams& p, PayoutState& state, double t, double u,
                         double dt) {
  PayoutCommand c;
  // the towing speed: PI on the surge, thrust in [0, max_thrust]
  PidParams pid;
  pid.kp = p.speed_kp;
  pid.ki = p.speed_ki;
  pid.out_min = 0.0;
  pid.out_max = p.max_thrust;
  c.vehicle.thrust = PidStep(pid, state.speed, p.tow_speed - u, 0.0, dt);
  const double direction = p.to_length >= p.from_length ? 1.0 : -1.0;
  switch (PayoutPhaseAt(p, t)) {
    case PayoutPhase::kApproach:
      c.winch_value = 0.0;
      break;
    case PayoutPhase::kPayout:
      c.winch_value = direction * p.rate;
      break;
    case PayoutPhase::kHold:
      c.winch_length_mode = true;
      c.winch_value = p.to_length;
      break;
    case PayoutPhase::kReelIn:
      c.winch_value = -direction * p.rate;
      break;
    case PayoutPhase::kDone:
      c.winch_length_mode = true;
      c.winch_value = p.from_length;
      break;
  }
  return c;
}

PayoutSheet::PayoutSheet(const PayoutParams& p, double sample_period)
    : p_(p), period_(sample_period) {}

void PayoutSheet::Add(const PayoutSample& s) {
  if (!started_ || s.t >= next_ - kTimeTolerance) {
    r_.samples.push_back(s);
    next_ = (started_ ? next_ : s.t) + period_;
    started_ = true;
  }
  // the phase ends: the latest sample of each phase so far
  switch (PayoutPhaseAt(p_, s.t)) {
    case PayoutPhase::kApproach:
      r_.approach = {true, s};
      break;
    case PayoutPhase::kPayout:
      r_.payout = {true, s};
      break;
    case PayoutPhase::kHold:
      r_.hold = {true, s};
      break;
    case PayoutPhase::kReelIn:
      r_.reel_in = {true, s};
      break;
    case PayoutPhase::kDone:
      break;
  }
  r_.final = {true, s};
  r_.max_length = std::max(r_.max_length, s.length);
  r_.max_depth = std::max(r_.max_depth, s.depth);
}

}  // namespace towsim::controllers
