#pragma once
// A vehicle of another size from a model: every coefficient of VehicleParams scaled by geometric
// similarity at equal water density and gravity (Froude similarity; Newman 1977, "Marine
// Hydrodynamics", ch. 2 on dimensional analysis and model testing; the ITTC's Froude scaling
// of model tests). The rules, their sources and the one term that is not similar:
// docs/vehicles.md §9 "Scaled vehicles".
//
// Let lambda = L_full / L_model. With rho and g the same, the base units scale as
//   length  l -> lambda l,
//   mass    m -> lambda^3 m        (rho l^3),
//   time    t -> lambda^(1/2) t    (sqrt(l / g): the Froude number U / sqrt(g L) is kept),
// so a quantity of SI unit kg^a m^b s^c (angles are dimensionless) scales by
//   lambda^(3a + b + c/2).                                                         (*)
// Per field of VehicleParams (unit -> exponent):
//   length, diameter, r_g, r_b, surfaces[i].position_B,
//   waterplane_point_B, design_depth                               m            -> 1
//   surfaces[i].area, waterplane_area                              m^2          -> 2
//   volume                                                         m^3          -> 3
//   waterplane_inertia_long, waterplane_inertia_trans              m^4          -> 4
//   mass                                                           kg           -> 3
//   inertia (about the CG)                                         kg m^2       -> 5
//   added_mass(i, j), i, j in 0..5: translational block            kg           -> 3
//                      translation-rotation blocks                 kg m         -> 4
//                      rotational block                            kg m^2       -> 5
//     i.e. M_A' = D M_A D with D = diag(lambda^1.5 I3, lambda^2.5 I3), a congruence: M_A' is
//     symmetric positive semi-definite when M_A is (and likewise M_RB' = D M_RB D).
//   quadratic damping, force per velocity^2: x_uu, y_vv, z_ww, y_uv, z_uw   kg/m  -> 2
//                      force per (velocity x rate): y_ur, z_uq               kg    -> 3
//                      force per rate^2: y_rr, z_qq                          kg m  -> 4
//                      moment per velocity^2: m_ww, n_vv, m_uw, n_uv         kg    -> 3
//                      moment per (velocity x rate): m_uq, n_ur              kg m  -> 4
//                      moment per rate^2: m_qq, n_rr, k_pp                   kg m^2 -> 5
//   linear damping, moment per rate: k_p                            kg m^2 / s  -> 4.5
//     (a linear force damping, kg / s, would scale by lambda^2.5: none in VehicleParams)
//   propeller max_thrust                                            kg m / s^2  -> 3
//   thrust_time_constant                                            s           -> 1/2
//   rudder, elevator max_rate                                       rad / s     -> -1/2
//   unchanged (dimensionless): munk_moment, has_propeller, surfaces' normal, aspect ratio,
//     lift slope, Oswald factor, cd0, stall angle, incidence, deflection sign, channel, name;
//     max_deflection (an angle); source (the text of the model file).
// Every force term of the model then scales by lambda^3 and every moment by lambda^4 when the
// state scales as p_W -> lambda p_W, nu = [v; omega] -> [lambda^(1/2) v; lambda^(-1/2) omega]:
// e.g. x_uu u|u| -> lambda^2 lambda = lambda^3, m_qq q|q| -> lambda^5 lambda^-1 = lambda^4,
// 1/2 rho S CL U^2 -> lambda^2 lambda, C_RB(nu) nu -> lambda^3 lambda^(1/2) lambda^(-1/2). So
// nu_dot scales as [lambda^0; lambda^-1] and the scaled vehicle moves as the model does in the
// scaled time. Exceptions: the fin servo's lag (actuator.h, kFinServoTimeConstant) is a fixed
// 0.05 s, not part of VehicleParams (the fins' transients are not similar; their steady angles
// are), and the environment (current, waves, seabed) belongs to the scene, not to the vehicle.

#include "core/vehicle_model.h"

namespace towsim::core {

// The vehicle lambda times the size of `model` (lambda > 0, finite): every field by the rule
// above. lambda = 1 returns every field bit-equal to the model's (each factor is exactly 1).
// A new field of VehicleParams needs its rule here.
VehicleParams ScaleVehicle(const VehicleParams& model, double lambda);

}  // namespace towsim::core
