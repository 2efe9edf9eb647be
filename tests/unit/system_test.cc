#include "core/system.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "core/initial_shape.h"
#include "core/state.h"
#include "core/step_sampler.h"

namespace towsim::core {
namespace {

// a sphere-ended cable with every load on, a current, a clamped start and axial damping
Model FullModel() {
  Model m;
  m.cables[0].length = 30.0;
  m.cables[0].elements = 4;
  m.cables[0].axial_damping = 0.01;
  m.cables[0].initial = InitialShape::kStraight;
  m.cables[0].start.kind = EndKind::kDriven;
  m.cables[0].start.position = Vec3(0, 0, 2);
  m.cables[0].start.velocity = Vec3(1.5, 0, 0);
  m.cables[0].start.clamped = true;
  m.cables[0].start.slope = Vec3(-1, 0, 2).normalized();
  m.cables[0].end.kind = EndKind::kSphere;
  m.cables[0].end.body = 0;
  m.environment.current = CurrentField::Uniform(Vec3(0.2, 0.4, 0.0));
  SphereBody b;
  b.name = "fish";
  b.mass = 50;
  b.volume = 0.02;
  b.position = Vec3(-12, 1, 28);
  m.spheres.push_back(b);
  SphereBody free_sphere = b;  // unattached: its own block
  free_sphere.name = "buoy";
  free_sphere.position = Vec3(5, 5, 5);
  m.spheres.push_back(free_sphere);
  return m;
}

Eigen::MatrixXd Dense(BlockTridiagonal& m) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(m.size(), m.size());
  for (int i = m.first_block(); i < m.num_blocks(); ++i) {
    d.block(m.block_offset(i), m.block_offset(i), m.block_size(i), m.block_size(i)) = m.diag(i);
    if (i + 1 < m.num_blocks()) {
      d.block(m.block_offset(i), m.block_offset(i + 1), m.block_size(i), m.block_size(i + 1)) =
          m.upper(i);
      d.block(m.block_offset(i + 1), m.block_offset(i), m.block_size(i + 1), m.block_size(i)) =
          m.lower(i);
    }
  }
  return d;
}

// the network's matrix (network_matrix.h) written out: the cables' blocks, the hubs' H and
// the borders B_c, C_c
Eigen::MatrixXd Dense(NetworkMatrix& m) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(m.size(), m.size());
  const int oh = m.hub_offset(), nh = m.hub_size();
  for (int c = 0; c < m.num_cables(); ++c) {
    const int o = m.cable_offset(c), n = m.cable(c).size();
    d.block(o, o, n, n) = Dense(m.cable(c));
    for (int j = 0; j < nh; ++j)
      for (int i = 0; i < n; ++i) {
        d(o + i, oh + j) = m.border_column(c, i, j);
        d(oh + j, o + i) = m.border_row(c, j, i);
      }
  }
  for (int i = 0; i < nh; ++i)
    for (int j = 0; j < nh; ++j) d(oh + i, oh + j) = m.hub(i, j);
  return d;
}

// The assembled Newton matrix c_a dR/da + c_q dR/dq + c_v dR/dv (with Phi_q) equals finite
// differences of the residual and constraints: checks every element, load, sphere and joint
// term and the block placement. With waves, the samples are held (as the integrator holds them
// over a step), so the matrix is exact for the residual it solves.
void CheckNewtonMatrix(const Model& model, bool waves) {
  const System sys(model);
  State s;
  BuildInitialState(sys, &s);
  const int n = sys.num_q(), m = sys.num_lambda();
  // perturb away from symmetry
  for (int i = 0; i < n; ++i) {
    s.q(i) += 0.01 * std::sin(1.3 * i);
    s.v(i) += 0.3 * std::cos(0.7 * i);
    s.a(i) = 0.2 * std::sin(0.4 * i + 1);
  }
  s.lambda = Eigen::VectorXd::LinSpaced(m, -50, 80);
  StepInputs in;
  const StepSampler sampler(sys);
  sampler.Resize(&in);
  sampler.TakeMotions(s, &in);
  if (waves) sampler.SampleWaves(s.q, 0.3, &in);
  const EvaluateOptions options{1.0, {1.0, 7.0, 300.0}};
  const JacobianCoefficients& cf = options.coeffs;
  NetworkMatrix jac = sys.MakeMatrix();
  Eigen::VectorXd r, phi;
  sys.Evaluate({s.q, s.v, s.a, s.lambda, 0.3}, in, options, {&r, &phi, &jac});
  const Eigen::MatrixXd analytic = Dense(jac);
  // the element laws are written once for both uses (ancf_element.cc, cable_loads.cc): the
  // residual without the matrix is the same to the bit
  Eigen::VectorXd r_only, phi_only;
  sys.Evaluate({s.q, s.v, s.a, s.lambda, 0.3}, in, options, {&r_only, &phi_only});
  EXPECT_EQ(r, r_only);
  EXPECT_EQ(phi, phi_only);

  // finite differences in block order: x = [q; lambda] mapped through ToBlocks
  auto stacked = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& a,
                     const Eigen::VectorXd& l) {
    Eigen::VectorXd rr, pp, x;
    sys.Evaluate({q, v, a, l, 0.3}, in, options, {&rr, &pp});
    sys.ToBlocks(rr, pp, &x);
    return x;
  };
  Eigen::MatrixXd fd(n + m, n + m);
  const double h = 1e-6;
  for (int j = 0; j < n + m; ++j) {
    Eigen::VectorXd unit_blocks = Eigen::VectorXd::Zero(n + m), dq, dl;
    unit_blocks(j) = 1.0;
    sys.FromBlocks(unit_blocks, &dq, &dl);
    // moving q by dq moves v by c_v dq and a by c_a dq (the integrator's chain rule)
    const Eigen::VectorXd xp =
        stacked(s.q + h * dq, s.v + cf.c_v * h * dq, s.a + cf.c_a * h * dq, s.lambda + h * dl);
    const Eigen::VectorXd xm =
        stacked(s.q - h * dq, s.v - cf.c_v * h * dq, s.a - cf.c_a * h * dq, s.lambda - h * dl);
    fd.col(j) = (xp - xm) / (2 * h);
  }
  constexpr double kJacRelTol = 1e-6;  // central differences
  EXPECT_LT((analytic - fd).norm(), kJacRelTol * fd.norm())
      << "max entry error " << (analytic - fd).cwiseAbs().maxCoeff();
}

TEST(System, NewtonMatrixMatchesFiniteDifferences) { CheckNewtonMatrix(FullModel(), false); }

// the same in a sea: a sheared current profile (its dU/dz enters dR/dq), regular waves
// (Morison's fluid inertia on the cable and the spheres) and a flat seabed the lower cable lies
// on (penalty normal force with damping and smoothed Coulomb friction, seabed_contact.h)
TEST(System, NewtonMatrixMatchesFiniteDifferencesInASea) {
  Model m = FullModel();
  m.environment.current = CurrentField::Profile(
      {{0.0, Vec3(0.6, 0.2, 0.0)}, {10.0, Vec3(0.3, 0.1, 0.0)}, {40.0, Vec3(0.1, -0.05, 0.0)}});
  m.environment.waves = WaveField::Regular(1.5, 6.0, 0.4, 0.3, 25.0, m.environment.gravity,
                                           m.environment.water_density);
  m.environment.seabed = Seabed::Flat(25.0);
  SeabedContact c;
  c.stiffness = 3.0e4;  // [Pa/m]
  c.damping = 500.0;    // [Pa s/m]
  c.friction = 0.4;
  m.environment.seabed.set_contact(c);
  m.spheres[1].position = Vec3(5, 5, 8);  // the buoy below the waves
  CheckNewtonMatrix(m, true);
}

// A network: a sphere held by two cables (a hub, solved by the Schur complement) and a third
// cable hanging from a fixed point to a sphere it alone holds; the same finite-difference check
// covers the hub's own block and the borders
Model NetworkModel() {
  Model m = FullModel();
  CableParams lower = m.cables[0];
  lower.name = "lower";
  lower.start = CableEnd();
  lower.start.kind = EndKind::kSphere;
  lower.start.body = 0;
  lower.end = CableEnd();
  lower.end.kind = EndKind::kFixed;
  lower.end.position = Vec3(-30, 2, 40);
  lower.length = 25.0;
  lower.elements = 3;
  CableParams third = m.cables[0];
  third.name = "third";
  third.start = CableEnd();
  third.start.kind = EndKind::kFixed;
  third.start.position = Vec3(10, 0, 0);
  third.end = CableEnd();
  third.end.kind = EndKind::kSphere;
  third.end.body = 1;
  third.length = 6.0;
  third.elements = 2;
  m.cables.push_back(lower);
  m.cables.push_back(third);
  return m;
}

TEST(System, NetworkNewtonMatrixMatchesFiniteDifferences) {
  const System sys(NetworkModel());
  EXPECT_EQ(sys.num_hubs(), 1);
  CheckNewtonMatrix(NetworkModel(), false);
}

// The network's Newton matrix of `model` with `cf` at its initial state, solved for its own
// residual both by the Schur complement (network_matrix.h) and by a dense LU of the same
// matrix (full pivoting when `full_pivot`): *network and *dense
void SolveBothWays(const Model& model, const JacobianCoefficients& cf, bool full_pivot,
                   Eigen::VectorXd* network, Eigen::VectorXd* dense) {
  const System sys(model);
  State s;
  BuildInitialState(sys, &s);
  StepInputs in;
  const StepSampler sampler(sys);
  sampler.Resize(&in);
  sampler.TakeMotions(s, &in);
  NetworkMatrix jac = sys.MakeMatrix();
  Eigen::VectorXd r, phi;
  sys.Evaluate({s.q, s.v, s.a, s.lambda, 0.3}, in, {1.0, cf}, {&r, &phi, &jac});
  const Eigen::MatrixXd matrix = Dense(jac);
  sys.ToBlocks(r, phi, network);
  *dense = full_pivot ? Eigen::VectorXd(matrix.fullPivLu().solve(*network))
                      : Eigen::VectorXd(matrix.partialPivLu().solve(*network));
  ASSERT_TRUE(jac.Solve(network));
}

// The Schur-complement solve (network_matrix.h) against a dense LU of the same matrix
TEST(System, NetworkSolveMatchesADenseSolve) {
  Eigen::VectorXd x, expected;
  SolveBothWays(NetworkModel(), {1.0, 7.0, 300.0}, false, &x, &expected);
  constexpr double kSolveRelTol = 1e-9;  // two direct solves of a well-conditioned system
  EXPECT_LT((x - expected).norm(), kSolveRelTol * expected.norm());
}

// A massless junction (a hub with H = 0) is solvable: the cables' end compliances make S
// positive definite
TEST(System, MasslessJunctionSolves) {
  Model m = NetworkModel();
  m.spheres[0].mass = 0.0;
  m.spheres[0].volume = 0.0;
  m.cables[0].loads.drag = m.cables[1].loads.drag = false;
  Eigen::VectorXd x, expected;
  SolveBothWays(m, {1.0, 0.0, 0.0}, true, &x, &expected);
  constexpr double kSolveRelTol = 1e-8;
  EXPECT_LT((x - expected).norm(), kSolveRelTol * expected.norm());
}

TEST(System, ConstraintHoldsTheEndAtTheSupport) {
  const System sys(FullModel());
  State s;
  BuildInitialState(sys, &s);
  Eigen::VectorXd r, phi;
  StepInputs in;
  StepSampler(sys).TakeMotions(s, &in);
  sys.Evaluate({s.q, s.v, s.a, s.lambda, 2.0}, in, {}, {&r, &phi});
  // the driven start has moved 2 s * 1.5 m/s along x since t = 0
  EXPECT_NEAR(phi(0), 0.0 - 3.0, 1e-12);
  // body end: cable end at the body initially
  const Vec3 end = s.q.segment<3>(sys.CableDof(sys.num_nodes() - 1));
  EXPECT_TRUE((end - Vec3(-12, 1, 28)).norm() < 1e-12);
}

}  // namespace
}  // namespace towsim::core
