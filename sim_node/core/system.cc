#include "core/system.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include <Eigen/Geometry>

#include "core/seabed_contact.h"

namespace towsim::core {
namespace {

using Eigen::VectorXd;

ElementProperties MakeElementProperties(const CableParams& c) {
  ElementProperties p;
  p.length = c.length / c.elements;
  p.ea = c.axial_stiffness;
  p.ei = c.loads.bending ? c.bending_stiffness : 0.0;
  p.axial_damping = c.axial_damping;
  p.mass_per_length = c.mass_per_length;
  return p;
}

CableLoadContext MakeLoadContext(const Model& m, const CableParams& c) {
  const Environment& env = m.environment;
  CableLoadContext ctx;
  ctx.fluid = {env.water_density, env.dynamic_viscosity};
  ctx.diameter = c.diameter;
  ctx.drag = c.loads.drag;
  ctx.drag_law = c.drag;
  ctx.added_mass_per_length =
      c.loads.added_mass ? c.added_mass.normal * env.water_density * c.area() : 0.0;
  ctx.tangential_added_mass_per_length =
      c.loads.added_mass ? c.added_mass.tangential * env.water_density * c.area() : 0.0;
  // Morison's fluid inertia (cable_loads.h): the Froude-Krylov part goes with buoyancy (both
  // are the pressure field on the section), the C_a part with added mass
  ctx.fluid_inertia_per_length =
      (c.loads.buoyancy ? env.water_density * c.area() : 0.0) + ctx.added_mass_per_length;
  // Eq. 15-16: m g e_z (gravity, m = rho_c A for a solid section) and -rho_w A g e_z
  // (buoyancy), NED z down
  double w = 0.0;
  if (c.loads.gravity) w += c.mass_per_length * env.gravity;
  if (c.loads.buoyancy) w -= env.water_density * c.area() * env.gravity;
  ctx.weight_per_length = Vec3(0.0, 0.0, w);
  return ctx;
}

// two unit vectors normal to s
void Normals(const Vec3& s, Vec3* n1, Vec3* n2) {
  const Vec3 t = s.normalized();
  const Vec3 trial = std::abs(t.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  *n1 = (trial - trial.dot(t) * t).normalized();
  *n2 = t.cross(*n1);
}

}  // namespace

System::System(const Model& model) : model_(model), sea_(model.environment) {
  const int nb = num_spheres();
  const int nc = static_cast<int>(model_.cables.size());
  // which cable ends hold each sphere: one folds the sphere into that end's block, two or
  // more make it a hub
  std::vector<int> holders(nb, 0);
  sphere_end_.assign(nb, -1);
  for (int c = 0; c < nc; ++c)
    for (int k = 0; k < 2; ++k) {
      const CableEnd& end = k == 0 ? model_.cables[c].start : model_.cables[c].end;
      if (end.kind != EndKind::kSphere) continue;
      ++holders[end.body];
      sphere_end_[end.body] = 2 * c + k;
    }
  hub_local_.assign(nb, -1);
  for (int b = 0; b < nb; ++b) {
    if (holders[b] < 2) continue;
    sphere_end_[b] = -2;
    hub_local_[b] = 3 * static_cast<int>(hubs_.size());
    hubs_.push_back(b);
  }
  int q_offset = 3 * nb, node_base = 0, lambda_offset = 0;
  for (int c = 0; c < nc; ++c) {
    const CableParams& cp = model_.cables[c];
    CablePart p{AncfElement(MakeElementProperties(cp)), MakeLoadContext(model_, cp)};
    p.state_dependent_loads = p.loads.drag || p.loads.added_mass_per_length > 0.0 ||
                              p.loads.tangential_added_mass_per_length > 0.0 ||
                              (!sea_.uniform() && p.loads.fluid_inertia_per_length > 0.0) ||
                              sea_.has_seabed();
    p.weight_load = UniformLoad(p.loads.weight_per_length, p.element.props().length);
    p.load_fields = p.state_dependent_loads ? LoadFields(p.loads, sea_) : 0;
    p.load_fields_clear = p.state_dependent_loads ? LoadFields(p.loads, sea_, false) : 0;
    p.winch = cp.winch.has_value();  // the scene puts the winched cables first (model.h)
    if (p.winch) num_winches_ = c + 1;
    p.num_nodes = cp.elements + 1;
    p.max_nodes = p.winch ? std::max(p.num_nodes, WinchMaxNodes(cp)) : p.num_nodes;
    p.first_node = p.max_nodes - p.num_nodes;
    p.drum_length = p.element.props().length;
    p.q_offset = q_offset;
    p.node_base = node_base;
    p.lambda_offset = lambda_offset;
    const CableEnd* ends[2] = {&cp.start, &cp.end};
    for (int k = 0; k < 2; ++k) {
      const CableEnd& end = *ends[k];
      p.lambda_count[k] = end.kind == EndKind::kFree ? 0 : 3 + (end.clamped ? 2 : 0);
      if (end.clamped) Normals(end.slope, &p.clamp_dirs[k][0], &p.clamp_dirs[k][1]);
    }
    q_offset += 6 * p.max_nodes;
    node_base += p.max_nodes;
    lambda_offset += p.lambda_count[0] + p.lambda_count[1];
    cables_.push_back(std::move(p));
  }
  num_q_ = q_offset;
  total_array_nodes_ = node_base;
  num_lambda_ = lambda_offset;

  for (const SphereBody& b : model_.spheres) {
    const double rho = model_.environment.water_density;
    const double radius = std::cbrt(3.0 * b.volume / (4.0 * kPi));
    sphere_mass_eff_.push_back(b.mass + b.added_mass_coefficient * rho * b.volume);
    sphere_drag_k_.push_back(0.5 * rho * b.drag_coefficient * kPi * radius * radius);
    sphere_radius_.push_back(radius);
  }
  q_index_.assign(num_q_, {0, -1, -1});
  lambda_index_.assign(num_lambda_, {0, -1, -1});
  q_pos_.assign(num_q_, -1);
  lambda_pos_.assign(num_lambda_, -1);
  // the block sizes with node 0 at array node 0 (MakeMatrix), then the layout in use
  for (int c = 0; c < nc; ++c) {
    CablePart& p = cables_[c];
    const int saved_first = p.first_node, saved_nodes = p.num_nodes;
    p.first_node = 0;
    p.num_nodes = p.max_nodes;
    BuildCableLayout(c);
    p.base_block_sizes = p.block_sizes;
    p.first_node = saved_first;
    p.num_nodes = saved_nodes;
  }
  BuildLayout();
}

void System::BuildCableLayout(int c) {
  // block k = array node k of cable c; the parked nodes' blocks are empty
  CablePart& p = cables_[c];
  const int nb = num_spheres();
  auto folded_at = [&](int end) {
    const CableEnd& e = End(end, c);
    return e.kind == EndKind::kSphere && sphere_end_[e.body] == 2 * c + end ? e.body : -1;
  };
  const int sphere_at[2] = {folded_at(0), folded_at(1)};
  auto place_sphere = [&](int b, int block, int* local) {
    for (int i = 0; i < 3; ++i) q_index_[SphereDof(b) + i] = {c, block, (*local)++};
  };
  auto place_lambda = [&](int end, int block, int* local) {
    for (int i = 0; i < p.lambda_count[end]; ++i)
      lambda_index_[EndLambda(end, c) + i] = {c, block, (*local)++};
  };
  auto place_node = [&](int node, int block, int* local) {
    for (int i = 0; i < 6; ++i) q_index_[CableDof(node, c) + i] = {c, block, (*local)++};
  };
  for (int k = 0; k < p.max_nodes; ++k)
    for (int i = 0; i < 6; ++i) q_index_[ArrayDof(k, c) + i] = {c, -1, -1};
  const int nn = p.num_nodes;
  p.block_sizes.assign(p.max_nodes, 0);  // same size after the first call: no allocation
  for (int node = 0; node < nn; ++node) {
    int local = 0;
    const int block = p.first_node + node;
    if (node == 0) {
      if (sphere_at[0] >= 0) place_sphere(sphere_at[0], block, &local);
      place_lambda(0, block, &local);
    }
    place_node(node, block, &local);
    if (node == nn - 1) {
      place_lambda(1, block, &local);
      if (sphere_at[1] >= 0) place_sphere(sphere_at[1], block, &local);
    }
    p.block_sizes[block] = local;
  }
  if (c == 0) {
    for (int b = 0; b < nb; ++b) {
      if (sphere_end_[b] != -1) continue;  // held by a cable end, or a hub
      int local = 0;
      const int block = static_cast<int>(p.block_sizes.size());
      place_sphere(b, block, &local);
      p.block_sizes.push_back(local);
    }
  }
  p.block_offsets.assign(p.block_sizes.size(), 0);
  for (size_t i = 1; i < p.block_sizes.size(); ++i)
    p.block_offsets[i] = p.block_offsets[i - 1] + p.block_sizes[i - 1];
}

void System::BuildLayout() {
  int offset = 0;
  for (int c = 0; c < num_cables(); ++c) {
    BuildCableLayout(c);
    const CablePart& p = cables_[c];
    for (int i = 0; i < num_q_; ++i) {
      const BlockIndex& bi = q_index_[i];
      if (bi.part != c) continue;
      q_pos_[i] = bi.block < 0 ? -1 : offset + p.block_offsets[bi.block] + bi.local;
    }
    for (int i = 0; i < num_lambda_; ++i) {
      const BlockIndex& bi = lambda_index_[i];
      if (bi.part == c) lambda_pos_[i] = offset + p.block_offsets[bi.block] + bi.local;
    }
    offset += p.block_offsets.back() + p.block_sizes.back();
  }
  for (int h = 0; h < num_hubs(); ++h)
    for (int i = 0; i < 3; ++i) {
      const int dof = SphereDof(hubs_[h]) + i;
      q_index_[dof] = {kHub, 0, 3 * h + i};
      q_pos_[dof] = offset + 3 * h + i;
    }
}

void System::SetLayout(int nodes, double length, int c) {
  CablePart& p = cables_[c];
  p.drum_length = length - (nodes - 2) * element_length(c);
  if (nodes == p.num_nodes) return;
  p.num_nodes = nodes;
  p.first_node = p.max_nodes - nodes;
  BuildLayout();
}

AncfElement System::DrumElement(double length, int c) const {
  ElementProperties p = cables_[c].element.props();
  p.length = length;
  return AncfElement(p);
}

NetworkMatrix System::MakeMatrix() const {
  std::vector<BlockTridiagonal> parts;
  std::vector<std::vector<int>> touched(num_cables());
  for (int c = 0; c < num_cables(); ++c) {
    const CablePart& p = cables_[c];
    parts.emplace_back(p.base_block_sizes, p.winch ? p.max_nodes - 2 : 0);
    parts.back().SetFirstBlock(p.first_node);
    for (int k = 0; k < 2; ++k) {
      const CableEnd& e = End(k, c);
      if (e.kind != EndKind::kSphere || hub_local_[e.body] < 0) continue;
      for (int i = 0; i < 3; ++i) touched[c].push_back(hub_local_[e.body] + i);
    }
  }
  return NetworkMatrix(std::move(parts), 3 * num_hubs(), std::move(touched));
}

void System::Add3(BlockTridiagonal* jac, int i, int j, const Eigen::Matrix3d& m) const {
  const BlockIndex bi = q_index_[i], bj = q_index_[j];
  if (bi.block == bj.block) {
    jac->diag(bi.block).block<3, 3>(bi.local, bj.local) += m;
  } else if (bj.block == bi.block + 1) {
    jac->upper(bi.block).block<3, 3>(bi.local, bj.local) += m;
  } else {  // bj.block == bi.block - 1: L_{bj} holds rows of block bj + 1
    jac->lower(bj.block).block<3, 3>(bi.local, bj.local) += m;
  }
}

void System::Add3(NetworkMatrix* jac, int i, int j, const Eigen::Matrix3d& m) const {
  const BlockIndex bi = q_index_[i], bj = q_index_[j];
  if (bi.part != kHub) return Add3(&jac->cable(bi.part), i, j, m);
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) jac->hub(bi.local + r, bj.local + s) += m(r, s);
}

void System::AddQL(NetworkMatrix* jac, int qi, int li, const Vec3& col) const {
  // a multiplier sits in the block of the node / sphere it constrains; a hub's column of a
  // cable's joint rows goes to the border (network_matrix.h)
  const BlockIndex bq = q_index_[qi], bl = lambda_index_[li];
  BlockTridiagonal& t = jac->cable(bl.part);
  if (bq.part == kHub) {
    const int row = t.block_offset(bl.block) + bl.local;
    for (int k = 0; k < 3; ++k) {
      jac->border_column(bl.part, row, bq.local + k) += col(k);
      jac->border_row(bl.part, bq.local + k, row) += col(k);
    }
    return;
  }
  BlockTridiagonal::Map d = t.diag(bq.block);
  d.block<3, 1>(bq.local, bl.local) += col;
  d.block<1, 3>(bl.local, bq.local) += col.transpose();
}

Vec3 System::SupportPosition(int end, const VectorXd& q, double t,
                             const std::vector<SupportMotion>* supports, int c) const {
  const CableEnd& e = End(end, c);
  switch (e.kind) {
    case EndKind::kFixed:
      return e.position;
    case EndKind::kDriven:
      return e.position + t * e.velocity;
    case EndKind::kSphere:
      return q.segment<3>(SphereDof(e.body)) + e.at_B;  // sphere frames stay world-aligned
    case EndKind::kVehicle:
    case EndKind::kVessel: {
      if (!supports) break;
      const SupportMotion& s = (*supports)[2 * c + end];
      if (s.t1 <= s.t0) return s.p1;
      return s.p0 + ((t - s.t0) / (s.t1 - s.t0)) * (s.p1 - s.p0);
    }
    case EndKind::kFree:
      break;
  }
  return Vec3::Constant(std::nan(""));
}

void System::Evaluate(const SystemPoint& x, const StepInputs& in, const EvaluateOptions& options,
                      const SystemResidual& out) const {
  out.residual->setZero(num_q_);
  out.phi->setZero(num_lambda_);
  if (out.jac) {
    for (int c = 0; c < num_cables(); ++c) {
      BlockTridiagonal& t = out.jac->cable(c);
      if (t.first_block() != cables_[c].first_node) t.SetFirstBlock(cables_[c].first_node);
    }
    out.jac->SetZero();
  }
  for (int c = 0; c < num_cables(); ++c) AssembleCable(c, x, in, options, out);
  AssembleSpheres(x, in, options, out);
  for (int c = 0; c < num_cables(); ++c)
    for (int end = 0; end < 2; ++end) AssembleJoint(c, end, x, in, out);
}

void System::AssembleCable(int cable_index, const SystemPoint& x, const StepInputs& in,
                           const EvaluateOptions& options, const SystemResidual& out) const {
  // cable elements: M e_ddot + F_int + R_load (Eq. 25), element e of `element` (the drum
  // element's rest length moves: its own element, weight load and rate; system.h); R_load the
  // weight in water (Eq. 15-16), drag (Eq. 17-21) and added mass (Eq. 22-23)
  const VectorXd &q = x.q, &v = x.v, &a = x.a;
  const JacobianCoefficients& cf = options.coeffs;
  VectorXd* residual = out.residual;
  const int ci = cable_index;
  const CablePart& part = cables_[ci];
  BlockTridiagonal* jac = out.jac ? &out.jac->cable(ci) : nullptr;
  const bool waves = in.has_waves;
  Vec12 force;
  Mat12 k, c, j;
  ElementLoadJacobians lj;
  GaussFields fields;  // r', r_dot, ... interpolated once per element for both laws
  GaussWaves drum_waves;  // the drum element's waves at its Gauss points
  const auto add_element = [&](int e, const AncfElement& element, const Vec12& qw,
                               double drum_rate) {
    const int o = CableDof(e, ci);
    const Mat12& mass = element.mass();
    const Vec12 ee = q.segment<12>(o), ed = v.segment<12>(o), ea = a.segment<12>(o);
    // the waves at the Gauss points: the step's (StepSampler::SampleWaves), the drum
    // element's from its nodes here (its shape functions change with its rest length)
    const GaussWaves* w = nullptr;
    if (waves) {
      const int i = part.node_base + e;
      if (part.winch && e == 0) {
        drum_waves =
            WavesAtGaussPoints(element, NodeWaves(in.waves.nodes[i], in.waves.nodes[i + 1]));
        w = &drum_waves;
      } else {
        w = &in.waves.elements[i];
      }
    }
    // an element clear of the seabed looks for no contact (exact: cable_loads.h)
    const bool bed_in_reach =
        part.state_dependent_loads && !ClearOfSeabed(sea_, ee, element.props().length);
    element.InterpolateFields(ee, ed, ea, bed_in_reach ? part.load_fields : part.load_fields_clear,
                              &fields);
    element.InternalForce(fields, &force, jac ? &k : nullptr, jac ? &c : nullptr);
    if (!part.state_dependent_loads) {
      // weight in water only: R_load = -scale Q_w, no Jacobian
      residual->segment<12>(o) += element.MassTimes(ea) + force - options.load_scale * qw;
      if (jac) {
        j = cf.c_a * mass + cf.c_q * k;
        if (cf.c_v != 0.0) j += cf.c_v * c;
      }
    } else {
      const Vec12 rl = ElementLoadResidual(element, part.loads, sea_, x.t, w, fields,
                                           options.load_scale, jac ? &lj : nullptr, bed_in_reach);
      residual->segment<12>(o) += element.MassTimes(ea) + force + rl;
      if (jac) {
        // J_e = c_a (M + M_a) + c_q (K + dR_load/de) + c_v (C + dR_load/de_dot)
        j = cf.c_a * (mass + lj.added_mass) + cf.c_q * (k + lj.d_de);
        if (cf.c_v != 0.0) j += cf.c_v * (c + lj.d_dedot);
      }
    }
    if (drum_rate != 0.0) {
      // material entering / leaving at the drum with the drum's velocity (system.h):
      // dl_0/dt (dM/dl) e_dot - rho_c A dl_0/dt v_0
      const double m_dot = element.props().mass_per_length * drum_rate;
      Vec12 flux = drum_rate * element.MassLengthDerivativeTimes(ed);
      flux.segment<3>(0) -= m_dot * ed.segment<3>(0);
      residual->segment<12>(o) += flux;
      if (jac && cf.c_v != 0.0) {
        j += (cf.c_v * drum_rate) * element.MassLengthDerivative();
        j.block<3, 3>(0, 0) -= (cf.c_v * m_dot) * Mat3::Identity();
      }
    }
    if (!jac) return;
    for (int r = 0; r < 4; ++r)
      for (int s = 0; s < 4; ++s) Add3(jac, o + 3 * r, o + 3 * s, j.block<3, 3>(3 * r, 3 * s));
  };
  int first_plain = 0;  // the elements from here on have the nominal length l_e
  if (part.winch) {
    // the drum element's rest length l_0(t) and its rate at t (DrumMotion, state.h)
    const DrumMotion& motion = in.drums[ci];  // winch ci on cable ci (model.h)
    const double drum_l = motion.LengthAt(x.t);
    const double drum_rate = motion.RateAt(x.t);
    // on the stack: Evaluate does not allocate
    const AncfElement drum = DrumElement(drum_l, ci);
    add_element(0, drum, UniformLoad(part.loads.weight_per_length, drum_l), drum_rate);
    first_plain = 1;
  }
  for (int e = first_plain; e < NumElements(ci); ++e)
    add_element(e, part.element, part.weight_load, 0.0);
}

void System::AssembleSpheres(const SystemPoint& x, const StepInputs& in,
                             const EvaluateOptions& options, const SystemResidual& out) const {
  // spheres (Morison): (m + m_a) a - (rho V + m_a) a_w - (m - rho V) g e_z * scale
  //   + k |V| V * scale, V = v - u_w, m_a = C_a rho V, u_w and a_w the water's velocity and
  //   material acceleration Du/Dt at the sphere (a neutrally buoyant sphere follows the water)
  const VectorXd &q = x.q, &v = x.v, &a = x.a;
  const JacobianCoefficients& cf = options.coeffs;
  const double load_scale = options.load_scale;
  const Environment& env = model_.environment;
  for (int b = 0; b < num_spheres(); ++b) {
    const SphereBody& sphere = model_.spheres[b];
    const int o = SphereDof(b);
    Vec3 shear = Vec3::Zero();
    FlowSample flow;
    if (sea_.uniform()) {
      flow.velocity = sea_.uniform_current();
    } else {
      flow = sea_.Current(q.segment<3>(o), x.t, &shear);
      if (in.has_waves) {
        flow.velocity += in.waves.spheres[b].velocity;
        flow.acceleration += in.waves.spheres[b].acceleration;
      }
    }
    const Vec3 vr = RelativeVelocity(v.segment<3>(o), flow);
    const double speed = vr.norm();
    const double net_weight = (sphere.mass - env.water_density * sphere.volume) * env.gravity;
    Vec3 r = sphere_mass_eff_[b] * a.segment<3>(o) + load_scale * sphere_drag_k_[b] * speed * vr;
    r.z() -= load_scale * net_weight;
    if (!sea_.uniform())
      r -= (sphere_mass_eff_[b] - sphere.mass + env.water_density * sphere.volume) *
           flow.acceleration;
    // the seabed under the sphere's lowest point, on its frontal area pi r^2 (seabed_contact.h)
    ContactLoad contact;
    if (sea_.has_seabed()) {
      const Vec3 p_b = q.segment<3>(o);
      const Vec3 low = p_b - sphere_radius_[b] * sea_.SeabedNormal(p_b.x(), p_b.y());
      const double area = kPi * sphere_radius_[b] * sphere_radius_[b];
      contact =
          SeabedContactLoad(sea_, area, low, v.segment<3>(o), Vec3::Zero(), out.jac != nullptr);
      if (contact.active) r -= contact.f;
    }
    out.residual->segment<3>(o) += r;
    if (!out.jac) continue;
    Mat3 jb = cf.c_a * sphere_mass_eff_[b] * Mat3::Identity();
    if (contact.active) jb -= cf.c_q * contact.df_dr + cf.c_v * contact.df_dv;
    if (speed > 0.0) {
      // d(k |V| V)/dV; V depends on v (c_v) and, in a sheared current, on z (c_q)
      const Mat3 dd =
          load_scale * sphere_drag_k_[b] * (speed * Mat3::Identity() + vr * vr.transpose() / speed);
      if (cf.c_v != 0.0) jb += cf.c_v * dd;
      if (!shear.isZero()) jb -= cf.c_q * dd * shear * Vec3::UnitZ().transpose();
    }
    Add3(out.jac, o, o, jb);
  }
}

void System::AssembleJoint(int c, int end, const SystemPoint& x, const StepInputs& in,
                           const SystemResidual& out) const {
  // the joint at a cable end (Eq. 24): Phi = r_end - p_support; R += Phi_q^T lambda (Eq. 26)
  const CablePart& part = cables_[c];
  const int nl = part.lambda_count[end];
  if (nl == 0) return;
  const VectorXd &q = x.q, &lambda = x.lambda;
  VectorXd* residual = out.residual;
  VectorXd* phi = out.phi;
  const CableEnd& ce = End(end, c);
  const int nd = CableDof(end == 0 ? 0 : num_nodes(c) - 1, c);
  const int lo = EndLambda(end, c);
  phi->segment<3>(lo) = q.segment<3>(nd) - SupportPosition(end, q, x.t, &in.supports, c);
  // a support that answers the force (state.h, vehicle_coupling.h):
  //   Phi -= f C (lambda - lambda1), f the fraction of its motion at t
  const SupportMotion& sm = in.supports[2 * c + end];
  double f_c = 0.0;
  if (ce.kind == EndKind::kVehicle && !sm.compliance.isZero()) {
    f_c = sm.t1 <= sm.t0 ? 1.0 : (x.t - sm.t0) / (sm.t1 - sm.t0);
    phi->segment<3>(lo) -= f_c * (sm.compliance * (lambda.segment<3>(lo) - sm.lambda1));
  }
  residual->segment<3>(nd) += lambda.segment<3>(lo);
  const bool sphere = ce.kind == EndKind::kSphere;
  if (sphere) residual->segment<3>(SphereDof(ce.body)) -= lambda.segment<3>(lo);
  if (ce.clamped) {
    // direction held: n_k . r' = 0 for the two normals of the slope
    for (int i = 0; i < 2; ++i) {
      const Vec3& n = part.clamp_dirs[end][i];
      (*phi)(lo + 3 + i) = n.dot(q.segment<3>(nd + 3));
      residual->segment<3>(nd + 3) += lambda(lo + 3 + i) * n;
    }
  }
  NetworkMatrix* jac = out.jac;
  if (!jac) return;
  for (int i = 0; i < 3; ++i) {
    AddQL(jac, nd, lo + i, Vec3::Unit(i));
    if (sphere) AddQL(jac, SphereDof(ce.body), lo + i, -Vec3::Unit(i));
  }
  if (ce.clamped)
    for (int i = 0; i < 2; ++i) AddQL(jac, nd + 3, lo + 3 + i, part.clamp_dirs[end][i]);
  if (f_c != 0.0) {
    // dPhi/dlambda = -f C
    const BlockIndex bl = lambda_index_[lo];
    jac->cable(c).diag(bl.block).block<3, 3>(bl.local, bl.local) -= f_c * sm.compliance;
  }
}

void System::ToBlocks(const VectorXd& r, const VectorXd& phi, VectorXd* x) const {
  x->resize(num_q_ + num_lambda_);
  for (int i = 0; i < num_q_; ++i)
    if (q_pos_[i] >= 0) (*x)(q_pos_[i]) = r(i);  // not a parked node (winch)
  for (int i = 0; i < num_lambda_; ++i) (*x)(lambda_pos_[i]) = phi(i);
}

void System::FromBlocks(const VectorXd& x, VectorXd* dq, VectorXd* dlambda) const {
  dq->resize(num_q_);
  dlambda->resize(num_lambda_);
  for (int i = 0; i < num_q_; ++i) (*dq)(i) = q_pos_[i] < 0 ? 0.0 : x(q_pos_[i]);  // parked: 0
  for (int i = 0; i < num_lambda_; ++i) (*dlambda)(i) = x(lambda_pos_[i]);
}

double System::KineticEnergy(const VectorXd& q, const VectorXd& v) const {
  double ke = 0.0;
  ElementLoadJacobians lj;
  for (int c = 0; c < num_cables(); ++c) {
    const CablePart& p = cables_[c];
    const std::optional<AncfElement> drum = DrumElementNow(c);
    CableLoadContext am_only = p.loads;
    am_only.drag = false;
    am_only.fluid_inertia_per_length = 0.0;
    am_only.weight_per_length.setZero();
    for (int e = 0; e < NumElements(c); ++e) {
      const int o = CableDof(e, c);
      const AncfElement& element = ElementAt(c, e, drum);
      const Vec12 ed = v.segment<12>(o);
      Mat12 m = element.mass();
      if (p.loads.added_mass_per_length > 0.0 || p.loads.tangential_added_mass_per_length > 0.0) {
        ElementLoadResidual(element, am_only, sea_, 0.0, nullptr, q.segment<12>(o), ed,
                            Vec12::Zero(), 1.0, &lj);
        m += lj.added_mass;
      }
      ke += 0.5 * ed.dot(m * ed);
    }
  }
  for (int b = 0; b < num_spheres(); ++b)
    ke += 0.5 * sphere_mass_eff_[b] * v.segment<3>(SphereDof(b)).squaredNorm();
  return ke;
}

double System::PotentialEnergy(const VectorXd& q) const {
  // V = - int w . r dx (uniform load) - sum (m - rho V) g z_b
  double pe = 0.0;
  for (int c = 0; c < num_cables(); ++c) {
    const CablePart& p = cables_[c];
    const Vec12 qw = UniformLoad(p.loads.weight_per_length, p.element.props().length);
    for (int e = 0; e < NumElements(c); ++e) {
      const Vec12 qe = p.winch && e == 0 ? UniformLoad(p.loads.weight_per_length, p.drum_length)
                                         : Vec12(qw);
      pe -= qe.dot(q.segment<12>(CableDof(e, c)));
    }
  }
  const Environment& env = model_.environment;
  for (int b = 0; b < num_spheres(); ++b) {
    const SphereBody& sphere = model_.spheres[b];
    pe -= (sphere.mass - env.water_density * sphere.volume) * env.gravity * q(SphereDof(b) + 2);
  }
  return pe;
}

double System::StrainEnergy(const VectorXd& q) const {
  double u = 0.0;
  for (int c = 0; c < num_cables(); ++c) {
    const std::optional<AncfElement> drum = DrumElementNow(c);
    for (int e = 0; e < NumElements(c); ++e)
      u += ElementAt(c, e, drum).StrainEnergy(q.segment<12>(CableDof(e, c)));
  }
  return u;
}

double System::NodeTension(const VectorXd& q, const VectorXd& v, int node, int c) const {
  // average of the adjacent elements' end values
  double sum = 0.0;
  int n = 0;
  const std::optional<AncfElement> drum = DrumElementNow(c);
  if (node > 0) {
    const int o = CableDof(node - 1, c);
    sum += ElementAt(c, node - 1, drum).AxialForce(q.segment<12>(o), v.segment<12>(o), 1.0);
    ++n;
  }
  if (node < NumElements(c)) {
    const int o = CableDof(node, c);
    sum += ElementAt(c, node, drum).AxialForce(q.segment<12>(o), v.segment<12>(o), 0.0);
    ++n;
  }
  return sum / n;
}

std::string System::DescribeDof(int i, const VectorXd& q) const {
  std::ostringstream s;
  if (i < 3 * num_spheres()) {
    s << "body '" << model_.spheres[i / 3].name << "'";
    return s.str();
  }
  int c = num_cables() - 1;
  while (c > 0 && i < cables_[c].q_offset) --c;
  const CablePart& p = cables_[c];
  const int node = (i - p.q_offset) / 6 - p.first_node;
  const Vec3 r = q.segment<3>(CableDof(node, c));
  if (num_cables() > 1) s << "cable '" << model_.cables[c].name << "' ";
  s << (num_cables() > 1 ? "node " : "cable node ") << node
    << " (s = " << node * p.element.props().length << " m, at [" << r.x() << ", " << r.y()
    << ", " << r.z() << "])";
  return s.str();
}

std::vector<int> System::VehicleEnds(int v) const {
  std::vector<int> ends;
  for (int end = 0; end < num_ends(); ++end) {
    const CableEnd& e = End(end % 2, end / 2);
    if (e.kind == EndKind::kVehicle && e.body == v) ends.push_back(end);
  }
  return ends;
}

}  // namespace towsim::core
