#pragma once
// Lift and drag of one LiftingSurface (a fin or a half-wing, vehicle_model.h) on the local
// relative flow at its centre of pressure: finite-wing theory as in
// docs/vehicle_coefficients.md §5 (Prestero 2001 local-angle fin model;
// Helmbold lift slope; induced drag CL^2 / (pi e AR)).
//
// Geometry: n = normal_B (unit), chord c = x_B projected on the plane normal to n (the fins and
// wings of both vehicles are aligned with the hull axis). The surface moves through the water with
// v = v_O + omega x r - v_current (in B); its in-plane components are
//   u_c = v . c,  u_n = v . n,  U_p = sqrt(u_c^2 + u_n^2)  (spanwise flow ignored),
// the flow angle is alpha_f = atan2(-u_n, u_c) (a surface moving along -n sees the water arrive
// from -n and lifts along +n) and the effective angle of attack is
//   alpha = alpha_f + incidence + deflection_sign * delta.
// Coefficients (alpha_s = stall_angle, a = lift slope, Helmbold when lift_slope == 0):
//   CL = a alpha                                     |alpha| <= alpha_s
//      = a alpha_s sign(alpha) (2 - |alpha|/alpha_s)  alpha_s < |alpha| < 2 alpha_s
//      = 0                                           beyond
//   CD = cd0 + CL^2 / (pi e AR) + ramp(|alpha|) kFlatPlateNormal sin^2(alpha),
// ramp = 0 below stall, rising linearly to 1 at 2 alpha_s (the flat-plate drag that takes over).
// Force (lift normal to the flow in the (c, n) plane, drag along the flow):
//   e_L = (u_c n - u_n c) / U_p,  e_D = -(u_c c + u_n n) / U_p,
//   F = 1/2 rho S U_p^2 (CL e_L + CD e_D),  moment about O: r x F.

#include "core/vehicle_model.h"

namespace towsim::core {

// Normal-force coefficient of a flat plate of aspect ratio 2-5 broadside to the flow
// (Hoerner, Fluid-Dynamic Drag, 1965, ch. 3: 1.2 for AR ~ 2-5, 1.98 for AR -> infinity).
inline constexpr double kFlatPlateNormal = 1.2;

// Helmbold lift slope of a finite wing, 2 pi AR / (2 + sqrt(AR^2 + 4)) [1/rad] (§3.2)
double HelmboldLiftSlope(double aspect_ratio);

// the lift slope a surface uses: lift_slope, or Helmbold's when lift_slope == 0 [1/rad]
double EffectiveLiftSlope(const LiftingSurface& s);

// CL(alpha) and CD(alpha) as above; alpha [rad] in (-pi, pi]
double LiftCoefficient(const LiftingSurface& s, double alpha);
double DragCoefficient(const LiftingSurface& s, double alpha);

struct SurfaceLoad {
  Vec3 force_B = Vec3::Zero();   // [N], in B
  Vec3 moment_B = Vec3::Zero();  // about the body origin O [N m], in B
  double alpha = 0.0;            // effective angle of attack [rad]
  double speed = 0.0;            // in-plane speed U_p [m/s]
  double cl = 0.0, cd = 0.0;
};

// Load on surface s moving through the water with velocity v_rel_B (its point's velocity minus
// the current, in B) [m/s], its channel at deflection delta [rad], in water of density rho.
SurfaceLoad SurfaceForce(const LiftingSurface& s, double rho, const Vec3& v_rel_B, double delta);

}  // namespace towsim::core
