// Several winches in one scene (docs/winch.md "Several winches"): the network of
// tests/integration/scenes/two_winches.yaml, two towed cables each with a drum at its start,
// driven offline by the scene's script, each entry naming its winch. Each drum must follow its
// own commands as if it were alone: its paid-out length against the continuous drum
// kinematics of its commands under its own acceleration limit (the analytic reference), its
// cable's unstretched length and mass against that length at every step.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/script.h"
#include "core/simulation.h"
#include "core/system.h"
#include "scene/scene_loader.h"

namespace towsim {
namespace {

const std::string kScene =
    std::string(TOWSIM_SOURCE_DIR) + "/tests/integration/scenes/two_winches.yaml";

// the drum's continuous kinematics (docs/winch.md "The drum"): from rest at L0, each event
// (t, V) drives the speed toward V at the acceleration limit a; the length is the exact
// integral of that piecewise-linear speed
struct SpeedEvent {
  double t, speed;
};
double DrumLength(double L0, double a, const std::vector<SpeedEvent>& events, double t) {
  double L = L0, v = 0.0, now = 0.0, target = 0.0;
  size_t next = 0;
  while (now < t) {
    const double until = next < events.size() ? std::min(t, events[next].t) : t;
    // ramp toward target, then hold it
    const double ramp = std::min(until - now, std::abs(target - v) / a);
    const double accel = target > v ? a : (target < v ? -a : 0.0);
    L += v * ramp + 0.5 * accel * ramp * ramp;
    v += accel * ramp;
    if (ramp < until - now) {
      v = target;
      L += v * (until - now - ramp);
    }
    now = until;
    if (next < events.size() && now >= events[next].t) target = events[next++].speed;
  }
  return L;
}

// the mass of cable c's elements in use: 1^T M 1 over the translational coordinates of each
// element's consistent mass matrix (paper Eq. 7)
double CableMass(const core::System& sys, int c) {
  double mass = 0.0;
  for (int e = 0; e < sys.NumElements(c); ++e) {
    const core::AncfElement element = sys.DrumElement(sys.RestLength(e, c), c);
    const core::Mat12& m = element.mass();
    for (int i : {0, 6})
      for (int j : {0, 6}) mass += m(i, j);
  }
  return mass;
}

TEST(WinchNetworkCore, TwoDrumsEachFollowTheirScriptAtOnce) {
  const core::Model model = scene::LoadScene(kScene);
  ASSERT_EQ(model.cables.size(), 2u);
  ASSERT_TRUE(model.cables[0].winch && model.cables[1].winch);
  EXPECT_EQ(model.cables[0].winch->name, "port_winch");
  EXPECT_EQ(model.cables[1].winch->name, "starboard_winch");
  core::Simulation sim(model);
  ASSERT_EQ(sim.num_winches(), 2);
  core::ScriptRunner script(model);
  const double h = model.time.step;

  // the analytic profiles of the script: port 1 m/s from 1 s, then to 70 m from 6 s (the
  // time-optimal stop: coast, then brake at a to rest at the target); starboard -1 m/s from
  // 2 s, +0.25 m/s from 10 s
  const core::WinchParams& port = *model.cables[0].winch;
  const core::WinchParams& star = *model.cables[1].winch;
  const double L0 = model.cables[0].length;
  const double at_6 = DrumLength(L0, port.max_acceleration, {{1, 1.0}}, 6.0);
  const double brake_at = 6.0 + (70.0 - at_6 - 1.0 / (2.0 * port.max_acceleration)) / 1.0;
  const std::vector<SpeedEvent> port_events = {{1, 1.0}, {brake_at, 0.0}};
  const std::vector<SpeedEvent> star_events = {{2, -1.0}, {10, 0.25}};
  const double stop_at = brake_at + 1.0 / port.max_acceleration;  // 13 s

  // the speed commands' ramps end on whole steps (1 / 0.5 = 40 h, 1 / 0.2 = 100 h,
  // 1.25 / 0.2 = 125 h): the drum's trapezoidal update (winch.h) is exact for a piecewise
  // constant acceleration, so only rounding is left
  constexpr double kExactProfileTol = 1e-9;  // [m]
  // the length command arrives within two steps of the continuous time-optimal profile
  // (docs/winch.md "The drum"): the length within two steps' travel at full speed
  const double kStopProfileTol = 2.0 * h * port.max_speed;  // [m]
  // the cable's outboard mass is m' L exactly: rounding of the element masses
  constexpr double kMassRelTol = 1e-13;

  script.Apply(&sim);
  double worst_port = 0.0, worst_star = 0.0, worst_mass = 0.0, worst_stop = 0.0;
  int port_nodes_min = sim.num_nodes(0), port_nodes_max = sim.num_nodes(0);
  int star_nodes_min = sim.num_nodes(1), star_nodes_max = sim.num_nodes(1);
  const int steps = static_cast<int>(std::lround(20.0 / h));
  for (int i = 0; i < steps; ++i) {
    ASSERT_TRUE(sim.Step().ok()) << "step " << i;
    script.Apply(&sim);
    const double t = sim.time();
    const double port_ref = DrumLength(L0, port.max_acceleration, port_events, t);
    const double star_ref = DrumLength(model.cables[1].length, star.max_acceleration,
                                       star_events, t);
    const double port_err = std::abs(sim.cable_length(0) - port_ref);
    if (t < 6.0 - 0.5 * h || t > stop_at + 2.0 * h) {
      worst_port = std::max(worst_port, port_err);
    } else {
      worst_stop = std::max(worst_stop, port_err);
    }
    worst_star = std::max(worst_star, std::abs(sim.cable_length(1) - star_ref));
    // each cable: its unstretched length and mass are its drum's paid-out length
    for (int c = 0; c < 2; ++c) {
      const core::System& sys = sim.system();
      const double rest = sys.drum_length(c) + (sys.num_nodes(c) - 2) * sys.element_length(c);
      ASSERT_NEAR(rest, sim.cable_length(c), 1e-12 * sim.cable_length(c)) << "cable " << c;
      // the elements' rest lengths (RestLength: the drum element's first, on either cable)
      double rest_sum = 0.0;
      for (int e = 0; e < sys.NumElements(c); ++e) rest_sum += sys.RestLength(e, c);
      ASSERT_NEAR(rest_sum, sim.cable_length(c), 1e-12 * sim.cable_length(c)) << "cable " << c;
      const double mass = model.cables[c].mass_per_length * sim.cable_length(c);
      worst_mass = std::max(worst_mass, std::abs(CableMass(sys, c) / mass - 1.0));
    }
    port_nodes_min = std::min(port_nodes_min, sim.num_nodes(0));
    port_nodes_max = std::max(port_nodes_max, sim.num_nodes(0));
    star_nodes_min = std::min(star_nodes_min, sim.num_nodes(1));
    star_nodes_max = std::max(star_nodes_max, sim.num_nodes(1));
  }
  std::printf("port: L %.9f m at 20 s (70 expected), worst |L - analytic| %.3e m on the speed "
              "commands, %.3e m over the stop; nodes %d..%d\n",
              sim.cable_length(0), worst_port, worst_stop, port_nodes_min, port_nodes_max);
  std::printf("starboard: L %.9f m at 20 s (%.9f expected), worst |L - analytic| %.3e m; "
              "nodes %d..%d; worst outboard mass error %.3e\n",
              sim.cable_length(1),
              DrumLength(model.cables[1].length, star.max_acceleration, star_events, 20.0),
              worst_star, star_nodes_min, star_nodes_max, worst_mass);
  EXPECT_LE(worst_port, kExactProfileTol);
  EXPECT_LE(worst_star, kExactProfileTol);
  EXPECT_LE(worst_stop, kStopProfileTol);
  EXPECT_NEAR(sim.cable_length(0), 70.0, kExactProfileTol);  // exactly at its target
  EXPECT_EQ(sim.winch_speed(0), 0.0);
  EXPECT_NEAR(sim.winch_speed(1), 0.25, kExactProfileTol);
  EXPECT_LE(worst_mass, kMassRelTol);
  // both drums changed their meshes: port split (60 -> 70 m), starboard merged (60 -> 52.2 m)
  EXPECT_GT(port_nodes_max, port_nodes_min);
  EXPECT_LT(star_nodes_min, star_nodes_max);
  // the commands held are the script's last, each on its own winch
  EXPECT_EQ(sim.winch_command(0).mode, core::WinchCommand::Mode::kLength);
  EXPECT_EQ(sim.winch_command(0).value, 70.0);
  EXPECT_EQ(sim.winch_command(1).mode, core::WinchCommand::Mode::kSpeed);
  EXPECT_EQ(sim.winch_command(1).value, 0.25);
}

// each drum alone: the port cable as a one-cable scene under the same commands gives the
// same drum and the same cable. The network's two cables share no body, so each cable's solve
// is its own; what is global is the solvers' stopping: the static start's and each step's
// Newton test and the kept Newton matrix's refresh (its contraction rate is measured on the
// whole system, and the starboard drum's merge drops it). Started straight and without winch
// commands the two runs are bit-identical; with the static start they differ by 2.0e-6 m, the
// static solve's tolerance, the same with or without the drums moving; started straight with
// the drums moving, by 3.3e-6 m from the refreshes.
TEST(WinchNetworkCore, EachDrumAsIfAlone) {
  const core::Model model = scene::LoadScene(kScene);
  core::Model alone = model;
  alone.cables.resize(1);
  alone.spheres.resize(1);
  alone.script.clear();
  for (const core::ScriptEntry& e : model.script)
    if (e.winch_index == 0) alone.script.push_back(e);
  ASSERT_EQ(alone.script.size(), 2u);
  core::Simulation both(model), one(alone);
  core::ScriptRunner both_script(model), one_script(alone);
  both_script.Apply(&both);
  one_script.Apply(&one);
  // the drums' kinematics do not depend on the cable: identical; the cable to the solvers'
  // tolerance: integrator.tolerance 1e-8 relative to the state's scale, ~60 m here, 6e-7 m a
  // solve, of which a few add up (measured 2.0e-6 m from the static start alone, above)
  constexpr double kSameCableTol = 1e-5;  // [m]
  double worst = 0.0;
  for (int i = 0; i < static_cast<int>(std::lround(20.0 / model.time.step)); ++i) {
    ASSERT_TRUE(both.Step().ok());
    ASSERT_TRUE(one.Step().ok());
    both_script.Apply(&both);
    one_script.Apply(&one);
    ASSERT_EQ(both.cable_length(0), one.cable_length(0)) << "t " << both.time();
    ASSERT_EQ(both.num_nodes(0), one.num_nodes(0)) << "t " << both.time();
    for (int n = 0; n < one.num_nodes(0); ++n)
      worst = std::max(worst, (both.node_position(n, 0) - one.node_position(n, 0)).norm());
  }
  std::printf("port cable in the network against alone: worst node distance %.3e m\n", worst);
  EXPECT_LE(worst, kSameCableTol);
}

}  // namespace
}  // namespace towsim
