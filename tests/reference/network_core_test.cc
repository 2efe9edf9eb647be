// Networks of cables (docs/physics.md "Networks", docs/scene_format.md "Networks"): several
// cables in one implicit step, spheres shared by several cable ends (hubs, solved by the
// Schur complement), checked against independent solutions:
//   - a cable split into two at a massless junction reproduces the one-cable solution: a
//     static catenary (and both against the analytic elastic catenary) and a steady tow;
//   - a two-part tow (tow point, main cable, depressor, tether, towfish) in its steady state
//     against the towed-cable equations integrated through the chain (towed_cable_steady.h:
//     the tether from the towfish up, then the main cable from the depressor up with the
//     tether's pull on the depressor), at two speeds;
//   - a bridle: a heavy sphere held by two symmetric, neutrally buoyant lines from two fixed
//     points, against the exact static solution of two straight elastic lines;
//   - energy: a network with drag off, on the trapezoidal rule, conserves its energy.
// The scenes are YAML, read by the scene loader (the `cables:` form end to end).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "core/state.h"
#include "elastic_catenary.h"
#include "network_models.h"
#include "scene/scene_loader.h"
#include "towed_cable_steady.h"

namespace towsim::reference {
namespace {

using core::Vec3;

// The split catenary: the junction sits where the one cable's middle node sits and the
// tensions at the supports agree. The one cable's slope is continuous through its middle
// node, the split's is not (two nodes meet at a pin), so the two discretizations differ by a
// discretization error, which the analytic elastic catenary measures: the split must not be
// further from the exact curve than twice the one cable is. Measured (20 elements of 6 m):
// at the middle one cable vs exact 5.9e-5 m, split vs exact 3.0e-6 m (its pin sits at the
// middle), split vs one cable 6.1e-5 m.
TEST(NetworkCore, SplitCatenaryReproducesTheOneCable) {
  const core::Simulation one(NetworkModel(SplitCatenaryYaml(false, 1)));
  const core::Simulation split(NetworkModel(SplitCatenaryYaml(true, 1)));
  ASSERT_EQ(split.num_cables(), 2);
  const Vec3 middle = one.node_position(10);
  const Vec3 junction = split.body_position(0);
  const Vec3 upper_end = split.node_position(10, 0);
  // the exact elastic catenary through the same supports (elastic_catenary.h)
  const core::CableParams& c = one.model().cables[0];
  CatenaryProblem p;
  p.length = c.length;
  p.weight = (c.mass_per_length - one.model().environment.water_density * c.area()) * 9.81;
  p.ea = c.axial_stiffness;
  p.span = 100.0;
  p.height = -20.0;  // the end 20 m deeper (NED z down, the reference's y up)
  const CatenarySolution exact = SolveElasticCatenary(p);
  const CatenaryPoint exact_middle =
      CatenaryShape(p, exact.horizontal_tension, exact.vertical_force_a, 0.5 * c.length);
  const double one_error = std::hypot(middle.x() - exact_middle.x, middle.z() + exact_middle.y);
  const double split_error =
      std::hypot(junction.x() - exact_middle.x, junction.z() + exact_middle.y);
  std::printf("middle: one cable vs exact %.3e m, split vs exact %.3e m, split vs one %.3e m\n",
              one_error, split_error, (junction - middle).norm());
  // both are 20 elements of 6 m of the same curve: the split within twice the one cable's
  // discretization error of the exact curve, and both well within a centimetre
  constexpr double kExactTol = 1e-2;  // [m]
  EXPECT_LT(one_error, kExactTol);
  EXPECT_LT(split_error, 2.0 * one_error + 1e-6);
  EXPECT_LT((upper_end - junction).norm(), 1e-8);  // the joint holds
  constexpr double kTensionRelTol = 1e-6;
  EXPECT_NEAR(split.end_force(0, 0).norm(), one.end_force(0).norm(),
              kTensionRelTol * one.end_force(0).norm());
  EXPECT_NEAR(split.end_force(1, 1).norm(), one.end_force(1).norm(),
              kTensionRelTol * one.end_force(1).norm());
}


// a driven tow point at `speed` [m/s], `depth` 3.5 m, and a 416 kg sphere below (the shipped
// steady_tow's system, config/scenes/steady_tow.yaml); split: the same cable as two halves
// meeting at a massless junction
std::string SteadyTow(bool split, double speed) {
  const std::string v = std::to_string(speed);
  const std::string head =
      "name: steady_tow\n"
      "time: {step: 0.05, duration: 1, output_rate: 10}\n"
      "environment: {current: [0, 0, 0]}\n"
      "bodies:\n"
      "  towfish: {model: ../vehicles/sphere_416kg.yaml, position: [0, 0, 203.5]}\n";
  const std::string line =
      "diameter: 0.041, density: 1300, youngs_modulus: 7.0e8, "
      "loads: [gravity, buoyancy, drag, added_mass, bending], initial: static, "
      "initial_velocity: [" + v + ", 0, 0]";
  const std::string top = "{driven: {position: [0, 0, 3.5], velocity: [" + v + ", 0, 0]}}";
  if (!split) {
    return head + "cable: {length: 200, elements: 20, " + line + ", start: " + top +
           ", end: {body: towfish}}\n";
  }
  return head + "  junction: {type: sphere, mass: 0, volume: 0, position: [0, 0, 103.5]}\n" +
         "cables:\n"
         "  upper: {length: 100, elements: 10, " + line + ", start: " + top +
         ", end: {body: junction}}\n"
         "  lower: {length: 100, elements: 10, " + line +
         ", start: {body: junction}, end: {body: towfish}}\n";
}

core::Model LoadIn(const std::string& yaml, const std::string& dir) {
  return scene::LoadSceneFromString(yaml, "network.yaml", dir);
}

// The split tow in its steady state (the static solve in the frame moving with the tow) and
// after 20 s of dynamics: the towfish where the one cable has it and the same top tension.
// As for the catenary the split frees the slope at the junction (and with bending, the
// moment): the differences are discretization differences, bounded by the steady tow's
// discretization error at 20 elements (steady_tow_core_test: 1e-3 of layback, depth and
// tension against the converged reference).
TEST(NetworkCore, SplitSteadyTowReproducesTheOneCable) {
  const std::string dir = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes";
  for (double speed : {3.0, 6.0}) {
    core::Simulation one(LoadIn(SteadyTow(false, speed), dir));
    core::Simulation split(LoadIn(SteadyTow(true, speed), dir));
    ASSERT_EQ(split.num_cables(), 2);
    const int fish = 0;  // the towfish is body 0 in both
    constexpr double kRelTol = 1e-3;
    for (int pass = 0; pass < 2; ++pass) {
      const Vec3 a = one.body_position(fish), b = split.body_position(fish);
      const double top_one = one.end_force(0).norm(), top_split = split.end_force(0, 0).norm();
      std::printf("%.0f m/s, t = %.0f s: towfish [%.3f %.3f] vs [%.3f %.3f], top %.2f vs %.2f N\n",
                  speed, one.time(), a.x(), a.z(), b.x(), b.z(), top_one, top_split);
      const double layback = speed * one.time() - a.x();
      EXPECT_NEAR(b.x(), a.x(), kRelTol * layback) << speed << " m/s, t " << one.time();
      EXPECT_NEAR(b.z(), a.z(), kRelTol * a.z()) << speed << " m/s, t " << one.time();
      EXPECT_NEAR(top_split, top_one, kRelTol * top_one) << speed << " m/s, t " << one.time();
      if (pass == 1) break;
      while (one.time() < 20.0 - 1e-9) {
        ASSERT_TRUE(one.Step().ok());
        const core::StepStatus st = split.Step();
        ASSERT_TRUE(st.ok()) << st.message;
      }
    }
  }
}

// the towed-cable problem of cable k of the model, with sphere `body` at its lower end
TowedCableProblem ChainLink(const core::Model& m, int k, int body, double speed) {
  TowedCableProblem p;
  const core::CableParams& c = m.cables[k];
  p.length = c.length;
  p.diameter = c.diameter;
  p.density = c.mass_per_length / c.area();
  p.youngs_modulus = c.axial_stiffness / c.area();
  const core::SphereBody& b = m.spheres[body];
  p.sphere_mass = b.mass;
  p.sphere_volume = b.volume;
  p.sphere_cd = b.drag_coefficient;
  p.fluid.density = m.environment.water_density;
  p.fluid.dynamic_viscosity = m.environment.dynamic_viscosity;
  p.gravity = m.environment.gravity;
  p.tow_velocity = Vec3(speed, 0.0, 0.0);
  p.stretch_law = StretchLaw::kGreenTrueTension;
  return p;
}

// Against the chain of towed-cable equations: the tether from the towfish up gives the
// depressor's position relative to the towfish and the tether's pull on the depressor; the
// main cable from the depressor up (that pull added to the depressor's own weight and drag)
// gives the tow point's position relative to the depressor and the top tension. 20 elements
// per cable against the converged reference: discretization error (as steady_tow_core_test's
// static start, 1e-3).
TEST(NetworkCore, TwoPartTowSteadyStateMatchesTheChainedReference) {
  for (double speed : {2.5, 5.0}) {
    const core::Simulation sim(NetworkModel(TwoPartTowYaml(speed, 1)));
    const core::Model& m = sim.model();
    ASSERT_EQ(m.cables[0].name, "main");
    const int depressor = 0, towfish = 1;
    const TowedCableSolution tether = SolveTowedCableSteady(ChainLink(m, 1, towfish, speed));
    TowedCableProblem main = ChainLink(m, 0, depressor, speed);
    main.sphere_extra_force = tether.top_force;
    const TowedCableSolution upper = SolveTowedCableSteady(main);

    const Vec3 top = m.cables[0].start.position;  // t = 0
    const Vec3 d = sim.body_position(depressor), f = sim.body_position(towfish);
    const Vec3 d_ref = top - upper.top_minus_sphere;
    const Vec3 f_ref = d_ref - tether.top_minus_sphere;
    std::printf(
        "%.1f m/s: depressor [%.3f %.3f] vs [%.3f %.3f], towfish [%.3f %.3f] vs [%.3f %.3f], "
        "top %.1f vs %.1f N, tether top %.1f vs %.1f N\n",
        speed, d.x(), d.z(), d_ref.x(), d_ref.z(), f.x(), f.z(), f_ref.x(), f_ref.z(),
        sim.end_force(0, 0).norm(), upper.top_tension, sim.end_force(0, 1).norm(),
        tether.top_tension);
    constexpr double kRelTol = 1e-3;
    EXPECT_NEAR(d.x(), d_ref.x(), kRelTol * std::abs(d_ref.x())) << speed;
    EXPECT_NEAR(d.z(), d_ref.z(), kRelTol * d_ref.z()) << speed;
    EXPECT_NEAR(f.x(), f_ref.x(), kRelTol * std::abs(f_ref.x())) << speed;
    EXPECT_NEAR(f.z(), f_ref.z(), kRelTol * f_ref.z()) << speed;
    EXPECT_NEAR(sim.end_force(0, 0).norm(), upper.top_tension, kRelTol * upper.top_tension)
        << speed;
    EXPECT_NEAR(sim.end_force(0, 1).norm(), tether.top_tension, kRelTol * tether.top_tension)
        << speed;
  }
}

// A bridle: a 2000 kg sphere (0.2 m^3) held by two neutrally buoyant lines (no weight in
// water, drag off) from fixed points 40 m apart. Straight lines: with the sphere at depth z
// below the supports, each line's stretched length sqrt(20^2 + z^2) = L (1 + eps) with the
// core's law T = EA eps (1 + eps) (Green strain, true tension: eps = (lambda^2 - 1) / 2,
// lambda = 1 + e, solved exactly below), and vertical balance 2 T z / sqrt(20^2 + z^2) = W.
// One equation in z, solved by bisection: the tensions and the depth the network must find.
TEST(NetworkCore, BridleMatchesTheStaticSolution) {
  const core::Model m = NetworkModel(BridleYaml(1));
  const core::Simulation sim(m);
  const core::CableParams& c = m.cables[0];
  // neutrally buoyant: m = rho_w A
  ASSERT_NEAR(c.mass_per_length, m.environment.water_density * c.area(), 1e-4);
  const double w = (2000.0 - m.environment.water_density * 0.2) * m.environment.gravity;
  const double ea = c.axial_stiffness, l0 = c.length, half = 20.0;
  // residual of vertical balance at depth z: the stretch from the geometry, T from the law
  auto balance = [&](double z) {
    const double len = std::hypot(half, z);
    const double lambda = len / l0;
    const double tension = ea * 0.5 * (lambda * lambda - 1.0) * lambda;
    return 2.0 * tension * z / len - w;
  };
  double lo = std::sqrt(l0 * l0 - half * half), hi = lo + 5.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (balance(mid) > 0.0 ? hi : lo) = mid;
  }
  const double z = 0.5 * (lo + hi);
  const double len = std::hypot(half, z), lambda = len / l0;
  const double tension = ea * 0.5 * (lambda * lambda - 1.0) * lambda;
  const Vec3 p = sim.body_position(0);
  const Vec3 port = sim.end_force(1, 0), starboard = sim.end_force(1, 1);
  std::printf("bridle: depth %.6f vs %.6f m, tensions %.3f, %.3f vs %.3f N\n", p.z(), z,
              port.norm(), starboard.norm(), tension);
  constexpr double kDepthTol = 1e-6;       // [m], the solver's tolerance times the length
  constexpr double kTensionRelTol = 1e-6;  // exact for straight two-node-per-element lines
  EXPECT_NEAR(p.z(), z, kDepthTol);
  EXPECT_NEAR(p.y(), 0.0, kDepthTol);
  // the lateral components cancel, the tensions match
  EXPECT_NEAR(port.y() + starboard.y(), 0.0, kTensionRelTol * tension);
  EXPECT_NEAR(port.norm(), tension, kTensionRelTol * tension);
  EXPECT_NEAR(starboard.norm(), tension, kTensionRelTol * tension);
}

// Energy: the split catenary released from its static shape with a kick, drag and added mass
// off, on the trapezoidal rule: kinetic + potential + strain energy stay constant to the rule's
// truncation error (swinging_cable_core_test: 1e-3 of the energy swing at a resolving step)
TEST(NetworkCore, NetworkWithoutDragConservesEnergy) {
  core::Simulation sim(KickedNetwork(1));
  KickTheClump(&sim);
  auto energy = [&] { return sim.KineticEnergy() + sim.PotentialEnergy() + sim.StrainEnergy(); };
  const double e0 = energy(), ke0 = sim.KineticEnergy();
  double max_dev = 0.0;
  while (sim.time() < 20.0 - 1e-9) {
    const core::StepStatus st = sim.StepBy(0.01);
    ASSERT_TRUE(st.ok()) << st.message;
    max_dev = std::max(max_dev, std::abs(energy() - e0));
  }
  std::printf("energy: initial kinetic %.3f J, max |E - E0| %.3e J\n", ke0, max_dev);
  constexpr double kDriftRelTol = 1e-3;
  EXPECT_LT(max_dev, kDriftRelTol * ke0);
}

// The shipped two-part tow (config/scenes/two_part_tow.yaml): the whole network's static start
// in the sea's frame, then 10 s of the coupled run in its JONSWAP sea: every step converges,
// the joints hold (the tether's top node on the depressor, the main cable's on the vehicle's
// A-frame point)
TEST(NetworkCore, ShippedTwoPartTowRuns) {
  const std::string dir = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes";
  core::Simulation sim(scene::LoadScene(dir + "/two_part_tow.yaml"));
  ASSERT_EQ(sim.num_cables(), 2);
  ASSERT_EQ(sim.cable_name(0), "main");
  ASSERT_EQ(sim.body_name(0), "depressor");  // spheres first, then the vehicles
  while (sim.time() < 10.0 - 1e-9) {
    const core::StepStatus st = sim.Step();
    ASSERT_TRUE(st.ok()) << st.message;
  }
  constexpr double kJointTol = 1e-6;  // [m]
  EXPECT_LT((sim.node_position(0, 1) - sim.body_position(0)).norm(), kJointTol);
  EXPECT_LT((sim.node_position(sim.num_nodes(0) - 1, 0) - sim.body_position(0)).norm(),
            kJointTol);
  // both cables pull on the depressor (the script's thrust is not run here: the tow slows)
  EXPECT_TRUE(sim.end_force(1, 0).allFinite());
  EXPECT_GT(sim.end_force(1, 0).norm(), 0.0);
  EXPECT_GT(sim.end_force(0, 1).norm(), 0.0);
}

}  // namespace
}  // namespace towsim::reference
