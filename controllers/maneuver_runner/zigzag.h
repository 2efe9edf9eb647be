#pragma once
// The zig-zag (Z) manoeuvre of the IMO / ITTC manoeuvring trials (ITTC 7.5-04-02-01 §2.3;
// IMO MSC.137(76)) as a pure state machine on the live heading (no DDS), and its trials
// sheet. A "delta/psi" zig-zag, e.g. 10/10 or 20/20:
//   - thrust T all along; at t >= start the rudder goes to +delta (starboard first, or -delta);
//   - when the heading change from the heading at execute, psi - psi_0, reaches +psi the
//     rudder reverses to -delta; when it reaches -psi it reverses to +delta, and so on;
//   - after `reversals` reversals, the next time the switch angle is reached the rudder goes
//     to 0 and the manoeuvre is complete (so every reversal's overshoot is fully measured).
// The heading change is unwrapped step by step (change += WrapPi(yaw - last_yaw)), so the
// heading crossing +-180 deg does not upset it (valid while the heading changes by less than
// 180 deg between two answered steps).
// Trials sheet: the overshoot angle of reversal k is how far the heading change runs past the
// switch angle after the rudder has reversed, max over [t_k, t_k+1) of d_k (psi - psi_0) - psi,
// with d_k the turn direction before reversal k; the time of that extreme (time to check yaw);
// the period, the time of one full cycle, t_{k+2} - t_k (the ITTC "period" between every
// other reversal); the initial turning time, t_1 - t_execute.

#include <vector>

#include "maneuver_runner/uturn.h"

namespace towsim::controllers {

struct ZigZagParams {
  double thrust = 4165.0;                     // [N]
  double rudder = 0.17453292519943295;        // delta [rad], > 0
  double switch_angle = 0.17453292519943295;  // psi [rad], > 0
  double start = 55.0;                        // execute time [s]
  int reversals = 4;                          // rudder reversals before the end, >= 1
  bool port_first = false;                    // first rudder -delta (bow to port)
};

struct ZigZagOvershoot {
  double t_reversal = 0.0;  // time of the reversal [s]
  double overshoot = 0.0;   // angle past the switch angle [rad], >= 0 once measured
  double t_peak = 0.0;      // time of the extreme heading change [s]
};

struct ZigZagState {
  bool started = false, finished = false;
  double t_execute = 0.0, t_finished = 0.0;
  double psi0 = 0.0;                       // heading at execute [rad]
  double last_yaw = 0.0;                   // [rad]
  double change = 0.0;                     // unwrapped heading change since execute [rad]
  int direction = 1;                       // current rudder sign: +1 starboard (heading increasing)
  std::vector<ZigZagOvershoot> reversals;  // one per reversal, in order
};

// the command answering the state at time t [s] with heading yaw [rad] (in (-pi, pi])
ManeuverCommand ZigZagStep(const ZigZagParams& p, ZigZagState& state, double t, double yaw);

// the trials sheet of a (possibly unfinished) zig-zag
struct ZigZagResults {
  double t_execute = 0.0;
  double initial_turning_time = -1.0;      // t_1 - t_execute [s]; < 0: no reversal yet
  std::vector<double> overshoots;          // [rad], reversals whose overshoot is complete
  std::vector<double> times_to_check_yaw;  // t_peak_k - t_reversal_k [s]
  std::vector<double> periods;             // t_{k+2} - t_k [s]
  bool finished = false;
};
ZigZagResults ZigZagSheet(const ZigZagState& state);

}  // namespace towsim::controllers
