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

#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

namespace towsim::core {

class BlockTridiagonal {
 public:
  BlockTridiagonal() = default;
  explicit BlockTridiagonal(const std::vector<int>& block_sizes);

  int num_blocks() const { return static_cast<int>(sizes_.size()); }
  int block_size(int i) const { return sizes_[i]; }
  int block_offset(int i) const { return offsets_[i]; }
  int size() const { return size_; }

  void SetZero();
  Eigen::MatrixXd& diag(int i) { return diag_[i]; }    // D_i (s_i x s_i)
  Eigen::MatrixXd& upper(int i) { return upper_[i]; }  // U_i (s_i x s_{i+1})
  Eigen::MatrixXd& lower(int i) { return lower_[i]; }  // L_i (s_{i+1} x s_i)

  // factor and solve in place: x overwrites b (size() x 1). Returns false if a pivot block is
  // singular or non-finite. Destroys the stored matrix (Factor, then SolveFactored).
  bool Solve(Eigen::VectorXd* b);
  // LU of the stored matrix; false if a pivot block is singular or non-finite. The factors
  // stay valid until the next Factor or Solve; the diagonal blocks are overwritten.
  bool Factor();
  // x = A^-1 b in place with the factors of the last successful Factor (false: non-finite x)
  bool SolveFactored(Eigen::VectorXd* b);

 private:
  std::vector<int> sizes_, offsets_;
  int size_ = 0;
  std::vector<Eigen::MatrixXd> diag_, upper_, lower_, x_;              // x_i = D^_i^-1 U_i
  std::vector<Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>>> lu6_;  // of the 6 x 6 D^_i
  std::vector<Eigen::PartialPivLU<Eigen::MatrixXd>> lu_;
  std::vector<Eigen::VectorXd> tmp_;
};

}  // namespace towsim::core
