#pragma once
// The cable's drag (hydrodynamics.h, CableDrag) for a law chosen at compile time: kConstant
// false is Choo & Casarella's C_Dn(Re), Nu(Re) (paper Eq. 17-20), true the constant
// coefficients of a line type in the same form with mu = 1:
//   G = rho d C_n |V_n|,  Nu = 1/2 rho d C_t |V_t|,  Re G' = G,  Re Nu' = Nu,
// so that h = -1/2 mu G V_n - pi mu Nu V_t is
//   -1/2 rho C_n d |V_n| V_n - 1/2 rho C_t pi d |V_t| V_t.
// One body for both; each law is instantiated in its own file (hydrodynamics.cc,
// constant_drag.cc), so that the default law compiles to the code it had before line types
// (two instantiations in one file share Eigen's out-of-line helpers: 1.5 % more instructions
// per Jacobian evaluation, measured).

#include <cmath>

#include <Eigen/Core>

#include "core/constants.h"
#include "core/hydrodynamics.h"

namespace towsim::core {

template <bool kConstant>
DragResult CableDragOf(const FluidProperties& fluid, const CableDragLaw& law, double diameter,
                       const Eigen::Vector3d& a, const Eigen::Vector3d& v_rel, bool jacobians) {
  using Vec3 = Eigen::Vector3d;
  using Mat3 = Eigen::Matrix3d;
  DragResult out;
  const double stretch = a.norm();
  const Vec3 t = a / stretch;
  const double vt_s = t.dot(v_rel);
  const Vec3 vt = vt_s * t;
  const Vec3 vn = v_rel - vt;
  const double vn_norm = vn.norm();
  const double vt_norm = std::abs(vt_s);
  // G and Nu of the law; constant coefficients in the same form with mu = 1:
  // G = rho d C_n |V_n|, Nu = 1/2 rho d C_t |V_t|, and Re G' = G, Re Nu' = Nu
  const double mu = kConstant ? 1.0 : fluid.viscosity;
  DragLaw ln, lt;
  if constexpr (kConstant) {
    const double gn = fluid.density * diameter * law.normal * vn_norm;
    const double gt = 0.5 * fluid.density * diameter * law.tangential * vt_norm;
    ln = {gn, gn};
    lt = {gt, gt};
  } else {
    const double k = fluid.density * diameter / fluid.viscosity;  // Re per unit speed
    ln = NormalDragLaw(k * vn_norm);
    lt = TangentialDragLaw(k * vt_norm);
  }
  // per stretched length: h = h_n + h_t
  const Vec3 h = -0.5 * mu * ln.g * vn - kPi * mu * lt.g * vt;
  out.f = stretch * h;
  if (!jacobians) return out;

  const Mat3 I = Mat3::Identity();
  const Mat3 tt = t * t.transpose();
  // dh_n/dV_n = -1/2 mu (G I + Re G' nh nh^T), dh_t/dV_t = -pi mu (Nu I + Re Nu' th th^T)
  Mat3 dn = -0.5 * mu * ln.g * I;
  if (vn_norm > 0.0) {
    const Vec3 nh = vn / vn_norm;
    dn -= 0.5 * mu * ln.re_dg * nh * nh.transpose();
  }
  // V_t is parallel to t, so th th^T = t t^T
  const Mat3 dt = -kPi * mu * (lt.g * I + lt.re_dg * tt);
  // dh/dV = Dn (I - t t^T) + Dt t t^T
  out.df_dv = stretch * (dn * (I - tt) + dt * tt);
  // dV_t/dt = (t.V) I + t V^T, dV_n/dt = -dV_t/dt
  const Mat3 dvt_dt = vt_s * I + t * v_rel.transpose();
  const Mat3 dh_dt = (dt - dn) * dvt_dt;
  const Mat3 dt_da = (I - tt) / stretch;
  // f = |a| h: df/da = h t^T + |a| dh/dt dt/da
  out.df_da = h * t.transpose() + stretch * dh_dt * dt_da;
  return out;
}

extern template DragResult CableDragOf<false>(const FluidProperties&, const CableDragLaw&, double,
                                              const Eigen::Vector3d&, const Eigen::Vector3d&, bool);
extern template DragResult CableDragOf<true>(const FluidProperties&, const CableDragLaw&, double,
                                             const Eigen::Vector3d&, const Eigen::Vector3d&, bool);

}  // namespace towsim::core
