#include "common/laws.h"

#include <algorithm>
#include <cmath>

namespace towsim::controllers {

double WrapPi(double angle) {
  double a = std::fmod(angle, 2.0 * kPi);
  if (a <= -kPi) a += 2.0 * kPi;
  if (a > kPi) a -= 2.0 * kPi;
  return a;
}

Euler EulerFromQuaternion(double qx, double qy, double qz, double qw) {
  Euler e;
  e.roll = std::atan2(2.0 * (qw * qx + qy * qz), 1.0 - 2.0 * (qx * qx + qy * qy));
  const double s = std::clamp(2.0 * (qw * qy - qz * qx), -1.0, 1.0);
  e.pitch = std::asin(s);
  e.yaw = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
  return e;
}

Vec3 BodyToWorld(double x, double y, double z, double w, const Vec3& v) {
  // rotation matrix of the unit quaternion (body -> world)
  const double r00 = 1 - 2 * (y * y + z * z), r01 = 2 * (x * y - w * z), r02 = 2 * (x * z + w * y);
  const double r10 = 2 * (x * y + w * z), r11 = 1 - 2 * (x * x + z * z), r12 = 2 * (y * z - w * x);
  const double r20 = 2 * (x * z - w * y), r21 = 2 * (y * z + w * x), r22 = 1 - 2 * (x * x + y * y);
  return {r00 * v.x + r01 * v.y + r02 * v.z, r10 * v.x + r11 * v.y + r12 * v.z,
          r20 * v.x + r21 * v.y + r22 * v.z};
}

double PidStep(const PidParams& p, PidState& s, double error, double measurement_rate, double dt) {
  if (!s.initialized) {
    s.initialized = true;
    s.output = 0.0;
  }
  const double unsat_before = p.kp * error + p.ki * s.integral - p.kd * measurement_rate;
  const bool high = unsat_before > p.out_max && error > 0.0;
  const bool low = unsat_before < p.out_min && error < 0.0;
  const bool outside_zone = p.integral_zone > 0.0 && std::abs(error) >= p.integral_zone;
  if (!high && !low && !outside_zone) s.integral += error * dt;  // conditional integration
  if (p.ki > 0.0) {
    s.integral = std::clamp(s.integral, p.out_min / p.ki, p.out_max / p.ki);
  }
  double u = p.kp * error + p.ki * s.integral - p.kd * measurement_rate;
  u = std::clamp(u, p.out_min, p.out_max);
  if (p.rate_limit > 0.0) {
    const double step = p.rate_limit * dt;
    u = std::clamp(u, s.output - step, s.output + step);
  }
  s.output = u;
  return u;
}

}  // namespace towsim::controllers
