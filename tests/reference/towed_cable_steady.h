#pragma once
// Steady state of a cable towed at constant velocity with a sphere hanging at its lower end,
// computed independently of the core by integrating the static cable equations along the
// cable, from the sphere up to the tow point.
//
// In the frame moving with the tow point everything is at rest and the water streams past;
// the cable moves relative to the water with V = U_tow - U_current. Unstretched arc length s
// runs from the sphere (s = 0) to the tow point (s = L); t_hat is the unit tangent towards
// the tow point and F(s) = T t_hat the force the upper part of the cable exerts across s.
// Equilibrium of the piece below s, with f the external load per unit unstretched length:
//
//   dF/ds = -f,   f = w e_z + lambda(T) [F_n(V_n) + F_t(V_t)]   (cable_drag.h, per stretched
//                                                                length, times the stretch;
//                                                                Choo & Casarella's laws or
//                                                                constant coefficients)
//   dr/ds = lambda(T) t_hat,  t_hat = F / |F|
//   F(0) = -(sphere net weight + sphere drag + sphere_extra_force)   (the sphere is in
//          equilibrium; no shooting)
//
// with w = (rho_c - rho_w) A g and the stretch lambda(T) from the chosen constitutive law.
// Integrated with classical RK4; world NED (z down).
//
// A depth-varying current U(z) (current_profile) makes the loads depend on where the cable is:
// V(s) = U_tow - U(z_sphere + r_z(s)), and the sphere's drag on U(z_sphere). The tow point's
// depth then fixes the unknown z_sphere: shooting, z_sphere + r_z(L; z_sphere) = tow_depth,
// solved by the secant method to 1e-12 L (a uniform current needs none: U is the same
// everywhere and the shape does not depend on z_sphere).

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "cable_drag.h"

namespace towsim::reference {

enum class StretchLaw {
  kHooke,             // lambda = 1 + T / EA (engineering strain)
  kGreenTrueTension,  // T = EA eps lambda, eps = (lambda^2 - 1) / 2 (the core's law)
};

struct TowedCableProblem {
  // cable
  double length = 200.0;        // unstretched L [m]
  double diameter = 0.041;      // d [m]
  double density = 1300.0;      // rho_c [kg/m^3]
  double youngs_modulus = 7e8;  // E [Pa]
  // constant drag coefficients instead of Choo & Casarella's laws (cable_drag.h)
  std::optional<ConstantDragCoefficients> drag_coefficients;
  // sphere at the lower end
  double sphere_mass = 416.0;  // m [kg]
  double sphere_volume = 0.2;  // V [m^3]
  double sphere_cd = 0.5;      // C_D on pi r^2, r = (3V / 4pi)^(1/3)
  // environment and motion
  Fluid fluid;
  double gravity = 9.81;                              // g [m/s^2], along +z
  Eigen::Vector3d current = Eigen::Vector3d::Zero();  // U_current [m/s]
  // a current that varies with the NED depth z; when set it replaces `current`, and the tow
  // point is at depth tow_depth
  std::function<Eigen::Vector3d(double z)> current_profile;
  double tow_depth = 0.0;  // z of the tow point (NED) [m], with current_profile
  Eigen::Vector3d tow_velocity{6.0, 0.0, 0.0};  // U_tow [m/s]
  // a further force on the sphere (world NED) [N]: in a chain of cables (a two-part tow) the
  // force the cable below the sphere exerts on it, that cable's top_force
  Eigen::Vector3d sphere_extra_force = Eigen::Vector3d::Zero();
  // switches (for self-checks)
  bool cable_drag = true;
  bool cable_weight = true;
  StretchLaw stretch_law = StretchLaw::kGreenTrueTension;
};

struct TowedCablePoint {
  double s = 0.0;                               // unstretched arc length from the sphere
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  // position relative to the sphere [m]
  double tension = 0.0;                         // T [N]
};

struct TowedCableSolution {
  Eigen::Vector3d top_minus_sphere = Eigen::Vector3d::Zero();  // r(L) - r(0) [m]
  double layback = 0.0;         // x_top - x_sphere [m] (> 0: the sphere trails behind)
  double depth = 0.0;           // z_sphere - z_top [m] (> 0: the sphere below the tow point)
  double top_tension = 0.0;     // T(L), magnitude of the force on the tow point [N]
  double bottom_tension = 0.0;  // T(0) [N]
  Eigen::Vector3d top_force = Eigen::Vector3d::Zero();  // force of the cable on the tow point
  std::vector<TowedCablePoint> shape;                   // samples, s from 0 to L
  double sphere_z = 0.0;  // z of the sphere (NED): tow_depth + depth [m], with current_profile
  int shooting_iterations = 0;  // secant iterations on z_sphere (0 for a uniform current)
};

// the sphere's net external force (weight - buoyancy + drag) at relative velocity V [N]
Eigen::Vector3d SphereExternalForce(const TowedCableProblem& p);
// the same in a current U at the sphere
Eigen::Vector3d SphereExternalForce(const TowedCableProblem& p, const Eigen::Vector3d& current);

// the stretch lambda = ds_stretched / ds for tension T under the problem's law
double CableStretch(const TowedCableProblem& p, double tension);

// integrate with `steps` RK4 steps; `samples` + 1 shape points are stored
TowedCableSolution SolveTowedCableSteady(const TowedCableProblem& p, int steps = 20000,
                                         int samples = 20);

}  // namespace towsim::reference
