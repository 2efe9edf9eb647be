#include "core/cable_loads.h"

#include "core/cable_drag.h"
#include "core/seabed_contact.h"

namespace towsim::core {

using Vec3 = Eigen::Vector3d;

Vec12 UniformLoad(const Vec3& f, double l) {
  Vec12 q;
  q << 0.5 * l * f, (l * l / 12.0) * f, 0.5 * l * f, (-l * l / 12.0) * f;
  return q;
}

namespace {

// the water at Gauss point g of a sea that varies in space or time, at r_p and t: the current
// there (and its shear dU/dz where asked) and the waves interpolated from the nodes
[[gnu::always_inline]] inline FlowSample FlowAt(const EnvironmentField& sea, int g, const Vec3& r_p,
                                                double t, const GaussWaves* waves, Vec3* shear) {
  FlowSample f;
  if (sea.steady_uniform_current())
    f.velocity = sea.uniform_current();  // waves only: no look-up per point
  else
    f = sea.Current(r_p, t, shear);
  if (waves) {
    f.velocity += waves->velocity.col(g);
    f.acceleration += waves->acceleration.col(g);
  }
  return f;
}

// The load law at the Gauss points, once for both uses: from the element's fields there
// (GaussFields, interpolated once per element for this and the internal force) the load per
// unit length f at each point, R = -int S^T f dx = -F N^T (3 x 4, F the weighted f).
// kWithJacobian: also M_a, dR/de and dR/de_dot into *jac; the residual is the same to the bit
// either way.
// kSea = false: still water or a steady uniform current, no seabed and no tangential added
// mass (the sea's and the line types' code compiled out, so that a scene without them costs
// what it did before they existed)
template <bool kSea, bool kWithJacobian>
Vec12 Residual(const AncfElement& element, const CableLoadContext& ctx, const EnvironmentField& sea,
               double t, const GaussWaves* waves, const GaussFields& fields, double scale,
               ElementLoadJacobians* jac, bool bed_in_reach) {
  const double l = element.props().length;
  Vec12 r = -scale * UniformLoad(ctx.weight_per_length, l);
  if constexpr (kWithJacobian) {
    jac->added_mass.setZero();
    jac->d_de.setZero();
    jac->d_dedot.setZero();
  }
  const bool added = ctx.added_mass_per_length > 0.0;
  const bool added_t = kSea && ctx.tangential_added_mass_per_length > 0.0;
  const bool any_added = added || added_t;  // M_a is assembled
  // water that moves differently from point to point or in time: sampled per Gauss point
  const bool local_flow = kSea && !sea.uniform();
  const bool fluid_inertia = local_flow && ctx.fluid_inertia_per_length > 0.0;
  const bool contact = kSea && bed_in_reach && sea.has_seabed();
  if (!ctx.drag && !added && !added_t && !fluid_inertia && !contact) return r;
  Mat35 f_w;        // the load per unit length at each point, weighted
  FlowSample flow;  // the same at every point without local flow
  if (!local_flow) flow.velocity = sea.uniform_current();
  // (r is interpolated only where the current is looked up at it: LoadFields)
  const bool at_r = local_flow && !sea.steady_uniform_current();
  for (int g = 0; g < 5; ++g) {
    const ShapeAtPoint& p = element.points()[g];
    const Vec3 a = fields.r_x.col(g);
    Vec3 shear = Vec3::Zero();  // dU/dz of a sheared current (with the Jacobians)
    if (local_flow)
      flow = FlowAt(sea, g, at_r ? Vec3(fields.r.col(g)) : Vec3(), t, waves,
                    kWithJacobian ? &shear : nullptr);
    Vec3 f = Vec3::Zero();  // load per unit length, enters R with a minus sign
    Mat3 f_a, f_v, m_pt;    // df/da, df/dr_dot, the added mass per length at this point
    bool f_r = false;       // df/dr = -f_v dU/dz e_z^T (a sheared current)
    if constexpr (kWithJacobian) {
      f_a.setZero();
      f_v.setZero();
      m_pt.setZero();
    }
    if (ctx.drag) {
      const Vec3 v_rel = RelativeVelocity(fields.v.col(g), flow);
      // the law's own instantiation (cable_drag.h)
      const DragResult d =
          ctx.drag_law.kind == CableDragLaw::kConstant
              ? CableDragOf<true>(ctx.fluid, ctx.drag_law, ctx.diameter, a, v_rel, kWithJacobian)
              : CableDragOf<false>(ctx.fluid, ctx.drag_law, ctx.diameter, a, v_rel, kWithJacobian);
      f = scale * d.f;
      if constexpr (kWithJacobian) {
        f_a += scale * d.df_da;
        f_v += scale * d.df_dv;
        if constexpr (kSea) f_r = local_flow && !shear.isZero();
      }
    }
    if (added || fluid_inertia) {
      // the normal inertia load: f_am = -m_a (I - t t^T) r_ddot (Eq. 22-23) and
      // f_fl = (rho_w A + m_a) (I - t t^T) a_fluid, together -(I - t t^T) acc with
      // acc = m_a r_ddot - (rho_w A + m_a) a_fluid
      Vec3 acc = Vec3::Zero();
      if (added) acc = ctx.added_mass_per_length * fields.acc.col(g);
      if (fluid_inertia) acc -= ctx.fluid_inertia_per_length * flow.acceleration;
      const Vec3 tn = a.normalized();
      f -= acc - tn.dot(acc) * tn;
      if constexpr (kWithJacobian) {
        // d/da at fixed acc (the projector turns with the tangent)
        f_a += AddedMassTangentDerivative(1.0, a, acc);
        if (added) m_pt = ctx.added_mass_per_length * NormalProjector(a);
      }
    }
    if (kSea && added_t) {
      // the tangential added mass: f_at = -t t^T acc_t, acc_t = m_at (r_ddot - a_fluid)
      Vec3 acc_t = fields.acc.col(g);
      if (local_flow) acc_t -= flow.acceleration;
      acc_t *= ctx.tangential_added_mass_per_length;
      const Vec3 tn = a.normalized();
      f -= tn.dot(acc_t) * tn;
      if constexpr (kWithJacobian) {
        f_a -= AddedMassTangentDerivative(1.0, a, acc_t);
        m_pt += ctx.tangential_added_mass_per_length * (tn * tn.transpose());
      }
    }
    Mat3 f_pos;  // df/dr where f_r
    if constexpr (kSea) {
      if constexpr (kWithJacobian) {
        if (f_r) f_pos = -f_v * shear * Vec3::UnitZ().transpose();
        if (fluid_inertia && !shear.isZero()) {
          // the current's material acceleration U_z dU/dz varies with z: d/dz = (dU_z/dz) dU/dz
          // (a piecewise-linear profile has no U'')
          const Mat3 d = ctx.fluid_inertia_per_length * NormalProjector(a) * (shear.z() * shear) *
                         Vec3::UnitZ().transpose();
          f_pos = f_r ? Mat3(f_pos + d) : d;
          f_r = true;
        }
      }
      // (a point above the bed has no contact: tested here before the load is built)
      if (contact && fields.r(2, g) > sea.SeabedDepth(fields.r(0, g), fields.r(1, g))) {
        // the seabed (seabed_contact.h): contact width = the cable's diameter; df/dr, df/dr_dot
        const ContactLoad cl = SeabedContactLoad(sea, ctx.diameter, fields.r.col(g),
                                                 fields.v.col(g), a, kWithJacobian);
        if (cl.active) {
          f += cl.f;
          if constexpr (kWithJacobian) {
            f_pos = f_r ? Mat3(f_pos + cl.df_dr) : cl.df_dr;
            f_v += cl.df_dv;
            f_a += cl.df_da;
            f_r = true;
          }
        }
      }
    }
    const double w = p.weight_dx;
    f_w.col(g) = w * f;
    if constexpr (kWithJacobian) {
      // R = -int S^T f dx: dR/de = -int S_k (f_a S'_j + f_pos S_j) dx = -int S_k D_j dx,
      // dR/de_dot = -int S_k f_v S_j dx = -int S_k V_j dx, M_a = int S_k m S_j dx = int S_k A_j dx
      Mat3 d_j[4], v_j[4], a_j[4];
      for (int j = 0; j < 4; ++j) {
        d_j[j] = (w * p.dn[j]) * f_a;
        if (kSea && f_r) d_j[j] += (w * p.n[j]) * f_pos;
        v_j[j] = (w * p.n[j]) * f_v;
        if (any_added) a_j[j] = (w * p.n[j]) * m_pt;
      }
      for (int k = 0; k < 4; ++k) {
        for (int j = 0; j < 4; ++j) jac->d_de.block<3, 3>(3 * k, 3 * j) -= p.n[k] * d_j[j];
        // (the blocks of dR/de_dot and M_a have the weights S_k S_j: k <= j here, mirrored
        // below)
        for (int j = k; j < 4; ++j) {
          jac->d_dedot.block<3, 3>(3 * k, 3 * j) -= p.n[k] * v_j[j];
          if (any_added) jac->added_mass.block<3, 3>(3 * k, 3 * j) += p.n[k] * a_j[j];
        }
      }
    }
  }
  Eigen::Map<Eigen::Matrix<double, 3, 4>>(r.data()).noalias() -=
      f_w * element.shape_n().transpose();
  if constexpr (kWithJacobian) {
    for (int k = 1; k < 4; ++k)
      for (int j = 0; j < k; ++j) {
        jac->d_dedot.block<3, 3>(3 * k, 3 * j) = jac->d_dedot.block<3, 3>(3 * j, 3 * k);
        if (any_added)
          jac->added_mass.block<3, 3>(3 * k, 3 * j) = jac->added_mass.block<3, 3>(3 * j, 3 * k);
      }
  }
  return r;
}

}  // namespace

ElementWaves NodeWaves(const WaveSample& start, const WaveSample& end) {
  // [w, dw/dx] at the two nodes, in the layout of e
  ElementWaves w;
  int k = 0;
  for (const WaveSample* s : {&start, &end}) {
    w.velocity.segment<3>(6 * k) = s->velocity;
    w.velocity.segment<3>(6 * k + 3) = s->d_velocity;
    w.acceleration.segment<3>(6 * k) = s->acceleration;
    w.acceleration.segment<3>(6 * k + 3) = s->d_acceleration;
    ++k;
  }
  return w;
}

GaussWaves WavesAtGaussPoints(const AncfElement& element, const ElementWaves& waves) {
  // W N: the element's shape table at its Gauss points, as for r (ancf_element.h)
  return {AtGaussPoints(waves.velocity, element.shape_n()),
          AtGaussPoints(waves.acceleration, element.shape_n())};
}

Vec12 ElementLoadResidual(const AncfElement& element, const CableLoadContext& ctx,
                          const EnvironmentField& sea, double t, const ElementWaves* waves,
                          const Vec12& e, const Vec12& e_dot, const Vec12& e_ddot, double scale,
                          ElementLoadJacobians* jac) {
  const bool bed_in_reach = !ClearOfSeabed(sea, e, element.props().length);
  GaussFields fields;
  element.InterpolateFields(e, e_dot, e_ddot, LoadFields(ctx, sea, bed_in_reach), &fields);
  GaussWaves at_points;
  if (waves) at_points = WavesAtGaussPoints(element, *waves);
  return ElementLoadResidual(element, ctx, sea, t, waves ? &at_points : nullptr, fields, scale, jac,
                             bed_in_reach);
}

unsigned LoadFields(const CableLoadContext& ctx, const EnvironmentField& sea, bool bed_in_reach) {
  unsigned f = 0;
  if (ctx.drag) f |= kFieldVelocity;
  if (ctx.added_mass_per_length > 0.0 || ctx.tangential_added_mass_per_length > 0.0)
    f |= kFieldAcceleration;
  if (!sea.uniform() && !sea.steady_uniform_current()) f |= kFieldPosition;  // the current at r
  if (sea.has_seabed() && bed_in_reach) f |= kFieldPosition | kFieldVelocity;
  return f;
}

Vec12 ElementLoadResidual(const AncfElement& element, const CableLoadContext& ctx,
                          const EnvironmentField& sea, double t, const GaussWaves* waves,
                          const GaussFields& fields, double scale, ElementLoadJacobians* jac,
                          bool bed_in_reach) {
  const bool sea_code =
      !sea.uniform() || sea.has_seabed() || ctx.tangential_added_mass_per_length > 0.0;
  if (jac)
    return sea_code
               ? Residual<true, true>(element, ctx, sea, t, waves, fields, scale, jac, bed_in_reach)
               : Residual<false, true>(element, ctx, sea, t, waves, fields, scale, jac,
                                       bed_in_reach);
  return sea_code ? Residual<true, false>(element, ctx, sea, t, waves, fields, scale, nullptr,
                                          bed_in_reach)
                  : Residual<false, false>(element, ctx, sea, t, waves, fields, scale, nullptr,
                                           bed_in_reach);
}

}  // namespace towsim::core
