// Self-checks of the grounded elastic catenary reference (grounded_catenary.h).

#include "grounded_catenary.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

namespace towsim::reference {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// the solver converges the two equations to 1e-13 of the chord; 1e-9 relative leaves room for
// the finite-difference Jacobian's conditioning
constexpr double kSolverRelTol = 1e-9;

// Hand-checked inextensible line: catenary parameter a = H / w = 100 m and a suspended part
// spanning 100 m: suspended length a sinh(1) = 117.520119 m, height a (cosh 1 - 1) =
// 54.308063 m, fairlead tension w a cosh(1) = 154.308063 w. With L = 300 m the grounded
// length is 182.479881 m and the span 282.479881 m.
TEST(GroundedCatenary, HandCheckedInextensibleLine) {
  const double a = 100.0, w = 2.0;
  GroundedCatenaryProblem p;
  p.length = 300.0;
  p.span = 300.0 - a * std::sinh(1.0) + 100.0;
  p.height = a * (std::cosh(1.0) - 1.0);
  p.weight = w;
  p.ea = kInf;
  EXPECT_NEAR(p.span, 282.479881, 1e-6);
  EXPECT_NEAR(p.height, 54.308063, 1e-6);
  const GroundedCatenarySolution s = SolveGroundedCatenary(p);
  EXPECT_FALSE(s.suspended);
  EXPECT_NEAR(s.horizontal_tension, w * a, kSolverRelTol * w * a);
  EXPECT_NEAR(s.vertical_force, w * 117.520119, 1e-6 * w);
  EXPECT_NEAR(s.fairlead_tension, 154.308063 * w, 1e-6 * w);
  EXPECT_NEAR(s.grounded_length, 182.479881, 1e-6);
  EXPECT_NEAR(s.touchdown, 182.479881, 1e-6);
  EXPECT_EQ(s.anchor_tension, s.horizontal_tension);
}

// an elastic line (a chain-like mooring: 60 m water, EA = 5e7 N, w = 1000 N/m): the suspended
// part must be Irvine's elastic catenary (elastic_catenary.h, solved independently) from the
// touchdown point, leaving it horizontally (V_A = 0), to the fairlead
TEST(GroundedCatenary, SuspendedPartIsIrvinesCatenaryFromTheTouchdown) {
  GroundedCatenaryProblem p;
  p.length = 400.0;
  p.span = 370.0;
  p.height = 55.0;
  p.weight = 1000.0;
  p.ea = 5e7;
  const GroundedCatenarySolution s = SolveGroundedCatenary(p);
  ASSERT_FALSE(s.suspended);
  ASSERT_GT(s.grounded_length, 10.0);
  CatenaryProblem free;
  free.length = p.length - s.grounded_length;
  free.span = p.span - s.touchdown;
  free.height = p.height;
  free.weight = p.weight;
  free.ea = p.ea;
  const CatenarySolution c = SolveElasticCatenary(free);
  EXPECT_NEAR(c.horizontal_tension, s.horizontal_tension, 1e-7 * s.horizontal_tension);
  EXPECT_NEAR(c.vertical_force_a, 0.0, 1e-7 * s.horizontal_tension);
  EXPECT_NEAR(c.tension_b, s.fairlead_tension, 1e-7 * s.fairlead_tension);
  // the shape ends at the fairlead and is continuous at the touchdown
  const GroundedCatenaryPoint end = GroundedCatenaryShape(p, s, p.length);
  EXPECT_NEAR(end.x, p.span, 1e-9 * p.span);
  EXPECT_NEAR(end.y, p.height, 1e-9 * p.span);
  EXPECT_NEAR(end.tension, s.fairlead_tension, 1e-9 * s.fairlead_tension);
  const GroundedCatenaryPoint below = GroundedCatenaryShape(p, s, s.grounded_length - 1e-9);
  const GroundedCatenaryPoint above = GroundedCatenaryShape(p, s, s.grounded_length + 1e-9);
  EXPECT_NEAR(below.x, above.x, 1e-8);
  EXPECT_NEAR(above.y, 0.0, 1e-8);
  std::printf(
      "grounded catenary L = 400 m, span 370 m, height 55 m, w = 1000 N/m, EA = 5e7 N: "
      "H = %.4f N, V_F = %.4f N, grounded %.4f m, touchdown %.4f m\n",
      s.horizontal_tension, s.vertical_force, s.grounded_length, s.touchdown);
}

// no grounded length: where the free catenary from the anchor leaves it horizontally
// (V_A = 0) the two references meet; farther away the line lifts off (suspended), nearer it
// grounds, and H is continuous across the boundary
TEST(GroundedCatenary, NoGroundedLengthReducesToTheElasticCatenary) {
  const double w = 500.0, ea = 2e7, length = 250.0, h = 80000.0;
  // Irvine's catenary with V_A = 0 at the anchor: its far end gives the boundary span, height
  CatenaryProblem c;
  c.length = length;
  c.weight = w;
  c.ea = ea;
  const CatenaryPoint end = CatenaryShape(c, h, 0.0, length);
  GroundedCatenaryProblem p;
  p.length = length;
  p.height = end.y;
  p.weight = w;
  p.ea = ea;
  p.span = end.x;
  const GroundedCatenarySolution at = SolveGroundedCatenary(p);
  EXPECT_NEAR(at.horizontal_tension, h, 1e-7 * h);
  EXPECT_LT(at.grounded_length, 1e-5 * length);
  p.span = end.x + 0.5;
  const GroundedCatenarySolution lifted = SolveGroundedCatenary(p);
  EXPECT_TRUE(lifted.suspended);
  EXPECT_EQ(lifted.grounded_length, 0.0);
  EXPECT_GT(lifted.horizontal_tension, h);
  EXPECT_GT(lifted.anchor_tension, lifted.horizontal_tension);  // the anchor pulls down too
  p.span = end.x - 0.5;
  const GroundedCatenarySolution grounded = SolveGroundedCatenary(p);
  EXPECT_FALSE(grounded.suspended);
  EXPECT_GT(grounded.grounded_length, 0.0);
  EXPECT_LT(grounded.horizontal_tension, h);
  // and a 1 m change of span changes H by a few percent at most: continuous
  EXPECT_LT((lifted.horizontal_tension - grounded.horizontal_tension) / h, 0.1);
}

}  // namespace
}  // namespace towsim::reference
