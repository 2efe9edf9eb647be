#pragma once
// The towing vehicle's autopilot as a pure function (no DDS): three decoupled loops, each a
// PID with anti-windup (common/laws.h PidStep: conditional integration, integral clamped)
// and a rate limit on its command.
//   speed    thrust = T_ff(u_d) + PID(u_d - u), T_ff = k_ff u_d |u_d| (the calibrated drag of
//            the towed system: 4165 N at 6 m/s, scenes/case1_forward.yaml); the PID's limits
//            are the thrust limits shifted by T_ff, so the total stays within them; the total
//            is rate-limited to `thrust_rate` [N/s], and the integral is frozen while that
//            ramp holds the thrust back in the direction of the error (no windup from the start)
//   heading  rudder = PID(WrapPi(psi_d - psi)) with the derivative on the yaw rate r (no kick
//            on a setpoint step), saturated to +-max_rudder and rate-limited (the fin's rate);
//            the wrap makes 179 deg -> -179 deg a 2 deg turn, not 358
//   depth    elevator = sign * PID(z_d - z), derivative on the depth rate; optional. The tow
//            vehicle (config/vehicles/tow_vehicle.yaml) is a surface-piercing semi-submersible:
//            its waterplane gives 49 kN of restoring force per metre of sinkage, while both
//            elevators at 25 deg and 6 m/s lift ~9 kN, i.e. < 0.2 m of depth change; the
//            loop is therefore off by default and meant for a submerged vehicle.
// Positive rudder turns the bow to starboard (yaw increasing); positive elevator pushes the
// stern down, the bow up (a submerged vehicle rises): sign = -1 maps "deeper" to negative.

#include "common/laws.h"

namespace towsim::controllers {

struct AutopilotGains {
  // thrust [N] on the speed error [m/s]; limits = the propeller's [-max/4, max]
  PidParams speed{1500.0, 300.0, 0.0, -3000.0, 12000.0, 0.0};
  double thrust_ff = 4165.0 / 36.0;  // k_ff [N/(m/s)^2]
  double thrust_rate = 2000.0;       // [N/s], <= 0: none
  // rudder [rad] on the heading error [rad], D on r [rad/s]; 25 deg, 20 deg/s; the integral
  // only within 5 deg of the setpoint. Tuned on the tow vehicle of
  // config/scenes/case1_forward.yaml at 6 m/s: on a 30 deg heading step, PD alone does not
  // overshoot; ki = 0.05 integrating everywhere overshoots 2.6 deg and creeps back over 60 s
  // (the vehicle runs straight with its fins centred, so the integral only remembers the
  // step's own error); the zone keeps ki for slow disturbances (asymmetric tow, current)
  PidParams heading{1.0,
                    0.05,
                    2.0,
                    -0.4363323129985824,
                    0.4363323129985824,
                    0.3490658503988659,
                    0.08726646259971647};
  // elevator [rad] on the depth error [m], D on the depth rate [m/s]
  PidParams depth{0.15, 0.01, 0.5, -0.4363323129985824, 0.4363323129985824, 0.3490658503988659};
  double depth_sign = -1.0;  // -1: positive elevator makes the vehicle rise
  bool depth_enabled = false;
};

struct AutopilotSetpoint {
  double speed = 6.0;    // surge speed u_d [m/s]
  double heading = 0.0;  // psi_d [rad]
  double depth = 0.0;    // z_d [m], used if depth_enabled
};

struct AutopilotMeasurement {
  double u = 0.0;      // surge [m/s]
  double yaw = 0.0;    // [rad]
  double r = 0.0;      // yaw rate [rad/s]
  double z = 0.0;      // depth [m]
  double z_dot = 0.0;  // depth rate [m/s]
};

struct AutopilotState {
  PidState speed, heading, depth;
  double thrust = 0.0;  // the last thrust command (rate limit reference) [N]
  bool initialized = false;
};

struct AutopilotCommand {
  double thrust = 0.0, rudder = 0.0, elevator = 0.0;  // [N, rad, rad]
};

// one step of length dt > 0 [s]
AutopilotCommand AutopilotStep(const AutopilotGains& g, AutopilotState& state,
                               const AutopilotSetpoint& sp, const AutopilotMeasurement& m,
                               double dt);

// x moved towards `target` by at most rate * dt (rate <= 0: no limit)
double RateLimit(double x, double target, double rate, double dt);

}  // namespace towsim::controllers
