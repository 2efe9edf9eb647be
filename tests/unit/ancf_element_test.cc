#include "core/ancf_element.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/constants.h"

namespace towsim::core {
namespace {

// paper cable: d = 0.041 m, E = 7e8 Pa, rho = 1300 kg/m^3, element of 10 m
ElementProperties PaperElement(double c = 0.0) {
  const double d = 0.041, pi = kPi;
  ElementProperties p;
  p.length = 10.0;
  p.ea = 7e8 * pi * d * d / 4;
  p.ei = 7e8 * pi * d * d * d * d / 64;
  p.axial_damping = c;
  p.mass_per_length = 1300 * pi * d * d / 4;
  return p;
}

// a curved, stretched configuration (no special symmetry)
Vec12 CurvedCoordinates() {
  Vec12 e;
  e << 0.1, -0.2, 0.3, 0.95, 0.2, -0.1,  //
      9.7, 1.1, -0.8, 0.9, 0.05, -0.25;
  return e;
}

TEST(AncfElement, MassMatrixSumsToElementMass) {
  const AncfElement el(PaperElement());
  // a rigid unit translation along each axis: e = [u, 0, u, 0]
  for (int axis = 0; axis < 3; ++axis) {
    Vec12 e = Vec12::Zero();
    e(axis) = 1.0;
    e(6 + axis) = 1.0;
    const double m = e.dot(el.mass() * e);
    EXPECT_NEAR(m, el.props().mass_per_length * el.props().length, 1e-12 * m);
  }
  EXPECT_TRUE(el.mass().isApprox(el.mass().transpose(), 1e-14));
}

TEST(AncfElement, NoElasticForceForRigidMotionsOfTheStraightCable) {
  const AncfElement el(PaperElement());
  const double l = el.props().length;
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())).toRotationMatrix();
  const Eigen::Vector3d p(3.0, -4.0, 5.0), t = R * Eigen::Vector3d::UnitX();
  Vec12 e;
  e << p, t, p + l * t, t;
  Vec12 f;
  Mat12 k;
  el.InternalForce(e, Vec12::Zero(), &f, &k, nullptr);
  // force scale EA ~ 9e5 N: round-off level only
  constexpr double kRigidTol = 1e-9;
  EXPECT_LT(f.norm(), kRigidTol * el.props().ea);
  EXPECT_NEAR(el.StrainEnergy(e), 0.0, 1e-12 * el.props().ea * l);
}

TEST(AncfElement, ForceIsTheGradientOfTheStrainEnergy) {
  const AncfElement el(PaperElement());
  const Vec12 e = CurvedCoordinates();
  Vec12 f;
  el.InternalForce(e, Vec12::Zero(), &f, nullptr, nullptr);
  Vec12 fd;
  const double h = 1e-6;  // central differences: O(h^2) truncation ~ 1e-12 relative
  for (int i = 0; i < 12; ++i) {
    Vec12 ep = e, em = e;
    ep(i) += h;
    em(i) -= h;
    fd(i) = (el.StrainEnergy(ep) - el.StrainEnergy(em)) / (2 * h);
  }
  constexpr double kGradRelTol = 1e-6;  // round-off of U (~1e5 J) over 2h
  EXPECT_LT((f - fd).norm(), kGradRelTol * f.norm())
      << "F = " << f.transpose() << "\nFD = " << fd.transpose();
}

TEST(AncfElement, TangentIsTheDerivativeOfTheForce) {
  for (const bool bending : {false, true}) {
    ElementProperties p = PaperElement(0.05);
    if (!bending) p.ei = 0.0;
    p.ei *= 1e3;  // make bending visible next to the axial terms
    const AncfElement el(p);
    const Vec12 e = CurvedCoordinates();
    Vec12 ed;
    ed << 0.3, -0.1, 0.2, 0.01, -0.02, 0.03, -0.2, 0.4, 0.1, 0.02, 0.01, -0.01;
    Vec12 f;
    Mat12 k, c;
    el.InternalForce(e, ed, &f, &k, &c);
    Mat12 k_fd, c_fd;
    const double h = 1e-7;
    for (int i = 0; i < 12; ++i) {
      Vec12 fp, fm;
      Vec12 ep = e, em = e;
      ep(i) += h;
      em(i) -= h;
      el.InternalForce(ep, ed, &fp, nullptr, nullptr);
      el.InternalForce(em, ed, &fm, nullptr, nullptr);
      k_fd.col(i) = (fp - fm) / (2 * h);
      Vec12 vp = ed, vm = ed;
      vp(i) += h;
      vm(i) -= h;
      el.InternalForce(e, vp, &fp, nullptr, nullptr);
      el.InternalForce(e, vm, &fm, nullptr, nullptr);
      c_fd.col(i) = (fp - fm) / (2 * h);
    }
    constexpr double kTangentRelTol = 1e-6;  // central differences, h = 1e-7
    EXPECT_LT((k - k_fd).norm(), kTangentRelTol * k.norm()) << "bending " << bending;
    EXPECT_LT((c - c_fd).norm(), kTangentRelTol * c.norm()) << "bending " << bending;
    EXPECT_TRUE(k.isApprox(k.transpose(), 1e-6) || p.axial_damping > 0.0);
  }
}

// one law computes the force with and without the Jacobians (ancf_element.cc): the force is
// the same to the bit whichever of K and C is asked for
TEST(AncfElement, ForceIsBitIdenticalWithAndWithoutTheJacobians) {
  Vec12 ed;
  ed << 0.3, -0.1, 0.2, 0.01, -0.02, 0.03, -0.2, 0.4, 0.1, 0.02, 0.01, -0.01;
  for (const bool bending : {false, true})
    for (const double c : {0.0, 0.05}) {
      ElementProperties p = PaperElement(c);
      if (!bending) p.ei = 0.0;
      const AncfElement el(p);
      Vec12 f, f_kc, f_k, f_c;
      Mat12 k, d;
      el.InternalForce(CurvedCoordinates(), ed, &f, nullptr, nullptr);
      el.InternalForce(CurvedCoordinates(), ed, &f_kc, &k, &d);
      el.InternalForce(CurvedCoordinates(), ed, &f_k, &k, nullptr);
      el.InternalForce(CurvedCoordinates(), ed, &f_c, nullptr, &d);
      EXPECT_EQ(f, f_kc) << "bending " << bending << ", c " << c;
      EXPECT_EQ(f, f_k) << "bending " << bending << ", c " << c;
      EXPECT_EQ(f, f_c) << "bending " << bending << ", c " << c;
    }
}

TEST(AncfElement, ExactCurvatureOfACircularArc) {
  // nodes on a circle of radius R with unit tangents: the interpolated curvature ~ 1/R and
  // the energy ~ EI l / (2 R^2) (cubic Hermite arc, error ~ (l/R)^4)
  ElementProperties p = PaperElement();
  p.ea = 0.0;
  const AncfElement el(p);
  const double R = 50.0, l = p.length, th = l / R;
  Vec12 e;
  e << 0, 0, 0, 1, 0, 0, R * std::sin(th), R * (1 - std::cos(th)), 0, std::cos(th), std::sin(th), 0;
  const double expected = 0.5 * p.ei * l / (R * R);
  constexpr double kArcRelTol = 1e-3;  // (l/R)^4 = 1.6e-3 bound on the interpolation error
  EXPECT_NEAR(el.StrainEnergy(e), expected, kArcRelTol * expected);
}

// DeepestBound: the cubic Hermite segment is the Bezier curve of r_0, r_0 + l/3 r'_0,
// r_1 - l/3 r'_1, r_1, inside their convex hull, so no point of the element is deeper than the
// deepest control point; a straight element's control points lie on its chord, so there the
// bound is the deeper end exactly
TEST(AncfElement, NoPointIsDeeperThanTheDeepestBound) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double tightest = 1e300;  // the smallest bound - deepest point seen, [m]
  for (int k = 0; k < 2000; ++k) {
    ElementProperties p;
    p.length = 1.0 + 19.0 * 0.5 * (u(rng) + 1.0);
    const AncfElement el(p);
    Vec12 e;
    for (int i = 0; i < 12; ++i) e(i) = (i % 6 < 3 ? 10.0 : 1.0) * u(rng);  // slopes ~1
    const double bound = DeepestBound(e, p.length);
    double deepest = -1e300;
    for (int j = 0; j <= 1000; ++j) {
      const ShapeAtPoint s = EvaluateShape(j / 1000.0, p.length);
      deepest = std::max(deepest, Interpolate(s.n, e).z());
    }
    ASSERT_LE(deepest, bound + 1e-12 * (std::abs(bound) + p.length)) << "element " << k;
    tightest = std::min(tightest, bound - deepest);
  }
  EXPECT_GE(tightest, -1e-12);
  Vec12 straight;
  const Eigen::Vector3d r0(1.0, 2.0, 3.0), r1(8.0, -1.0, 11.0);
  const Eigen::Vector3d d = (r1 - r0) / 10.0;
  straight << r0, d, r1, d;
  EXPECT_NEAR(DeepestBound(straight, 10.0), 11.0, 1e-14);
}

}  // namespace
}  // namespace towsim::core
