#pragma once
// The coupled cable-sphere system: DOF layout, residual, constraints (paper Eq. 24-26) and the
// Newton matrix in block-tridiagonal form.
//
// Equations of motion with the joint multipliers lambda (Eq. 26, at position level):
//   R(q, v, a, lambda) = M_eff(q) a + F_int(q, v) - Q_ext(q, v) + Phi_q^T lambda = 0   (n x 1)
//   Phi(q, t) = 0                                                                    (m x 1)
// M_eff = cable mass (Eq. 7) + normal added mass (Eq. 23) + sphere masses. The constraints
// hold a cable end's position to a fixed point, a driven point, a sphere point or a vehicle
// point (Eq. 24) and, for a clamped end, its direction. With Phi = r_end - p_support, lambda
// is the force the cable exerts on its support (on a body: the interaction force of
// Eq. 29-30).
//
// A vehicle support that answers the joint force (SupportMotion::compliance, the strong
// coupling of vehicle_coupling.h) adds -C (lambda - lambda1) to its Phi and -C to the
// multiplier block of the Newton matrix.
//
// Block ordering for the linear solve: [start sphere | start multipliers | node 0], node 1, ...,
// node N-1, [node N | end multipliers | end sphere], then one block per unattached sphere.
//
// With a winch (docs/winch.md) the cable's arrays are preallocated for the most nodes a run
// can have (max_nodes()); the nodes not in use are parked at the start of the arrays, so the
// node i in use (0 = the drum) sits at array node first_node() + i, and the solve runs over the
// blocks in use (BlockTridiagonal::SetFirstBlock). Every element keeps the nominal rest
// length cable.length / cable.elements except element 0 at the drum, whose rest length l_0(t)
// follows the winch (DrumMotion, state.h). With dl_0/dt != 0 element 0 carries the momentum
// of the material entering or leaving at the drum with the drum's velocity v_0 (the cable's
// momentum balance d/dt (M e_dot) = Q + m_dot v_0, m_dot = rho_c A dl_0/dt):
//   R_0 += dl_0/dt (dM/dl) e_dot - rho_c A dl_0/dt [v_0, 0, 0, 0]        (12 x 1)
// (added mass and the fluid carry no such term: their momentum is the water's).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/ancf_element.h"
#include "core/block_tridiagonal.h"
#include "core/cable_loads.h"
#include "core/environment_field.h"
#include "core/model.h"
#include "core/state.h"
#include "core/step_inputs.h"

namespace towsim::core {

// Newton matrix = c_a dR/da + c_q dR/dq + c_v dR/dv (with the constraint Jacobian blocks)
struct JacobianCoefficients {
  double c_q = 1.0;
  double c_v = 0.0;
  double c_a = 0.0;
};

// the point R and Phi are evaluated at: the unknowns and the time (all (n x 1) but lambda,
// (m x 1))
struct SystemPoint {
  const Eigen::VectorXd& q;
  const Eigen::VectorXd& v;
  const Eigen::VectorXd& a;
  const Eigen::VectorXd& lambda;
  double t;
};

struct EvaluateOptions {
  // scales the external loads (weight, buoyancy, drag) for the static load continuation
  double load_scale = 1.0;
  JacobianCoefficients coeffs;  // of the Newton matrix (when asked for)
};

// what Evaluate fills: R (n x 1), Phi (m x 1) and, when jac != nullptr, the Newton matrix
struct SystemResidual {
  Eigen::VectorXd* residual;
  Eigen::VectorXd* phi;
  BlockTridiagonal* jac = nullptr;
};

class System {
 public:
  explicit System(const Model& model);

  const Model& model() const { return model_; }
  int num_q() const { return num_q_; }
  int num_lambda() const { return num_lambda_; }
  // the nodes and elements in use (node 0 at the cable's start)
  int num_nodes() const { return num_nodes_; }
  int NumElements() const { return num_nodes_ - 1; }
  int num_spheres() const { return static_cast<int>(model_.spheres.size()); }
  // node i in use -> its coordinates in q (the array node first_node() + i)
  int CableDof(int node) const { return cable_offset_ + 6 * (first_node_ + node); }
  // the preallocated nodes (elements + 1 without a winch) and the array index of node 0
  int max_nodes() const { return max_nodes_; }
  int first_node() const { return first_node_; }
  // q offset of array node k (in use or parked)
  int ArrayDof(int k) const { return cable_offset_ + 6 * k; }
  // the nominal element rest length cable.length / cable.elements [m]
  double element_length() const { return element_.props().length; }
  // with a winch: `nodes` in use and the paid-out length L, so the drum element's rest length
  // is L - (nodes - 2) element_length(); rebuilds the block layout (does not allocate)
  void SetLayout(int nodes, double length);
  double drum_length() const { return drum_length_; }
  bool has_winch() const { return winch_; }
  // the element e in use with rest length l (drum element) or the shared one
  AncfElement DrumElement(double length) const;
  int SphereDof(int sphere) const { return 3 * sphere; }
  // multiplier offset and count of a cable end (0 = start, 1 = end)
  int EndLambda(int end) const { return end == 0 ? 0 : lambda_count_[0]; }
  int end_lambda_count(int end) const { return lambda_count_[end]; }
  const AncfElement& element() const { return element_; }

  // Evaluates R and Phi at x, and the Newton matrix when out.jac != nullptr: the cable
  // (AssembleCable), the spheres (AssembleSpheres) and each cable end's joint (AssembleJoint).
  // The waves come from in.waves (calm water without in.has_waves), the current is evaluated
  // here; a cable end on a vehicle follows in.supports[end], the drum element in.drum
  // (step_inputs.h).
  void Evaluate(const SystemPoint& x, const StepInputs& in, const EvaluateOptions& options,
                const SystemResidual& out) const;

  // the sea every load reads (environment_field.h)
  const EnvironmentField& sea() const { return sea_; }

  // an empty Newton matrix with this system's block structure
  BlockTridiagonal MakeMatrix() const;
  // rhs (block order) from the global residual and constraint vectors, and back
  void ToBlocks(const Eigen::VectorXd& r, const Eigen::VectorXd& phi, Eigen::VectorXd* x) const;
  void FromBlocks(const Eigen::VectorXd& x, Eigen::VectorXd* dq, Eigen::VectorXd* dlambda) const;

  // element e's 12 coordinates from q
  Vec12 ElementCoordinates(const Eigen::VectorXd& q, int e) const {
    return q.segment<12>(CableDof(e));
  }
  // world position of the support of a cable end at time t (fixed / driven / sphere point; a
  // vehicle point from `supports`, the motion the coupling scheme set for the step: the
  // vehicles are not unknowns of the cable's Newton solve, for it they are driven supports)
  Vec3 SupportPosition(int end, const Eigen::VectorXd& q, double t,
                       const SupportMotion* supports) const;

  double KineticEnergy(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  double PotentialEnergy(const Eigen::VectorXd& q) const;
  double StrainEnergy(const Eigen::VectorXd& q) const;
  double NodeTension(const Eigen::VectorXd& q, const Eigen::VectorXd& v, int node) const;
  // describes DOF i for diagnostics ("cable node 12 (x = 118.2 m)", "body towfish")
  std::string DescribeDof(int i, const Eigen::VectorXd& q) const;

 private:
  struct BlockIndex {
    int block;
    int local;
  };
  // adds a 3 x 3 block at global q indices (i, j) into the Newton matrix
  void Add3(BlockTridiagonal* jac, int i, int j, const Eigen::Matrix3d& m) const;
  void AddQL(BlockTridiagonal* jac, int qi, int li, const Eigen::Vector3d& col) const;
  // the block of each DOF and multiplier for the nodes in use (SetLayout)
  void BuildLayout();
  // the three parts of Evaluate (see there), each adding its terms into out
  void AssembleCable(const SystemPoint& x, const StepInputs& in, const EvaluateOptions& options,
                     const SystemResidual& out) const;
  void AssembleSpheres(const SystemPoint& x, const StepInputs& in, const EvaluateOptions& options,
                       const SystemResidual& out) const;
  // the joint at cable end `end` (0 = start, 1 = end)
  void AssembleJoint(int end, const SystemPoint& x, const StepInputs& in,
                     const SystemResidual& out) const;

  Model model_;
  EnvironmentField sea_;
  AncfElement element_;
  CableLoadContext loads_;
  // without drag and added mass the load on an element is its weight in water alone, the same
  // uniform load on every element with no Jacobian: a scene without those terms pays nothing
  // for them
  bool state_dependent_loads_ = false;
  Vec12 weight_load_ = Vec12::Zero();  // UniformLoad(weight_per_length, l)
  unsigned load_fields_ = 0;  // the fields the loads read at the Gauss points (LoadFields)
  int num_q_ = 0, num_lambda_ = 0, cable_offset_ = 0;
  bool winch_ = false;
  int max_nodes_ = 0, num_nodes_ = 0, first_node_ = 0;
  double drum_length_ = 0.0;  // element 0's rest length now (winch)
  std::vector<int> base_block_sizes_;  // the block sizes with first_node_ = 0
  int lambda_count_[2] = {0, 0};
  Eigen::Vector3d clamp_dirs_[2][2];  // two normals to the slope of a clamped end
  std::vector<int> block_sizes_, block_offsets_;
  std::vector<BlockIndex> q_index_, lambda_index_;
  std::vector<double> sphere_mass_eff_, sphere_drag_k_;  // m + C_a rho V, 1/2 rho C_D pi r^2
  std::vector<double> sphere_radius_;                    // r = (3 V / 4 pi)^(1/3)
};

}  // namespace towsim::core
