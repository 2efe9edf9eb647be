// Self-checks of the cantilever elastica reference (elastica_cantilever.h) against the
// published table of Mattiasson (1981), "Numerical results from large deflection beam and
// frame problems analysed by means of elliptic integrals", IJNME 17, Table 1.

#include "elastica_cantilever.h"

#include <gtest/gtest.h>

namespace towsim::reference {
namespace {

// the table has 5 decimals: half a unit of the last digit
constexpr double kTableTol = 5e-6;

struct Row {
  double alpha;       // P L^2 / EI
  double deflection;  // v / L
  double shortening;  // u / L
};

TEST(CantileverElastica, MatchesMattiassonTable) {
  const Row rows[] = {
      {1.0, 0.30172, 0.05643},
      {2.0, 0.49346, 0.16064},
      {5.0, 0.71379, 0.38763},
      {10.0, 0.81061, 0.55500},
  };
  for (const Row& row : rows) {
    const ElasticaTip tip = SolveCantileverElastica(row.alpha);
    EXPECT_NEAR(tip.deflection, row.deflection, kTableTol) << "alpha = " << row.alpha;
    EXPECT_NEAR(tip.shortening, row.shortening, kTableTol) << "alpha = " << row.alpha;
  }
}

// RK4 converges at order 4: halving the steps changes the answer by far less than the table
TEST(CantileverElastica, ConvergedInSteps) {
  const ElasticaTip a = SolveCantileverElastica(5.0, 1000);
  const ElasticaTip b = SolveCantileverElastica(5.0, 2000);
  EXPECT_NEAR(a.deflection, b.deflection, 1e-10);
  EXPECT_NEAR(a.shortening, b.shortening, 1e-10);
}

// small loads: Euler-Bernoulli v/L = alpha/3 (the first nonlinear correction is O(alpha^3)),
// and the shortening is second order
TEST(CantileverElastica, SmallLoadIsLinearBeam) {
  const double alpha = 3e-3;
  const ElasticaTip tip = SolveCantileverElastica(alpha);
  const double linear = LinearCantileverDeflection(alpha);
  EXPECT_NEAR(tip.deflection, linear, 1e-5 * linear);
  // u/L = 1/2 int theta^2 = alpha^2 / 15 for theta = alpha (s - s^2/2)
  EXPECT_NEAR(tip.shortening, alpha * alpha / 15.0, 1e-3 * alpha * alpha / 15.0);
}

}  // namespace
}  // namespace towsim::reference
