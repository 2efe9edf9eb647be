#include "core/hydrodynamics.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/cable_loads.h"
#include "core/constants.h"
#include "core/environment_field.h"

namespace towsim::core {
namespace {

// paper Eq. 18, written out independently
double Eq18(double re) {
  if (re <= 1.0) {
    const double s = -0.07721 + std::log(8.0 / re);
    return 8.0 * kPi / (re * s) * (1.0 - 0.87 / (s * s));
  }
  if (re < 30.0) return 1.45 + 8.55 * std::pow(re, -0.9);
  return 1.1 + 4.0 * std::pow(std::min(re, 1e5), -0.5);
}

TEST(ChooCasarella, NormalDragCoefficientMatchesEq18) {
  constexpr double kCoefRelTol = 1e-12;
  for (double re : {1e-6, 0.01, 0.5, 1.0, 1.5, 10.0, 29.9, 30.0, 1000.0, 1e5, 2.5e5, 1e7}) {
    EXPECT_NEAR(NormalDragCoefficient(re), Eq18(re), kCoefRelTol * Eq18(re)) << "Re = " << re;
  }
  // hand-checked values: Re = 10 -> 1.45 + 8.55 * 10^-0.9 = 2.526381; Re = 1e4 -> 1.14
  EXPECT_NEAR(NormalDragCoefficient(10.0), 2.526381, 1e-6);
  EXPECT_NEAR(NormalDragCoefficient(1e4), 1.14, 1e-12);
  // beyond 1e5 the 1e5 value
  EXPECT_DOUBLE_EQ(NormalDragCoefficient(3e6), NormalDragCoefficient(1e5));
}

TEST(ChooCasarella, NusseltNumberMatchesEq19) {
  for (double re : {0.1, 1.0, 100.0, 1e5}) {
    const double nu = 0.55 * std::sqrt(re) + 0.084 * std::pow(re, 2.0 / 3.0);
    EXPECT_NEAR(NusseltNumber(re), nu, 1e-12 * nu);
  }
  EXPECT_EQ(NusseltNumber(0.0), 0.0);
}

TEST(ChooCasarella, DragStaysFiniteAndVanishesAsTheSpeedGoesToZero) {
  const FluidProperties fluid;
  const Eigen::Vector3d a = Eigen::Vector3d::UnitX();
  for (double v : {1e-9, 1e-15, 1e-200, 0.0}) {
    const Eigen::Vector3d vel(0.3 * v, 0, v);
    const DragResult d = CableDrag(fluid, {}, 0.041, a, vel, true);
    EXPECT_TRUE(d.f.allFinite() && d.df_dv.allFinite() && d.df_da.allFinite()) << v;
    // Re < 1 (Stokes-Oseen): |f| = mu G |V_n| / 2 with G = 8 pi (1/S - 0.87/S^3) < 10
    EXPECT_LE(d.f.norm(), 5.0 * fluid.viscosity * vel.norm()) << v;
  }
}

TEST(CableDrag, JacobiansMatchFiniteDifferences) {
  const FluidProperties fluid;
  const Eigen::Vector3d a(1.003, 0.2, -0.1);
  for (const Eigen::Vector3d& v : {Eigen::Vector3d(0.5, -1.2, 2.0),        // Re ~ 1e5
                                   Eigen::Vector3d(1e-4, 2e-4, -1e-4),     // Re ~ 10
                                   Eigen::Vector3d(3e-6, -1e-6, 5e-6)}) {  // Re < 1
    const DragResult d = CableDrag(fluid, {}, 0.041, a, v, true);
    Eigen::Matrix3d fv, fa;
    for (int i = 0; i < 3; ++i) {
      const double hv = 1e-7 * v.norm(), ha = 1e-7;
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
      fv.col(i) = (CableDrag(fluid, {}, 0.041, a, v + hv * e, false).f -
                   CableDrag(fluid, {}, 0.041, a, v - hv * e, false).f) /
                  (2 * hv);
      fa.col(i) = (CableDrag(fluid, {}, 0.041, a + ha * e, v, false).f -
                   CableDrag(fluid, {}, 0.041, a - ha * e, v, false).f) /
                  (2 * ha);
    }
    constexpr double kJacRelTol = 1e-5;  // central differences on a smooth branch
    EXPECT_LT((d.df_dv - fv).norm(), kJacRelTol * fv.norm()) << v.transpose();
    EXPECT_LT((d.df_da - fa).norm(), kJacRelTol * fa.norm() + 1e-12) << v.transpose();
  }
}

// a straight cable along x translating along z: every point has the same relative velocity
TEST(CableLoads, NormalTranslationGetsDragAndAddedMassOfTheRightSize) {
  const double d = 0.041, l = 10.0, rho = 1025.0, mu = 1e-3, area = kPi * d * d / 4;
  ElementProperties p;
  p.length = l;
  p.ea = 1e6;
  const AncfElement el(p);
  CableLoadContext ctx;
  ctx.fluid = {rho, mu};
  ctx.diameter = d;
  ctx.drag = true;
  ctx.added_mass_per_length = rho * area;  // C_a = 1
  const EnvironmentField sea{Environment()};  // still water
  const ElementWaves* waves = nullptr;
  Vec12 e, ed, edd;
  e << 0, 0, 0, 1, 0, 0, l, 0, 0, 1, 0, 0;
  const double u = 2.0;
  ed << 0, 0, u, 0, 0, 0, 0, 0, u, 0, 0, 0;
  edd.setZero();
  Vec12 r = ElementLoadResidual(el, ctx, sea, 0.3, waves, e, ed, edd, 1.0, nullptr);
  // the resultant force on the element is the sum of the position components of -R
  const Eigen::Vector3d drag = -(r.segment<3>(0) + r.segment<3>(6));
  const double re = rho * u * d / mu;
  const double expected = 0.5 * rho * d * Eq18(re) * u * u * l;
  constexpr double kLoadRelTol = 1e-12;  // the load is uniform: quadrature is exact
  EXPECT_NEAR(drag.z(), -expected, kLoadRelTol * expected);
  EXPECT_NEAR(drag.x(), 0.0, 1e-12 * expected);
  EXPECT_NEAR(drag.y(), 0.0, 1e-12 * expected);

  // added mass: normal acceleration -> -rho A a L; tangential acceleration -> nothing
  ed.setZero();
  edd << 0, 0, 3.0, 0, 0, 0, 0, 0, 3.0, 0, 0, 0;
  r = ElementLoadResidual(el, ctx, sea, 0.3, waves, e, ed, edd, 1.0, nullptr);
  const Eigen::Vector3d am = -(r.segment<3>(0) + r.segment<3>(6));
  EXPECT_NEAR(am.z(), -rho * area * 3.0 * l, kLoadRelTol * rho * area * 3.0 * l);
  edd << 3.0, 0, 0, 0, 0, 0, 3.0, 0, 0, 0, 0, 0;
  r = ElementLoadResidual(el, ctx, sea, 0.3, waves, e, ed, edd, 1.0, nullptr);
  EXPECT_LT(r.norm(), 1e-12);

  // tangential towing: pi mu V_t Nu(Re_t) per unit length
  edd.setZero();
  ed << u, 0, 0, 0, 0, 0, u, 0, 0, 0, 0, 0;
  r = ElementLoadResidual(el, ctx, sea, 0.3, waves, e, ed, edd, 1.0, nullptr);
  const double nu = 0.55 * std::sqrt(re) + 0.084 * std::pow(re, 2.0 / 3.0);
  EXPECT_NEAR(-(r(0) + r(6)), -kPi * mu * u * nu * l, 1e-9 * kPi * mu * u * nu * l);
}

// constant coefficients (a line type's drag): the forces of hydrodynamics.h written out,
//   f = |a| (-1/2 rho C_n d |V_n| V_n - 1/2 rho C_t pi d |V_t| V_t)
TEST(ConstantDrag, ForcesAreQuadraticOnDAndPiD) {
  const FluidProperties fluid;  // rho 1025, mu 1e-3
  const CableDragLaw law{CableDragLaw::kConstant, 1.5, 0.01};
  const double d = 0.0173;
  // stretched 1 %: a = 1.01 e_x; V = (2, 0, -3): V_t = 2 e_x, V_n = -3 e_z
  const Eigen::Vector3d a(1.01, 0.0, 0.0), v(2.0, 0.0, -3.0);
  const DragResult r = CableDrag(fluid, law, d, a, v, false);
  const double fn = 0.5 * 1025.0 * 1.5 * d * 3.0 * 3.0 * 1.01;         // 120.8 N/m, along +z
  const double ft = 0.5 * 1025.0 * 0.01 * kPi * d * 2.0 * 2.0 * 1.01;  // 1.125 N/m, along -x
  constexpr double kForceRelTol = 1e-14;
  EXPECT_NEAR(r.f.z(), fn, kForceRelTol * fn);
  EXPECT_NEAR(r.f.x(), -ft, kForceRelTol * fn);
  EXPECT_EQ(r.f.y(), 0.0);
  // hand-checked: 512.5 x 1.5 = 768.75; x 0.0173 = 13.299375; x 9 x 1.01 = 120.8913 N/m
  EXPECT_NEAR(fn, 120.8913, 1e-4);
  // no viscosity in it: the same force at 10x the viscosity
  const FluidProperties thick{1025.0, 1e-2};
  EXPECT_EQ(CableDrag(thick, law, d, a, v, false).f, r.f);
}

TEST(ConstantDrag, JacobiansMatchFiniteDifferences) {
  const FluidProperties fluid;
  const CableDragLaw law{CableDragLaw::kConstant, 1.2, 0.008};
  const Eigen::Vector3d a(1.003, 0.2, -0.1);
  for (const Eigen::Vector3d& v :
       {Eigen::Vector3d(0.5, -1.2, 2.0), Eigen::Vector3d(-3.0, 0.1, 0.2)}) {
    const DragResult d = CableDrag(fluid, law, 0.041, a, v, true);
    Eigen::Matrix3d fv, fa;
    for (int i = 0; i < 3; ++i) {
      const double hv = 1e-7 * v.norm(), ha = 1e-7;
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
      fv.col(i) = (CableDrag(fluid, law, 0.041, a, v + hv * e, false).f -
                   CableDrag(fluid, law, 0.041, a, v - hv * e, false).f) /
                  (2 * hv);
      fa.col(i) = (CableDrag(fluid, law, 0.041, a + ha * e, v, false).f -
                   CableDrag(fluid, law, 0.041, a - ha * e, v, false).f) /
                  (2 * ha);
    }
    constexpr double kJacRelTol = 1e-6;  // central differences of a quadratic law
    EXPECT_LT((d.df_dv - fv).norm(), kJacRelTol * fv.norm()) << v.transpose();
    EXPECT_LT((d.df_da - fa).norm(), kJacRelTol * fa.norm()) << v.transpose();
  }
}

// a line type's tangential added mass: an element along x accelerating along x carries
// m_at a L, and none across (the normal part is C_an's)
TEST(CableLoads, TangentialAddedMassActsAlongTheCable) {
  const double l = 10.0, m_at = 0.4;
  ElementProperties p;
  p.length = l;
  const AncfElement el(p);
  CableLoadContext ctx;
  ctx.tangential_added_mass_per_length = m_at;
  const EnvironmentField sea{Environment()};
  Vec12 e, ed, edd;
  e << 0, 0, 0, 1, 0, 0, l, 0, 0, 1, 0, 0;
  ed.setZero();
  edd << 3.0, 0, 0, 0, 0, 0, 3.0, 0, 0, 0, 0, 0;
  ElementLoadJacobians jac;
  Vec12 r = ElementLoadResidual(el, ctx, sea, 0.0, nullptr, e, ed, edd, 1.0, &jac);
  constexpr double kLoadRelTol = 1e-12;
  EXPECT_NEAR(r(0) + r(6), m_at * 3.0 * l, kLoadRelTol * m_at * 3.0 * l);
  // M_a e_ddot is the residual (the load is the added mass alone)
  EXPECT_LT((jac.added_mass * edd - r).norm(), 1e-12);
  edd << 0, 0, 3.0, 0, 0, 0, 0, 0, 3.0, 0, 0, 0;
  r = ElementLoadResidual(el, ctx, sea, 0.0, nullptr, e, ed, edd, 1.0, nullptr);
  EXPECT_LT(r.norm(), 1e-12);
}

// the paper cable's loads (drag, added mass, fluid inertia, weight in water) with a drag law
// and a tangential added mass
CableLoadContext PaperCableLoads(const CableDragLaw& law = {}, double tangential_added_mass = 0.0) {
  CableLoadContext ctx;
  ctx.diameter = 0.041;
  ctx.drag = true;
  ctx.drag_law = law;
  ctx.tangential_added_mass_per_length = tangential_added_mass;
  ctx.added_mass_per_length = 1.35;
  ctx.fluid_inertia_per_length = 1.35 + 1.1;
  ctx.weight_per_length = Eigen::Vector3d(0, 0, 3.5);
  return ctx;
}

// element velocities and accelerations of no special symmetry
void SomeRates(Vec12* ed, Vec12* edd) {
  *ed << 1.0, -0.5, 2.0, 0.1, 0.0, 0.05, 1.5, 0.2, -1.0, 0.0, 0.1, 0.0;
  *edd << 0.2, 0.1, -0.3, 0.0, 0.01, 0.0, 0.5, -0.2, 0.1, 0.02, 0.0, 0.01;
}

void CheckLoadJacobians(const Environment& env, const ElementWaves* waves,
                        const CableDragLaw& law = {}, double tangential_added_mass = 0.0) {
  ElementProperties p;
  p.length = 10.0;
  const AncfElement el(p);
  const CableLoadContext ctx = PaperCableLoads(law, tangential_added_mass);
  const EnvironmentField sea(env);
  Vec12 e, ed, edd;
  e << 0.1, -0.2, 0.3, 0.95, 0.2, -0.1, 9.7, 1.1, -0.8, 0.9, 0.05, -0.25;
  SomeRates(&ed, &edd);
  ElementLoadJacobians jac;
  const Vec12 r0 = ElementLoadResidual(el, ctx, sea, 0.3, waves, e, ed, edd, 1.0, &jac);
  // one load law with and without the Jacobians (cable_loads.cc): the same residual to the bit
  EXPECT_EQ(r0, ElementLoadResidual(el, ctx, sea, 0.3, waves, e, ed, edd, 1.0, nullptr));
  Mat12 de, dv, da;
  const double h = 1e-6;
  for (int i = 0; i < 12; ++i) {
    Vec12 p1 = e, m1 = e;
    p1(i) += h;
    m1(i) -= h;
    de.col(i) = (ElementLoadResidual(el, ctx, sea, 0.3, waves, p1, ed, edd, 1.0, nullptr) -
                 ElementLoadResidual(el, ctx, sea, 0.3, waves, m1, ed, edd, 1.0, nullptr)) /
                (2 * h);
    p1 = ed, m1 = ed;
    p1(i) += h;
    m1(i) -= h;
    dv.col(i) = (ElementLoadResidual(el, ctx, sea, 0.3, waves, e, p1, edd, 1.0, nullptr) -
                 ElementLoadResidual(el, ctx, sea, 0.3, waves, e, m1, edd, 1.0, nullptr)) /
                (2 * h);
    p1 = edd, m1 = edd;
    p1(i) += h;
    m1(i) -= h;
    da.col(i) = (ElementLoadResidual(el, ctx, sea, 0.3, waves, e, ed, p1, 1.0, nullptr) -
                 ElementLoadResidual(el, ctx, sea, 0.3, waves, e, ed, m1, 1.0, nullptr)) /
                (2 * h);
  }
  constexpr double kJacRelTol = 1e-6;
  EXPECT_LT((jac.d_de - de).norm(), kJacRelTol * de.norm());
  EXPECT_LT((jac.d_dedot - dv).norm(), kJacRelTol * dv.norm());
  EXPECT_LT((jac.added_mass - da).norm(), kJacRelTol * da.norm());
  EXPECT_TRUE(r0.allFinite());
}

TEST(CableLoads, JacobiansMatchFiniteDifferences) {
  Environment env;
  env.current = CurrentField::Uniform(Eigen::Vector3d(0.3, -0.2, 0.0));
  CheckLoadJacobians(env, nullptr);
}

// in a sea, each effect alone and all together: a sheared current (dU/dz enters dR/de), waves
// held at the nodes (Morison's fluid inertia turns with the tangent) and a sloping seabed the
// element lies on (penalty, damping, friction: seabed_contact.h)
Environment ShearedCurrent() {
  Environment env;
  env.current = CurrentField::Profile(
      {{-1.0, Eigen::Vector3d(0.5, 0.1, 0.0)}, {2.0, Eigen::Vector3d(0.1, -0.3, 0.02)}});
  return env;
}

ElementWaves SomeWaves() {
  ElementWaves w;
  for (int i = 0; i < 12; ++i) {
    w.velocity(i) = 0.3 * std::sin(0.9 * i + 0.2);
    w.acceleration(i) = 0.25 * std::cos(1.7 * i);
  }
  return w;
}

Environment OnASlopingSeabed(Environment env) {
  env.seabed = Seabed::Plane(0.1, 0.05, 0.3);
  SeabedContact c;
  c.stiffness = 2.0e4;
  c.damping = 300.0;
  c.friction = 0.6;
  env.seabed.set_contact(c);
  return env;
}

// a line type: constant drag coefficients and a tangential added mass
TEST(CableLoads, JacobiansMatchFiniteDifferencesWithALineType) {
  const CableDragLaw law{CableDragLaw::kConstant, 1.5, 0.01};
  Environment env;
  env.current = CurrentField::Uniform(Eigen::Vector3d(0.3, -0.2, 0.0));
  CheckLoadJacobians(env, nullptr, law, 0.4);
  Environment sea;
  sea.waves = WaveField::Regular(1.0, 5.0, 0.0, 0.0, 50.0, sea.gravity, sea.water_density);
  const ElementWaves w = SomeWaves();
  CheckLoadJacobians(sea, &w, law, 0.4);
}

TEST(CableLoads, JacobiansMatchFiniteDifferencesInAShearedCurrent) {
  CheckLoadJacobians(ShearedCurrent(), nullptr);
}

TEST(CableLoads, JacobiansMatchFiniteDifferencesInWaves) {
  Environment env;
  env.waves = WaveField::Regular(1.0, 5.0, 0.0, 0.0, 50.0, env.gravity, env.water_density);
  const ElementWaves w = SomeWaves();
  CheckLoadJacobians(env, &w);
}

TEST(CableLoads, JacobiansMatchFiniteDifferencesOnTheSeabed) {
  CheckLoadJacobians(OnASlopingSeabed(Environment()), nullptr);
}

// friction across the cable larger than along it: the split turns with the tangent
TEST(CableLoads, JacobiansMatchFiniteDifferencesOnTheSeabedWithLateralFriction) {
  Environment env = OnASlopingSeabed(Environment());
  SeabedContact c = env.seabed.contact();
  c.friction_lateral = 1.1;
  env.seabed.set_contact(c);
  CheckLoadJacobians(env, nullptr);
}

TEST(CableLoads, JacobiansMatchFiniteDifferencesInASea) {
  Environment env = OnASlopingSeabed(ShearedCurrent());
  env.waves = WaveField::Regular(1.0, 5.0, 0.0, 0.0, 50.0, env.gravity, env.water_density);
  const ElementWaves w = SomeWaves();
  CheckLoadJacobians(env, &w);
}

// An element whose control polygon (ancf_element.h, DeepestBound) is above the shallowest bed
// looks for no contact (ClearOfSeabed): its residual and Jacobians are those of the full test
// to the bit, without r at the Gauss points; an element whose ends are above the bed but
// whose middle sags into it is not skipped
TEST(CableLoads, AnElementClearOfTheSeabedLooksForNoContact) {
  Environment env;
  env.seabed = Seabed::Flat(20.0);
  const EnvironmentField sea(env);
  ElementProperties p;
  p.length = 10.0;
  const AncfElement el(p);
  const CableLoadContext ctx = PaperCableLoads();
  Vec12 ed, edd;
  SomeRates(&ed, &edd);
  // 3 m above the bed at its deepest control point, r_1 - l/3 r'_1: 16 + 10/3 0.3 = 17 m
  Vec12 above;
  above << 0.0, 0.0, 15.0, 0.98, 0.0, 0.2, 9.8, 0.0, 16.0, 0.98, 0.0, -0.3;
  ASSERT_NEAR(DeepestBound(above, 10.0), 17.0, 1e-12);
  EXPECT_TRUE(ClearOfSeabed(sea, above, 10.0));
  for (const bool with_jacobians : {false, true}) {
    GaussFields all, fewer;
    el.InterpolateFields(above, ed, edd, LoadFields(ctx, sea, true), &all);
    el.InterpolateFields(above, ed, edd, LoadFields(ctx, sea, false), &fewer);
    EXPECT_EQ(LoadFields(ctx, sea, false) & kFieldPosition, 0u);
    ElementLoadJacobians ja, jb;
    const Vec12 ra = ElementLoadResidual(el, ctx, sea, 0.0, nullptr, all, 1.0,
                                         with_jacobians ? &ja : nullptr, true);
    const Vec12 rb = ElementLoadResidual(el, ctx, sea, 0.0, nullptr, fewer, 1.0,
                                         with_jacobians ? &jb : nullptr, false);
    EXPECT_EQ(ra, rb);
    if (with_jacobians) {
      EXPECT_EQ(ja.d_de, jb.d_de);
      EXPECT_EQ(ja.d_dedot, jb.d_dedot);
      EXPECT_EQ(ja.added_mass, jb.added_mass);
    }
  }
  // ends at 19.5 m and 19.8 m, slopes down then up: the middle reaches 21.5 m, under the bed
  Vec12 sagging;
  sagging << 0.0, 0.0, 19.5, 0.9, 0.0, 0.5, 9.8, 0.0, 19.8, 0.9, 0.0, -0.5;
  EXPECT_GT(Interpolate(EvaluateShape(0.5, 10.0).n, sagging).z(), 20.0);
  EXPECT_FALSE(ClearOfSeabed(sea, sagging, 10.0));
  Environment no_bed;
  const EnvironmentField calm(no_bed);
  EXPECT_FALSE(ClearOfSeabed(calm, sagging, 10.0));  // nothing to be clear of
  const Vec12 on_bed =
      ElementLoadResidual(el, ctx, sea, 0.0, nullptr, sagging, ed, edd, 1.0, nullptr);
  const Vec12 free =
      ElementLoadResidual(el, ctx, calm, 0.0, nullptr, sagging, ed, edd, 1.0, nullptr);
  EXPECT_GT((on_bed - free).norm(), 1.0);  // the contact load is there [N]
}

}  // namespace
}  // namespace towsim::core
