#include "core/ancf_element.h"

namespace towsim::core {
namespace {

using Vec3 = Eigen::Vector3d;

// Energy density u(a, b) of the bending term with a = r', b = r'':
//   u = 1/2 EI g w,  g = A B - C^2,  w = A^-3,  A = a.a, B = b.b, C = a.b
// and its gradient and Hessian in (a, b).
struct BendingDensity {
  double u;
  Vec3 u_a, u_b;
  Mat3 u_aa, u_ab, u_bb;  // u_ab: rows a, columns b
};

BendingDensity Bending(double ei, const Vec3& a, const Vec3& b, bool hessian) {
  BendingDensity d;
  const double A = a.squaredNorm(), B = b.squaredNorm(), C = a.dot(b);
  const double g = A * B - C * C;
  const double w = 1.0 / (A * A * A);
  const Vec3 g_a = 2.0 * B * a - 2.0 * C * b;
  const Vec3 g_b = 2.0 * A * b - 2.0 * C * a;
  const Vec3 w_a = (-6.0 * w / A) * a;
  const double k = 0.5 * ei;
  d.u = k * g * w;
  d.u_a = k * (w * g_a + g * w_a);
  d.u_b = k * w * g_b;
  if (hessian) {
    const Mat3 I = Mat3::Identity();
    // g_aa = 2B I - 2 b b^T, g_ab = 4 a b^T - 2 b a^T - 2C I, g_bb = 2A I - 2 a a^T
    const Mat3 g_aa = 2.0 * B * I - 2.0 * b * b.transpose();
    const Mat3 g_ab = 4.0 * a * b.transpose() - 2.0 * b * a.transpose() - 2.0 * C * I;
    const Mat3 g_bb = 2.0 * A * I - 2.0 * a * a.transpose();
    // w_aa = -6 A^-4 I + 48 A^-5 a a^T
    const Mat3 w_aa = (-6.0 * w / A) * I + (48.0 * w / (A * A)) * a * a.transpose();
    d.u_aa = k * (w * g_aa + g_a * w_a.transpose() + w_a * g_a.transpose() + g * w_aa);
    d.u_ab = k * (w * g_ab + w_a * g_b.transpose());
    d.u_bb = k * w * g_bb;
  }
  return d;
}

}  // namespace

ShapeAtPoint EvaluateShape(double xi, double l) {
  ShapeAtPoint s;
  const double x2 = xi * xi, x3 = x2 * xi;
  // paper Eq. 4
  s.n = {1.0 - 3.0 * x2 + 2.0 * x3, l * (xi - 2.0 * x2 + x3), 3.0 * x2 - 2.0 * x3, l * (x3 - x2)};
  // d/dx = (1/l) d/dxi
  s.dn = {(-6.0 * xi + 6.0 * x2) / l, 1.0 - 4.0 * xi + 3.0 * x2, (6.0 * xi - 6.0 * x2) / l,
          3.0 * x2 - 2.0 * xi};
  s.ddn = {(-6.0 + 12.0 * xi) / (l * l), (-4.0 + 6.0 * xi) / l, (6.0 - 12.0 * xi) / (l * l),
           (6.0 * xi - 2.0) / l};
  s.weight_dx = 0.0;
  return s;
}

AncfElement::AncfElement(const ElementProperties& props) : props_(props) {
  const double l = props_.length;
  const GaussRule<5> rule = Gauss5();
  for (int g = 0; g < 5; ++g) {
    points_[g] = EvaluateShape(rule.xi[g], l);
    points_[g].weight_dx = rule.weight[g] * l;
    for (int k = 0; k < 4; ++k) {
      n_(k, g) = points_[g].n[k];
      dn_(k, g) = points_[g].dn[k];
      ddn_(k, g) = points_[g].ddn[k];
    }
    wdx_(g) = points_[g].weight_dx;
  }
  ends_[0] = EvaluateShape(0.0, l);
  ends_[1] = EvaluateShape(1.0, l);

  // M = rho A l / 420 [156, 22l, 54, -13l; 22l, 4l^2, 13l, -3l^2; ...] (x) I3  (Eq. 7)
  Eigen::Matrix4d m;
  m << 156, 22 * l, 54, -13 * l,              //
      22 * l, 4 * l * l, 13 * l, -3 * l * l,  //
      54, 13 * l, 156, -22 * l,               //
      -13 * l, -3 * l * l, -22 * l, 4 * l * l;
  m *= props_.mass_per_length * l / 420.0;
  mass4_ = m;
  Eigen::Matrix4d dm;
  dm << 156, 44 * l, 54, -26 * l,                 //
      44 * l, 12 * l * l, 26 * l, -9 * l * l,     //
      54, 26 * l, 156, -44 * l,                   //
      -26 * l, -9 * l * l, -44 * l, 12 * l * l;
  dmass4_ = dm * (props_.mass_per_length / 420.0);
  mass_.setZero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) mass_.block<3, 3>(3 * i, 3 * j) = m(i, j) * Mat3::Identity();
}

double AncfElement::StrainEnergy(const Vec12& e) const {
  double u = 0.0;
  for (const ShapeAtPoint& p : points_) {
    const Vec3 a = Interpolate(p.dn, e);
    const double eps = 0.5 * (a.squaredNorm() - 1.0);
    double density = 0.5 * props_.ea * eps * eps;
    if (props_.ei > 0.0) density += Bending(props_.ei, a, Interpolate(p.ddn, e), false).u;
    u += p.weight_dx * density;
  }
  return u;
}

Vec12 AncfElement::MassTimes(const Vec12& e_ddot) const {
  Vec12 f;
  for (int i = 0; i < 4; ++i)
    f.segment<3>(3 * i) = mass4_(i, 0) * e_ddot.segment<3>(0) +
                          mass4_(i, 1) * e_ddot.segment<3>(3) +
                          mass4_(i, 2) * e_ddot.segment<3>(6) + mass4_(i, 3) * e_ddot.segment<3>(9);
  return f;
}

Mat12 AncfElement::MassLengthDerivative() const {
  Mat12 d = Mat12::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) d.block<3, 3>(3 * i, 3 * j) = dmass4_(i, j) * Mat3::Identity();
  return d;
}

Vec12 AncfElement::MassLengthDerivativeTimes(const Vec12& e_dot) const {
  Vec12 f;
  for (int i = 0; i < 4; ++i)
    f.segment<3>(3 * i) = dmass4_(i, 0) * e_dot.segment<3>(0) + dmass4_(i, 1) * e_dot.segment<3>(3) +
                          dmass4_(i, 2) * e_dot.segment<3>(6) + dmass4_(i, 3) * e_dot.segment<3>(9);
  return f;
}

void AncfElement::InterpolateFields(const Vec12& e, const Vec12& e_dot, const Vec12& e_ddot,
                                    unsigned load_fields, GaussFields* f) const {
  f->r_x = AtGaussPoints(e, dn_);
  if (props_.ei > 0.0) f->r_xx = AtGaussPoints(e, ddn_);
  if (props_.axial_damping > 0.0) f->v_x = AtGaussPoints(e_dot, dn_);
  if (load_fields & kFieldPosition) f->r = AtGaussPoints(e, n_);
  if (load_fields & kFieldVelocity) f->v = AtGaussPoints(e_dot, n_);
  if (load_fields & kFieldAcceleration) f->acc = AtGaussPoints(e_ddot, n_);
}

namespace {

// The internal force F = dU/de + damping force from the fields at the Gauss points (one law
// for both uses): at point g the densities u_a = EA (eps + c eps_dot) r' + dU_b/dr' and
// u_b = dU_b/dr'' (eps = (r'.r' - 1)/2, eps_dot = r'.r_dot', Eq. 8-10), weighted, give
//   F = [F_0 .. F_3] = U_a N'^T + U_b N''^T (3 x 4).
// kWithJacobian: also K = dF/de and C = dF/de_dot where asked (stiffness, damping non-null).
template <bool kWithJacobian>
void InternalForceAt(const AncfElement& element, const GaussFields& f, Vec12* force,
                     Mat12* stiffness, Mat12* damping) {
  const ElementProperties& props = element.props();
  const double ea = props.ea, c = props.axial_damping;
  const bool bending = props.ei > 0.0;
  // without damping K is the Hessian of U, symmetric: the blocks k <= j are summed, the others
  // mirrored at the end (K_jk = K_kj^T)
  const bool symmetric = c == 0.0;
  if constexpr (kWithJacobian) {
    if (stiffness) stiffness->setZero();
    if (damping) damping->setZero();
  }
  Mat35 u_a, u_b;
  for (int g = 0; g < 5; ++g) {
    const double wdx = element.weights_dx()(g);
    const Vec3 a = f.r_x.col(g);
    // axial: u_a = EA (eps + c eps_dot) a
    double n = ea * 0.5 * (a.squaredNorm() - 1.0);
    if (c > 0.0) n += ea * c * a.dot(f.v_x.col(g));
    Vec3 f_a = n * a;
    BendingDensity bd;
    if (bending) {
      bd = Bending(props.ei, a, f.r_xx.col(g), kWithJacobian && stiffness);
      f_a += bd.u_a;
      u_b.col(g) = wdx * bd.u_b;
    }
    u_a.col(g) = wdx * f_a;
    if constexpr (kWithJacobian) {
      const ShapeAtPoint& p = element.points()[g];
      if (stiffness) {
        // K_kj = int ( S'_k S'_j u_aa + S'_k S''_j u_ab + S''_k S'_j u_ba + S''_k S''_j u_bb ) dx
        //      = int ( S'_k P_j + S''_k Q_j ) dx,  P_j = S'_j u_aa + S''_j u_ab,
        //                                          Q_j = S'_j u_ba + S''_j u_bb
        Mat3 k_aa = n * Mat3::Identity() + ea * a * a.transpose();
        if (c > 0.0) k_aa += ea * c * a * f.v_x.col(g).transpose();
        if (bending) k_aa += bd.u_aa;
        const Mat3 w_aa = wdx * k_aa;
        if (bending) {
          const Mat3 w_ab = wdx * bd.u_ab, w_ba = w_ab.transpose(), w_bb = wdx * bd.u_bb;
          Mat3 p_j[4], q_j[4];
          for (int j = 0; j < 4; ++j) {
            p_j[j] = p.dn[j] * w_aa + p.ddn[j] * w_ab;
            q_j[j] = p.dn[j] * w_ba + p.ddn[j] * w_bb;
          }
          for (int k = 0; k < 4; ++k)
            for (int j = symmetric ? k : 0; j < 4; ++j)
              stiffness->block<3, 3>(3 * k, 3 * j) += p.dn[k] * p_j[j] + p.ddn[k] * q_j[j];
        } else {
          for (int k = 0; k < 4; ++k)
            for (int j = symmetric ? k : 0; j < 4; ++j)
              stiffness->block<3, 3>(3 * k, 3 * j) += (p.dn[k] * p.dn[j]) * w_aa;
        }
      }
      if (damping && c > 0.0) {
        // C_kj = int S'_k S'_j EA c a a^T dx
        const Mat3 c_aa = (wdx * ea * c) * a * a.transpose();
        for (int k = 0; k < 4; ++k)
          for (int j = 0; j < 4; ++j)
            damping->block<3, 3>(3 * k, 3 * j) += (p.dn[k] * p.dn[j]) * c_aa;
      }
    }
  }
  Eigen::Map<Eigen::Matrix<double, 3, 4>> out(force->data());
  out.noalias() = u_a * element.shape_dn().transpose();
  if (bending) out.noalias() += u_b * element.shape_ddn().transpose();
  if constexpr (kWithJacobian) {
    if (stiffness && symmetric)
      for (int k = 1; k < 4; ++k)
        for (int j = 0; j < k; ++j)
          stiffness->block<3, 3>(3 * k, 3 * j) = stiffness->block<3, 3>(3 * j, 3 * k).transpose();
  }
}

}  // namespace

void AncfElement::InternalForce(const GaussFields& fields, Vec12* force, Mat12* stiffness,
                                Mat12* damping) const {
  if (stiffness || damping)
    InternalForceAt<true>(*this, fields, force, stiffness, damping);
  else
    InternalForceAt<false>(*this, fields, force, nullptr, nullptr);
}

void AncfElement::InternalForce(const Vec12& e, const Vec12& e_dot, Vec12* force, Mat12* stiffness,
                                Mat12* damping) const {
  GaussFields fields;
  InterpolateFields(e, e_dot, e_dot, 0, &fields);
  InternalForce(fields, force, stiffness, damping);
}

double AncfElement::AxialForce(const Vec12& e, const Vec12& e_dot, double xi) const {
  const ShapeAtPoint& p = ends_[xi < 0.5 ? 0 : 1];
  const Vec3 a = Interpolate(p.dn, e);
  double n = props_.ea * 0.5 * (a.squaredNorm() - 1.0);
  if (props_.axial_damping > 0.0)
    n += props_.ea * props_.axial_damping * a.dot(Interpolate(p.dn, e_dot));
  return n * a.norm();
}

}  // namespace towsim::core
