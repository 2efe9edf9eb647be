#include "core/vehicle_scaling.h"

#include <cmath>

namespace towsim::core {

VehicleParams ScaleVehicle(const VehicleParams& model, double lambda) {
  // lambda^n for the exponents of the header's table, (*): lambda^(3a + b + c/2)
  const auto f = [lambda](double n) { return std::pow(lambda, n); };
  VehicleParams p = model;

  // rigid body: lengths x lambda, mass and volume x lambda^3, inertia x lambda^5
  p.length *= f(1);
  p.diameter *= f(1);
  p.mass *= f(3);
  p.inertia *= f(5);
  p.r_g *= f(1);
  p.r_b *= f(1);
  p.volume *= f(3);

  // semi-submersible waterplane: area x lambda^2, point and depth x lambda, second moments x
  // lambda^4
  p.waterplane_area *= f(2);
  p.waterplane_point_B *= f(1);
  p.design_depth *= f(1);
  p.waterplane_inertia_long *= f(4);
  p.waterplane_inertia_trans *= f(4);

  // M_A' = D M_A D, D = diag(lambda^1.5 I3, lambda^2.5 I3): entry (i, j) x lambda^(e_i + e_j)
  // with e = 1.5 for a translation and 2.5 for a rotation (3, 4 or 5: integer exponents, so
  // each factor is one pow, not a product of two)
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      const double e = (i < 3 ? 1.5 : 2.5) + (j < 3 ? 1.5 : 2.5);
      p.added_mass(i, j) *= f(e);
    }
  }

  // quadratic damping: force per velocity^2 [kg/m] x lambda^2
  for (double* c : {&p.x_uu, &p.y_vv, &p.z_ww, &p.y_uv, &p.z_uw}) *c *= f(2);
  // force per velocity x rate [kg/rad], moment per velocity^2 [kg] x lambda^3
  for (double* c : {&p.y_ur, &p.z_uq, &p.m_ww, &p.n_vv, &p.m_uw, &p.n_uv}) *c *= f(3);
  // force per rate^2 [kg m/rad^2], moment per velocity x rate [kg m/rad] x lambda^4
  for (double* c : {&p.y_rr, &p.z_qq, &p.m_uq, &p.n_ur}) *c *= f(4);
  // moment per rate^2 [kg m^2/rad^2] x lambda^5
  for (double* c : {&p.m_qq, &p.n_rr, &p.k_pp}) *c *= f(5);
  // linear roll damping, moment per rate [N m s = kg m^2/s] x lambda^4.5
  p.k_p *= f(4.5);

  // lifting surfaces: centre of pressure x lambda, area x lambda^2; the coefficients
  // (aspect ratio, lift slope, e, cd0, angles) are dimensionless
  for (LiftingSurface& s : p.surfaces) {
    s.position_B *= f(1);
    s.area *= f(2);
  }

  // actuators: angles unchanged, rates [rad/s] x lambda^-0.5; thrust [N] x lambda^3, its lag
  // [s] x lambda^0.5
  p.rudder.max_rate *= f(-0.5);
  p.elevator.max_rate *= f(-0.5);
  p.max_thrust *= f(3);
  p.thrust_time_constant *= f(0.5);
  return p;
}

}  // namespace towsim::core
