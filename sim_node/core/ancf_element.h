#pragma once
// Lower-order (gradient-deficient) 3D ANCF cable element, Gerstmayr & Shabana (2006).
//
// Element coordinates e (12 x 1) = [r_0, r'_0, r_1, r'_1] (paper Eq. 1), r' = dr/dx with x the
// unstretched arc length. r(x) = S(xi) e with the cubic Hermite shape functions of paper Eq. 4,
// xi = x / l. Strain energy (paper Eq. 8)
//   U = 1/2 int_0^l ( EA eps^2 + EI kappa^2 ) dx,
// with the Green strain eps = (r'.r' - 1) / 2 (Eq. 10) and the exact curvature
//   kappa^2 = |r' x r''|^2 / |r'|^6 = ((r'.r')(r''.r'') - (r'.r'')^2) / (r'.r')^3,
// not the small-deflection form of Eq. 12-13. Forces are exact gradients of U and the tangent is
// the exact Hessian (tests check both against finite differences).

#include <algorithm>
#include <array>

#include <Eigen/Core>

#include "core/gauss_quadrature.h"

namespace towsim::core {

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Mat3 = Eigen::Matrix3d;
using Mat35 = Eigen::Matrix<double, 3, 5>;
using Mat45 = Eigen::Matrix<double, 4, 5>;

// Scalar Hermite weights at one point: r = sum_k n[k] e_k, r' = sum_k dn[k] e_k, r'' = ...
struct ShapeAtPoint {
  std::array<double, 4> n;    // S_1..S_4 (Eq. 4)
  std::array<double, 4> dn;   // dS_k/dx  [1/m]
  std::array<double, 4> ddn;  // d2S_k/dx2 [1/m^2]
  double weight_dx;           // Gauss weight times l [m]
};

ShapeAtPoint EvaluateShape(double xi, double l);

// An element's fields at its five Gauss points (column g: point g), each interpolated once per
// evaluation and read by both the internal force and the loads (cable_loads.h). With the
// coordinates as the 3 x 4 matrix E = [r_0 r'_0 r_1 r'_1] and the shape tables N, N', N''
// (4 x 5: S_k, dS_k/dx, d2S_k/dx2 of Eq. 4 at the points): r = E N, r' = E N', r'' = E N''.
// Which ones are filled: AncfElement::InterpolateFields.
struct GaussFields {
  Mat35 r_x;   // r' (always)
  Mat35 r_xx;  // r'' (with bending)
  Mat35 v_x;   // r_dot' (with axial damping)
  Mat35 r;     // r (kFieldPosition)
  Mat35 v;     // r_dot (kFieldVelocity)
  Mat35 acc;   // r_ddot (kFieldAcceleration)
};
// the fields a load asks InterpolateFields for, besides the element's own
inline constexpr unsigned kFieldPosition = 1, kFieldVelocity = 2, kFieldAcceleration = 4;

// x(x_g) at the five Gauss points for element coordinates x (12 x 1) and a shape table
// (4 x 5): X S, X = x as 3 x 4
inline Mat35 AtGaussPoints(const Vec12& x, const Mat45& table) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 4>>(x.data()) * table;
}

struct ElementProperties {
  double length = 1.0;           // l [m]
  double ea = 0.0;               // E A [N]
  double ei = 0.0;               // E I [N m^2] (0 switches bending off)
  double axial_damping = 0.0;    // c [s]: N = EA (eps + c deps/dt)
  double mass_per_length = 0.0;  // rho_c A [kg/m]
};

// Precomputed shape tables of one element length (all elements of a cable share them).
class AncfElement {
 public:
  explicit AncfElement(const ElementProperties& props);

  const ElementProperties& props() const { return props_; }
  // consistent mass matrix M = int rho A S^T S dx (Eq. 7), constant
  const Mat12& mass() const { return mass_; }
  const std::array<ShapeAtPoint, 5>& points() const { return points_; }
  // the shape tables at the Gauss points (4 x 5, column g: point g; GaussFields) and the
  // weights times l [m]
  const Mat45& shape_n() const { return n_; }
  const Mat45& shape_dn() const { return dn_; }
  const Mat45& shape_ddn() const { return ddn_; }
  const Eigen::Matrix<double, 1, 5>& weights_dx() const { return wdx_; }

  // the fields at the Gauss points: r' always, r'' with bending, r_dot' with axial damping,
  // and those of `load_fields` (kFieldPosition | kFieldVelocity | kFieldAcceleration)
  void InterpolateFields(const Vec12& e, const Vec12& e_dot, const Vec12& e_ddot,
                         unsigned load_fields, GaussFields* fields) const;
  // the internal force F = dU/de + damping force from the fields (InterpolateFields), and
  // where asked (non-null) its Jacobians K = dF/de (12 x 12) and C = dF/de_dot (12 x 12); the
  // force is the same to the bit with or without them (one law, ancf_element.cc)
  void InternalForce(const GaussFields& fields, Vec12* force, Mat12* stiffness,
                     Mat12* damping) const;

  // strain energy U(e) (Eq. 8)
  double StrainEnergy(const Vec12& e) const;

  // M e_ddot, with M = m4 (x) I3 applied block-wise (48 multiply-adds instead of 144)
  Vec12 MassTimes(const Vec12& e_ddot) const;
  // dM/dl (the consistent mass's derivative in the element length; a winch's drum element,
  // system.h) and dM/dl e_dot:
  //   dM/dl = rho A / 420 [156, 44l, 54, -26l; 44l, 12l^2, 26l, -9l^2;
  //                        54, 26l, 156, -44l; -26l, -9l^2, -44l, 12l^2] (x) I3
  Mat12 MassLengthDerivative() const;
  Vec12 MassLengthDerivativeTimes(const Vec12& e_dot) const;

  // the same from the element coordinates (the fields interpolated here)
  void InternalForce(const Vec12& e, const Vec12& e_dot, Vec12* force, Mat12* stiffness,
                     Mat12* damping) const;

  // true axial force N |r'| = EA eps |r'| (+ damping) at xi in {0, 1} [N]
  double AxialForce(const Vec12& e, const Vec12& e_dot, double xi) const;

 private:
  ElementProperties props_;
  Mat12 mass_;
  Eigen::Matrix4d mass4_;  // M = mass4_ (x) I3
  Eigen::Matrix4d dmass4_;  // dM/dl = dmass4_ (x) I3
  std::array<ShapeAtPoint, 5> points_;
  Mat45 n_, dn_, ddn_;  // points_ as tables
  Eigen::Matrix<double, 1, 5> wdx_;
  std::array<ShapeAtPoint, 2> ends_;
};

// An upper bound of the depth z over the element (of length l, coordinates e): the cubic Hermite
// segment is the Bezier curve with the control points r_0, r_0 + l/3 r'_0, r_1 - l/3 r'_1, r_1,
// which lies in their convex hull
inline double DeepestBound(const Vec12& e, double l) {
  const double third = l / 3.0;
  return std::max(std::max(e(2), e(2) + third * e(5)), std::max(e(8) - third * e(11), e(8)));
}

// r, r', r'' at a point from element coordinates
inline Eigen::Vector3d Interpolate(const std::array<double, 4>& w, const Vec12& e) {
  return w[0] * e.segment<3>(0) + w[1] * e.segment<3>(3) + w[2] * e.segment<3>(6) +
         w[3] * e.segment<3>(9);
}

}  // namespace towsim::core
