// sim_node/dds/markers: the MarkerArray of a scene (docs/frames.md) against the state it is
// drawn from: the cable's points are the CableState positions in `world` (ENU, converted here
// by the axis permutation of REP-103, not by the library's helper), the colours follow the
// legend, hulls and fins have the vehicle file's dimensions, the force arrows the end forces.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/script.h"
#include "core/simulation.h"
#include "dds/markers.h"
#include "dds/translators.h"
#include "network_scene.h"
#include "scene/scene_loader.h"

namespace towsim::dds {
namespace {

constexpr double kExact = 0.0;        // copied or permuted numbers
constexpr double kScaledTol = 1e-12;  // a force times a scale [m]: rounding only
constexpr float kColorTol = 1e-6f;    // float32 channels

constexpr const char* kScene = R"(
name: dds_markers
time: {step: 0.05, duration: 1, output_rate: 10}
cable:
  length: 200
  elements: 10
  diameter: 0.041
  density: 1300
  youngs_modulus: 7.0e8
  initial: vertical
  start: {body: tow_vehicle, at: [0, 0, 0.2]}
  end: {body: towfish, at: [1.65, 0, 0]}
bodies:
  tow_vehicle: {model: ../vehicles/tow_vehicle.yaml, position: [0, 0, 3.5], euler_deg: [0, 0, 30]}
  towfish: {model: ../vehicles/towfish.yaml, position: [-1.65, 0, 203.7]}
script:
  - {at: 0, body: tow_vehicle, thrust: 4165}
)";

const MarkerMsg* Find(const MarkerArrayMsg& a, const std::string& ns, int id) {
  for (uint32_t i = 0; i < a.markers._length; ++i) {
    const MarkerMsg& m = a.markers._buffer[i];
    if (ns == m.ns && m.id == id) return &m;
  }
  return nullptr;
}

core::Model Load(const char* yaml) {
  return scene::LoadSceneFromString(yaml, "dds_markers.yaml",
                                    std::string(TOWSIM_SOURCE_DIR) + "/config/scenes");
}

// `steps` steps with the scene's script; false on a solver failure
bool StepScripted(const core::Model& model, int steps, core::Simulation* sim) {
  core::ScriptRunner script(model);
  for (int k = 0; k < steps; ++k) {
    script.Apply(sim);
    if (!sim->Step().ok()) return false;
  }
  return true;
}

TEST(TensionColorTest, LegendFromBlueThroughGreenToRed) {
  auto expect = [](double t, float r, float g, float b) {
    const ColorMsg c = TensionColor(t);
    EXPECT_NEAR(c.r, r, kColorTol) << t;
    EXPECT_NEAR(c.g, g, kColorTol) << t;
    EXPECT_NEAR(c.b, b, kColorTol) << t;
    EXPECT_EQ(c.a, 1.0f);
  };
  expect(0.0, 0, 0, 1);
  expect(-100.0, 0, 0, 1);  // compression: blue
  expect(0.25 * kTensionLegendMax, 0, 0.5f, 0.5f);
  expect(0.5 * kTensionLegendMax, 0, 1, 0);
  expect(0.75 * kTensionLegendMax, 0.5f, 0.5f, 0);
  expect(kTensionLegendMax, 1, 0, 0);
  expect(3 * kTensionLegendMax, 1, 0, 0);
}

TEST(SceneMarkersTest, DrawsTheStateItWasUpdatedFrom) {
  const core::Model model = Load(kScene);
  core::Simulation sim(model);
  SceneMarkers markers(sim);
  ASSERT_TRUE(StepScripted(model, 10, &sim));
  markers.Update(sim);
  const MarkerArrayMsg& a = markers.msg;

  // the cable: CableState's positions (NED) permuted to ENU (x_E = y_N, y_E = x_N, z_E = -z_N)
  CableStateMessage state(kWorldFrame, sim.num_nodes());
  ToCableState(sim, 10, &state);
  const MarkerMsg* cable = Find(a, "cable", 0);
  ASSERT_NE(cable, nullptr);
  EXPECT_EQ(cable, &a.markers._buffer[markers.cable_marker()]);
  EXPECT_STREQ(cable->header.frame_id, "world");
  EXPECT_EQ(cable->type, visualization_msgs_msg_dds__Marker_Constants_LINE_STRIP);
  EXPECT_EQ(cable->header.stamp.sec, state.msg.header.stamp.sec);
  EXPECT_EQ(cable->header.stamp.nanosec, state.msg.header.stamp.nanosec);
  ASSERT_EQ(cable->points._length, state.msg.positions._length);
  ASSERT_EQ(cable->colors._length, state.msg.positions._length);
  for (uint32_t i = 0; i < cable->points._length; ++i) {
    const auto& p = cable->points._buffer[i];
    const auto& n = state.msg.positions._buffer[i];
    EXPECT_NEAR(p.x, n.y, kExact);
    EXPECT_NEAR(p.y, n.x, kExact);
    EXPECT_NEAR(p.z, -n.z, kExact);
    const ColorMsg c = TensionColor(state.msg.tensions._buffer[i]);
    EXPECT_EQ(cable->colors._buffer[i].r, c.r);
    EXPECT_EQ(cable->colors._buffer[i].b, c.b);
  }
  EXPECT_GT(state.msg.tensions._buffer[0], 0.0);  // a towed cable: not all blue

  // hulls: cylinders of the vehicle files' length and diameter, axis along the body x
  const MarkerMsg* hull = Find(a, "hull", 0);
  ASSERT_NE(hull, nullptr);
  EXPECT_STREQ(hull->header.frame_id, "tow_vehicle");
  EXPECT_EQ(hull->type, visualization_msgs_msg_dds__Marker_Constants_CYLINDER);
  EXPECT_EQ(hull->scale.z, 8.2);
  EXPECT_EQ(hull->scale.x, 1.0);
  EXPECT_TRUE(hull->frame_locked);
  const auto& o = hull->pose.orientation;
  const core::Vec3 axis = Eigen::Quaterniond(o.w, o.x, o.y, o.z) * core::Vec3::UnitZ();
  EXPECT_NEAR((axis - core::Vec3::UnitX()).norm(), 0.0, kScaledTol);
  const MarkerMsg* fish = Find(a, "hull", 1);
  ASSERT_NE(fish, nullptr);
  EXPECT_EQ(fish->scale.z, 3.3);
  EXPECT_EQ(fish->scale.x, 0.47);

  // fins: one plate per lifting surface, at its centre of pressure (FRD -> FLU), its area
  int fins = 0;
  for (const core::Vehicle& v : model.vehicles) {
    for (const core::LiftingSurface& s : v.params.surfaces) {
      const MarkerMsg* f = Find(a, "fins", fins++);
      ASSERT_NE(f, nullptr) << s.name;
      EXPECT_EQ(std::string(f->header.frame_id), v.name);
      EXPECT_EQ(f->pose.position.x, s.position_B.x());
      EXPECT_EQ(f->pose.position.y, -s.position_B.y());
      EXPECT_EQ(f->pose.position.z, -s.position_B.z());
      EXPECT_NEAR(f->scale.x * f->scale.y, s.area, 1e-12) << s.name;
      // the plate's thin axis (z) is the surface normal, FRD -> FLU
      const auto& q = f->pose.orientation;
      const core::Vec3 n = Eigen::Quaterniond(q.w, q.x, q.y, q.z) * core::Vec3::UnitZ();
      const core::Vec3 expected(s.normal_B.x(), -s.normal_B.y(), -s.normal_B.z());
      EXPECT_NEAR((n - expected.normalized()).norm(), 0.0, 1e-12) << s.name;
    }
  }
  EXPECT_GT(fins, 0);
  EXPECT_EQ(Find(a, "fins", fins), nullptr);

  // force arrows: from the end node along the end force, kForceArrowScale m/N, in world (ENU)
  for (int e = 0; e < 2; ++e) {
    const MarkerMsg* arrow = Find(a, "cable_force", e);
    ASSERT_NE(arrow, nullptr);
    ASSERT_EQ(arrow->points._length, 2u);
    const core::Vec3 node = sim.node_position(e == 0 ? 0 : sim.num_nodes() - 1);
    const core::Vec3 f = sim.end_force(e);
    const auto& p0 = arrow->points._buffer[0];
    const auto& p1 = arrow->points._buffer[1];
    EXPECT_EQ(p0.x, node.y());
    EXPECT_EQ(p0.y, node.x());
    EXPECT_EQ(p0.z, -node.z());
    EXPECT_NEAR(p1.x - p0.x, kForceArrowScale * f.y(), kScaledTol);
    EXPECT_NEAR(p1.y - p0.y, kForceArrowScale * f.x(), kScaledTol);
    EXPECT_NEAR(p1.z - p0.z, -kForceArrowScale * f.z(), kScaledTol);
    EXPECT_GT(f.norm(), 100.0);
  }
}

// a network (tests/unit/network_scene.h): one line strip per cable (ns "cable", id c) with that
// cable's CableState points in ENU and colours by its tensions, one arrow per held end
// (ns "cable_force", id 2c + e) along that end's force
TEST(SceneMarkersTest, DrawsEveryCableOfANetwork) {
  const core::Model model = test::LoadNetwork();
  core::Simulation sim(model);
  SceneMarkers markers(sim);
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(sim.Step().ok());
  markers.Update(sim);
  const MarkerArrayMsg& a = markers.msg;
  // two cables, two spheres, four arrows; no sea
  EXPECT_EQ(a.markers._length, 2u + 2u + 4u);
  for (int c = 0; c < 2; ++c) {
    SCOPED_TRACE(sim.cable_name(c));
    CableStateMessage state(kWorldFrame, MaxCableNodes(sim, c));
    ToCableState(sim, 5, &state, c);
    const MarkerMsg* cable = Find(a, "cable", c);
    ASSERT_NE(cable, nullptr);
    EXPECT_EQ(cable, &a.markers._buffer[markers.cable_marker(c)]);
    EXPECT_EQ(cable->type, visualization_msgs_msg_dds__Marker_Constants_LINE_STRIP);
    EXPECT_STREQ(cable->header.frame_id, "world");
    ASSERT_EQ(cable->points._length, state.msg.node_count);
    ASSERT_EQ(cable->colors._length, state.msg.node_count);
    for (uint32_t i = 0; i < cable->points._length; ++i) {
      const auto& p = cable->points._buffer[i];
      const auto& n = state.msg.positions._buffer[i];
      EXPECT_NEAR(p.x, n.y, kExact);
      EXPECT_NEAR(p.y, n.x, kExact);
      EXPECT_NEAR(p.z, -n.z, kExact);
      const ColorMsg col = TensionColor(state.msg.tensions._buffer[i]);
      EXPECT_EQ(cable->colors._buffer[i].r, col.r);
      EXPECT_EQ(cable->colors._buffer[i].g, col.g);
      EXPECT_EQ(cable->colors._buffer[i].b, col.b);
    }
    for (int e = 0; e < 2; ++e) {
      const MarkerMsg* arrow = Find(a, "cable_force", 2 * c + e);
      ASSERT_NE(arrow, nullptr) << e;
      ASSERT_EQ(arrow->points._length, 2u);
      const core::Vec3 node = sim.node_position(e == 0 ? 0 : sim.num_nodes(c) - 1, c);
      const core::Vec3 f = sim.end_force(e, c);
      const auto& p0 = arrow->points._buffer[0];
      const auto& p1 = arrow->points._buffer[1];
      EXPECT_EQ(p0.x, node.y());
      EXPECT_EQ(p0.y, node.x());
      EXPECT_EQ(p0.z, -node.z());
      EXPECT_NEAR(p1.z - p0.z, -kForceArrowScale * f.z(), kScaledTol);
      EXPECT_GT(f.norm(), 100.0);  // the hanging weight below
    }
  }
  EXPECT_EQ(Find(a, "cable", 2), nullptr);
  EXPECT_EQ(Find(a, "cable_force", 4), nullptr);
}

// the scene of kScene in a sea: a regular wave and a sloping seabed (deeper toward north-east)
constexpr const char* kSeaScene = R"(
name: dds_markers_sea
time: {step: 0.05, duration: 1, output_rate: 10}
environment:
  waves: {regular: {height: 2, period: 8, direction_deg: 30, phase_deg: 40}}
  seabed: {depth: 260, slope_deg: 2, slope_direction_deg: 45}
cable:
  length: 200
  elements: 10
  diameter: 0.041
  density: 1300
  youngs_modulus: 7.0e8
  initial: vertical
  start: {body: tow_vehicle, at: [0, 0, 0.2]}
  end: {body: towfish, at: [1.65, 0, 0]}
bodies:
  tow_vehicle: {model: ../vehicles/tow_vehicle.yaml, position: [33, -17, 3.5], euler_deg: [0, 0, 30]}
  towfish: {model: ../vehicles/towfish.yaml, position: [31.35, -17, 203.7]}
script:
  - {at: 0, body: tow_vehicle, thrust: 4165}
)";

// Airy elevation of the wave: the scene's H / 2 [m]
constexpr double kAmplitude = 1.0;
// the marker's heights against core's WaveField::Elevation (the same Airy sum, per point instead
// of the grid's separated sines and cosines): rounding of a phase of O(10) rad on a 1 m
// amplitude, ~1e-14 m
constexpr double kElevationTol = 1e-12;
// the seabed's plane d_0 + tan(slope) (x cos c + y sin c), evaluated here: rounding of a
// depth of O(300) m
constexpr double kDepthTol = 1e-10;

TEST(SceneMarkersTest, SeaSurfaceAndSeabedPatchesAroundTheTowVehicle) {
  const core::Model model = Load(kSeaScene);
  core::Simulation sim(model);
  SceneMarkers markers(sim);
  ASSERT_TRUE(StepScripted(model, 10, &sim));
  markers.Update(sim);
  const MarkerMsg* sea = Find(markers.msg, "sea_surface", 0);
  const MarkerMsg* bed = Find(markers.msg, "seabed", 0);
  ASSERT_NE(sea, nullptr);
  ASSERT_NE(bed, nullptr);
  for (const MarkerMsg* m : {sea, bed}) {
    EXPECT_STREQ(m->header.frame_id, "world_ned");
    EXPECT_EQ(m->type, visualization_msgs_msg_dds__Marker_Constants_TRIANGLE_LIST);
    EXPECT_EQ(m->header.stamp.sec, 0);
    EXPECT_EQ(m->header.stamp.nanosec, 500000000u);  // 10 steps of 0.05 s
    ASSERT_EQ(m->points._length, 6u * kSeaPatchCells * kSeaPatchCells);
  }
  ASSERT_EQ(sea->colors._length, sea->points._length);

  // the tow vehicle is the one with a propeller; the patch's centre is the grid corner
  // nearest it, and every vertex is a corner of the fixed lattice
  const int tow = markers.patch_body();
  ASSERT_GE(tow, 0);
  EXPECT_EQ(sim.body_name(tow), "tow_vehicle");
  const core::Vec3 p_tow = sim.body_position(tow);
  double x_min = 1e300, x_max = -1e300, y_min = 1e300, y_max = -1e300;
  const double t = sim.time();
  const double slope = 2.0 * core::kPi / 180.0, c = 45.0 * core::kPi / 180.0;
  double eta_lo = 1e300, eta_hi = -1e300;
  for (uint32_t k = 0; k < sea->points._length; ++k) {
    const auto& p = sea->points._buffer[k];
    const auto& q = bed->points._buffer[k];
    EXPECT_EQ(p.x, q.x);
    EXPECT_EQ(p.y, q.y);
    x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x);
    y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
    EXPECT_NEAR(p.x / kSeaPatchCellSize, std::round(p.x / kSeaPatchCellSize), 1e-12);
    EXPECT_NEAR(p.y / kSeaPatchCellSize, std::round(p.y / kSeaPatchCellSize), 1e-12);
    // NED: the surface at z = -eta, the bottom at z = d
    const double eta = model.environment.waves.Elevation(p.x, p.y, t);
    EXPECT_NEAR(p.z, -eta, kElevationTol) << k;
    EXPECT_NEAR(q.z, 260.0 + std::tan(slope) * (q.x * std::cos(c) + q.y * std::sin(c)), kDepthTol)
        << k;
    eta_lo = std::min(eta_lo, eta), eta_hi = std::max(eta_hi, eta);
    // the legend: s = eta / (2 a) + 1/2, deep blue at a trough, pale blue at a crest
    const double shade = 0.5 + eta / (2.0 * kAmplitude);
    const ColorMsg& col = sea->colors._buffer[k];
    EXPECT_NEAR(col.r, 0.6 * shade, kColorTol);
    EXPECT_NEAR(col.g, 0.15 + 0.7 * shade, kColorTol);
    EXPECT_NEAR(col.b, 0.45 + 0.55 * shade, kColorTol);
    EXPECT_EQ(col.a, kSeaAlpha);
  }
  // a 200 m square whose centre is within half a cell of the vehicle in x and y
  const double side = kSeaPatchCells * kSeaPatchCellSize;
  EXPECT_NEAR(x_max - x_min, side, 1e-9);
  EXPECT_NEAR(y_max - y_min, side, 1e-9);
  EXPECT_LE(std::abs(0.5 * (x_min + x_max) - p_tow.x()), 0.5 * kSeaPatchCellSize + 1e-9);
  EXPECT_LE(std::abs(0.5 * (y_min + y_max) - p_tow.y()), 0.5 * kSeaPatchCellSize + 1e-9);
  // the patch spans more than a wavelength (~100 m at 8 s in 260 m of water): crest and trough
  EXPECT_GT(eta_hi, 0.9 * kAmplitude);
  EXPECT_LT(eta_lo, -0.9 * kAmplitude);
}

TEST(SceneMarkersTest, NoSeaPatchesInACalmBottomlessScene) {
  const core::Model model = Load(kScene);
  core::Simulation sim(model);
  SceneMarkers markers(sim);
  EXPECT_EQ(Find(markers.msg, "sea_surface", 0), nullptr);
  EXPECT_EQ(Find(markers.msg, "seabed", 0), nullptr);
}

}  // namespace
}  // namespace towsim::dds
