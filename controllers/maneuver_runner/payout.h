#pragma once
// The payout manoeuvre (docs/controllers.md "maneuver_runner"): a winch trial as a pure state
// machine on the simulation time (no DDS). The tow vehicle holds a towing speed with its
// thrust (PI on the surge u); the winch at the cable's start:
//   - before `start`: speed 0 (the scene's initial length, from_length, e.g. 150 m);
//   - payout:  speed +rate for (to_length - from_length) / rate seconds, then the length
//              to_length (the drum's acceleration ramp leaves it rate^2 / (2 a) short: the
//              length command drives it the rest of the way and stops there);
//   - hold:    length to_length for `hold` seconds;
//   - reel-in: speed -rate for the same time, then the length from_length for the rest of the
//              run.
// Every decision is on time alone, so that the winch's commands in lockstep are a function of
// the step (bit-deterministic runs); the sheet's lengths come from the cable state.

#include <vector>

#include "common/laws.h"
#include "maneuver_runner/uturn.h"

namespace towsim::controllers {

struct PayoutParams {
  double tow_speed = 3.0;       // surge held by the thrust [m/s]
  double max_thrust = 4165.0;   // the thrust's upper limit [N] (lower: 0)
  double speed_kp = 2000.0;     // [N / (m/s)]
  double speed_ki = 200.0;      // [N / m]
  double start = 100.0;         // payout begins [s]
  double from_length = 150.0;   // [m]
  double to_length = 250.0;     // [m]
  double rate = 1.0;            // |drum speed| of payout and reel-in [m/s], > 0
  double hold = 100.0;          // [s] at to_length
};

enum class PayoutPhase { kApproach, kPayout, kHold, kReelIn, kDone };
const char* PayoutPhaseName(PayoutPhase phase);

// the phase at time t [s] (the times of the schedule above)
PayoutPhase PayoutPhaseAt(const PayoutParams& p, double t);
// the times the phases begin: payout, hold, reel-in, done [s]
struct PayoutTimes {
  double payout = 0.0, hold = 0.0, reel_in = 0.0, done = 0.0;
};
PayoutTimes PayoutSchedule(const PayoutParams& p);

struct PayoutState {
  PidState speed;  // the thrust's PI
};

// what the manoeuvre commands at time t [s], surge u [m/s], step dt [s]: the tow vehicle's
// thrust, and the winch (winch_length: the length mode with that target; else the speed mode
// with winch_speed)
struct PayoutCommand {
  ManeuverCommand vehicle;
  bool winch_length_mode = false;
  double winch_value = 0.0;  // [m] or [m/s]
};
PayoutCommand PayoutStep(const PayoutParams& p, PayoutState& state, double t, double u, double dt);

// the trials sheet: the towfish's depth against the paid-out length and time
struct PayoutSample {
  double t = 0.0;       // [s]
  double length = 0.0;  // paid-out length [m]
  double depth = 0.0;   // the towfish's depth z [m]
  double tow_depth = 0.0;  // the tow vehicle's depth z [m]
  double speed = 0.0;   // the tow vehicle's surge [m/s]
};
struct PayoutResults {
  std::vector<PayoutSample> samples;  // every `sample_period` from the start of the run
  // at the end of each phase (the last sample before the next one begins); valid = false if
  // the run ended before
  struct PhaseEnd {
    bool valid = false;
    PayoutSample at;
  };
  PhaseEnd approach, payout, hold, reel_in, final;  // final: the last sample of the run
  double max_length = 0.0;  // [m]
  double max_depth = 0.0;   // [m]
};

// collects the sheet sample by sample (each step whose cable length is known)
class PayoutSheet {
 public:
  PayoutSheet(const PayoutParams& p, double sample_period);
  void Add(const PayoutSample& s);
  const PayoutResults& results() const { return r_; }

 private:
  PayoutParams p_;
  double period_;
  double next_ = 0.0;
  bool started_ = false;
  PayoutResults r_;
};

}  // namespace towsim::controllers
