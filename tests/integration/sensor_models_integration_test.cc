// Sensor models through a real node (docs/sensors.md "Sensor models"): sim_node in fast mode
// with the two-part tow (tests/integration/scenes/network_two_part_tow.yaml), once with perfect
// sensors and once with the towfish's odometry given a rate, a latency and a bias by --set.
// The fast run is deterministic, so the second run's towfish odometry at step n must be the
// first run's at step max(0, n - L) plus the bias, exactly, published only at the rate's sample
// instants; the depressor, without sensor keys, publishes the same odometry in both runs. DDS
// domain 227 (held through DomainLease by the fixture).

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testing/sim_node.h"

namespace towsim::testing {
namespace {

constexpr double kStep = 0.05;  // the scene's time.step [s]

// the odometry samples of `body` of one run by step
std::map<long, OdometrySample> ByStep(const SimNode& node, const std::string& body) {
  std::map<long, OdometrySample> out;
  for (const OdometrySample& o : node.odometry_history(body)) out[std::lround(o.t / kStep)] = o;
  return out;
}

SimNodeOptions Options(std::vector<std::string> set) {
  SimNodeOptions o;
  o.scene = std::string(TOWSIM_SOURCE_DIR) + "/tests/integration/scenes/network_two_part_tow.yaml";
  o.mode = "fast";
  o.domain = 227;
  o.duration = 3.0;
  o.set = std::move(set);
  o.set.push_back("publish.odom=0");  // every step
  return o;
}

TEST(SensorModelsOnTheWire, OdometryRateLatencyAndBiasAgainstThePerfectRun) {
  std::map<long, OdometrySample> truth, depressor_truth;
  {
    SimNode node(Options({}));
    ASSERT_EQ(node.Wait(60.0).exit_code, 0) << node.log();
    truth = ByStep(node, "towfish");
    depressor_truth = ByStep(node, "depressor");
  }
  const int latency = 3;
  const double bias = 10.0;
  const double rate = 4.0;  // every 5 steps at h = 0.05 s
  SimNode node(Options({"bodies.towfish.sensors.odometry.rate=4",
                        "bodies.towfish.sensors.odometry.latency_steps=3",
                        "bodies.towfish.sensors.odometry.bias=10"}));
  ASSERT_EQ(node.Wait(60.0).exit_code, 0) << node.log();
  const std::map<long, OdometrySample> modelled = ByStep(node, "towfish");
  const std::map<long, OdometrySample> depressor = ByStep(node, "depressor");

  ASSERT_GE(truth.size(), 10u) << "too few samples of the perfect run arrived";
  ASSERT_GE(modelled.size(), 3u);
  int compared = 0;
  for (const auto& [n, o] : modelled) {
    // the sample instants of 4 Hz at 0.05 s: every 5th step
    EXPECT_EQ(n % 5, 0) << "step " << n;
    // before step L the first measurement
    const auto t = truth.find(n < latency ? 0 : n - latency);
    if (t == truth.end()) continue;  // that sample of the perfect run was not taken
    EXPECT_EQ(o.x, t->second.x + bias) << n;
    EXPECT_EQ(o.y, t->second.y + bias) << n;
    EXPECT_EQ(o.z, t->second.z + bias) << n;
    EXPECT_EQ(o.u, t->second.u) << n;  // no velocity bias given
    EXPECT_EQ(o.qw, t->second.qw) << n;
    ++compared;
  }
  EXPECT_GE(compared, 3);
  // at most rate T + 1 samples in T = 3 s (steps 0, 5, ..., 60: 13)
  EXPECT_LE(static_cast<double>(modelled.size()), rate * 3.0 + 1.0);
  // the depressor's sensors are perfect in both runs
  int same = 0;
  for (const auto& [n, o] : depressor) {
    const auto t = depressor_truth.find(n);
    if (t == depressor_truth.end()) continue;
    EXPECT_EQ(o.x, t->second.x) << n;
    EXPECT_EQ(o.z, t->second.z) << n;
    ++same;
  }
  EXPECT_GE(same, 10);
}

}  // namespace
}  // namespace towsim::testing
