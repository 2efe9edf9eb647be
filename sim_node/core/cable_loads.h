#pragma once
// Distributed external loads of one cable element, as generalized forces (paper Eq. 14):
// gravity and buoyancy (Eq. 15-16), drag (Eq. 17-21) and normal added mass (Eq. 22-23).
// They enter the residual as
//   R_load(e, e_dot, e_ddot) = M_a(e) e_ddot - Q_drag(e, e_dot) - Q_weight
// where M_a = int m_a S^T (I - t t^T) S dx depends on the tangent t; the implicit solve needs
// M_a and the Jacobians dR_load/de (at fixed e_ddot) and dR_load/de_dot.

#include <Eigen/Core>

#include "core/ancf_element.h"
#include "core/hydrodynamics.h"

namespace towsim::core {

struct CableLoadContext {
  FluidProperties fluid;
  double diameter = 0.0;               // d [m]
  double added_mass_per_length = 0.0;  // m_a = C_a rho_w A [kg/m] (0: off)
  bool drag = false;
  Eigen::Vector3d current = Eigen::Vector3d::Zero();            // U [m/s]
  Eigen::Vector3d weight_per_length = Eigen::Vector3d::Zero();  // (rho_c - rho_w) A g e_z [N/m]
};

struct ElementLoadJacobians {
  Mat12 added_mass;  // M_a (12 x 12)
  Mat12 d_de;        // dR_load/de
  Mat12 d_dedot;     // dR_load/de_dot
};

// Generalized load residual of one element; `scale` multiplies weight and drag (static load
// continuation). Jacobians are filled when jac != nullptr.
Vec12 ElementLoadResidual(const AncfElement& element, const CableLoadContext& ctx, const Vec12& e,
                          const Vec12& e_dot, const Vec12& e_ddot, double scale,
                          ElementLoadJacobians* jac);

// Consistent generalized force of a uniform load f per unit unstretched length:
//   Q_k = f int S_k dx = f l [1/2, l/12, 1/2, -l/12]_k
Vec12 UniformLoad(const Eigen::Vector3d& f, double l);

}  // namespace towsim::core
