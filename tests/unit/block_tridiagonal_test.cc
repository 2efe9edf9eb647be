#include "core/block_tridiagonal.h"

#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace towsim::core {
namespace {

TEST(BlockTridiagonal, SolvesLikeADenseLU) {
  // blocks of unequal sizes, including a saddle-point end block (zero diagonal entries)
  const std::vector<int> sizes = {9, 6, 6, 6, 12, 3};
  BlockTridiagonal m(sizes);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(m.size(), m.size());
  for (int i = 0; i < m.num_blocks(); ++i) {
    Eigen::MatrixXd d = Eigen::MatrixXd::NullaryExpr(sizes[i], sizes[i], [&] { return u(rng); });
    d += 10.0 * Eigen::MatrixXd::Identity(sizes[i], sizes[i]);
    if (i == 0) d.block(0, 0, 3, 3).setZero();  // multiplier rows of a KKT block
    m.diag(i) = d;
    dense.block(m.block_offset(i), m.block_offset(i), sizes[i], sizes[i]) = d;
    if (i + 1 < m.num_blocks()) {
      Eigen::MatrixXd up =
          Eigen::MatrixXd::NullaryExpr(sizes[i], sizes[i + 1], [&] { return u(rng); });
      Eigen::MatrixXd lo =
          Eigen::MatrixXd::NullaryExpr(sizes[i + 1], sizes[i], [&] { return u(rng); });
      m.upper(i) = up;
      m.lower(i) = lo;
      dense.block(m.block_offset(i), m.block_offset(i + 1), sizes[i], sizes[i + 1]) = up;
      dense.block(m.block_offset(i + 1), m.block_offset(i), sizes[i + 1], sizes[i]) = lo;
    }
  }
  Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(m.size(), [&] { return u(rng); });
  const Eigen::VectorXd expected = dense.fullPivLu().solve(b);
  ASSERT_TRUE(m.Solve(&b));
  constexpr double kSolveTol = 1e-10;  // well-conditioned system, round-off only
  EXPECT_LT((b - expected).norm(), kSolveTol * expected.norm());
}

// Factor once, solve many (the integrator's modified Newton): every right-hand side solved with
// the kept factors as a dense LU would, and the stored blocks are not needed again
TEST(BlockTridiagonal, FactorsOnceAndSolvesManyRightHandSides) {
  const std::vector<int> sizes = {9, 6, 6, 6, 6, 12};
  BlockTridiagonal m(sizes);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(m.size(), m.size());
  for (int i = 0; i < m.num_blocks(); ++i) {
    Eigen::MatrixXd d = Eigen::MatrixXd::NullaryExpr(sizes[i], sizes[i], [&] { return u(rng); });
    d += 8.0 * Eigen::MatrixXd::Identity(sizes[i], sizes[i]);
    if (i == 0) d.block(0, 0, 3, 3).setZero();  // multiplier rows of a KKT block
    m.diag(i) = d;
    dense.block(m.block_offset(i), m.block_offset(i), sizes[i], sizes[i]) = d;
    if (i + 1 < m.num_blocks()) {
      const Eigen::MatrixXd up =
          Eigen::MatrixXd::NullaryExpr(sizes[i], sizes[i + 1], [&] { return u(rng); });
      const Eigen::MatrixXd lo =
          Eigen::MatrixXd::NullaryExpr(sizes[i + 1], sizes[i], [&] { return u(rng); });
      m.upper(i) = up;
      m.lower(i) = lo;
      dense.block(m.block_offset(i), m.block_offset(i + 1), sizes[i], sizes[i + 1]) = up;
      dense.block(m.block_offset(i + 1), m.block_offset(i), sizes[i + 1], sizes[i]) = lo;
    }
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(dense);
  ASSERT_TRUE(m.Factor());
  constexpr double kSolveTol = 1e-10;  // well-conditioned system, round-off only
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd b = Eigen::VectorXd::NullaryExpr(m.size(), [&] { return u(rng); });
    const Eigen::VectorXd expected = lu.solve(b);
    ASSERT_TRUE(m.SolveFactored(&b));
    EXPECT_LT((b - expected).norm(), kSolveTol * expected.norm()) << "right-hand side " << k;
  }
}

TEST(BlockTridiagonal, ReportsASingularBlock) {
  BlockTridiagonal m({3, 3});
  m.SetZero();
  Eigen::VectorXd b = Eigen::VectorXd::Ones(6);
  EXPECT_FALSE(m.Solve(&b));
}

}  // namespace
}  // namespace towsim::core
