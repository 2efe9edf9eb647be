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

bool BlockTridiagonal::Solve(Eigen::VectorXd* b) {
  const int n = num_blocks();
  for (int i = 0; i < n; ++i) {
    auto bi = b->segment(offsets_[i], sizes_[i]);
    if (i > 0) {
      // D^_i = D_i - L_{i-1} X_{i-1};  y_i = b_i - L_{i-1} z_{i-1}
      diag_[i].noalias() -= lower_[i - 1] * x_[i - 1];
      bi.noalias() -= lower_[i - 1] * tmp_[i - 1];
    }
    lu_[i].compute(diag_[i]);
    // a zero or non-finite pivot shows in the determinant of the triangular factor
    const double det = lu_[i].matrixLU().diagonal().cwiseAbs().minCoeff();
    if (!(det > 0.0) || !std::isfinite(det)) return false;
    tmp_[i] = lu_[i].solve(bi);  // z_i = D^_i^-1 y_i
    if (i + 1 < n) x_[i] = lu_[i].solve(upper_[i]);
  }
  // back substitution: x_i = z_i - X_i x_{i+1}
  b->segment(offsets_[n - 1], sizes_[n - 1]) = tmp_[n - 1];
  for (int i = n - 2; i >= 0; --i) {
    tmp_[i].noalias() -= x_[i] * b->segment(offsets_[i + 1], sizes_[i + 1]);
    b->segment(offsets_[i], sizes_[i]) = tmp_[i];
  }
  return std::isfinite(b->squaredNorm());
}

}  // namespace towsim::core
