#pragma once
// Pure control-law building blocks shared by the controllers (no DDS, no clocks): attitude
// from the odometry quaternion, angle wrapping, and a PID with anti-windup and a rate limit.
// Unit-tested in tests/unit (controllers_tests.cmake).

namespace towsim::controllers {

constexpr double kPi = 3.14159265358979323846;
inline double Deg(double rad) { return rad * 180.0 / kPi; }
inline double Rad(double deg) { return deg * kPi / 180.0; }

// an angle wrapped into (-pi, pi] [rad]
double WrapPi(double angle);

// ZYX Euler angles [rad] of the unit quaternion (x, y, z, w) (body -> world NED); yaw and roll
// in (-pi, pi], pitch in [-pi/2, pi/2]
struct Euler {
  double roll = 0.0, pitch = 0.0, yaw = 0.0;
};
Euler EulerFromQuaternion(double qx, double qy, double qz, double qw);

// the world-frame (NED) velocity of a body whose body-frame velocity is (u, v, w) [m/s]
struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
};
Vec3 BodyToWorld(double qx, double qy, double qz, double qw, const Vec3& body);

// PID on an error with the derivative taken on the measurement (no kick on setpoint steps):
//   u = kp e + ki I - kd dmeasurement/dt, saturated to [out_min, out_max], rate-limited to
//   |du/dt| <= rate_limit (<= 0: none). Anti-windup: the integral only grows while the
//   unsaturated output is within the limits or the error drives it back inside (conditional
//   integration), and it is clamped so that ki I alone stays within the limits; optionally
//   only inside an integral zone |error| < integral_zone.
struct PidParams {
  double kp = 0.0, ki = 0.0, kd = 0.0;
  double out_min = -1.0, out_max = 1.0;
  double rate_limit = 0.0;  // [output units / s]
  // > 0: the integral only grows while |error| < integral_zone (a large setpoint step is
  // left to P and D; the integral trims the small steady error that remains)
  double integral_zone = 0.0;
};
struct PidState {
  double integral = 0.0;
  double output = 0.0;  // the last output (rate limit reference)
  bool initialized = false;
};
// one step of length dt > 0 [s]; `measurement_rate` is d(measurement)/dt; returns the output
// and updates `state`
double PidStep(const PidParams& p, PidState& state, double error, double measurement_rate,
               double dt);

}  // namespace towsim::controllers
