#pragma once
// Contact with the seabed (docs/environment.md): a penalty normal force with damping and a
// smoothed Coulomb friction, as MoorDyn's seabed model has it (MoorDyn 2, Line.cpp: kbot, cbot,
// with the contact width the cable's diameter), with its Jacobian for the Newton system.
//
// The scene's environment.seabed {stiffness, damping, friction} (SeabedContact) mean:
//   stiffness k [Pa/m = N/m^3]: normal pressure per metre of penetration, on a contact area of
//                               width w (the cable's diameter) per unit length;
//   damping   c [Pa s/m]:       normal pressure per m/s of penetration rate, on the same area;
//   friction  mu [-]:           Coulomb coefficient, axial (along the cable's tangent projected
//                               on the bed); 0 is frictionless;
//   friction_lateral mu_l [-]:  across it (default: mu). A point without a tangent (a body's
//                               contact point) takes mu in every direction.
// At a point r with velocity v, the bed at depth d(x, y) with unit normal n into the water:
//   penetration  delta = (z - d(x, y)) |n_z|        (> 0: in contact; exact for a plane)
//   normal       f_n   = w (k e(delta) - c s(delta) v.n) n   per unit unstretched length,
//                e = delta - d0/2, s = 1 beyond the onset depth d0 = kContactOnset, and
//                e = delta^2 / (2 d0), s = delta / d0 within it
//   friction     f_t   = -|f_n| [mu_a tanh(v_a / v_s) t_a + mu_l tanh(|v_l| / v_s) v_l / |v_l|]
// with v_t = (I - n n^T) v the sliding velocity, t_a the unit tangent projected on the bed,
// v_a = v_t . t_a, v_l = v_t - v_a t_a, and v_s = kFrictionSlipSpeed the speed below which the
// friction grows linearly instead of jumping (the smoothing keeps Newton's matrix finite; a
// body resting on the bed creeps at most at about v_s times the ratio of the pull to the
// friction limit). Like MoorDyn the normal force is not clipped at zero while in contact (the
// damping may pull while the point leaves the bed at speed). The onset makes the force and
// its derivative continuous as a point touches down (a penalty switched on at delta = 0 with
// its full stiffness and damping makes Newton's matrix jump, and the iterations chatter
// between in and out of contact); it shifts the resting penetration by at most d0 / 2.

#include <Eigen/Core>

namespace towsim::core {

class EnvironmentField;  // environment_field.h

// penetration over which the contact force ramps in [m]
constexpr double kContactOnset = 1e-3;
// speed over which the friction grows from 0 to its Coulomb limit (tanh, 76 % at v_s) [m/s]
constexpr double kFrictionSlipSpeed = 0.01;

struct ContactLoad {
  bool active = false;                              // in contact
  Eigen::Vector3d f = Eigen::Vector3d::Zero();      // force (per unit length, or a force)
  Eigen::Matrix3d df_dr = Eigen::Matrix3d::Zero();  // d f / d r
  Eigen::Matrix3d df_dv = Eigen::Matrix3d::Zero();  // d f / d v
  Eigen::Matrix3d df_da = Eigen::Matrix3d::Zero();  // d f / d a (anisotropic friction)
  double normal = 0.0;                              // |f_n|
};

// the contact load at r (velocity v, cable tangent a: only its direction is used; zero: the
// friction is isotropic) for a contact width w [m] (a point of contact area A: pass w = A, the
// load is then a force); the Jacobians when asked
ContactLoad SeabedContactLoad(const EnvironmentField& sea, double width, const Eigen::Vector3d& r,
                              const Eigen::Vector3d& v, const Eigen::Vector3d& a, bool jacobians);

}  // namespace towsim::core
