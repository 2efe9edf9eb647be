#pragma once
// The coupled cable-sphere system, one cable or a network of them: DOF layout, residual, constraints (paper Eq. 24-26) and the
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
// Unknowns: q = [spheres | cable 0 | cable 1 | ...], lambda = [cable 0 start, cable 0 end,
// cable 1 start, ...]; one cable: the paper's system. Block ordering for the linear solve,
// per cable: [start sphere | start multipliers | node 0], node 1, ..., node N-1, [node N |
// end multipliers | end sphere], after cable 0's one block per sphere no cable end holds; a
// sphere held by exactly one cable end sits in that end's block, one held by two or more
// (a depressor between two cables, a junction, a bridle's ring) is a hub, solved by the
// Schur complement on the hubs (network_matrix.h, docs/physics.md "Networks").
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

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/ancf_element.h"
#include "core/block_tridiagonal.h"
#include "core/network_matrix.h"
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
  NetworkMatrix* jac = nullptr;
};

class System {
 public:
  explicit System(const Model& model);

  const Model& model() const { return model_; }
  int num_q() const { return num_q_; }
  int num_lambda() const { return num_lambda_; }
  int num_cables() const { return static_cast<int>(cables_.size()); }
  const CableParams& cable(int c) const { return model_.cables[c]; }
  // the nodes and elements of cable c in use (node 0 at the cable's start)
  int num_nodes(int c = 0) const { return cables_[c].num_nodes; }
  int NumElements(int c = 0) const { return cables_[c].num_nodes - 1; }
  int num_spheres() const { return static_cast<int>(model_.spheres.size()); }
  // node i in use of cable c -> its coordinates in q (the array node first_node(c) + i)
  int CableDof(int node, int c = 0) const {
    const CablePart& p = cables_[c];
    return p.q_offset + 6 * (p.first_node + node);
  }
  // the preallocated nodes (elements + 1 without a winch) and the array index of node 0
  int max_nodes(int c = 0) const { return cables_[c].max_nodes; }
  int first_node(int c = 0) const { return cables_[c].first_node; }
  // q offset of array node k (in use or parked) of cable c
  int ArrayDof(int k, int c = 0) const { return cables_[c].q_offset + 6 * k; }
  // cable c's node k (in use) in the network's list of nodes (WaveSamples::nodes): each
  // cable's max_nodes entries one after the other
  int NodeIndex(int k, int c = 0) const { return cables_[c].node_base + k; }
  int total_array_nodes() const { return total_array_nodes_; }
  // the nominal element rest length cable.length / cable.elements [m]
  double element_length(int c = 0) const { return cables_[c].element.props().length; }
  // element e's rest length on cable c: the drum element's (drum_length) for element 0 of a
  // winched cable, else element_length
  double RestLength(int e, int c = 0) const {
    return e == 0 && has_winch(c) ? drum_length(c) : element_length(c);
  }
  // the winches (docs/winch.md): the winched cables come first in Model::cables, so winch w
  // sits at the start of cable w, w < num_winches()
  int num_winches() const { return num_winches_; }
  // cable c's winch: `nodes` in use and the paid-out length L, so the drum element's rest
  // length is L - (nodes - 2) element_length(c); rebuilds the block layout (does not allocate)
  void SetLayout(int nodes, double length, int c = 0);
  double drum_length(int c = 0) const { return cables_[c].drum_length; }
  bool has_winch(int c = 0) const { return cables_[c].winch; }
  // cable c's element with rest length l (the drum element)
  AncfElement DrumElement(double length, int c = 0) const;
  int SphereDof(int sphere) const { return 3 * sphere; }
  // cable ends: end k of cable c is end 2 c + k (0 start, 1 end) of the network; its
  // multipliers' offset and count
  int num_ends() const { return 2 * num_cables(); }
  // the ends (2 c + k) that vehicle v holds, in network order (its attachments)
  std::vector<int> VehicleEnds(int v) const;
  int EndLambda(int end, int c = 0) const {
    return cables_[c].lambda_offset + (end == 0 ? 0 : cables_[c].lambda_count[0]);
  }
  int end_lambda_count(int end, int c = 0) const { return cables_[c].lambda_count[end]; }
  const CableEnd& End(int end, int c = 0) const {
    return end == 0 ? model_.cables[c].start : model_.cables[c].end;
  }
  const AncfElement& element(int c = 0) const { return cables_[c].element; }
  // the spheres held by two or more cable ends (solved as hubs, network_matrix.h)
  int num_hubs() const { return static_cast<int>(hubs_.size()); }

  // Evaluates R and Phi at x, and the Newton matrix when out.jac != nullptr: each cable
  // (AssembleCable), the spheres (AssembleSpheres) and each cable end's joint
  // (AssembleJoint). The waves come from in.waves (calm water without in.has_waves), the
  // current is evaluated here; a cable end on a vehicle follows in.supports[2 c + end], the
  // drum element of winch w in.drums[w] (step_inputs.h).
  void Evaluate(const SystemPoint& x, const StepInputs& in, const EvaluateOptions& options,
                const SystemResidual& out) const;

  // the sea every load reads (environment_field.h)
  const EnvironmentField& sea() const { return sea_; }

  // an empty Newton matrix with this system's block structure
  NetworkMatrix MakeMatrix() const;
  // rhs (block order) from the global residual and constraint vectors, and back
  void ToBlocks(const Eigen::VectorXd& r, const Eigen::VectorXd& phi, Eigen::VectorXd* x) const;
  void FromBlocks(const Eigen::VectorXd& x, Eigen::VectorXd* dq, Eigen::VectorXd* dlambda) const;

  // element e's 12 coordinates of cable c from q
  Vec12 ElementCoordinates(const Eigen::VectorXd& q, int e, int c = 0) const {
    return q.segment<12>(CableDof(e, c));
  }
  // world position of the support of end `end` (0, 1) of cable c at time t (fixed / driven /
  // sphere point; a vehicle point from `supports` (indexed 2 c + end), the motion the coupling
  // scheme set for the step: the vehicles are not unknowns of the cables' Newton solve, for
  // it they are driven supports)
  Vec3 SupportPosition(int end, const Eigen::VectorXd& q, double t,
                       const std::vector<SupportMotion>* supports, int c = 0) const;

  double KineticEnergy(const Eigen::VectorXd& q, const Eigen::VectorXd& v) const;
  double PotentialEnergy(const Eigen::VectorXd& q) const;
  double StrainEnergy(const Eigen::VectorXd& q) const;
  double NodeTension(const Eigen::VectorXd& q, const Eigen::VectorXd& v, int node,
                     int c = 0) const;
  // describes DOF i for diagnostics ("cable node 12 (x = 118.2 m)", "body towfish")
  std::string DescribeDof(int i, const Eigen::VectorXd& q) const;

 private:
  // where an unknown sits in the Newton matrix: cable `part`'s block and its row in it, or
  // (part kHub) the hub unknowns' row `local`; block -1: a parked node (winch)
  static constexpr int kHub = -1;
  struct BlockIndex {
    int part;
    int block;
    int local;
  };
  // one cable of the network: its element, loads and block layout
  struct CablePart {
    AncfElement element;
    CableLoadContext loads;
    // without drag and added mass the load on an element is its weight in water alone, the
    // same uniform load on every element with no Jacobian: a scene without those terms pays
    // nothing for them
    bool state_dependent_loads = false;
    Vec12 weight_load = Vec12::Zero();  // UniformLoad(weight_per_length, l)
    unsigned load_fields = 0;  // the fields the loads read at the Gauss points (LoadFields)
    unsigned load_fields_clear = 0;  // ... on an element clear of the seabed (ClearOfSeabed)
    bool winch = false;
    int max_nodes = 0, num_nodes = 0, first_node = 0;
    double drum_length = 0.0;  // element 0's rest length now (winch)
    int q_offset = 0, node_base = 0, lambda_offset = 0;
    int lambda_count[2] = {0, 0};
    Vec3 clamp_dirs[2][2];  // two normals to the slope of a clamped end
    std::vector<int> base_block_sizes;  // the block sizes with first_node = 0
    std::vector<int> block_sizes, block_offsets;
  };
  // adds a 3 x 3 block at global q indices (i, j) of cable part's matrix (both in it)
  void Add3(BlockTridiagonal* jac, int i, int j, const Eigen::Matrix3d& m) const;
  // the same anywhere (a sphere's own block: folded into a cable end, free, or a hub)
  void Add3(NetworkMatrix* jac, int i, int j, const Eigen::Matrix3d& m) const;
  void AddQL(NetworkMatrix* jac, int qi, int li, const Eigen::Vector3d& col) const;
  // the block of each DOF and multiplier for the nodes in use (SetLayout)
  void BuildLayout();
  void BuildCableLayout(int c);
  // the three parts of Evaluate (see there), each adding its terms into out
  void AssembleCable(int cable_index, const SystemPoint& x, const StepInputs& in,
                     const EvaluateOptions& options, const SystemResidual& out) const;
  void AssembleSpheres(const SystemPoint& x, const StepInputs& in, const EvaluateOptions& options,
                       const SystemResidual& out) const;
  // the joint at end `end` (0 = start, 1 = end) of cable c
  void AssembleJoint(int c, int end, const SystemPoint& x, const StepInputs& in,
                     const SystemResidual& out) const;
  // the array elements of cable c from e_0 (`drum`: cable c's drum element with a winch)
  const AncfElement& ElementAt(int c, int e, const std::optional<AncfElement>& drum) const {
    return drum && e == 0 ? *drum : cables_[c].element;
  }
  // cable c's drum element at its rest length now (none without a winch)
  std::optional<AncfElement> DrumElementNow(int c) const {
    std::optional<AncfElement> drum;
    if (has_winch(c)) drum.emplace(DrumElement(drum_length(c), c));
    return drum;
  }

  Model model_;
  EnvironmentField sea_;
  std::vector<CablePart> cables_;
  int num_q_ = 0, num_lambda_ = 0, total_array_nodes_ = 0, num_winches_ = 0;
  // each sphere's place: the cable end whose block it is folded into (2 c + end), -1 free
  // (its own block after cable 0's), -2 a hub
  std::vector<int> sphere_end_;
  std::vector<int> hubs_;       // the hub spheres, in hub order
  std::vector<int> hub_local_;  // per sphere: its first row among the hub unknowns (or -1)
  std::vector<BlockIndex> q_index_, lambda_index_;
  // each unknown's position in the vector of the blocks in use (ToBlocks; -1: parked)
  std::vector<int> q_pos_, lambda_pos_;
  std::vector<double> sphere_mass_eff_, sphere_drag_k_;  // m + C_a rho V, 1/2 rho C_D pi r^2
  std::vector<double> sphere_radius_;                    // r = (3 V / 4 pi)^(1/3)
};

}  // namespace towsim::core
