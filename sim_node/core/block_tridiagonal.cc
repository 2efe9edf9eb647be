#include "core/block_tridiagonal.h"

#include <algorithm>
#include <cmath>

namespace towsim::core {

BlockTridiagonal::BlockTridiagonal(const std::vector<int>& block_sizes, int max_first)
    : base_sizes_(block_sizes), sizes_(block_sizes), max_first_(max_first) {
  const int n = num_blocks();
  // the largest size each block can take: the head's for the blocks that may become first
  std::vector<int> cap(block_sizes);
  for (int i = 1; i <= max_first_ && i < n; ++i) cap[i] = std::max(cap[i], block_sizes[0]);
  offsets_.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    diag_.emplace_back(Eigen::VectorXd::Zero(cap[i] * cap[i]));
    lu_.emplace_back(base_sizes_[i]);
    lu6_.emplace_back();
    tmp_.emplace_back(Eigen::VectorXd::Zero(cap[i]));
  }
  if (max_first_ > 0) lu_head_ = Eigen::PartialPivLU<Eigen::MatrixXd>(base_sizes_[0]);
  for (int i = 0; i + 1 < n; ++i) {
    upper_.emplace_back(Eigen::VectorXd::Zero(cap[i] * cap[i + 1]));
    lower_.emplace_back(Eigen::VectorXd::Zero(cap[i] * cap[i + 1]));
    x_.emplace_back(Eigen::VectorXd::Zero(cap[i] * cap[i + 1]));
  }
  SetFirstBlock(0);
}

void BlockTridiagonal::SetFirstBlock(int first) {
  first_ = first;
  const int n = num_blocks();
  for (int i = 0; i < n; ++i) {
    sizes_[i] = i < first ? 0 : base_sizes_[i];
  }
  if (first > 0) sizes_[first] = base_sizes_[0];
  size_ = 0;
  for (int i = 0; i < n; ++i) {
    offsets_[i] = size_;
    size_ += sizes_[i];
  }
}

void BlockTridiagonal::SetZero() {
  for (int i = first_; i < num_blocks(); ++i) {
    diag(i).setZero();
    if (i + 1 < num_blocks()) {
      upper(i).setZero();
      lower(i).setZero();
    }
  }
}

bool BlockTridiagonal::Solve(Eigen::VectorXd* b) { return Factor() && SolveFactored(b); }

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using ConstMap6 = Eigen::Map<const Mat6>;

}  // namespace

bool BlockTridiagonal::Factor() {
  const int n = num_blocks();
  for (int i = first_; i < n; ++i) {
    Map d = diag(i);
    // D^_i = D_i - L_{i-1} X_{i-1} (fixed size between two 6 x 6 blocks)
    if (i > first_) {
      if (sizes_[i] == 6 && sizes_[i - 1] == 6)
        Eigen::Map<Mat6>(d.data()).noalias() -=
            ConstMap6(lower_[i - 1].data()) * ConstMap6(x_[i - 1].data());
      else
        d.noalias() -= lower(i - 1) * x(i - 1);
    }
    double det;
    if (sizes_[i] == 6) {
      lu6_[i].compute(Eigen::Map<const Eigen::Matrix<double, 6, 6>>(d.data()));
      det = lu6_[i].matrixLU().diagonal().cwiseAbs().minCoeff();
    } else {
      lu(i).compute(d);
      det = lu(i).matrixLU().diagonal().cwiseAbs().minCoeff();
    }
    // a zero or non-finite pivot shows in the determinant of the triangular factor
    if (!(det > 0.0) || !std::isfinite(det)) return false;
    if (i + 1 < n) {
      // X_i = D^_i^-1 U_i
      Map xi = x(i);
      if (sizes_[i] == 6 && sizes_[i + 1] == 6)
        Eigen::Map<Mat6>(x_[i].data()) = lu6_[i].solve(ConstMap6(upper_[i].data()));
      else if (sizes_[i] == 6)
        xi = lu6_[i].solve(upper(i));
      else
        xi = lu(i).solve(upper(i));
    }
  }
  return true;
}

namespace {

// y -= A x (A rows(y) x rows(x)), fixed size when both are 6
void SubtractProduct(const BlockTridiagonal::Map& a, const Eigen::Map<Eigen::VectorXd>& x,
                     Eigen::Ref<Eigen::VectorXd> y) {
  if (a.rows() == 6 && a.cols() == 6) {
    Eigen::Map<Vec6>(y.data()).noalias() -= ConstMap6(a.data()) * Eigen::Map<const Vec6>(x.data());
  } else {
    y.noalias() -= a * x;
  }
}

}  // namespace

bool BlockTridiagonal::SolveFactored(Eigen::VectorXd* b, int at) {
  const int n = num_blocks();
  for (int i = first_; i < n; ++i) {
    // y_i = b_i - L_{i-1} z_{i-1};  z_i = D^_i^-1 y_i
    auto bi = b->segment(at + offsets_[i], sizes_[i]);
    if (i > first_) SubtractProduct(lower(i - 1), tmp(i - 1), bi);
    if (sizes_[i] == 6)
      Eigen::Map<Vec6>(tmp_[i].data()) = lu6_[i].solve(Eigen::Map<const Vec6>(bi.data()));
    else
      tmp(i) = lu(i).solve(bi);
  }
  // back substitution: x_i = z_i - X_i x_{i+1}
  b->segment(at + offsets_[n - 1], sizes_[n - 1]) = tmp(n - 1);
  for (int i = n - 2; i >= first_; --i) {
    const auto next = b->segment(at + offsets_[i + 1], sizes_[i + 1]);
    if (sizes_[i] == 6 && sizes_[i + 1] == 6)
      Eigen::Map<Vec6>(tmp_[i].data()).noalias() -=
          ConstMap6(x_[i].data()) * Eigen::Map<const Vec6>(next.data());
    else
      tmp(i).noalias() -= x(i) * next;
    b->segment(at + offsets_[i], sizes_[i]) = tmp(i);
  }
  return std::isfinite(b->segment(at, size_).squaredNorm());
}

}  // namespace towsim::core
