#include "core/vehicle_coupling.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/simulation.h"

namespace towsim::core {
namespace {

constexpr double kRho = 1025.0, kG = 9.81;

// A neutrally buoyant vehicle (no damping, no surfaces) holding a 50 m cable with a heavy sphere
// at its lower end, all released at rest in water without drag: nothing but weight, buoyancy
// and the joint forces act, so the total vertical momentum
//   P(t) = (m - Z_wdot) w_veh + int rho_c A r_dot_z dx + (m_s + C_a rho V_s) v_s
// must grow as F t with F the total net weight (cable + sphere; the vehicle is neutral), while
// the cable stretches and oscillates under the partitioned coupling.
Model FallingModel(Coupling coupling, double h) {
  Model m;
  m.time.step = h;
  m.integrator.coupling = coupling;
  m.integrator.rho_inf = 0.6;
  m.cables[0].length = 50.0;
  m.cables[0].elements = 10;
  m.cables[0].loads = {true, true, false, false, true};  // no drag; vertical motion: no added mass
  m.cables[0].initial = InitialShape::kVertical;
  m.cables[0].start.kind = EndKind::kVehicle;
  m.cables[0].start.body = 0;
  m.cables[0].start.at_B = Vec3(0, 0, 0.5);
  m.cables[0].end.kind = EndKind::kSphere;
  m.cables[0].end.body = 0;
  Vehicle v;
  v.name = "vehicle";
  v.params.length = 5.0;
  v.params.mass = 1000.0;
  v.params.inertia = Vec3(200, 2000, 2000);
  v.params.r_g = Vec3(0, 0, 0.1);
  v.params.volume = v.params.mass / kRho;
  v.params.added_mass.diagonal() << 20, 500, 500, 10, 800, 800;
  v.position = Vec3(0, 0, 5.0);
  m.vehicles.push_back(v);
  SphereBody s;
  s.name = "weight";
  s.mass = 200.0;
  s.volume = 0.05;
  s.drag_coefficient = 0.0;
  s.added_mass_coefficient = 0.5;
  s.position = Vec3(0, 0, 5.5 + 50.0);
  m.spheres.push_back(s);
  return m;
}

double VerticalMomentum(const Simulation& sim) {
  const Model& m = sim.model();
  const VehicleParams& vp = m.vehicles[0].params;
  double p = (vp.mass + vp.added_mass(2, 2)) * sim.vehicle_state(0).nu(2);
  // cable: int rho A r_dot dx = sum over elements of rho A l [1/2, l/12, 1/2, -l/12] . e_dot
  const double l = m.cables[0].length / m.cables[0].elements;
  const double mu = m.cables[0].mass_per_length;
  for (int e = 0; e < m.cables[0].elements; ++e) {
    const State& st = sim.state();
    const int o = sim.cable_dof(e);
    p += mu * l *
         (0.5 * st.v(o + 2) + l / 12 * st.v(o + 5) + 0.5 * st.v(o + 8) - l / 12 * st.v(o + 11));
  }
  const SphereBody& s = m.spheres[0];
  p += (s.mass + s.added_mass_coefficient * kRho * s.volume) * sim.body_velocity(0).z();
  return p;
}

TEST(VehicleCoupling, MomentumBalanceAcrossTheJoint) {
  for (const Coupling coupling : {Coupling::kStrong, Coupling::kStaggered}) {
    const Model m = FallingModel(coupling, 0.01);
    Simulation sim(m);
    const double w_cable = (m.cables[0].mass_per_length - kRho * m.cables[0].area()) * kG * m.cables[0].length;
    const double w_sphere = (m.spheres[0].mass - kRho * m.spheres[0].volume) * kG;
    const double force = w_cable + w_sphere;
    for (int k = 0; k < 300; ++k) ASSERT_TRUE(sim.Step().ok());
    const double expected = force * sim.time();
    const double p = VerticalMomentum(sim);
    std::printf("%s: P = %.6f, F t = %.6f, rel. error %.2e, coupling iterations %d\n",
                coupling == Coupling::kStrong ? "strong" : "staggered", p, expected,
                p / expected - 1.0, sim.coupling_iterations());
    // strong: the impulse the vehicle receives over a step (trapezoidal in lambda) and the one
    // the cable delivers agree to O(h^2) per step; staggered lags lambda by one step: O(h)
    const double tol = coupling == Coupling::kStrong ? 2e-3 : 2e-2;
    EXPECT_NEAR(p, expected, tol * expected);
    // the vehicle is pulled down by the cable: it sinks
    EXPECT_GT(sim.vehicle_state(0).nu(2), 0.0);
  }
}

TEST(VehicleCoupling, StrongAndStaggeredAgreeAsTheStepShrinks) {
  double z[2][2];
  const double steps[2] = {0.02, 0.005};
  for (int i = 0; i < 2; ++i)
    for (int c = 0; c < 2; ++c) {
      Simulation sim(FallingModel(c == 0 ? Coupling::kStrong : Coupling::kStaggered, steps[i]));
      while (sim.time() < 2.0 - 1e-9) ASSERT_TRUE(sim.Step().ok());
      z[i][c] = sim.vehicle_state(0).p_W.z();
    }
  const double gap_coarse = std::abs(z[0][0] - z[0][1]), gap_fine = std::abs(z[1][0] - z[1][1]);
  std::printf("vehicle depth after 2 s: h = 0.02: %.6f / %.6f, h = 0.005: %.6f / %.6f\n",
              z[0][0], z[0][1], z[1][0], z[1][1]);
  // the staggered lag is first order in h: a 4x smaller step shrinks the gap at least 2x
  EXPECT_LT(gap_fine, 0.5 * gap_coarse);
}

}  // namespace
}  // namespace towsim::core
