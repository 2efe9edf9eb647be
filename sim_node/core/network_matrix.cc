#include "core/network_matrix.h"

#include <cmath>
#include <utility>

namespace towsim::core {

NetworkMatrix::NetworkMatrix(std::vector<BlockTridiagonal> cables, int hub_size,
                             std::vector<std::vector<int>> touched)
    : cables_(std::move(cables)), hub_size_(hub_size), touched_(std::move(touched)) {
  if (hub_size_ == 0) return;
  int largest = 0;
  for (const BlockTridiagonal& t : cables_) {
    // the largest size a cable takes: all its blocks in use (first block 0)
    int n = 0;
    for (int i = 0; i < t.num_blocks(); ++i) n += t.block_size(i);
    const int used = t.size();
    n = std::max(n, used);
    b_.emplace_back(Eigen::MatrixXd::Zero(n, hub_size_));
    c_.emplace_back(Eigen::MatrixXd::Zero(hub_size_, n));
    w_.emplace_back(Eigen::MatrixXd::Zero(n, hub_size_));
    largest = std::max(largest, n);
  }
  column_.setZero(largest);
  h_.setZero(hub_size_, hub_size_);
  s_.setZero(hub_size_, hub_size_);
  lu_s_ = Eigen::PartialPivLU<Eigen::MatrixXd>(hub_size_);
  rhs_h_.setZero(hub_size_);
  x_h_.setZero(hub_size_);
}

int NetworkMatrix::cable_offset(int c) const {
  int o = 0;
  for (int k = 0; k < c; ++k) o += cables_[k].size();
  return o;
}

void NetworkMatrix::SetZero() {
  for (BlockTridiagonal& t : cables_) t.SetZero();
  if (hub_size_ == 0) return;
  h_.setZero();
  for (size_t c = 0; c < cables_.size(); ++c) {
    b_[c].setZero();
    c_[c].setZero();
  }
}

bool NetworkMatrix::Factor() {
  bool ok = true;
  for (BlockTridiagonal& t : cables_) ok = t.Factor() && ok;
  if (!ok || hub_size_ == 0) return ok;
  // S = H - sum_c C_c W_c, W_c = T_c^-1 B_c on the columns cable c touches
  s_ = h_;
  for (size_t c = 0; c < cables_.size(); ++c) {
    const int n = cables_[c].size();
    for (int j : touched_[c]) {
      column_.head(n) = b_[c].col(j).head(n);
      if (!cables_[c].SolveFactored(&column_)) return false;
      w_[c].col(j).head(n) = column_.head(n);
    }
    for (int j : touched_[c])
      s_.col(j).noalias() -= c_[c].leftCols(n) * w_[c].col(j).head(n);
  }
  if (!s_.allFinite()) return false;
  lu_s_.compute(s_);
  const Eigen::VectorXd& d = lu_s_.matrixLU().diagonal();
  for (int i = 0; i < hub_size_; ++i)
    if (!(std::abs(d(i)) > 0.0)) return false;
  return true;
}

bool NetworkMatrix::SolveFactored(Eigen::VectorXd* b) {
  bool ok = true;
  int o = 0;
  for (BlockTridiagonal& t : cables_) {  // y_c = T_c^-1 b_c
    ok = t.SolveFactored(b, o) && ok;
    o += t.size();
  }
  if (hub_size_ == 0 || !ok) return ok;
  // S x_h = b_h - sum_c C_c y_c, then x_c = y_c - W_c x_h
  rhs_h_ = b->segment(o, hub_size_);
  int oc = 0;
  for (size_t c = 0; c < cables_.size(); ++c) {
    const int n = cables_[c].size();
    if (!touched_[c].empty()) rhs_h_.noalias() -= c_[c].leftCols(n) * b->segment(oc, n);
    oc += n;
  }
  x_h_.noalias() = lu_s_.solve(rhs_h_);
  b->segment(o, hub_size_) = x_h_;
  oc = 0;
  for (size_t c = 0; c < cables_.size(); ++c) {
    const int n = cables_[c].size();
    for (int j : touched_[c]) b->segment(oc, n).noalias() -= x_h_(j) * w_[c].col(j).head(n);
    oc += n;
  }
  return x_h_.allFinite();
}

}  // namespace towsim::core
