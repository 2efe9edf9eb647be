#pragma once
// The Newton matrix of a network of cables (docs/physics.md "Networks"): one block-tridiagonal
// matrix T_c per cable (its nodes, its end multipliers and the bodies folded into its end
// blocks, block_tridiagonal.h) and the hub unknowns x_h (3 per hub: a sphere held by two or
// more cable ends), bordered:
//   [ T_0            B_0 ] [x_0]   [b_0]
//   [      T_1       B_1 ] [x_1] = [b_1]
//   [           ...  ... ] [...]   [...]
//   [ C_0  C_1  ...  H   ] [x_h]   [b_h]
// B_c holds the hub's columns of cable c's joint rows (Phi = r_end - p_hub: -I), C_c the
// multipliers' columns of the hub's rows (the hub's residual -lambda: -I), H the hubs' own
// c_a M + c_v D + c_q K. Solved by the Schur complement on the hubs:
//   W_c = T_c^-1 B_c,  S = H - sum_c C_c W_c                      (Factor)
//   y_c = T_c^-1 b_c,  S x_h = b_h - sum_c C_c y_c,  x_c = y_c - W_c x_h   (SolveFactored)
// W_c costs one solve with T_c's factors per hub column cable c touches (3 per hub joint), S
// is 3 x 3 per hub: a network costs the sum of its cables plus those few solves. A massless
// hub (a junction, H = 0) is fine: -C_c W_c is the inverse of the cable's end compliance,
// positive definite. Without hubs every cable is solved on its own, and a single cable
// executes exactly BlockTridiagonal's arithmetic. Storage preallocated at construction;
// Factor and SolveFactored do not allocate.

#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "core/block_tridiagonal.h"

namespace towsim::core {

class NetworkMatrix {
 public:
  NetworkMatrix() = default;
  // cables[c]: cable c's matrix; hub_size: the hub unknowns (3 per hub); touched[c]: the hub
  // columns (0 .. hub_size - 1) cable c's border has entries in
  NetworkMatrix(std::vector<BlockTridiagonal> cables, int hub_size,
                std::vector<std::vector<int>> touched);

  int num_cables() const { return static_cast<int>(cables_.size()); }
  BlockTridiagonal& cable(int c) { return cables_[c]; }
  const BlockTridiagonal& cable(int c) const { return cables_[c]; }
  int hub_size() const { return hub_size_; }
  // offsets in the vector of the unknowns in use: cable c's, then the hubs' (after every cable)
  int cable_offset(int c) const;
  int hub_offset() const { return cable_offset(num_cables()); }
  int size() const { return hub_offset() + hub_size_; }

  void SetZero();
  // H (hub_size x hub_size), B_c (row of cable c's unknowns in use, hub column) and C_c (hub
  // row, column of cable c's unknowns in use)
  double& hub(int i, int j) { return h_(i, j); }
  double& border_column(int c, int row, int j) { return b_[c](row, j); }
  double& border_row(int c, int i, int col) { return c_[c](i, col); }

  // LU of every T_c and of S; false if a pivot block or S is singular or non-finite
  bool Factor();
  // x = A^-1 b in place with the last Factor's factors (false: non-finite x)
  bool SolveFactored(Eigen::VectorXd* b);
  bool Solve(Eigen::VectorXd* b) { return Factor() && SolveFactored(b); }

 private:
  std::vector<BlockTridiagonal> cables_;
  int hub_size_ = 0;
  std::vector<std::vector<int>> touched_;
  // for each cable, at its largest size: B_c, C_c and W_c's touched columns (zero elsewhere)
  std::vector<Eigen::MatrixXd> b_, c_, w_;
  Eigen::MatrixXd h_, s_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_s_;
  Eigen::VectorXd column_, rhs_h_, x_h_;
};

}  // namespace towsim::core
