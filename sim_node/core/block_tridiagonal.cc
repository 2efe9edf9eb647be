#include "core/block_tridiagonal.h"

#include <cmath>

namespace towsim::core {

BlockTridiagonal::BlockTridiagonal(const std::vector<int>& block_sizes) : sizes_(block_sizes) {
  const int n = num_blocks();
  offsets_.resize(n);
  for (int i = 0; i < n; ++i) {
    offsets_[i] = size_;
    size_ += sizes_[i];
    diag_.emplace_back(Eigen::MatrixXd::Zero(sizes_[i], sizes_[i]));
    lu_.emplace_back(sizes_[i]);
    lu6_.emplace_back();
    tmp_.emplace_back(Eigen::VectorXd::Zero(sizes_[i]));
  }
  for (int i = 0; i + 1 < n; ++i) {
    upper_.emplace_back(Eigen::MatrixXd::Zero(sizes_[i], sizes_[i + 1]));
    lower_.emplace_back(Eigen::MatrixXd::Zero(sizes_[i + 1], sizes_[i]));
    x_.emplace_back(Eigen::MatrixXd::Zero(sizes_[i], sizes_[i + 1]));
  }
}

void BlockTridiagonal::SetZero() {
  for (auto& m : diag_) m.setZero();
  for (auto& m : upper_) m.setZero();
  for (auto& m : lower_) m.setZero();
}

bool BlockTridiagonal::Solve(Eigen::VectorXd* b) { return Factor() && SolveFactored(b); }

bool BlockTridiagonal::Factor() {
  const int n = num_blocks();
  for (int i = 0; i < n; ++i) {
    // D^_i = D_i - L_{i-1} X_{i-1}
    if (i > 0) diag_[i].noalias() -= lower_[i - 1] * x_[i - 1];
    double det;
    if (sizes_[i] == 6) {
      lu6_[i].compute(Eigen::Map<const Eigen::Matrix<double, 6, 6>>(diag_[i].data()));
      det = lu6_[i].matrixLU().diagonal().cwiseAbs().minCoeff();
    } else {
      lu_[i].compute(diag_[i]);
      det = lu_[i].matrixLU().diagonal().cwiseAbs().minCoeff();
    }
    // a zero or non-finite pivot shows in the determinant of the triangular factor
    if (!(det > 0.0) || !std::isfinite(det)) return false;
    if (i + 1 < n) {
      // X_i = D^_i^-1 U_i
      if (sizes_[i] == 6)
        x_[i] = lu6_[i].solve(upper_[i]);
      else
        x_[i] = lu_[i].solve(upper_[i]);
    }
  }
  return true;
}

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using ConstMap6 = Eigen::Map<const Mat6>;

// y -= A x (A rows(y) x rows(x)), fixed size when both are 6
void SubtractProduct(const Eigen::MatrixXd& a, const Eigen::VectorXd& x,
                     Eigen::Ref<Eigen::VectorXd> y) {
  if (a.rows() == 6 && a.cols() == 6) {
    Eigen::Map<Vec6>(y.data()).noalias() -= ConstMap6(a.data()) * Eigen::Map<const Vec6>(x.data());
  } else {
    y.noalias() -= a * x;
  }
}

}  // namespace

bool BlockTridiagonal::SolveFactored(Eigen::VectorXd* b) {
  const int n = num_blocks();
  for (int i = 0; i < n; ++i) {
    // y_i = b_i - L_{i-1} z_{i-1};  z_i = D^_i^-1 y_i
    auto bi = b->segment(offsets_[i], sizes_[i]);
    if (i > 0) SubtractProduct(lower_[i - 1], tmp_[i - 1], bi);
    if (sizes_[i] == 6)
      Eigen::Map<Vec6>(tmp_[i].data()) = lu6_[i].solve(Eigen::Map<const Vec6>(bi.data()));
    else
      tmp_[i] = lu_[i].solve(bi);
  }
  // back substitution: x_i = z_i - X_i x_{i+1}
  b->segment(offsets_[n - 1], sizes_[n - 1]) = tmp_[n - 1];
  for (int i = n - 2; i >= 0; --i) {
    const auto next = b->segment(offsets_[i + 1], sizes_[i + 1]);
    if (x_[i].rows() == 6 && x_[i].cols() == 6)
      Eigen::Map<Vec6>(tmp_[i].data()).noalias() -=
          ConstMap6(x_[i].data()) * Eigen::Map<const Vec6>(next.data());
    else
      tmp_[i].noalias() -= x_[i] * next;
    b->segment(offsets_[i], sizes_[i]) = tmp_[i];
  }
  return std::isfinite(b->squaredNorm());
}

}  // namespace towsim::core
