// Self-checks of the elastic catenary reference (elastic_catenary.h).

#include "elastic_catenary.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace towsim::reference {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// the solver converges Irvine's equations to 1e-13 of the chord; 1e-9 relative leaves room
// for the conditioning of asinh / sqrt at the values used here
constexpr double kSolverRelTol = 1e-9;

// hand-checked inextensible catenary: a = H / w = 100 m over a 100 m level span, so
// L = 2 a sinh(0.5) = 104.219061 m, sag = a (cosh 0.5 - 1) = 12.762597 m,
// end tension = w a cosh(0.5) = 112.762597 w
TEST(ElasticCatenary, HandCheckedInextensibleLevelSpan) {
  const double a = 100.0;
  const double w = 2.0;
  CatenaryProblem p;
  p.length = 2.0 * a * std::sinh(0.5);
  p.span = 100.0;
  p.height = 0.0;
  p.weight = w;
  p.ea = kInf;
  EXPECT_NEAR(p.length, 104.219061, 1e-6);  // the hand value, 7 digits
  const CatenarySolution s = SolveElasticCatenary(p);
  EXPECT_NEAR(s.horizontal_tension, w * a, kSolverRelTol * w * a);
  EXPECT_NEAR(s.vertical_force_a, 0.5 * w * p.length, kSolverRelTol * w * a);
  EXPECT_NEAR(s.sag_mid_span, 12.762597, 1e-6);
  EXPECT_NEAR(s.tension_a, 112.762597 * w, 1e-6 * w);
  EXPECT_NEAR(s.tension_b, s.tension_a, kSolverRelTol * s.tension_a);
}

// EA -> inf reduces to the inextensible catenary, also with unequal heights; the elastic
// correction to H is O(T / EA)
TEST(ElasticCatenary, StiffLimitIsInextensibleCatenary) {
  CatenaryProblem p;
  p.length = 200.0;
  p.span = 150.0;
  p.height = 30.0;
  p.weight = 3.5;
  p.ea = kInf;
  const CatenarySolution rigid = SolveElasticCatenary(p);
  const double a = InextensibleCatenaryParameter(p.length, p.span, p.height);
  EXPECT_NEAR(rigid.horizontal_tension, p.weight * a, kSolverRelTol * p.weight * a);
  double previous_error = kInf;
  for (double ea : {1e6, 1e8, 1e10, 1e12}) {
    p.ea = ea;
    const CatenarySolution s = SolveElasticCatenary(p);
    const double error = std::abs(s.horizontal_tension / rigid.horizontal_tension - 1.0);
    // the relative change scales like T / EA: bound it by 10 T / EA, and it must shrink
    EXPECT_LT(error, 10.0 * rigid.tension_b / ea) << "EA = " << ea;
    EXPECT_LT(error, previous_error);
    previous_error = error;
  }
}

// the closed form against an independent RK4 quadrature of the shape equations
//   dx/ds = (1 + T/EA) H / T,   dy/ds = (1 + T/EA) (w s - V) / T
// for a strongly elastic cable with unequal heights; also V_A + V_B = w L
TEST(ElasticCatenary, ClosedFormMatchesQuadrature) {
  CatenaryProblem p;
  p.length = 120.0;
  p.span = 100.0;
  p.height = -25.0;  // B below A
  p.weight = 40.0;
  p.ea = 5.0e4;  // strains of several percent
  const CatenarySolution s = SolveElasticCatenary(p);
  const double h = s.horizontal_tension;
  const double v = s.vertical_force_a;
  EXPECT_NEAR(s.vertical_force_a + s.vertical_force_b, p.weight * p.length, 1e-9 * h);
  const int n = 4000;
  const double ds = p.length / n;
  auto rhs = [&](double sv) {
    const double vs = v - p.weight * sv;
    const double t = std::hypot(h, vs);
    const double stretch = 1.0 + t / p.ea;
    return std::pair<double, double>{stretch * h / t, -stretch * vs / t};
  };
  double x = 0.0;
  double y = 0.0;
  for (int i = 0; i < n; ++i) {
    // the integrand depends on s only: Simpson on each step is RK4
    const double s0 = i * ds;
    const auto k1 = rhs(s0);
    const auto k2 = rhs(s0 + 0.5 * ds);
    const auto k3 = rhs(s0 + ds);
    x += ds / 6.0 * (k1.first + 4.0 * k2.first + k3.first);
    y += ds / 6.0 * (k1.second + 4.0 * k2.second + k3.second);
  }
  // Simpson error ~ L ds^4 f'''' ~ 1e-10 m here
  constexpr double kQuadratureTol = 1e-8;  // [m]
  EXPECT_NEAR(x, p.span, kQuadratureTol);
  EXPECT_NEAR(y, p.height, kQuadratureTol);
  // the stretched length exceeds L by about T_mean L / EA
  EXPECT_GT(s.tension_a, s.tension_b);  // A is the higher support
}

// small-sag limit: a taut, nearly flat cable has sag ~ w l^2 / (8 H) (parabola)
TEST(ElasticCatenary, ShallowCableIsParabola) {
  CatenaryProblem p;
  p.length = 100.05;
  p.span = 100.0;
  p.height = 0.0;
  p.weight = 1.0;
  p.ea = 1.0e7;
  const CatenarySolution s = SolveElasticCatenary(p);
  const double parabola = p.weight * p.span * p.span / (8.0 * s.horizontal_tension);
  // the catenary/parabola difference is O((sag / span)^2) ~ 2e-4 relative here
  constexpr double kParabolaRelTol = 1e-3;
  EXPECT_NEAR(s.sag_mid_span, parabola, kParabolaRelTol * parabola);
}

// a cable shorter than the span is stretched: with negligible weight H -> EA (l / L - 1)
TEST(ElasticCatenary, PreStretchedNearlyWeightless) {
  CatenaryProblem p;
  p.length = 10.0;
  p.span = 10.1;
  p.height = 0.0;
  p.weight = 1e-6;
  p.ea = 1.0e5;
  const CatenarySolution s = SolveElasticCatenary(p);
  const double expected = p.ea * (p.span / p.length - 1.0);
  EXPECT_NEAR(s.horizontal_tension, expected, 1e-6 * expected);
}

}  // namespace
}  // namespace towsim::reference
