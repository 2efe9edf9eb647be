// The shipped scenes towed by a ship (config/scenes/case3_waves_ship.yaml,
// two_part_tow_ship.yaml; docs/vessels.md) run through their first 150 s, and what they are for
// shows: the ship's tow point moves with the waves (its vertical motion from the RAOs), and in
// the two-part tow the depressor takes most of it out of the towfish's motion.
//
// Measured over 50-150 s (after the sea's 20 s ramp and the start): the standard deviation of
// the tow point's depth, the depressor's and the towfish's. The bounds are the scene's
// purpose, not fitted numbers: the tow point must move (more than 0.1 m: a ship in Hs 2 m), and
// the towfish behind the depressor must move less than half as much as the tow point.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/simulation.h"
#include "scene/scene_loader.h"

namespace towsim::reference {
namespace {

const std::string kScenes = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/";

double StdDev(const std::vector<double>& x) {
  double mean = 0.0, var = 0.0;
  for (double v : x) mean += v / x.size();
  for (double v : x) var += (v - mean) * (v - mean) / x.size();
  return std::sqrt(var);
}

struct Motion {
  double tow_point = 0.0, depressor = 0.0, towfish = 0.0;
};

Motion RunScene(const std::string& scene) {
  const core::Model model = scene::LoadScene(kScenes + scene);
  core::Simulation sim(model);
  std::vector<double> top, dep, fish;
  int ship = -1, depressor = -1, towfish = -1;
  for (int b = 0; b < sim.num_bodies(); ++b) {
    if (sim.body_name(b) == "ship") ship = b;
    if (sim.body_name(b) == "depressor") depressor = b;
    if (sim.body_name(b) == "towfish") towfish = b;
  }
  EXPECT_GE(ship, 0);
  EXPECT_TRUE(sim.body_is_vessel(ship));
  while (sim.time() < 150.0 - 1e-9) {
    const core::StepStatus s = sim.Step();
    if (!s.ok()) {
      ADD_FAILURE() << scene << ": " << s.message;
      return {};
    }
    if (sim.time() < 50.0) continue;
    top.push_back(sim.node_position(0).z());  // the first cable's start: the tow point
    if (depressor >= 0) dep.push_back(sim.body_position(depressor).z());
    fish.push_back(sim.body_position(towfish).z());
  }
  Motion m{StdDev(top), dep.empty() ? 0.0 : StdDev(dep), StdDev(fish)};
  std::printf("%s: depth std over 50-150 s: tow point %.3f m, depressor %.3f m, towfish %.3f m\n",
              scene.c_str(), m.tow_point, m.depressor, m.towfish);
  return m;
}

TEST(VesselScenes, CaseThreeTowedByAShip) {
  const Motion m = RunScene("case3_waves_ship.yaml");
  EXPECT_GT(m.tow_point, 0.1);
}

TEST(VesselScenes, TwoPartTowTowedByAShip) {
  const Motion m = RunScene("two_part_tow_ship.yaml");
  EXPECT_GT(m.tow_point, 0.1);
  EXPECT_LT(m.towfish, 0.5 * m.tow_point);
}

}  // namespace
}  // namespace towsim::reference
