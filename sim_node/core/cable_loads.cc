#include "core/cable_loads.h"

#include "core/seabed_contact.h"

namespace towsim::core {

using Vec3 = Eigen::Vector3d;

Vec12 UniformLoad(const Vec3& f, double l) {
  Vec12 q;
  q << 0.5 * l * f, (l * l / 12.0) * f, 0.5 * l * f, (-l * l / 12.0) * f;
  return q;
}

namespace {

// the water at Gauss point p, at r_p and t: the current there and the waves interpolated from
// the nodes (local_flow: the water varies in space or time; otherwise the uniform current)
FlowSample FlowAt(const EnvironmentField& sea, bool local_flow, const ShapeAtPoint& p,
                  const Vec3& r_p, double t, const ElementWaves* waves, Vec3* shear) {
  FlowSample f;
  if (!local_flow) {
    f.velocity = sea.uniform_current();
    return f;
  }
  if (sea.steady_uniform_current())
    f.velocity = sea.uniform_current();  // waves only: no look-up per point
  else
    f = sea.Current(r_p, t, shear);
  if (waves) {
    f.velocity += Interpolate(p.n, waves->velocity);
    f.acceleration += Interpolate(p.n, waves->acceleration);
  }
  return f;
}

// kSea = false: still water or a steady uniform current, no seabed (the sea's code compiled
// out, so that a scene without it costs what it did before the sea existed)
template <bool kSea>
Vec12 ResidualOnly(const AncfElement& element, const CableLoadContext& ctx,
                   const EnvironmentField& sea, double t, const ElementWaves* waves,
                   const GaussFields& fields, double scale) {
  const double l = element.props().length;
  Vec12 r = -scale * UniformLoad(ctx.weight_per_length, l);
  const bool added = ctx.added_mass_per_length > 0.0;
  const bool local_flow = kSea && !sea.uniform();
  const bool fluid_inertia = local_flow && ctx.fluid_inertia_per_length > 0.0;
  const bool contact = kSea && sea.has_seabed();
  if (!ctx.drag && !added && !fluid_inertia && !contact) return r;
  // the load per unit length at each point, weighted: R -= int S^T f dx = F N^T (3 x 4)
  Mat35 f_w;
  FlowSample flow;  // the same at every point without local flow
  if (!local_flow) flow.velocity = sea.uniform_current();
  // (r is interpolated only where the current is looked up at it: LoadFields)
  const bool at_r = local_flow && !sea.steady_uniform_current();
  for (int g = 0; g < 5; ++g) {
    const ShapeAtPoint& p = element.points()[g];
    const Vec3 a = fields.r_x.col(g);
    if (local_flow)
      flow = FlowAt(sea, true, p, at_r ? Vec3(fields.r.col(g)) : Vec3(), t, waves, nullptr);
    Vec3 f = Vec3::Zero();
    if (ctx.drag) {
      const Vec3 v_rel = RelativeVelocity(fields.v.col(g), flow);
      f = scale * CableDrag(ctx.fluid, ctx.diameter, a, v_rel, false).f;
    }
    if (added || fluid_inertia) {
      // f_am = -m_a (I - t t^T) r_ddot (Eq. 22-23) + (rho_w A + m_a) (I - t t^T) a_fluid
      Vec3 acc = Vec3::Zero();
      if (added) acc = ctx.added_mass_per_length * fields.acc.col(g);
      if (fluid_inertia) acc -= ctx.fluid_inertia_per_length * flow.acceleration;
      const Vec3 tn = a.normalized();
      f -= acc - tn.dot(acc) * tn;
    }
    if (contact) {
      // the seabed (seabed_contact.h): contact width = the cable's diameter
      const ContactLoad cl =
          SeabedContactLoad(sea, ctx.diameter, fields.r.col(g), fields.v.col(g), a, false);
      if (cl.active) f += cl.f;
    }
    f_w.col(g) = p.weight_dx * f;
  }
  Eigen::Map<Eigen::Matrix<double, 3, 4>>(r.data()).noalias() -=
      f_w * element.shape_n().transpose();
  return r;
}

template <bool kSea>
Vec12 Residual(const AncfElement& element, const CableLoadContext& ctx, const EnvironmentField& sea,
               double t, const ElementWaves* waves, const Vec12& e, const Vec12& e_dot,
               const Vec12& e_ddot, double scale, ElementLoadJacobians* jac) {
  const double l = element.props().length;
  Vec12 r = -scale * UniformLoad(ctx.weight_per_length, l);
  jac->added_mass.setZero();
  jac->d_de.setZero();
  jac->d_dedot.setZero();
  const bool added = ctx.added_mass_per_length > 0.0;
  // water that moves differently from point to point or in time: sampled per Gauss point
  const bool local_flow = kSea && !sea.uniform();
  const bool fluid_inertia = local_flow && ctx.fluid_inertia_per_length > 0.0;
  const bool contact = kSea && sea.has_seabed();
  if (!ctx.drag && !added && !fluid_inertia && !contact) return r;

  // the residual and its Jacobians
  for (const ShapeAtPoint& p : element.points()) {
    const Vec3 a = Interpolate(p.dn, e);
    Vec3 shear = Vec3::Zero();
    const FlowSample flow =
        FlowAt(sea, local_flow, p, local_flow ? Interpolate(p.n, e) : Vec3(), t, waves, &shear);
    Vec3 f = Vec3::Zero();     // load per unit length, enters R with a minus sign
    Mat3 f_a = Mat3::Zero();   // df/da
    Mat3 f_v = Mat3::Zero();   // df/dr_dot
    Mat3 m_pt = Mat3::Zero();  // added mass per length at this point
    bool f_r = false;          // df/dr = -f_v dU/dz e_z^T (a sheared current)
    if (ctx.drag) {
      const Vec3 v_rel = RelativeVelocity(Interpolate(p.n, e_dot), flow);
      const DragResult d = CableDrag(ctx.fluid, ctx.diameter, a, v_rel, true);
      f += scale * d.f;
      f_a += scale * d.df_da;
      f_v += scale * d.df_dv;
      if constexpr (kSea) f_r = local_flow && !shear.isZero();
    }
    if (added) {
      // f_am = -m_a (I - t t^T) r_ddot  (Eq. 22-23)
      const Vec3 acc = Interpolate(p.n, e_ddot);
      m_pt = ctx.added_mass_per_length * NormalProjector(a);
      f -= m_pt * acc;
      f_a += AddedMassTangentDerivative(ctx.added_mass_per_length, a, acc);
    }
    if (fluid_inertia) {
      // f_fl = (rho_w A + m_a) (I - t t^T) a_fluid: the negative of the added-mass form
      const double c = ctx.fluid_inertia_per_length;
      f += c * (NormalProjector(a) * flow.acceleration);
      f_a -= AddedMassTangentDerivative(c, a, flow.acceleration);
    }
    Mat3 f_pos = Mat3::Zero();  // df/dr where f_r
    if constexpr (kSea) {
      if (f_r) f_pos = -f_v * shear * Vec3::UnitZ().transpose();
      if (fluid_inertia && !shear.isZero()) {
        // the current's material acceleration U_z dU/dz varies with z: d/dz = (dU_z/dz) dU/dz
        // (a piecewise-linear profile has no U'')
        const Mat3 d = ctx.fluid_inertia_per_length * NormalProjector(a) * (shear.z() * shear) *
                       Vec3::UnitZ().transpose();
        f_pos = f_r ? Mat3(f_pos + d) : d;
        f_r = true;
      }
      if (contact) {
        // the seabed (seabed_contact.h): contact width = the cable's diameter; df/dr, df/dr_dot
        const ContactLoad cl = SeabedContactLoad(sea, ctx.diameter, Interpolate(p.n, e),
                                                 Interpolate(p.n, e_dot), a, true);
        if (cl.active) {
          f += cl.f;
          f_pos = f_r ? Mat3(f_pos + cl.df_dr) : cl.df_dr;
          f_v += cl.df_dv;
          f_a += cl.df_da;
          f_r = true;
        }
      }
    }
    const double w = p.weight_dx;
    // R = -int S^T f dx: dR/de = -int S_k (f_a S'_j + f_pos S_j) dx = -int S_k D_j dx,
    // dR/de_dot = -int S_k f_v S_j dx = -int S_k V_j dx, M_a = int S_k m S_j dx = int S_k A_j dx
    Mat3 d_j[4], v_j[4], a_j[4];
    for (int j = 0; j < 4; ++j) {
      d_j[j] = (w * p.dn[j]) * f_a;
      if (kSea && f_r) d_j[j] += (w * p.n[j]) * f_pos;
      v_j[j] = (w * p.n[j]) * f_v;
      if (added) a_j[j] = (w * p.n[j]) * m_pt;
    }
    for (int k = 0; k < 4; ++k) {
      r.segment<3>(3 * k) -= (w * p.n[k]) * f;
      for (int j = 0; j < 4; ++j) jac->d_de.block<3, 3>(3 * k, 3 * j) -= p.n[k] * d_j[j];
      // (the blocks of dR/de_dot and M_a have the weights S_k S_j: k <= j here, mirrored below)
      for (int j = k; j < 4; ++j) {
        jac->d_dedot.block<3, 3>(3 * k, 3 * j) -= p.n[k] * v_j[j];
        if (added) jac->added_mass.block<3, 3>(3 * k, 3 * j) += p.n[k] * a_j[j];
      }
    }
  }
  for (int k = 1; k < 4; ++k)
    for (int j = 0; j < k; ++j) {
      jac->d_dedot.block<3, 3>(3 * k, 3 * j) = jac->d_dedot.block<3, 3>(3 * j, 3 * k);
      if (added)
        jac->added_mass.block<3, 3>(3 * k, 3 * j) = jac->added_mass.block<3, 3>(3 * j, 3 * k);
    }
  return r;
}

}  // namespace

Vec12 ElementLoadResidual(const AncfElement& element, const CableLoadContext& ctx,
                          const EnvironmentField& sea, double t, const ElementWaves* waves,
                          const Vec12& e, const Vec12& e_dot, const Vec12& e_ddot, double scale,
                          ElementLoadJacobians* jac) {
  if (!jac) {
    GaussFields fields;
    element.InterpolateFields(e, e_dot, e_ddot, LoadFields(ctx, sea), &fields);
    return ElementLoadResidual(element, ctx, sea, t, waves, fields, scale);
  }
  if (sea.uniform() && !sea.has_seabed())
    return Residual<false>(element, ctx, sea, t, waves, e, e_dot, e_ddot, scale, jac);
  return Residual<true>(element, ctx, sea, t, waves, e, e_dot, e_ddot, scale, jac);
}

unsigned LoadFields(const CableLoadContext& ctx, const EnvironmentField& sea) {
  unsigned f = 0;
  if (ctx.drag) f |= kFieldVelocity;
  if (ctx.added_mass_per_length > 0.0) f |= kFieldAcceleration;
  if (!sea.uniform() && !sea.steady_uniform_current()) f |= kFieldPosition;  // the current at r
  if (sea.has_seabed()) f |= kFieldPosition | kFieldVelocity;
  return f;
}

Vec12 ElementLoadResidual(const AncfElement& element, const CableLoadContext& ctx,
                          const EnvironmentField& sea, double t, const ElementWaves* waves,
                          const GaussFields& fields, double scale) {
  if (sea.uniform() && !sea.has_seabed())
    return ResidualOnly<false>(element, ctx, sea, t, waves, fields, scale);
  return ResidualOnly<true>(element, ctx, sea, t, waves, fields, scale);
}

}  // namespace towsim::core
