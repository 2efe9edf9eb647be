#include "core/lifting_surface.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace towsim::core {
namespace {
// below this in-plane speed the surface carries no load (avoids 0/0 in the flow angle) [m/s]
constexpr double kMinSpeed = 1.0e-9;
}  // namespace

double HelmboldLiftSlope(double aspect_ratio) {
  // a = 2 pi AR / (2 + sqrt(AR^2 + 4))  (Helmbold 1942; = Fossen's pi AR / (1 + sqrt(1 + AR^2/4)))
  return 2.0 * kPi * aspect_ratio / (2.0 + std::sqrt(aspect_ratio * aspect_ratio + 4.0));
}

double EffectiveLiftSlope(const LiftingSurface& s) {
  return s.lift_slope > 0.0 ? s.lift_slope : HelmboldLiftSlope(s.aspect_ratio);
}

double LiftCoefficient(const LiftingSurface& s, double alpha) {
  const double a = EffectiveLiftSlope(s);
  const double abs_alpha = std::abs(alpha);
  const double stall = s.stall_angle;
  // CL = a alpha below stall
  if (abs_alpha <= stall) return a * alpha;
  // falls back linearly to 0 at 2 alpha_s, then 0
  if (abs_alpha >= 2.0 * stall) return 0.0;
  return std::copysign(a * stall * (2.0 - abs_alpha / stall), alpha);
}

double DragCoefficient(const LiftingSurface& s, double alpha) {
  const double cl = LiftCoefficient(s, alpha);
  // CD = cd0 + CL^2 / (pi e AR)
  double cd = s.cd0 + cl * cl / (kPi * s.oswald * s.aspect_ratio);
  // + flat-plate drag ramped in between alpha_s and 2 alpha_s
  const double ramp = std::clamp((std::abs(alpha) - s.stall_angle) / s.stall_angle, 0.0, 1.0);
  if (ramp > 0.0) {  // (below stall the term is 0: no sine)
    const double sin_a = std::sin(alpha);
    cd += ramp * kFlatPlateNormal * sin_a * sin_a;
  }
  return cd;
}

SurfaceLoad SurfaceForce(const LiftingSurface& s, double rho, const Vec3& v_rel_B, double delta) {
  SurfaceLoad out;
  const Vec3 n = s.normal_B.normalized();
  // chord: x_B projected on the plane normal to n
  const Vec3 c = (Vec3::UnitX() - n.x() * n).normalized();
  const double u_c = v_rel_B.dot(c);
  const double u_n = v_rel_B.dot(n);
  const double speed = std::hypot(u_c, u_n);
  out.speed = speed;
  if (speed < kMinSpeed) return out;
  // alpha = atan2(-u_n, u_c) + incidence + sign * delta, wrapped to (-pi, pi]
  // (remainder(x, 2 pi) = x exactly for |x| <= pi: called only beyond)
  double alpha = std::atan2(-u_n, u_c) + s.incidence + s.deflection_sign * delta;
  if (std::abs(alpha) > kPi) alpha = std::remainder(alpha, 2.0 * kPi);
  out.alpha = alpha;
  out.cl = LiftCoefficient(s, alpha);
  out.cd = DragCoefficient(s, alpha);
  // F = 1/2 rho S U_p^2 (CL e_L + CD e_D), e_L = (u_c n - u_n c)/U_p, e_D = -(u_c c + u_n n)/U_p
  const double k = 0.5 * rho * s.area * speed;
  out.force_B = k * (out.cl * (u_c * n - u_n * c) - out.cd * (u_c * c + u_n * n));
  // moment about O: r x F
  out.moment_B = s.position_B.cross(out.force_B);
  return out;
}

}  // namespace towsim::core
