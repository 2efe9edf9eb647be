#include "core/cable_loads.h"

namespace towsim::core {

using Vec3 = Eigen::Vector3d;

Vec12 UniformLoad(const Vec3& f, double l) {
  Vec12 q;
  q << 0.5 * l * f, (l * l / 12.0) * f, 0.5 * l * f, (-l * l / 12.0) * f;
  return q;
}

Vec12 ElementLoadResidual(const AncfElement& element, const CableLoadContext& ctx, const Vec12& e,
                          const Vec12& e_dot, const Vec12& e_ddot, double scale,
                          ElementLoadJacobians* jac) {
  const double l = element.props().length;
  Vec12 r = -scale * UniformLoad(ctx.weight_per_length, l);
  if (jac) {
    jac->added_mass.setZero();
    jac->d_de.setZero();
    jac->d_dedot.setZero();
  }
  const bool added = ctx.added_mass_per_length > 0.0;
  if (!ctx.drag && !added) return r;

  if (!jac) {
    // the residual alone (Newton iterations with a kept matrix): R -= int S^T f dx
    for (const ShapeAtPoint& p : element.points()) {
      const Vec3 a = Interpolate(p.dn, e);
      Vec3 f = Vec3::Zero();
      if (ctx.drag) {
        const Vec3 v_rel = Interpolate(p.n, e_dot) - ctx.current;
        f = scale * CableDrag(ctx.fluid, ctx.diameter, a, v_rel, false).f;
      }
      if (added) {
        // f_am = -m_a (I - t t^T) r_ddot  (Eq. 22-23)
        const Vec3 acc = Interpolate(p.n, e_ddot);
        const Vec3 t = a.normalized();
        f -= ctx.added_mass_per_length * (acc - t.dot(acc) * t);
      }
      f *= p.weight_dx;
      for (int k = 0; k < 4; ++k) r.segment<3>(3 * k) -= p.n[k] * f;
    }
    return r;
  }

  // the residual and its Jacobians
  for (const ShapeAtPoint& p : element.points()) {
    const Vec3 a = Interpolate(p.dn, e);
    Vec3 f = Vec3::Zero();     // load per unit length, enters R with a minus sign
    Mat3 f_a = Mat3::Zero();   // df/da
    Mat3 f_v = Mat3::Zero();   // df/dr_dot
    Mat3 m_pt = Mat3::Zero();  // added mass per length at this point
    if (ctx.drag) {
      const Vec3 v_rel = Interpolate(p.n, e_dot) - ctx.current;
      const DragResult d = CableDrag(ctx.fluid, ctx.diameter, a, v_rel, true);
      f += scale * d.f;
      f_a += scale * d.df_da;
      f_v += scale * d.df_dv;
    }
    if (added) {
      // f_am = -m_a (I - t t^T) r_ddot  (Eq. 22-23)
      const Vec3 acc = Interpolate(p.n, e_ddot);
      m_pt = ctx.added_mass_per_length * NormalProjector(a);
      f -= m_pt * acc;
      f_a += AddedMassTangentDerivative(ctx.added_mass_per_length, a, acc);
    }
    const double w = p.weight_dx;
    for (int k = 0; k < 4; ++k) {
      r.segment<3>(3 * k) -= (w * p.n[k]) * f;
      for (int j = 0; j < 4; ++j) {
        // R = -int S^T f dx: dR/de = -int S_k f_a S'_j, dR/de_dot = -int S_k f_v S_j
        jac->d_de.block<3, 3>(3 * k, 3 * j) -= (w * p.n[k] * p.dn[j]) * f_a;
        jac->d_dedot.block<3, 3>(3 * k, 3 * j) -= (w * p.n[k] * p.n[j]) * f_v;
        if (added) jac->added_mass.block<3, 3>(3 * k, 3 * j) += (w * p.n[k] * p.n[j]) * m_pt;
      }
    }
  }
  return r;
}

}  // namespace towsim::core
