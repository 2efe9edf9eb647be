#pragma once
// Block-tridiagonal linear system A x = b, solved by block LU (block Thomas algorithm):
//   D^_0 = D_0,  D^_i = D_i - L_{i-1} D^_{i-1}^-1 U_{i-1},
// forward y_i = b_i - L_{i-1} D^_{i-1}^-1 y_{i-1}, back x_i = D^_i^-1 (y_i - U_i x_{i+1}).
// The cable couples node i only to nodes i-1 and i+1, so its Newton matrix has this shape;
// end blocks are larger when they carry a joint (multipliers and the attached body).
// Diagonal blocks are factored with partial pivoting, so the saddle-point (KKT) end blocks are
// fine. Cost O(n s^3) to factor, O(n s^2) per solve with the stored factors (the integrator
// reuses them across Newton iterations and steps: modified Newton). Storage preallocated at
// construction; Factor() and Solve() do not allocate.
//
// The cable's 6 x 6 pivot blocks are factored with fixed-size LUs (several times cheaper than
// the dynamic ones). Not explicit inverses: the axial and bending stiffnesses of a node differ
// by up to 1e8, and the inverse's larger error in the increments fooled the increment-based
// Newton test into accepting unconverged states (40 elements, h = 0.2 s).
//
// A cable whose length changes (the winch, docs/winch.md) keeps its unused nodes parked at the
// start of the preallocated arrays: SetFirstBlock(f) leaves blocks 0..f-1 out of the system
// and gives block f the size of the head block 0 (the start end's multipliers and body sit
// with the first node in use). Blocks 0..max_first are allocated for either size, so
// SetFirstBlock does not allocate either.

#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

namespace towsim::core {

class BlockTridiagonal {
 public:
  using Map = Eigen::Map<Eigen::MatrixXd>;

  BlockTridiagonal() = default;
  // block_sizes: the sizes with the first block in use at 0; blocks 0..max_first may become
  // the first block (SetFirstBlock)
  explicit BlockTridiagonal(const std::vector<int>& block_sizes, int max_first = 0);

  int num_blocks() const { return static_cast<int>(sizes_.size()); }
  int block_size(int i) const { return sizes_[i]; }      // 0 for a block left out
  int block_offset(int i) const { return offsets_[i]; }  // in the vector of the blocks in use
  int size() const { return size_; }
  int first_block() const { return first_; }
  // blocks before `first` (<= max_first) are left out; block `first` takes the head's size
  void SetFirstBlock(int first);

  void SetZero();
  Map diag(int i) { return Map(diag_[i].data(), sizes_[i], sizes_[i]); }  // D_i (s_i x s_i)
  Map upper(int i) {  // U_i (s_i x s_{i+1})
    return Map(upper_[i].data(), sizes_[i], sizes_[i + 1]);
  }
  Map lower(int i) {  // L_i (s_{i+1} x s_i)
    return Map(lower_[i].data(), sizes_[i + 1], sizes_[i]);
  }

  // factor and solve in place: x overwrites b (size() x 1). Returns false if a pivot block is
  // singular or non-finite. Destroys the stored matrix (Factor, then SolveFactored).
  bool Solve(Eigen::VectorXd* b);
  // LU of the stored matrix; false if a pivot block is singular or non-finite. The factors
  // stay valid until the next Factor or Solve; the diagonal blocks are overwritten.
  bool Factor();
  // x = A^-1 b in place with the factors of the last successful Factor (false: non-finite x);
  // x and b are the size() entries of *b from `at` on (a network's cable, network_matrix.h)
  bool SolveFactored(Eigen::VectorXd* b, int at = 0);

 private:
  Map x(int i) { return Map(x_[i].data(), sizes_[i], sizes_[i + 1]); }
  Eigen::Map<Eigen::VectorXd> tmp(int i) { return {tmp_[i].data(), sizes_[i]}; }
  // the LU of a block that is not 6 x 6: its own size, or the head's when it is the first
  Eigen::PartialPivLU<Eigen::MatrixXd>& lu(int i) {
    return i == first_ && first_ > 0 ? lu_head_ : lu_[i];
  }

  std::vector<int> base_sizes_;  // the sizes with first = 0
  std::vector<int> sizes_, offsets_;
  int size_ = 0;
  int first_ = 0, max_first_ = 0;
  // storage of each block for the largest size it can take (column-major, the leading
  // sizes_[i] x sizes_[j] entries in use)
  std::vector<Eigen::VectorXd> diag_, upper_, lower_, x_;              // x_i = D^_i^-1 U_i
  std::vector<Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>>> lu6_;  // of the 6 x 6 D^_i
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXd>> lu_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_head_;  // of the first block when first > 0
  std::vector<Eigen::VectorXd> tmp_;
};

}  // namespace towsim::core
