// An external vessel over DDS (docs/vessels.md "External vessels"): the real sim_node in
// lockstep with a ship `external: true`, fed step by step by towsim_vessel_feed from a time
// history, against sim_node offline with the same ship given the same file as its
// `time_history:`. The oracle is the offline run: bodies.csv, cable.csv and forces.csv are
// byte-identical, status.csv too without its wall-clock column (the poses cross the wire as
// doubles, the node applies them at its own step times and reports and attaches the ship by
// the attitude and twist as given). And a node in fast mode with nobody feeding the ship:
// it runs on, the ship carried at the scene's speed, every step counted missing in the
// summary, the warning said once. DDS domains 224 and 225.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testing/process.h"
#include "testing/sim_node.h"
#include "testing/test_logs.h"

namespace towsim::testing {
namespace {

constexpr double kDuration = 6.0;        // [s] of simulated time: 120 steps of 0.05 s
constexpr double kProcessTimeout = 120;  // [s] of wall time for a process
// the ship's position carried by its scene speed: 2 m/s x 6 s, sums of 120 steps of 0.05 s
constexpr double kCarriedTol = 1e-9;  // [m]

// a ship towing a sphere on a short cable; `ship`: the ship's keys after its type. The cable
// starts at rest in both runs (initial_velocity given: otherwise it takes the vessel's
// velocity at t = 0, the scene speed of the external ship or the history's rate).
std::string Scene(const std::string& ship) {
  return "name: ship_feed\n"
         "time: {step: 0.05, duration: 6, output_rate: 20}\n"
         "cable: {length: 60, elements: 6, diameter: 0.03, density: 1300, youngs_modulus: 1e9,\n"
         "        initial: straight, initial_velocity: [0, 0, 0],\n"
         "        start: {body: ship, at: [-25, 0, -2]}, end: {body: fish}}\n"
         "bodies:\n"
         "  ship: {type: vessel, " +
         ship +
         "}\n"
         "  fish: {type: sphere, mass: 300, volume: 0.15, drag_coefficient: 0.6,\n"
         "         added_mass_coefficient: 0.5, position: [-75, 0, 30]}\n";
}

// the ship's motion, sampled every 0.1 s over 8 s: 2 m/s ahead, a slow sway, heave, roll and
// pitch at wave periods, a slow turn; the first sample at the origin, level (the external
// scene's position, no euler_deg)
std::string History() {
  std::ostringstream s;
  s << "# t [s], x y z [m] world NED, roll pitch yaw [rad]\nt,x,y,z,roll,pitch,yaw\n";
  char line[256];
  const double kTwoPi = 2.0 * M_PI;
  for (int i = 0; i <= 80; ++i) {
    const double t = 0.1 * i;
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", t, 2.0 * t,
                  0.5 * std::sin(0.3 * t), -0.4 * std::sin(kTwoPi * t / 5.0),
                  0.05 * std::sin(kTwoPi * t / 7.0), 0.03 * std::sin(kTwoPi * t / 5.0) * t / 8.0,
                  0.02 * t);
    s << line;
  }
  return s.str();
}

void Write(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  ASSERT_TRUE(out.good()) << path;
}

// status.csv without its column wall_us (t,step,newton_iterations,residual,wall_us,...)
std::string WithoutWallTime(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, out;
  while (std::getline(in, line)) {
    size_t at = 0;
    for (int comma = 0; comma < 4 && at != std::string::npos; ++comma) at = line.find(',', at + 1);
    const size_t next = at == std::string::npos ? at : line.find(',', at + 1);
    out += (at == std::string::npos
                ? line
                : line.substr(0, at) + (next == std::string::npos ? "" : line.substr(next))) +
           "\n";
  }
  return out;
}

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(VesselFeed, ALockstepFeedGivesTheRunOfTheTimeHistory) {
  const std::string dir = LogPrefix("scenes");
  std::filesystem::create_directories(dir);
  Write(dir + "/track.csv", History());
  Write(dir + "/logged.yaml", Scene("time_history: track.csv"));
  Write(dir + "/fed.yaml", Scene("external: true, position: [0, 0, 0]"));

  // the oracle: offline, the ship from its time history
  const std::string offline_csv = dir + "/offline_csv";
  Process offline(
      {TOWSIM_SIM_NODE, "--scene", dir + "/logged.yaml", "--mode", "offline", "--csv", offline_csv},
      LogPrefix("offline"));
  ASSERT_TRUE(offline.Wait(kProcessTimeout));
  ASSERT_EQ(offline.exit_code(), 0) << offline.err();

  // the feeder first: lockstep waits for the ship's initial pose before its first state
  Process feeder(
      {TOWSIM_VESSEL_FEED, "--vessel", "ship", "--history", dir + "/track.csv", "--domain", "224"},
      LogPrefix("feeder"));
  SimNodeOptions o;
  o.scene = dir + "/fed.yaml";
  o.mode = "lockstep";
  o.domain = 224;
  o.duration = kDuration;
  SimNode node(o);
  const NodeResult end = node.Wait(kProcessTimeout);
  ASSERT_EQ(end.exit_code, 0) << node.log();
  ASSERT_TRUE(feeder.Wait(kProcessTimeout)) << feeder.err();
  EXPECT_EQ(feeder.exit_code(), 0) << feeder.err();
  // the pose of t = 0, then one per step
  EXPECT_EQ(feeder.out(), "towsim_vessel_feed: ship: 121 poses from " + dir + "/track.csv\n");
  EXPECT_NE(end.summary.find("120 steps"), std::string::npos) << end.summary;
  EXPECT_NE(end.summary.find("lockstep timeouts 0"), std::string::npos) << end.summary;
  EXPECT_NE(end.summary.find("vessel poses missing 0"), std::string::npos) << end.summary;
  EXPECT_NE(end.summary.find("commands 121 (rejected 0"), std::string::npos) << end.summary;

  for (const char* file : {"bodies.csv", "cable.csv", "forces.csv"}) {
    const std::string expected = ReadFile(offline_csv + "/" + file);
    const std::string got = ReadFile(node.csv_dir() + "/" + file);
    EXPECT_GT(Count(expected, "\n"), 240) << file;  // 121 output times
    EXPECT_TRUE(got == expected) << file << " differs from the offline run's";
  }
  const std::string status = WithoutWallTime(ReadFile(offline_csv + "/status.csv"));
  EXPECT_EQ(status.substr(0, status.find('\n')), "t,step,newton_iterations,residual,cable_length");
  EXPECT_EQ(WithoutWallTime(ReadFile(node.csv_dir() + "/status.csv")), status);
  // the ship moved as the history says: heave 0.4 m, 12 m ahead at the end
  const std::optional<OdometrySample> ship = node.odometry("ship");
  ASSERT_TRUE(ship.has_value());
  EXPECT_NEAR(ship->x, 12.0, 1e-3);  // the spline through samples of 2 t
}

TEST(VesselFeed, AMissingPoseIsCountedAndTheShipCarriedOn) {
  SimNodeOptions o;
  o.scene = LogPrefix("fed.yaml");
  Write(o.scene, Scene("external: true, position: [0, 0, 0], speed: 2"));
  o.mode = "fast";
  o.domain = 225;
  o.duration = kDuration;
  SimNode node(o);
  const NodeResult end = node.Wait(kProcessTimeout);
  ASSERT_EQ(end.exit_code, 0) << node.log();
  // every step went without its pose; said once on stderr
  EXPECT_NE(end.summary.find("120 steps"), std::string::npos) << end.summary;
  EXPECT_NE(end.summary.find("vessel poses missing 120"), std::string::npos) << end.summary;
  EXPECT_EQ(Count(node.log(), "warning: ship: no pose for t = 0.05 s (the end of step 0)"), 1)
      << node.log();
  EXPECT_EQ(Count(node.log(), "no pose for t ="), 1) << node.log();
  // the scene's motion carried on: 2 m/s north from the origin
  const std::optional<OdometrySample> ship = node.odometry("ship");
  ASSERT_TRUE(ship.has_value());
  EXPECT_NEAR(ship->t, kDuration, 1e-9);
  EXPECT_NEAR(ship->x, 2.0 * kDuration, kCarriedTol);
  EXPECT_NEAR(ship->y, 0.0, kCarriedTol);
  EXPECT_NEAR(ship->z, 0.0, kCarriedTol);
  EXPECT_NEAR(ship->u, 2.0, kCarriedTol);
}

}  // namespace
}  // namespace towsim::testing
