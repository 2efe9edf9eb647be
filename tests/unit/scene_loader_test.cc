// scene/: YAML scene -> core::Model. Broken scenes must fail with the key path, the value,
// file:line and the rule in the message; the shipped scenes must load with the right numbers.

#include "scene/scene_loader.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/constants.h"

namespace towsim::scene {
namespace {

namespace fs = std::filesystem;
using Model = core::Model;

constexpr double kDeg = core::kPi / 180.0;

const std::string kConfigDir = std::string(TOWSIM_SOURCE_DIR) + "/config";
const std::string kSteadyTow = kConfigDir + "/scenes/steady_tow.yaml";
const std::string kCatenary = kConfigDir + "/scenes/catenary.yaml";

// A small valid scene: a 100 m cable hanging from a fixed point with a sphere at its lower end.
// The broken cases below each change one thing in it. Line numbers matter to the assertions.
constexpr const char* kScene = R"(name: t
time: {step: 0.01, duration: 1, output_rate: 10}
cable:
  length: 100
  elements: 10
  diameter: 0.04
  density: 1300
  youngs_modulus: 7.0e8
  loads: [gravity, buoyancy, drag]
  initial: vertical
  start: {fixed: [0, 0, 0]}
  end: {body: fish}
bodies:
  fish: {type: sphere, mass: 10, volume: 0.001, position: [0, 0, 100]}
integrator: {rho_inf: 0.8}
)";

// kScene with the first occurrence of `from` replaced by `to`
std::string Edit(const std::string& from, const std::string& to) {
  std::string text = kScene;
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << from << "' not in the base scene";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// A small 6-DOF vehicle with a propeller and a rudder (no elevators). Line numbers matter.
constexpr const char* kBoatFile = R"(type: vehicle
source: test
length: 2
mass: 100
inertia: [1, 10, 10]
r_g: [0, 0, 0.05]
volume: 0.1
added_mass: {x_udot: -5, y_vdot: -80, z_wdot: -80, m_qdot: -9, n_rdot: -9, y_rdot: 2, n_vdot: 2}
damping: {x_uu: -3, n_ur: -4}
surfaces:
  - {name: rudder, channel: rudder, position: [-1, 0, 0], normal: [0, 2, 0], area: 0.01,
     aspect_ratio: 2, oswald: 0.9, cd0: 0.01, stall_angle_deg: 20, deflection_sign: -1}
rudder: {max_deflection_deg: 30, max_rate_deg: 10}
propeller: {max_thrust: 400, time_constant: 0.5}
)";

// An unpowered vehicle with a wing only.
constexpr const char* kFish6File = R"(type: vehicle
source: test
length: 1
mass: 20
inertia: [0.1, 1, 1]
r_g: [0.1, 0, 0]
volume: 0.02
munk_moment: false
surfaces:
  - {name: wing, channel: none, position: [0, 0, 0], normal: [0, 0, -1], area: 0.05,
     aspect_ratio: 4, oswald: 0.8, cd0: 0.01, stall_angle_deg: 14}
)";

// A 100 m cable from the boat's CG (at [0, 0, 1.05]) straight down to the fish's bow
// ([0.5, 0, 0] ahead of its origin), with a script. Line numbers matter.
constexpr const char* kVehicleScene = R"(name: v
time: {step: 0.01, duration: 1, output_rate: 10}
cable:
  length: 100
  elements: 10
  diameter: 0.04
  density: 1300
  youngs_modulus: 7.0e8
  initial: vertical
  start: {body: boat, at: [0, 0, 0.05]}
  end: {body: fish, at: [0.5, 0, 0]}
bodies:
  boat: {model: boat.yaml, position: [0, 0, 1]}
  fish: {model: fish6.yaml, position: [-0.5, 0, 101.05]}
script:
  - {body: boat, thrust: 200}
  - {at: 5, body: boat, rudder_deg: 10}
  - {at: 5, when: "boat.yaw_deg >= 90", body: boat, rudder: 0}
)";

// `text` with the first occurrence of `from` replaced by `to`
std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << from << "' not in the text";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// kVehicleScene with one edit
std::string EditV(const std::string& from, const std::string& to) {
  return Replace(kVehicleScene, from, to);
}

// A folder with vehicle model files, one per test process (ctest runs tests in parallel).
class SceneLoaderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::path(::testing::TempDir()) / ("scene_loader_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "good_fish.yaml")
        << "source: test\ntype: sphere\nmass: 20\nvolume: 0.01\n";
    std::ofstream(dir_ / "bad_fish.yaml") << "type: sphere\nmass: 20\ncolour: red\n";
    std::ofstream(dir_ / "box_fish.yaml") << "type: box\nmass: 20\n";
    std::ofstream(dir_ / "broken_fish.yaml") << "type: sphere\nmass: [20\n";
    std::ofstream(dir_ / "boat.yaml") << kBoatFile;
    std::ofstream(dir_ / "fish6.yaml") << kFish6File;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static Model Load(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
    return LoadSceneFromString(yaml, "t.yaml", dir_.string(), overrides);
  }

  static fs::path dir_;
};
fs::path SceneLoaderTest::dir_;

TEST_F(SceneLoaderTest, BaseSceneLoads) {
  const Model m = Load(kScene);
  EXPECT_EQ(m.name, "t");
  EXPECT_EQ(m.cables[0].elements, 10);
  ASSERT_EQ(m.spheres.size(), 1u);
  EXPECT_EQ(m.cables[0].end.kind, core::EndKind::kSphere);
  EXPECT_EQ(m.cables[0].end.body, 0);
  EXPECT_TRUE(m.cables[0].loads.drag);
  EXPECT_FALSE(m.cables[0].loads.added_mass);
  EXPECT_FALSE(m.cables[0].loads.bending);
  // no driven end, no initial_velocity: bodies start at rest
  EXPECT_EQ(m.spheres[0].velocity, core::Vec3::Zero());
  // defaults
  EXPECT_EQ(m.environment.water_density, 1025.0);
  EXPECT_EQ(m.integrator.max_iterations, 20);
  EXPECT_EQ(m.cables[0].axial_damping, 0.0);
  EXPECT_EQ(m.cables[0].added_mass.normal, 1.0);
  EXPECT_EQ(m.cables[0].added_mass.tangential, 0.0);
  EXPECT_EQ(m.cables[0].drag.kind, core::CableDragLaw::kChooCasarella);
}

TEST_F(SceneLoaderTest, MessageHasKeyValueFileLineAndRule) {
  try {
    Load(Edit("elements: 10", "elements: 0"));
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "cable.elements = 0 (t.yaml:5): must be >= 1");
    EXPECT_EQ(e.key(), "cable.elements");
    EXPECT_EQ(e.value(), "0");
    EXPECT_EQ(e.location(), "t.yaml:5");
    EXPECT_EQ(e.rule(), "must be >= 1");
  }
}

TEST_F(SceneLoaderTest, QuotedValueKeepsItsQuotes) {
  try {
    Load(Edit("length: 100", "length: \"100\""));
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(),
                 "cable.length = \"100\" (t.yaml:4): must be a number, not a quoted string");
  }
}

// initial: straight with a span more than 1 % longer than the cable: the message gives the
// axial force that stretch would take, N = EA (span / length - 1), at the cable's EA as the
// reader resolves it (docs/scene_format.md, `initial`): from axial_stiffness, and from a line
// type's axial_stiffness
TEST_F(SceneLoaderTest, StraightSpanTooLongGivesTheForceAtTheCablesEA) {
  const std::string straight =
      "initial: straight\n  start: {fixed: [0, 0, 0]}\n  end: {fixed: [103.4, 0, 0]}";
  const std::string from = "initial: vertical\n  start: {fixed: [0, 0, 0]}\n  end: {body: fish}";
  // EA = 2.6e7 N given; eps = 0.034: N = 2.6e7 x 0.034 = 884000 N
  try {
    Load(Replace(Edit(from, straight), "youngs_modulus: 7.0e8", "axial_stiffness: 2.6e7"));
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "cable.end");
    EXPECT_EQ(e.rule(),
              "with initial: straight the span from start [0, 0, 0] to end [103.4, 0, 0] is "
              "103.4 m, which would stretch the 100 m cable by 3.4% (at most 1%): 884 kN at EA "
              "2.6e+07 N");
  }
  // EA = 5e6 N from the line type; eps = 0.02: N = 5e6 x 0.02 = 100000 N
  const std::string typed =
      Replace(Replace(Edit(from, Replace(straight, "103.4", "102")),
                      "  diameter: 0.04\n  density: 1300\n  youngs_modulus: 7.0e8\n",
                      "  line_type: wire\n"),
              "cable:\n", "line_types:\n  wire: {diameter: 0.04, mass_per_length: 1.6, "
                          "axial_stiffness: 5.0e6}\ncable:\n");
  try {
    Load(typed);
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "cable.end");
    EXPECT_NE(e.rule().find("by 2% (at most 1%): 100 kN at EA 5e+06 N"), std::string::npos)
        << e.what();
  }
}

struct BrokenCase {
  const char* name;
  std::string yaml;
  std::string key;       // expected key path
  std::string rule;      // expected part of the rule
  std::string location;  // expected location, when the case checks it
};

std::ostream& operator<<(std::ostream& out, const BrokenCase& c) { return out << c.name; }

class BrokenSceneTest : public SceneLoaderTest, public ::testing::WithParamInterface<BrokenCase> {};

TEST_P(BrokenSceneTest, ThrowsWithKeyAndRule) {
  const BrokenCase& c = GetParam();
  try {
    Load(c.yaml);
    FAIL() << "no ConfigError for " << c.name;
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.key(), c.key) << what;
    EXPECT_NE(e.rule().find(c.rule), std::string::npos) << what;
    // what() = "<key> = <value> (<location>): <rule>"
    EXPECT_EQ(what.rfind(c.key + " = ", 0), 0u) << what;
    EXPECT_NE(what.find(c.rule), std::string::npos) << what;
    EXPECT_EQ(what, e.key() + " = " + e.value() + " (" + e.location() + "): " + e.rule());
    if (!c.location.empty()) {
      EXPECT_EQ(e.location(), c.location) << what;
    }
  }
}

const std::string kFishLine =
    "fish: {type: sphere, mass: 10, volume: 0.001, position: [0, 0, 100]}";

INSTANTIATE_TEST_SUITE_P(
    Table, BrokenSceneTest,
    ::testing::Values(
        // required keys, reported at the parent's line
        BrokenCase{"missing_key", Edit("  length: 100\n", ""), "cable.length", "is required",
                   "t.yaml:3"},
        BrokenCase{"missing_name", Edit("name: t\n", ""), "name", "is required", ""},
        BrokenCase{"negative_publish_rate", Edit("name: t\n", "name: t\npublish: {odom: -5}\n"),
                   "publish.odom", ">= 0", ""},
        BrokenCase{"negative_sensors_rate",
                   Edit("name: t\n", "name: t\npublish: {sensors: -1}\n"), "publish.sensors",
                   ">= 0", ""},
        BrokenCase{"zero_command_timeout",
                   Edit("name: t\n", "name: t\npublish: {command_timeout: 0}\n"),
                   "publish.command_timeout", "> 0", ""},
        BrokenCase{"unknown_publish_key", Edit("name: t\n", "name: t\npublish: {odometry: 5}\n"),
                   "publish.odometry", "unknown key", ""},
        BrokenCase{"missing_end", Edit("  end: {body: fish}\n", ""), "cable.end", "is required",
                   ""},
        // types
        BrokenCase{"string_for_number", Edit("length: 100", "length: abc"), "cable.length",
                   "must be a number", "t.yaml:4"},
        BrokenCase{"quoted_number", Edit("length: 100", "length: \"100\""), "cable.length",
                   "must be a number, not a quoted string", ""},
        BrokenCase{"fractional_integer", Edit("elements: 10", "elements: 2.5"), "cable.elements",
                   "must be an integer", ""},
        BrokenCase{"map_for_vector", Edit("fixed: [0, 0, 0]", "fixed: {x: 0}"), "cable.start.fixed",
                   "must be a list of 3 numbers", ""},
        BrokenCase{"section_not_a_map", Edit("integrator: {rho_inf: 0.8}", "integrator: fast"),
                   "integrator", "must be a map", "t.yaml:15"},
        // ranges
        BrokenCase{"negative_length", Edit("length: 100", "length: -5"), "cable.length",
                   "must be > 0", ""},
        BrokenCase{"elements_zero", Edit("elements: 10", "elements: 0"), "cable.elements",
                   "must be >= 1", "t.yaml:5"},
        BrokenCase{"elements_too_many", Edit("elements: 10", "elements: 10001"), "cable.elements",
                   "must be <= 10000", ""},
        BrokenCase{"rho_inf_above_one", Edit("rho_inf: 0.8", "rho_inf: 1.5"), "integrator.rho_inf",
                   "must be <= 1", "t.yaml:15"},
        BrokenCase{"tolerance_too_loose", Edit("rho_inf: 0.8", "tolerance: 0.1"),
                   "integrator.tolerance", "must be <= 0.01", ""},
        BrokenCase{"force_tolerance_zero", Edit("rho_inf: 0.8", "force_tolerance: 0"),
                   "integrator.force_tolerance", "must be > 0", ""},
        BrokenCase{"force_tolerance_one", Edit("rho_inf: 0.8", "force_tolerance: 1"),
                   "integrator.force_tolerance", "must be < 1", ""},
        BrokenCase{"step_longer_than_duration", Edit("step: 0.01", "step: 2"), "time.step",
                   "must be <= time.duration (1)", ""},
        // non-finite numbers
        BrokenCase{"nan", Edit("density: 1300", "density: .nan"), "cable.density",
                   "must be a finite number", ""},
        BrokenCase{"inf", Edit("youngs_modulus: 7.0e8", "youngs_modulus: .inf"),
                   "cable.youngs_modulus", "must be a finite number", ""},
        BrokenCase{"nan_in_vector", Edit("position: [0, 0, 100]", "position: [0, 0, .nan]"),
                   "bodies.fish.position[2]", "must be a finite number", "t.yaml:14"},
        // vectors
        BrokenCase{"vector_of_two", Edit("fixed: [0, 0, 0]", "fixed: [0, 0]"), "cable.start.fixed",
                   "must be a list of 3 numbers [x, y, z] (it has 2)", "t.yaml:11"},
        // unknown and duplicate keys
        BrokenCase{"unknown_top_level_key", Edit("name: t\n", "name: t\ncolour: red\n"), "colour",
                   "unknown key", "t.yaml:2"},
        BrokenCase{"unknown_nested_key", Edit("length: 100", "lenght: 100"), "cable.lenght",
                   "unknown key; did you mean length?", "t.yaml:4"},
        BrokenCase{"unknown_end_key",
                   Edit("end: {body: fish}", "end: {body: fish, att: [0, 0, 0]}"), "cable.end.att",
                   "unknown key; did you mean at?", ""},
        BrokenCase{"duplicate_key", Edit("  elements: 10\n", "  elements: 10\n  elements: 12\n"),
                   "cable.elements", "duplicate key (first given at t.yaml:5)", "t.yaml:6"},
        // not YAML, not a map
        BrokenCase{"not_yaml", "name: t\ncable: {length: [100\n", "t.yaml", "not valid YAML", ""},
        BrokenCase{"not_a_map", "- just\n- a list\n", "t.yaml", "a scene must be a map", ""},
        BrokenCase{"empty_file", "", "t.yaml", "a scene must be a map", ""},
        // loads
        BrokenCase{"bad_load", Edit("[gravity, buoyancy, drag]", "[gravity, wind]"),
                   "cable.loads[1]", "must be one of gravity, buoyancy, drag, added_mass, bending",
                   ""},
        BrokenCase{"duplicate_load", Edit("[gravity, buoyancy, drag]", "[gravity, drag, gravity]"),
                   "cable.loads[2]", "duplicate load", ""},
        BrokenCase{"loads_not_a_list", Edit("[gravity, buoyancy, drag]", "gravity"), "cable.loads",
                   "must be a list", ""},
        // enums
        BrokenCase{"bad_initial", Edit("initial: vertical", "initial: curly"), "cable.initial",
                   "must be one of vertical, straight, static", ""},
        BrokenCase{"bad_coupling", Edit("rho_inf: 0.8", "coupling: loose"), "integrator.coupling",
                   "must be one of strong, staggered", "t.yaml:15"},
        BrokenCase{"coupling_iterations_zero", Edit("rho_inf: 0.8", "max_coupling_iterations: 0"),
                   "integrator.max_coupling_iterations", "must be >= 1", ""},
        BrokenCase{"coupling_iterations_fractional",
                   Edit("rho_inf: 0.8", "max_coupling_iterations: 2.5"),
                   "integrator.max_coupling_iterations", "must be an integer", ""},
        // ends
        BrokenCase{"unknown_end_body", Edit("end: {body: fish}", "end: {body: shark}"),
                   "cable.end.body", "no such body (bodies: fish)", "t.yaml:12"},
        BrokenCase{"two_end_kinds",
                   Edit("start: {fixed: [0, 0, 0]}", "start: {fixed: [0, 0, 0], free: true}"),
                   "cable.start", "must be exactly one of", ""},
        BrokenCase{"no_end_kind", Edit("start: {fixed: [0, 0, 0]}", "start: {}"), "cable.start",
                   "must be exactly one of", ""},
        BrokenCase{"free_false", Edit("start: {fixed: [0, 0, 0]}", "start: {free: false}"),
                   "cable.start.free", "must be true", ""},
        BrokenCase{"slope_on_body_end",
                   Edit("end: {body: fish}", "end: {body: fish, slope: [1, 0, 0]}"),
                   "cable.end.slope", "applies only to a fixed end", ""},
        BrokenCase{"zero_slope",
                   Edit("start: {fixed: [0, 0, 0]}", "start: {fixed: [0, 0, 0], slope: [0, 0, 0]}"),
                   "cable.start.slope", "must be a non-zero direction", ""},
        BrokenCase{"both_ends_free",
                   Edit("start: {fixed: [0, 0, 0]}\n  end: {body: fish}",
                        "start: {free: true}\n  end: {free: true}"),
                   "cable.end", "both ends are free", "t.yaml:12"},
        BrokenCase{"both_ends_on_one_body",
                   Edit("start: {fixed: [0, 0, 0]}", "start: {body: fish}"), "cable.end",
                   "start and end are both on body fish", ""},
        BrokenCase{"two_driven_ends",
                   Edit("start: {fixed: [0, 0, 0]}\n  end: {body: fish}",
                        "start: {driven: {position: [0, 0, 0], velocity: [1, 0, 0]}}\n"
                        "  end: {driven: {position: [0, 0, 100], velocity: [1, 0, 0]}}"),
                   "cable.end", "both ends are driven", ""},
        BrokenCase{"driven_without_velocity",
                   Edit("start: {fixed: [0, 0, 0]}", "start: {driven: {position: [0, 0, 0]}}"),
                   "cable.start.driven.velocity", "is required", ""},
        // initial shape geometry
        BrokenCase{
            "straight_too_long",
            Edit("initial: vertical\n  start: {fixed: [0, 0, 0]}\n  end: {body: fish}",
                 "initial: straight\n  start: {fixed: [0, 0, 0]}\n  end: {fixed: [110, 0, 0]}"),
            "cable.end",
            // N = EA (span / length - 1) = 7e8 Pa x pi 0.04^2 / 4 x 0.1 = 87965 N
            "would stretch the 100 m cable by 10% (at most 1%): 88 kN at EA 8.8e+05 N", ""},
        BrokenCase{
            "straight_zero_span",
            Edit("initial: vertical\n  start: {fixed: [0, 0, 0]}\n  end: {body: fish}",
                 "initial: straight\n  start: {fixed: [0, 0, 0]}\n  end: {fixed: [0, 0, 0]}"),
            "cable.end", "must not coincide with the start", ""},
        BrokenCase{"straight_free_end",
                   Edit("initial: vertical\n  start: {fixed: [0, 0, 0]}\n  end: {body: fish}",
                        "initial: straight\n  start: {fixed: [0, 0, 0]}\n  end: {free: true}"),
                   "cable.end", "initial: straight needs both ends at known positions", ""},
        BrokenCase{
            "vertical_misplaced_end_body", Edit("position: [0, 0, 100]", "position: [5, 0, 100]"),
            "cable.end",
            "with initial: vertical the end must sit at start + [0, 0, length] = [0, 0, 100]",
            "t.yaml:12"},
        BrokenCase{"vertical_misplaced_attachment",
                   Edit("end: {body: fish}", "end: {body: fish, at: [0, 0, 1]}"), "cable.end",
                   "but it is at [0, 0, 101], 1 m away", ""},
        BrokenCase{"vertical_free_start", Edit("start: {fixed: [0, 0, 0]}", "start: {free: true}"),
                   "cable.start", "initial: vertical hangs the cable from the start", ""},
        // bodies
        BrokenCase{"bad_body_name", Edit("  fish:", "  2fish:"), "bodies.2fish",
                   "body names must match [A-Za-z_][A-Za-z0-9_]*", ""},
        BrokenCase{"negative_mass", Edit("mass: 10", "mass: -1"), "bodies.fish.mass",
                   "must be >= 0", ""},
        BrokenCase{"body_without_position", Edit(", position: [0, 0, 100]", ""),
                   "bodies.fish.position", "is required", "t.yaml:14"},
        BrokenCase{"unknown_type", Edit("type: sphere", "type: box"), "bodies.fish.type",
                   "must be one of sphere, vehicle", "t.yaml:14"},
        BrokenCase{"missing_type", Edit("type: sphere, ", ""), "bodies.fish.type",
                   "is required (type: sphere, type: vehicle or type: vessel", ""},
        BrokenCase{"vehicle_key_on_sphere",
                   Edit("volume: 0.001,", "volume: 0.001, euler_deg: [0, 0, 90],"),
                   "bodies.fish.euler_deg", "applies only to type: vehicle", "t.yaml:14"},
        BrokenCase{"vehicle_param_on_sphere", Edit("volume: 0.001,", "volume: 0.001, length: 2,"),
                   "bodies.fish.length", "applies only to type: vehicle", ""},
        BrokenCase{"missing_model_file",
                   Edit(kFishLine, "fish: {model: nope.yaml, position: [0, 0, 100]}"),
                   "bodies.fish.model", "cannot read the model file", "t.yaml:14"},
        BrokenCase{"model_file_unknown_key",
                   Edit(kFishLine, "fish: {model: bad_fish.yaml, position: [0, 0, 100]}"),
                   "bodies.fish.colour", "unknown key", "bad_fish.yaml:3"},
        BrokenCase{"model_file_unknown_type",
                   Edit(kFishLine, "fish: {model: box_fish.yaml, position: [0, 0, 100]}"),
                   "bodies.fish.type", "must be one of sphere, vehicle", "box_fish.yaml:1"},
        BrokenCase{"model_file_not_yaml",
                   Edit(kFishLine, "fish: {model: broken_fish.yaml, position: [0, 0, 100]}"),
                   "bodies.fish.model", "not valid YAML", ""},
        BrokenCase{"position_in_model_file_only", Edit(kFishLine, "fish: {model: good_fish.yaml}"),
                   "bodies.fish.position", "is required", ""},
        // script
        BrokenCase{"script_for_sphere",
                   std::string(kScene) + "script:\n  - {at: 0, body: fish, thrust: 100}\n",
                   "script[0].body", "spheres take no commands", "t.yaml:17"},
        BrokenCase{"script_unknown_body",
                   std::string(kScene) + "script:\n  - {at: 0, body: boat, thrust: 100}\n",
                   "script[0].body", "no such body", ""},
        BrokenCase{"script_negative_time",
                   std::string(kScene) + "script:\n  - {at: -1, body: fish}\n", "script[0].at",
                   "must be >= 0", ""}),
    [](const ::testing::TestParamInfo<BrokenCase>& info) { return std::string(info.param.name); });

// broken vehicle scenes: the vehicle keys in the scene, the ends, the commands, the script
INSTANTIATE_TEST_SUITE_P(
    Vehicles, BrokenSceneTest,
    ::testing::Values(
        // bodies
        BrokenCase{
            "sphere_key_on_vehicle",
            EditV("boat: {model: boat.yaml,", "boat: {model: boat.yaml, drag_coefficient: 1,"),
            "bodies.boat.drag_coefficient", "applies only to type: sphere", "t.yaml:13"},
        BrokenCase{"pitch_at_singularity",
                   EditV("position: [0, 0, 1]}", "position: [0, 0, 1], euler_deg: [0, 90, 0]}"),
                   "bodies.boat.euler_deg[1]", "must be < 90", "t.yaml:13"},
        BrokenCase{"euler_of_two",
                   EditV("position: [0, 0, 1]}", "position: [0, 0, 1], euler_deg: [0, 0]}"),
                   "bodies.boat.euler_deg", "must be a list of 3 numbers", ""},
        BrokenCase{"vehicle_position_missing", EditV(", position: [0, 0, 1]", ""),
                   "bodies.boat.position", "is required", "t.yaml:13"},
        BrokenCase{"inline_override_checked",
                   EditV("boat: {model: boat.yaml,", "boat: {model: boat.yaml, mass: 0,"),
                   "bodies.boat.mass", "must be > 0", "t.yaml:13"},
        BrokenCase{
            "inline_map_override_checked",
            EditV("boat: {model: boat.yaml,", "boat: {model: boat.yaml, damping: {x_uuu: 1},"),
            "bodies.boat.damping.x_uuu", "unknown key; did you mean x_uu?", "t.yaml:13"},
        // ends: the attachment point is p + R(euler) at on a vehicle
        BrokenCase{"vertical_misplaced_vehicle", EditV("[-0.5, 0, 101.05]", "[-0.5, 0, 102]"),
                   "cable.end",
                   "with initial: vertical the end must sit at start + [0, 0, length] = "
                   "[0, 0, 101.05]",
                   "t.yaml:11"},
        BrokenCase{"vertical_rotated_vehicle",
                   EditV("[-0.5, 0, 101.05]}", "[-0.5, 0, 101.05], euler_deg: [0, 0, 90]}"),
                   "cable.end", "but it is at [-0.5, 0.5, 101.05]", ""},
        BrokenCase{"both_ends_on_one_vehicle",
                   EditV("end: {body: fish, at: [0.5, 0, 0]}", "end: {body: boat, at: [1, 0, 0]}"),
                   "cable.end", "start and end are both on body boat", ""},
        BrokenCase{"end_on_unknown_body", EditV("end: {body: fish,", "end: {body: whale,"),
                   "cable.end.body", "no such body (bodies: boat, fish)", "t.yaml:11"},
        // initial commands
        BrokenCase{"command_thrust_too_high",
                   EditV("position: [0, 0, 1]}", "position: [0, 0, 1], command: {thrust: 500}}"),
                   "bodies.boat.command.thrust",
                   "must be in [-max_thrust/4, max_thrust] = [-100, 400] N for boat", "t.yaml:13"},
        BrokenCase{"command_thrust_without_propeller",
                   EditV("101.05]}", "101.05], command: {thrust: 10}}"),
                   "bodies.fish.command.thrust", "fish has no propeller", ""},
        BrokenCase{"command_rudder_beyond_limit",
                   EditV("position: [0, 0, 1]}", "position: [0, 0, 1], command: {rudder_deg: 31}}"),
                   "bodies.boat.command.rudder_deg", "must be within +-30 deg", ""},
        BrokenCase{
            "command_without_surface",
            EditV("position: [0, 0, 1]}", "position: [0, 0, 1], command: {elevator_deg: 5}}"),
            "bodies.boat.command.elevator_deg",
            "boat has no surface on channel elevator, so its elevator must be 0", ""},
        BrokenCase{"command_rudder_twice",
                   EditV("position: [0, 0, 1]}",
                         "position: [0, 0, 1], command: {rudder: 0.1, rudder_deg: 5}}"),
                   "bodies.boat.command.rudder_deg",
                   "give rudder [rad] or rudder_deg [deg], not both", ""},
        // script entries
        BrokenCase{"script_thrust_too_high",
                   EditV("{body: boat, thrust: 200}", "{body: boat, thrust: 401}"),
                   "script[0].thrust", "must be in [-max_thrust/4, max_thrust]", "t.yaml:16"},
        BrokenCase{"script_rudder_and_rudder_deg",
                   EditV("rudder_deg: 10}", "rudder_deg: 10, rudder: 0.1}"), "script[1].rudder_deg",
                   "give rudder [rad] or rudder_deg [deg], not both", "t.yaml:17"},
        BrokenCase{"script_rudder_beyond_limit", EditV("rudder_deg: 10}", "rudder_deg: -35}"),
                   "script[1].rudder_deg", "must be within +-30 deg", ""},
        BrokenCase{"script_elevator_without_surface", EditV("rudder_deg: 10}", "elevator: 0.1}"),
                   "script[1].elevator", "no surface on channel elevator", ""},
        BrokenCase{"script_thrust_without_propeller",
                   EditV("{body: boat, thrust: 200}", "{body: fish, thrust: 200}"),
                   "script[0].thrust", "fish has no propeller", ""},
        BrokenCase{"script_without_command", EditV("{body: boat, thrust: 200}", "{body: boat}"),
                   "script[0]", "gives no command; give at least one of thrust, rudder",
                   "t.yaml:16"},
        BrokenCase{"script_without_body", EditV("{body: boat, thrust: 200}", "{thrust: 200}"),
                   "script[0].body", "is required", ""},
        // script conditions: script[2].when
        BrokenCase{"when_unknown_quantity", EditV("boat.yaw_deg >= 90", "boat.yaw >= 90"),
                   "script[2].when",
                   "unknown quantity yaw; did you mean yaw_deg? (quantities: x, y, z, roll_deg, "
                   "pitch_deg, yaw_deg, u, v, w, p, q, r, speed)",
                   "t.yaml:18"},
        BrokenCase{"when_no_comparison", EditV("boat.yaw_deg >= 90", "boat.yaw_deg = 90"),
                   "script[2].when", "has no comparison (>=, <=, >, <)", ""},
        BrokenCase{"when_equality", EditV("boat.yaw_deg >= 90", "boat.yaw_deg == 90"),
                   "script[2].when", "has no comparison", ""},
        BrokenCase{"when_reversed_operator", EditV("boat.yaw_deg >= 90", "boat.yaw_deg => 90"),
                   "script[2].when", "unknown comparison =>; use one of >=, <=, >, <", ""},
        BrokenCase{"when_not_a_number", EditV("boat.yaw_deg >= 90", "boat.yaw_deg >= ninety"),
                   "script[2].when", "needs a finite number after >=, not 'ninety'", ""},
        BrokenCase{"when_trailing_unit", EditV("boat.yaw_deg >= 90", "boat.u > 1 m/s"),
                   "script[2].when", "needs a finite number after >, not '1 m/s'", ""},
        BrokenCase{"when_missing_number", EditV("boat.yaw_deg >= 90", "boat.yaw_deg >="),
                   "script[2].when", "needs a finite number after >=", ""},
        BrokenCase{"when_without_vehicle", EditV("boat.yaw_deg >= 90", "yaw_deg >= 90"),
                   "script[2].when", "needs <vehicle>.<quantity> before >=", ""},
        BrokenCase{"when_unknown_vehicle", EditV("boat.yaw_deg >= 90", "whale.yaw_deg >= 90"),
                   "script[2].when", "no vehicle named whale (vehicles: boat, fish)", ""},
        BrokenCase{"when_empty", EditV("\"boat.yaw_deg >= 90\"", "\"\""), "script[2].when",
                   "must be a condition <vehicle>.<quantity> <op> <number>", ""},
        BrokenCase{"when_not_a_string", EditV("\"boat.yaw_deg >= 90\"", "{yaw: 90}"),
                   "script[2].when", "must be a string", ""},
        BrokenCase{"when_on_a_sphere",
                   EditV("  fish: {model: fish6.yaml,",
                         "  ball: {type: sphere, mass: 1, position: [9, 9, 9]}\n"
                         "  fish: {model: fish6.yaml,") +
                       "  - {when: \"ball.z > 10\", body: boat, thrust: 0}\n",
                   "script[3].when", "ball is a sphere; conditions are on vehicles", "t.yaml:20"},
        BrokenCase{"script_for_sphere_among_vehicles",
                   EditV("  fish: {model: fish6.yaml,",
                         "  ball: {type: sphere, mass: 1, position: [9, 9, 9]}\n"
                         "  fish: {model: fish6.yaml,") +
                       "  - {body: ball, thrust: 0}\n",
                   "script[3].body", "ball is a sphere, and spheres take no commands", ""}),
    [](const ::testing::TestParamInfo<BrokenCase>& info) { return std::string(info.param.name); });

// A vehicle file with one edit: the error names the file, the line and the key path under the
// body (bodies.boat.<key>).
struct VehicleFileCase {
  const char* name;
  std::string from, to;  // the edit of kBoatFile
  std::string key;       // expected key path
  std::string rule;      // expected part of the rule
  int line;              // expected line in the vehicle file
};

std::ostream& operator<<(std::ostream& out, const VehicleFileCase& c) { return out << c.name; }

class BrokenVehicleFileTest : public SceneLoaderTest,
                              public ::testing::WithParamInterface<VehicleFileCase> {};

TEST_P(BrokenVehicleFileTest, ThrowsWithFileLineKeyAndRule) {
  const VehicleFileCase& c = GetParam();
  const std::string file = std::string("boat_") + c.name + ".yaml";
  std::ofstream(dir_ / file) << Replace(kBoatFile, c.from, c.to);
  try {
    Load(EditV("model: boat.yaml", "model: " + file));
    FAIL() << "no ConfigError for " << c.name;
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.key(), c.key) << what;
    EXPECT_NE(e.rule().find(c.rule), std::string::npos) << what;
    EXPECT_EQ(e.location(), file + ":" + std::to_string(c.line)) << what;
    EXPECT_EQ(what, e.key() + " = " + e.value() + " (" + e.location() + "): " + e.rule());
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, BrokenVehicleFileTest,
    ::testing::Values(
        VehicleFileCase{"unknown_key", "volume: 0.1\n", "volume: 0.1\ncolour: red\n",
                        "bodies.boat.colour", "unknown key", 8},
        VehicleFileCase{"sphere_key", "volume: 0.1\n", "volume: 0.1\ndrag_coefficient: 0.5\n",
                        "bodies.boat.drag_coefficient", "unknown key", 8},
        VehicleFileCase{"bad_type", "type: vehicle", "type: boat", "bodies.boat.type",
                        "must be one of sphere, vehicle", 1},
        VehicleFileCase{"missing_source", "source: test\n", "", "bodies.boat.source",
                        "is required (in the model file or the scene)", 1},
        VehicleFileCase{"empty_source", "source: test", "source: \"\"", "bodies.boat.source",
                        "must not be empty", 2},
        VehicleFileCase{"zero_length", "length: 2", "length: 0", "bodies.boat.length",
                        "must be > 0", 3},
        VehicleFileCase{"negative_mass", "mass: 100", "mass: -1", "bodies.boat.mass", "must be > 0",
                        4},
        VehicleFileCase{"zero_inertia", "inertia: [1, 10, 10]", "inertia: [1, 0, 10]",
                        "bodies.boat.inertia[1]", "must be > 0", 5},
        VehicleFileCase{"inertia_of_two", "inertia: [1, 10, 10]", "inertia: [1, 10]",
                        "bodies.boat.inertia", "must be a list of 3 numbers", 5},
        VehicleFileCase{"missing_r_g", "r_g: [0, 0, 0.05]\n", "", "bodies.boat.r_g", "is required",
                        1},
        VehicleFileCase{"negative_volume", "volume: 0.1", "volume: -0.1", "bodies.boat.volume",
                        "must be >= 0", 7},
        VehicleFileCase{"positive_diagonal_added_mass", "x_udot: -5", "x_udot: 5",
                        "bodies.boat.added_mass.x_udot", "must be <= 0", 8},
        VehicleFileCase{"indefinite_added_mass", "y_rdot: 2", "y_rdot: 200",
                        "bodies.boat.added_mass", "must be positive semi-definite", 8},
        VehicleFileCase{"unknown_added_mass_key", "m_qdot", "m_qdott",
                        "bodies.boat.added_mass.m_qdott", "unknown key; did you mean m_qdot?", 8},
        VehicleFileCase{"unknown_damping_key", "n_ur: -4", "n_rv: -4", "bodies.boat.damping.n_rv",
                        "unknown key", 9},
        VehicleFileCase{"damping_not_a_number", "x_uu: -3", "x_uu: high",
                        "bodies.boat.damping.x_uu", "must be a number", 9},
        VehicleFileCase{"munk_not_a_boolean", "volume: 0.1\n", "volume: 0.1\nmunk_moment: maybe\n",
                        "bodies.boat.munk_moment", "must be true or false", 8},
        VehicleFileCase{"surfaces_not_a_list", "  - {name: rudder", "  {name: rudder",
                        "bodies.boat.surfaces", "must be a list", 10},
        VehicleFileCase{"zero_normal", "normal: [0, 2, 0]", "normal: [0, 0, 0]",
                        "bodies.boat.surfaces[0].normal", "must be a non-zero direction", 11},
        VehicleFileCase{"bad_channel", "channel: rudder", "channel: aileron",
                        "bodies.boat.surfaces[0].channel", "must be one of rudder, elevator, none",
                        11},
        VehicleFileCase{"zero_area", "area: 0.01", "area: 0", "bodies.boat.surfaces[0].area",
                        "must be > 0", 11},
        VehicleFileCase{"stall_at_90", "stall_angle_deg: 20", "stall_angle_deg: 90",
                        "bodies.boat.surfaces[0].stall_angle_deg", "must be < 90", 12},
        VehicleFileCase{"oswald_zero", "oswald: 0.9", "oswald: 0", "bodies.boat.surfaces[0].oswald",
                        "must be > 0", 12},
        VehicleFileCase{"oswald_above_one", "oswald: 0.9", "oswald: 1.1",
                        "bodies.boat.surfaces[0].oswald", "must be <= 1", 12},
        VehicleFileCase{"negative_lift_slope", "aspect_ratio: 2,",
                        "aspect_ratio: 2, lift_slope: -1,", "bodies.boat.surfaces[0].lift_slope",
                        "must be >= 0", 12},
        VehicleFileCase{"bad_deflection_sign", "deflection_sign: -1", "deflection_sign: 0.5",
                        "bodies.boat.surfaces[0].deflection_sign", "must be 1 or -1", 12},
        VehicleFileCase{"missing_deflection_sign_on_rudder", ", deflection_sign: -1", "",
                        "bodies.boat.surfaces[0].deflection_sign", "is required", 11},
        VehicleFileCase{"unknown_surface_key", "cd0: 0.01", "cd_0: 0.01",
                        "bodies.boat.surfaces[0].cd_0", "unknown key; did you mean cd0?", 12},
        VehicleFileCase{"missing_surface_name", "{name: rudder, ", "{",
                        "bodies.boat.surfaces[0].name", "is required", 11},
        VehicleFileCase{"duplicate_surface_name", "rudder: {max_deflection_deg",
                        "  - {name: rudder, channel: none, position: [0, 0, 0], normal: [0, 0, 1], "
                        "area: 1, aspect_ratio: 2, oswald: 0.9, cd0: 0, stall_angle_deg: 10}\n"
                        "rudder: {max_deflection_deg",
                        "bodies.boat.surfaces[1].name", "duplicate surface name", 13},
        VehicleFileCase{"zero_rate", "max_rate_deg: 10", "max_rate_deg: 0",
                        "bodies.boat.rudder.max_rate_deg", "must be > 0", 13},
        VehicleFileCase{"deflection_limit_above_90", "max_deflection_deg: 30",
                        "max_deflection_deg: 95", "bodies.boat.rudder.max_deflection_deg",
                        "must be <= 90", 13},
        VehicleFileCase{"propeller_without_time_constant", ", time_constant: 0.5", "",
                        "bodies.boat.propeller.time_constant", "is required", 14},
        VehicleFileCase{"negative_max_thrust", "max_thrust: 400", "max_thrust: -400",
                        "bodies.boat.propeller.max_thrust", "must be > 0", 14},
        VehicleFileCase{"position_in_file", "volume: 0.1\n", "volume: 0.1\nposition: [0, 0, 1]\n",
                        "bodies.boat.position", "unknown key", 8}),
    [](const ::testing::TestParamInfo<VehicleFileCase>& info) {
      return std::string(info.param.name);
    });

TEST_F(SceneLoaderTest, VehicleSceneLoads) {
  const Model m = Load(kVehicleScene);
  EXPECT_TRUE(m.spheres.empty());
  ASSERT_EQ(m.vehicles.size(), 2u);
  const core::Vehicle& boat = m.vehicles[0];
  const core::VehicleParams& p = boat.params;
  EXPECT_EQ(boat.name, "boat");
  EXPECT_EQ(p.source, "test");
  EXPECT_EQ(p.length, 2.0);
  EXPECT_EQ(p.mass, 100.0);
  EXPECT_EQ(p.inertia, core::Vec3(1, 10, 10));
  EXPECT_EQ(p.r_g, core::Vec3(0, 0, 0.05));
  EXPECT_EQ(p.r_b, core::Vec3::Zero());  // default
  EXPECT_EQ(p.volume, 0.1);
  // M_A holds minus the Prestero coefficients, couplings at (1,5) y_rdot and (5,1) n_vdot
  core::Mat6 added = core::Mat6::Zero();
  added(0, 0) = 5;
  added(1, 1) = 80;
  added(2, 2) = 80;
  added(4, 4) = 9;
  added(5, 5) = 9;
  added(1, 5) = -2;
  added(5, 1) = -2;
  EXPECT_EQ(p.added_mass, added);
  EXPECT_TRUE(p.munk_moment);  // default
  EXPECT_EQ(p.x_uu, -3.0);
  EXPECT_EQ(p.n_ur, -4.0);
  EXPECT_EQ(p.y_vv, 0.0);  // default
  ASSERT_EQ(p.surfaces.size(), 1u);
  const core::LiftingSurface& rudder = p.surfaces[0];
  EXPECT_EQ(rudder.name, "rudder");
  EXPECT_EQ(rudder.channel, core::Channel::kRudder);
  EXPECT_EQ(rudder.position_B, core::Vec3(-1, 0, 0));
  EXPECT_EQ(rudder.normal_B, core::Vec3(0, 1, 0));  // normalized
  EXPECT_EQ(rudder.area, 0.01);
  EXPECT_EQ(rudder.aspect_ratio, 2.0);
  EXPECT_EQ(rudder.lift_slope, 0.0);  // default: Helmbold
  EXPECT_EQ(rudder.oswald, 0.9);
  EXPECT_EQ(rudder.cd0, 0.01);
  EXPECT_DOUBLE_EQ(rudder.stall_angle, 20.0 * kDeg);
  EXPECT_EQ(rudder.incidence, 0.0);
  EXPECT_EQ(rudder.deflection_sign, -1.0);
  EXPECT_DOUBLE_EQ(p.rudder.max_deflection, 30.0 * kDeg);
  EXPECT_DOUBLE_EQ(p.rudder.max_rate, 10.0 * kDeg);
  EXPECT_EQ(p.elevator.max_deflection, core::ActuatorLimits{}.max_deflection);  // default
  EXPECT_TRUE(p.has_propeller);
  EXPECT_EQ(p.max_thrust, 400.0);
  EXPECT_EQ(p.thrust_time_constant, 0.5);
  // initial state: at rest, level, no command
  EXPECT_EQ(boat.position, core::Vec3(0, 0, 1));
  EXPECT_EQ(boat.euler, core::Vec3::Zero());
  EXPECT_EQ(boat.nu, core::Vec6::Zero());
  EXPECT_EQ(boat.command.thrust, 0.0);

  const core::Vehicle& fish = m.vehicles[1];
  EXPECT_FALSE(fish.params.has_propeller);
  EXPECT_FALSE(fish.params.munk_moment);
  ASSERT_EQ(fish.params.surfaces.size(), 1u);
  EXPECT_EQ(fish.params.surfaces[0].channel, core::Channel::kNone);
  EXPECT_EQ(fish.params.surfaces[0].deflection_sign, 1.0);  // default where no command drives it

  // the cable ends are on vehicles: kVehicle, index into Model::vehicles
  EXPECT_EQ(m.cables[0].start.kind, core::EndKind::kVehicle);
  EXPECT_EQ(m.cables[0].start.body, 0);
  EXPECT_EQ(m.cables[0].start.at_B, core::Vec3(0, 0, 0.05));
  EXPECT_EQ(m.cables[0].end.kind, core::EndKind::kVehicle);
  EXPECT_EQ(m.cables[0].end.body, 1);
  EXPECT_EQ(m.cables[0].end.at_B, core::Vec3(0.5, 0, 0));
}

TEST_F(SceneLoaderTest, VehicleAttitudeVelocityAndCommand) {
  // yaw 90 deg (and a roll, which leaves the x axis alone): the fish's bow [0.5, 0, 0] points
  // east, so its origin sits 0.5 m west of the cable end; the cable moves north at 1 m/s, which
  // the fish sees in its own frame
  const Model m =
      Load(EditV("fish: {model: fish6.yaml, position: [-0.5, 0, 101.05]}",
                 "fish: {model: fish6.yaml, position: [0, -0.5, 101.05], euler_deg: [10, 0, 90]}"),
           {"cable.initial_velocity=[1, 0, 0]", "bodies.boat.velocity=[2, 0, 0]",
            "bodies.boat.command={thrust: -100, rudder_deg: -30}"});
  // in radians too
  const Model rad = Load(kVehicleScene, {"bodies.boat.command={rudder: 0.25}"});
  EXPECT_EQ(rad.vehicles[0].command.rudder, 0.25);
  const core::Vehicle& fish = m.vehicles[1];
  EXPECT_NEAR(fish.euler.x(), 10 * kDeg, 1e-15);
  EXPECT_EQ(fish.euler.y(), 0.0);
  EXPECT_NEAR(fish.euler.z(), 90 * kDeg, 1e-15);
  const core::Vec3 v_B = core::QuaternionFromEulerZYX(fish.euler).conjugate() * core::Vec3(1, 0, 0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(fish.nu(k), v_B(k), 1e-15) << k;
  EXPECT_EQ(fish.nu.tail<3>(), core::Vec3::Zero());
  // a given velocity is body-frame u, v, w
  const core::Vehicle& boat = m.vehicles[0];
  EXPECT_EQ(boat.nu.head<3>(), core::Vec3(2, 0, 0));
  EXPECT_EQ(boat.command.thrust, -100.0);
  EXPECT_DOUBLE_EQ(boat.command.rudder, -30 * kDeg);
  EXPECT_EQ(boat.command.elevator, 0.0);
}

// the winch (docs/winch.md): cable.winch and the winch script entries
const std::string kWinchLine =
    "  end: {body: fish}\n  winch: {min_length: 50, max_length: 150, max_speed: 1, "
    "max_acceleration: 0.2}\n";

TEST_F(SceneLoaderTest, WinchKeysAndScriptEntries) {
  const Model m = Load(Edit("  end: {body: fish}\n", kWinchLine) +
                       "script:\n  - {at: 10, winch_speed: -0.5}\n  - {at: 20, winch_length: 120}\n");
  ASSERT_TRUE(m.cables[0].winch.has_value());
  EXPECT_EQ(m.cables[0].winch->min_length, 50.0);
  EXPECT_EQ(m.cables[0].winch->max_length, 150.0);
  EXPECT_EQ(m.cables[0].winch->max_speed, 1.0);
  EXPECT_EQ(m.cables[0].winch->max_acceleration, 0.2);
  EXPECT_TRUE(std::isinf(m.cables[0].winch->brake_tension));  // optional: never slips
  ASSERT_EQ(m.script.size(), 2u);
  EXPECT_TRUE(m.script[0].set_winch);
  EXPECT_EQ(m.script[0].vehicle, -1);
  EXPECT_EQ(m.script[0].winch.mode, core::WinchCommand::Mode::kSpeed);
  EXPECT_EQ(m.script[0].winch.value, -0.5);
  EXPECT_EQ(m.script[1].winch.mode, core::WinchCommand::Mode::kLength);
  EXPECT_EQ(m.script[1].winch.value, 120.0);
  EXPECT_FALSE(Load(kScene).cables[0].winch.has_value());
}

TEST_F(SceneLoaderTest, WinchErrorsNameKeyValueAndRule) {
  const std::string winch = Edit("  end: {body: fish}\n", kWinchLine);
  auto error = [&](const std::string& yaml) -> std::string {
    try {
      Load(yaml);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  EXPECT_EQ(error(Replace(winch, "min_length: 50", "min_length: 120")),
            "cable.winch.min_length = 120 (t.yaml:13): must be <= cable.length = 100");
  EXPECT_EQ(error(Replace(winch, "max_length: 150", "max_length: 90")),
            "cable.winch.max_length = 90 (t.yaml:13): must be >= cable.length = 100");
  EXPECT_EQ(error(Replace(winch, "max_speed: 1", "max_speed: 0")),
            "cable.winch.max_speed = 0 (t.yaml:13): must be > 0");
  // the drum moves at most (1.6 - 1 - 0.4) l_e = 2 m a step of 0.01 s (l_e = 100 m / 10)
  EXPECT_EQ(error(Replace(winch, "max_speed: 1", "max_speed: 250")),
            "cable.winch.max_speed = 250 (t.yaml:13): must be <= 200 = 0.2 l_e / time.step (the "
            "drum moves at most 0.2 of an element a step, so its element stays within [0.4, "
            "1.6] l_e between splits and merges; l_e = cable.length / cable.elements = 10 m, "
            "time.step = 0.01 s)");
  EXPECT_EQ(error(Replace(winch, "max_speed: 1", "max_speed: 200")), "(accepted)");
  EXPECT_EQ(error(Replace(winch, "max_acceleration: 0.2", "max_acceleration: -1")),
            "cable.winch.max_acceleration = -1 (t.yaml:13): must be > 0");
  EXPECT_EQ(error(Replace(winch, "max_acceleration: 0.2", "max_acceleration: 0.2, brake: 5")),
            "cable.winch.brake = 5 (t.yaml:13): unknown key; did you mean brake_tension? "
            "(allowed: name, min_length, max_length, max_speed, max_acceleration, brake_tension)");
  EXPECT_EQ(error(winch + "script:\n  - {at: 1, winch_speed: 2}\n"),
            "script[0].winch_speed = 2 (t.yaml:18): must be within +-cable.winch.max_speed = 1");
  EXPECT_EQ(error(winch + "script:\n  - {at: 1, winch_length: 200}\n"),
            "script[0].winch_length = 200 (t.yaml:18): must be within cable.winch [min_length, "
            "max_length] = [50, 150]");
  EXPECT_EQ(error(kScene + std::string("script:\n  - {at: 1, winch_speed: 0.5}\n")),
            "script[0].winch_speed = 0.5 (t.yaml:17): the scene has no cable.winch");
}

TEST_F(SceneLoaderTest, ShippedWinchPayoutScene) {
  const Model m = LoadScene(kConfigDir + "/scenes/winch_payout.yaml");
  ASSERT_TRUE(m.cables[0].winch.has_value());
  EXPECT_EQ(m.cables[0].length, 150.0);
  EXPECT_EQ(m.cables[0].winch->max_speed, 1.0);
  ASSERT_EQ(m.script.size(), 2u);
  EXPECT_EQ(m.script[0].winch.value, 250.0);
  EXPECT_EQ(m.script[1].winch.value, 150.0);
}

TEST_F(SceneLoaderTest, ScriptEntriesAndConditions) {
  const Model m = Load(kVehicleScene);
  ASSERT_EQ(m.script.size(), 3u);
  // at defaults to 0; only the given fields are set
  const core::ScriptEntry& thrust = m.script[0];
  EXPECT_EQ(thrust.at, 0.0);
  EXPECT_EQ(thrust.body, "boat");
  EXPECT_EQ(thrust.vehicle, 0);
  EXPECT_FALSE(thrust.has_condition);
  EXPECT_TRUE(thrust.set_thrust);
  EXPECT_FALSE(thrust.set_rudder || thrust.set_elevator);
  EXPECT_EQ(thrust.thrust, 200.0);
  // rudder_deg in degrees, held in radians
  const core::ScriptEntry& turn = m.script[1];
  EXPECT_EQ(turn.at, 5.0);
  EXPECT_TRUE(turn.set_rudder);
  EXPECT_FALSE(turn.set_thrust || turn.set_elevator);
  EXPECT_DOUBLE_EQ(turn.rudder, 10 * kDeg);
  // when: the condition, with rudder in radians
  const core::ScriptEntry& back = m.script[2];
  EXPECT_TRUE(back.has_condition);
  EXPECT_EQ(back.condition.vehicle, 0);
  EXPECT_EQ(back.condition.quantity, core::ScriptCondition::kYawDeg);
  EXPECT_EQ(back.condition.op, core::ScriptCondition::kGreaterEqual);
  EXPECT_EQ(back.condition.value, 90.0);
  EXPECT_TRUE(back.set_rudder);
  EXPECT_EQ(back.rudder, 0.0);
}

TEST_F(SceneLoaderTest, ConditionForms) {
  using C = core::ScriptCondition;
  struct Form {
    const char* text;
    int vehicle;
    C::Quantity quantity;
    C::Op op;
    double value;
  };
  const Form forms[] = {
      {"boat.yaw_deg >= 170", 0, C::kYawDeg, C::kGreaterEqual, 170},
      {"fish.speed<2.5", 1, C::kSpeed, C::kLess, 2.5},
      {"  boat.z <= -1e1  ", 0, C::kZ, C::kLessEqual, -10},
      {"fish.pitch_deg > -5", 1, C::kPitchDeg, C::kGreater, -5},
      {"boat.x >= 0", 0, C::kX, C::kGreaterEqual, 0},
      {"boat.y >= 0", 0, C::kY, C::kGreaterEqual, 0},
      {"boat.roll_deg >= 0", 0, C::kRollDeg, C::kGreaterEqual, 0},
      {"boat.u >= 0", 0, C::kU, C::kGreaterEqual, 0},
      {"boat.v >= 0", 0, C::kV, C::kGreaterEqual, 0},
      {"boat.w >= 0", 0, C::kW, C::kGreaterEqual, 0},
      {"boat.p >= 0", 0, C::kP, C::kGreaterEqual, 0},
      {"boat.q >= 0", 0, C::kQ, C::kGreaterEqual, 0},
      {"boat.r >= 0.1", 0, C::kR, C::kGreaterEqual, 0.1},
  };
  for (const Form& f : forms) {
    const Model m = Load(EditV("boat.yaw_deg >= 90", f.text));
    const core::ScriptCondition& c = m.script.at(2).condition;
    EXPECT_EQ(c.vehicle, f.vehicle) << f.text;
    EXPECT_EQ(c.quantity, f.quantity) << f.text;
    EXPECT_EQ(c.op, f.op) << f.text;
    EXPECT_EQ(c.value, f.value) << f.text;
  }
}

TEST_F(SceneLoaderTest, VehicleOverridesMergeMapsKeyByKey) {
  // a map key set in the scene (here by --set) replaces that key only; the file gives the rest
  const Model m =
      Load(kVehicleScene, {"bodies.boat.damping.y_vv=-50", "bodies.boat.propeller.max_thrust=1000",
                           "bodies.boat.added_mass.k_pdot=-1", "bodies.boat.euler_deg=[0, 0, 45]",
                           "bodies.boat.mass=120", "integrator.coupling=staggered",
                           "integrator.max_coupling_iterations=7"});
  const core::VehicleParams& p = m.vehicles[0].params;
  EXPECT_EQ(p.y_vv, -50.0);
  EXPECT_EQ(p.x_uu, -3.0);  // from the file
  EXPECT_EQ(p.max_thrust, 1000.0);
  EXPECT_EQ(p.thrust_time_constant, 0.5);  // from the file
  EXPECT_EQ(p.added_mass(3, 3), 1.0);
  EXPECT_EQ(p.added_mass(0, 0), 5.0);  // from the file
  EXPECT_EQ(p.mass, 120.0);
  EXPECT_DOUBLE_EQ(m.vehicles[0].euler.z(), 45 * kDeg);
  EXPECT_EQ(m.integrator.coupling, core::Coupling::kStaggered);
  EXPECT_EQ(m.integrator.max_coupling_iterations, 7);
  // the same in the scene text, and surfaces replaced whole
  const Model inline_keys = Load(
      EditV("boat: {model: boat.yaml,",
            "boat: {model: boat.yaml, damping: {y_vv: -50}, surfaces: [{name: r2, channel: rudder, "
            "position: [-1, 0, 0], normal: [0, 1, 0], area: 0.02, aspect_ratio: 2, oswald: 0.9, "
            "cd0: 0.01, stall_angle_deg: 20, deflection_sign: 1}],"));
  const core::VehicleParams& q = inline_keys.vehicles[0].params;
  EXPECT_EQ(q.y_vv, -50.0);
  EXPECT_EQ(q.x_uu, -3.0);
  ASSERT_EQ(q.surfaces.size(), 1u);
  EXPECT_EQ(q.surfaces[0].name, "r2");
}

TEST_F(SceneLoaderTest, BadVehicleOverrideIsLocatedAtSet) {
  try {
    Load(kVehicleScene, {"bodies.boat.damping.x_uu=fast"});
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "bodies.boat.damping.x_uu = fast (--set): must be a number");
  }
  try {
    Load(kVehicleScene, {"bodies.boat.damping.x_uuu=1"});
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.location(), "--set") << e.what();
    EXPECT_NE(e.rule().find("did you mean x_uu?"), std::string::npos) << e.what();
  }
}

TEST_F(SceneLoaderTest, InlineVehicleWithoutModelFile) {
  // type: vehicle and every parameter in the scene itself
  const Model m =
      Load(EditV("fish: {model: fish6.yaml, position: [-0.5, 0, 101.05]}",
                 "fish: {type: vehicle, source: inline, length: 1, mass: 20, inertia: [0.1, 1, 1], "
                 "r_g: [0, 0, 0], volume: 0.02, position: [-0.5, 0, 101.05]}"));
  ASSERT_EQ(m.vehicles.size(), 2u);
  EXPECT_EQ(m.vehicles[1].params.source, "inline");
  EXPECT_TRUE(m.vehicles[1].params.surfaces.empty());
  EXPECT_FALSE(m.vehicles[1].params.has_propeller);
}

TEST_F(SceneLoaderTest, SpheresAndVehiclesTogether) {
  // a sphere hangs from the boat; the fish is unattached; names resolve across both kinds
  const Model m = Load(EditV("  end: {body: fish, at: [0.5, 0, 0]}\n", "  end: {body: ball}\n"),
                       {"bodies.ball={type: sphere, mass: 5, position: [0, 0, 101.05]}"});
  ASSERT_EQ(m.spheres.size(), 1u);
  ASSERT_EQ(m.vehicles.size(), 2u);
  EXPECT_EQ(m.cables[0].start.kind, core::EndKind::kVehicle);
  EXPECT_EQ(m.cables[0].end.kind, core::EndKind::kSphere);
  EXPECT_EQ(m.cables[0].end.body, 0);
}

TEST_F(SceneLoaderTest, PaperCaseScenes) {
  for (const char* name : {"case1_forward", "case2_uturn"}) {
    SCOPED_TRACE(name);
    const Model m = LoadScene(kConfigDir + "/scenes/" + name + ".yaml");
    EXPECT_EQ(m.name, name);
    EXPECT_EQ(m.time.step, 0.05);
    EXPECT_EQ(m.time.output_rate, 10.0);
    EXPECT_EQ(m.cables[0].length, 200.0);
    EXPECT_EQ(m.cables[0].elements, 20);
    EXPECT_EQ(m.cables[0].diameter, 0.041);
    EXPECT_EQ(m.cables[0].mass_per_length, 1300.0 * m.cables[0].area());
    EXPECT_EQ(m.cables[0].axial_stiffness, 7.0e8 * m.cables[0].area());
    const core::CableLoads& loads = m.cables[0].loads;
    EXPECT_TRUE(loads.gravity && loads.buoyancy && loads.drag && loads.added_mass && loads.bending);
    EXPECT_EQ(m.cables[0].initial, core::InitialShape::kVertical);
    EXPECT_EQ(m.cables[0].initial_velocity, core::Vec3::Zero());
    EXPECT_TRUE(m.spheres.empty());
    ASSERT_EQ(m.vehicles.size(), 2u);
    const core::Vehicle& tow = m.vehicles[0];
    const core::Vehicle& fish = m.vehicles[1];
    EXPECT_EQ(tow.name, "tow_vehicle");
    EXPECT_EQ(fish.name, "towfish");
    EXPECT_EQ(tow.position, core::Vec3(0, 0, 3.5));
    EXPECT_EQ(tow.nu, core::Vec6::Zero());
    EXPECT_EQ(fish.nu, core::Vec6::Zero());
    EXPECT_TRUE(tow.params.has_propeller);
    EXPECT_FALSE(fish.params.has_propeller);
    // the cable from the tow vehicle's CG to the towfish's bow, hanging straight down
    EXPECT_EQ(m.cables[0].start.kind, core::EndKind::kVehicle);
    EXPECT_EQ(m.cables[0].start.body, 0);
    EXPECT_EQ(m.cables[0].start.at_B, tow.params.r_g);
    EXPECT_EQ(m.cables[0].end.kind, core::EndKind::kVehicle);
    EXPECT_EQ(m.cables[0].end.body, 1);
    EXPECT_EQ(m.cables[0].end.at_B, core::Vec3(0.5 * fish.params.length, 0, 0));
    const core::Vec3 top = tow.position + tow.params.r_g;
    const core::Vec3 bow = fish.position + m.cables[0].end.at_B;
    EXPECT_EQ(bow, top + core::Vec3(0, 0, m.cables[0].length));
    EXPECT_EQ(m.integrator.coupling, core::Coupling::kStrong);
    // thrust from t = 0, the same in both cases
    ASSERT_GE(m.script.size(), 1u);
    EXPECT_EQ(m.script[0].at, 0.0);
    EXPECT_TRUE(m.script[0].set_thrust);
    EXPECT_EQ(m.script[0].vehicle, 0);
  }
  const Model c1 = LoadScene(kConfigDir + "/scenes/case1_forward.yaml");
  const Model c2 = LoadScene(kConfigDir + "/scenes/case2_uturn.yaml");
  EXPECT_EQ(c1.time.duration, 100.0);
  EXPECT_EQ(c1.script.size(), 1u);
  EXPECT_EQ(c2.script[0].thrust, c1.script[0].thrust);
  ASSERT_EQ(c2.script.size(), 3u);
  // 20 deg rudder at 55 s, back to 0 once the yaw reaches 170 deg
  EXPECT_EQ(c2.script[1].at, 55.0);
  EXPECT_DOUBLE_EQ(c2.script[1].rudder, 20 * kDeg);
  EXPECT_FALSE(c2.script[1].has_condition);
  EXPECT_EQ(c2.script[2].at, 55.0);
  EXPECT_TRUE(c2.script[2].has_condition);
  EXPECT_EQ(c2.script[2].condition.quantity, core::ScriptCondition::kYawDeg);
  EXPECT_EQ(c2.script[2].condition.op, core::ScriptCondition::kGreaterEqual);
  EXPECT_EQ(c2.script[2].condition.value, 170.0);
  EXPECT_EQ(c2.script[2].rudder, 0.0);
}

TEST_F(SceneLoaderTest, VehicleWaterplane) {
  // absent: fully submerged
  EXPECT_EQ(Load(kVehicleScene).vehicles[0].params.waterplane_area, 0.0);
  const Model m = Load(kVehicleScene, {"bodies.boat.waterplane={area: 0.5, position: [0, 0, -0.2], "
                                       "design_depth: 1, inertia_longitudinal: 0.1}"});
  const core::VehicleParams& p = m.vehicles[0].params;
  EXPECT_EQ(p.waterplane_area, 0.5);
  EXPECT_EQ(p.waterplane_point_B, core::Vec3(0, 0, -0.2));
  EXPECT_EQ(p.design_depth, 1.0);
  EXPECT_EQ(p.waterplane_inertia_long, 0.1);
  EXPECT_EQ(p.waterplane_inertia_trans, 0.0);  // default
  try {
    Load(kVehicleScene, {"bodies.boat.waterplane={area: 0.5, position: [0, 0, 0]}"});
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "bodies.boat.waterplane.design_depth") << e.what();
    EXPECT_EQ(e.rule(), "is required") << e.what();
  }
  try {
    Load(kVehicleScene, {"bodies.boat.waterplane.area=0"});
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "bodies.boat.waterplane.area = 0 (--set): must be > 0");
  }
}

TEST_F(SceneLoaderTest, VehicleFileAlone) {
  // the shipped vehicle files, read by themselves, equal what the paper scenes hold
  const Model c1 = LoadScene(kConfigDir + "/scenes/case1_forward.yaml");
  const char* names[] = {"tow_vehicle", "towfish"};
  for (int i = 0; i < 2; ++i) {
    SCOPED_TRACE(names[i]);
    const core::VehicleParams p = LoadVehicleFile(kConfigDir + "/vehicles/" + names[i] + ".yaml");
    const core::VehicleParams& q = c1.vehicles.at(i).params;
    EXPECT_FALSE(p.source.empty());
    EXPECT_EQ(p.source, q.source);
    EXPECT_EQ(p.mass, q.mass);
    EXPECT_EQ(p.inertia, q.inertia);
    EXPECT_EQ(p.added_mass, q.added_mass);
    EXPECT_EQ(p.n_rr, q.n_rr);
    EXPECT_EQ(p.surfaces.size(), q.surfaces.size());
    EXPECT_EQ(p.has_propeller, q.has_propeller);
  }
  // errors name the file and line; key paths start at its root
  std::ofstream(dir_ / "boat_alone.yaml") << Replace(kBoatFile, "mass: 100", "mass: -1");
  try {
    LoadVehicleFile((dir_ / "boat_alone.yaml").string());
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "mass = -1 (boat_alone.yaml:4): must be > 0");
  }
  try {
    LoadVehicleFile((dir_ / "good_fish.yaml").string());
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "type") << e.what();
    EXPECT_NE(e.rule().find("must be vehicle"), std::string::npos) << e.what();
  }
  EXPECT_THROW(LoadVehicleFile((dir_ / "nope.yaml").string()), ConfigError);
}

TEST_F(SceneLoaderTest, ModelFileErrorNamesTheFile) {
  try {
    Load(Edit(kFishLine, "fish: {model: bad_fish.yaml, position: [0, 0, 100]}"));
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).find("bodies.fish.colour = red (bad_fish.yaml:3): unknown key"),
              0u)
        << e.what();
  }
}

TEST_F(SceneLoaderTest, MissingModelFileNamesThePath) {
  try {
    Load(Edit(kFishLine, "fish: {model: nope.yaml, position: [0, 0, 100]}"));
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.value(), "nope.yaml");
    EXPECT_NE(e.rule().find((dir_ / "nope.yaml").string()), std::string::npos) << e.what();
  }
}

TEST_F(SceneLoaderTest, NonYamlReportsParserLine) {
  try {
    Load("name: t\ntime: {step: 0.1\ncable: 3\n");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "t.yaml");
    EXPECT_EQ(e.location().rfind("t.yaml:", 0), 0u) << e.what();
    EXPECT_NE(e.rule().find("not valid YAML: "), std::string::npos) << e.what();
  }
}

TEST_F(SceneLoaderTest, MissingSceneFileNamesThePath) {
  const std::string path = (dir_ / "no_such_scene.yaml").string();
  try {
    LoadScene(path);
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.value(), path);
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
    EXPECT_NE(e.rule().find("cannot read the scene file (no such file)"), std::string::npos)
        << e.what();
  }
}

TEST_F(SceneLoaderTest, ModelFileValuesAndInlineOverride) {
  // the file gives type, mass and volume; the scene overrides mass; Cd, Ca keep the defaults
  const Model m =
      Load(Edit(kFishLine, "fish: {model: good_fish.yaml, mass: 15, position: [0, 0, 100]}"));
  ASSERT_EQ(m.spheres.size(), 1u);
  EXPECT_EQ(m.spheres[0].mass, 15.0);
  EXPECT_EQ(m.spheres[0].volume, 0.01);
  EXPECT_EQ(m.spheres[0].drag_coefficient, core::SphereBody{}.drag_coefficient);
}

TEST_F(SceneLoaderTest, LoadsAndSlopes) {
  // loads absent: all on; a clamped start gets a unit slope
  const Model m = Load(Edit("  loads: [gravity, buoyancy, drag]\n", ""));
  EXPECT_TRUE(m.cables[0].loads.gravity && m.cables[0].loads.buoyancy && m.cables[0].loads.drag &&
              m.cables[0].loads.added_mass && m.cables[0].loads.bending);
  const Model none = Load(Edit("[gravity, buoyancy, drag]", "[]"));
  EXPECT_FALSE(none.cables[0].loads.gravity || none.cables[0].loads.buoyancy || none.cables[0].loads.drag ||
               none.cables[0].loads.added_mass || none.cables[0].loads.bending);
  const Model clamped =
      Load(Edit("start: {fixed: [0, 0, 0]}", "start: {fixed: [0, 0, 0], slope: [0, 0, 2]}"));
  EXPECT_TRUE(clamped.cables[0].start.clamped);
  EXPECT_EQ(clamped.cables[0].start.slope, core::Vec3(0, 0, 1));
  EXPECT_FALSE(clamped.cables[0].end.clamped);
}

TEST_F(SceneLoaderTest, PublishRatesAndCommandTimeout) {
  const Model defaults = Load(Edit("", ""));
  EXPECT_EQ(defaults.publishing.rates[core::PublishRate::kOdom], 0.0);
  EXPECT_EQ(defaults.publishing.rates[core::PublishRate::kCableState], -1.0);
  EXPECT_EQ(defaults.publishing.rates[core::PublishRate::kSensors], 0.0);
  EXPECT_EQ(defaults.publishing.command_timeout, 0.5);
  const Model m = Load(Edit(
      "name: t\n", "name: t\npublish: {odom: 50, cable_state: 5, status: 1, command_timeout: 2}\n"));
  EXPECT_EQ(m.publishing.rates[core::PublishRate::kOdom], 50.0);
  EXPECT_EQ(m.publishing.rates[core::PublishRate::kCableState], 5.0);
  EXPECT_EQ(m.publishing.rates[core::PublishRate::kStatus], 1.0);
  EXPECT_EQ(m.publishing.rates[core::PublishRate::kClock], 0.0);
  EXPECT_EQ(m.publishing.command_timeout, 2.0);
  const Model sensors = Load(Edit("name: t\n", "name: t\npublish: {sensors: 10}\n"));
  EXPECT_EQ(sensors.publishing.rates[core::PublishRate::kSensors], 10.0);
}

// security.open_outputs (docs/security.md): false unless the scene says true; a boolean
TEST_F(SceneLoaderTest, OpenOutputsKey) {
  EXPECT_FALSE(Load(Edit("", "")).publishing.open_outputs);
  EXPECT_TRUE(Load(Edit("name: t\n", "name: t\nsecurity: {open_outputs: true}\n"))
                  .publishing.open_outputs);
  try {
    Load(Edit("name: t\n", "name: t\nsecurity: {open_outputs: 3}\n"));
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "security.open_outputs") << e.what();
  }
  try {
    Load(Edit("name: t\n", "name: t\nsecurity: {open: true}\n"));
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "security.open") << e.what();
    EXPECT_NE(std::string(e.what()).find("unknown key"), std::string::npos) << e.what();
  }
}

TEST_F(SceneLoaderTest, InitialVelocityIsTheBodiesDefault) {
  const Model m =
      Load(Edit("  initial: vertical\n", "  initial: vertical\n  initial_velocity: [1, 2, 3]\n"));
  EXPECT_EQ(m.spheres[0].velocity, core::Vec3(1, 2, 3));
  const Model given =
      Load(Edit("position: [0, 0, 100]", "position: [0, 0, 100], velocity: [0, 0, 1]"));
  EXPECT_EQ(given.spheres[0].velocity, core::Vec3(0, 0, 1));
}

TEST_F(SceneLoaderTest, StraightWithinOnePercentStretchLoads) {
  const Model m =
      Load(Edit("initial: vertical\n  start: {fixed: [0, 0, 0]}\n  end: {body: fish}",
                "initial: straight\n  start: {fixed: [0, 0, 0]}\n  end: {fixed: [100.5, 0, 0]}"));
  EXPECT_EQ(m.cables[0].initial, core::InitialShape::kStraight);
  EXPECT_EQ(m.cables[0].end.kind, core::EndKind::kFixed);
}

TEST_F(SceneLoaderTest, CatenaryScene) {
  const Model m = LoadScene(kCatenary);
  EXPECT_EQ(m.name, "catenary");
  EXPECT_EQ(m.time.step, 0.05);
  EXPECT_EQ(m.time.duration, 30.0);
  EXPECT_EQ(m.time.output_rate, 10.0);
  EXPECT_EQ(m.cables[0].length, 200.0);
  EXPECT_EQ(m.cables[0].elements, 20);
  EXPECT_EQ(m.cables[0].diameter, 0.041);
  // the solid section: m = rho_c A, EA = E A, EI = E I
  EXPECT_EQ(m.cables[0].mass_per_length, 1300.0 * m.cables[0].area());
  EXPECT_EQ(m.cables[0].axial_stiffness, 7.0e8 * m.cables[0].area());
  EXPECT_EQ(m.cables[0].bending_stiffness, 7.0e8 * m.cables[0].second_moment());
  EXPECT_EQ(m.cables[0].initial, core::InitialShape::kStatic);
  EXPECT_EQ(m.cables[0].start.kind, core::EndKind::kFixed);
  EXPECT_EQ(m.cables[0].end.kind, core::EndKind::kFixed);
  EXPECT_EQ(m.cables[0].start.position, core::Vec3(0, 0, 10));
  EXPECT_EQ(m.cables[0].end.position, core::Vec3(150, 0, 10));
  const core::CableLoads& loads = m.cables[0].loads;
  EXPECT_TRUE(loads.gravity && loads.buoyancy && loads.drag && loads.added_mass && loads.bending);
  EXPECT_EQ(m.integrator.scheme, core::Scheme::kGeneralizedAlpha);
  EXPECT_EQ(m.integrator.rho_inf, 0.8);
  EXPECT_TRUE(m.spheres.empty());
  EXPECT_TRUE(m.script.empty());
}

TEST_F(SceneLoaderTest, SteadyTowScene) {
  const Model m = LoadScene(kSteadyTow);
  EXPECT_EQ(m.name, "steady_tow");
  EXPECT_EQ(m.time.step, 0.05);
  EXPECT_EQ(m.time.duration, 300.0);
  EXPECT_EQ(m.time.output_rate, 10.0);
  EXPECT_EQ(m.cables[0].length, 200.0);
  EXPECT_EQ(m.cables[0].elements, 20);
  EXPECT_EQ(m.cables[0].initial, core::InitialShape::kVertical);
  EXPECT_EQ(m.cables[0].start.kind, core::EndKind::kDriven);
  EXPECT_EQ(m.cables[0].start.position, core::Vec3(0, 0, 3.5));
  EXPECT_EQ(m.cables[0].start.velocity, core::Vec3(6, 0, 0));
  EXPECT_EQ(m.cables[0].end.kind, core::EndKind::kSphere);
  EXPECT_EQ(m.cables[0].end.body, 0);
  EXPECT_EQ(m.cables[0].end.at_B, core::Vec3::Zero());
  ASSERT_EQ(m.spheres.size(), 1u);
  const core::SphereBody& fish = m.spheres[0];
  EXPECT_EQ(fish.name, "towfish");
  EXPECT_EQ(fish.mass, 416.0);
  EXPECT_EQ(fish.volume, 0.2);
  EXPECT_EQ(fish.drag_coefficient, 0.5);
  EXPECT_EQ(fish.added_mass_coefficient, 0.5);
  EXPECT_EQ(fish.position, core::Vec3(0, 0, 203.5));
  // no velocity given: the body starts with the driven end
  EXPECT_EQ(fish.velocity, core::Vec3(6, 0, 0));
  EXPECT_EQ(m.integrator.scheme, core::Scheme::kGeneralizedAlpha);
  EXPECT_EQ(m.integrator.rho_inf, 0.8);
  EXPECT_EQ(m.integrator.coupling, core::Coupling::kStrong);
  EXPECT_EQ(m.integrator.tolerance, 1e-7);
  EXPECT_EQ(m.integrator.force_tolerance, 3e-4);
  EXPECT_EQ(m.integrator.max_iterations, 20);
}

TEST_F(SceneLoaderTest, Overrides) {
  const Model m =
      LoadScene(kSteadyTow, {"cable.elements=40", "cable.initial=static", "bodies.towfish.mass=500",
                             "environment.current=[0.5,0,0]"});
  EXPECT_EQ(m.cables[0].elements, 40);
  EXPECT_EQ(m.cables[0].initial, core::InitialShape::kStatic);
  EXPECT_EQ(m.spheres[0].mass, 500.0);
  EXPECT_EQ(m.spheres[0].volume, 0.2);  // still from the model file
  EXPECT_EQ(m.environment.current.Velocity(0.0, 0.0), core::Vec3(0.5, 0, 0));
  EXPECT_EQ(m.cables[0].length, 200.0);  // untouched
}

TEST_F(SceneLoaderTest, OverridesCreateValidKeysAndApplyInOrder) {
  // absent keys and sections may be created; the last override of a key wins
  const Model m =
      Load(kScene, {"cable.axial_damping=0.01", "environment.gravity=9.8", "cable.elements=12",
                    "cable.elements=14", "bodies.buoy={type: sphere, mass: 1, position: [5, 0, 0]}",
                    "cable.start={fixed: [0, 0, 0], slope: [0, 0, 1]}"});
  EXPECT_EQ(m.cables[0].axial_damping, 0.01);
  EXPECT_EQ(m.environment.gravity, 9.8);
  EXPECT_EQ(m.cables[0].elements, 14);
  ASSERT_EQ(m.spheres.size(), 2u);
  EXPECT_EQ(m.spheres[1].name, "buoy");
  EXPECT_TRUE(m.cables[0].start.clamped);
}

struct BadOverride {
  const char* name;
  std::string override_text;
  std::string key;
  std::string rule;
};

std::ostream& operator<<(std::ostream& out, const BadOverride& c) { return out << c.name; }

class BadOverrideTest : public SceneLoaderTest,
                        public ::testing::WithParamInterface<BadOverride> {};

TEST_P(BadOverrideTest, ThrowsNamingThePath) {
  const BadOverride& c = GetParam();
  try {
    Load(kScene, {c.override_text});
    FAIL() << "no ConfigError for " << c.override_text;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), c.key) << e.what();
    EXPECT_EQ(e.location(), "--set") << e.what();
    EXPECT_NE(e.rule().find(c.rule), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.key), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, BadOverrideTest,
    ::testing::Values(
        BadOverride{"no_equals", "cable.elements", "cable.elements", "must be key.path=value"},
        BadOverride{"empty_component", "cable..elements=3", "cable..elements",
                    "names joined by dots"},
        BadOverride{"unknown_key", "cable.lenght=3", "cable.lenght",
                    "cable: unknown key; did you mean length?"},
        BadOverride{"unknown_section", "solver.tolerance=1e-6", "solver.tolerance",
                    "the scene: unknown key"},
        BadOverride{"unknown_body", "bodies.shark.mass=5", "bodies.shark.mass",
                    "no body named shark in the scene (bodies: fish)"},
        BadOverride{"into_a_vector", "environment.current.x=1", "environment.current.x",
                    "environment.current holds a value, not keys"},
        BadOverride{"bad_yaml", "cable.elements=[1", "cable.elements", "value is not valid YAML"},
        // valid paths, invalid values: validated like the file, located at --set
        BadOverride{"out_of_range", "cable.elements=0", "cable.elements", "must be >= 1"},
        BadOverride{"wrong_type", "cable.length=long", "cable.length", "must be a number"},
        BadOverride{"vector_of_two", "environment.current=[0.5,0]", "environment.current",
                    "must be a list of 3 numbers"},
        BadOverride{"element_of_set_vector", "environment.current=[0.5,0,.nan]",
                    "environment.current[2]", "must be a finite number"},
        BadOverride{"created_section_misses_keys", "time={step: 0.1}", "time.duration",
                    "is required"}),
    [](const ::testing::TestParamInfo<BadOverride>& info) { return std::string(info.param.name); });

// a network's cables by name (docs/command_line.md --set): cables.<name>.<key>
TEST_F(SceneLoaderTest, OverrideOfANamedCable) {
  const std::string two_part = kConfigDir + "/scenes/two_part_tow.yaml";
  const core::Model base = LoadScene(two_part);
  ASSERT_EQ(base.cables.size(), 2u);
  const core::Model m = LoadScene(two_part, {"cables.tether.elements=17", "cables.main.length=450"});
  int changed = 0;
  for (size_t c = 0; c < m.cables.size(); ++c) {
    const bool tether = m.cables[c].elements != base.cables[c].elements;
    if (tether) {
      EXPECT_EQ(m.cables[c].elements, 17);
      ++changed;
    }
    if (m.cables[c].length != base.cables[c].length) {
      EXPECT_DOUBLE_EQ(m.cables[c].length, 450.0);
      ++changed;
    }
  }
  EXPECT_EQ(changed, 2);
  // an unknown cable is named with the scene's cables; a bad key with the cable's path
  try {
    LoadScene(two_part, {"cables.tow.elements=3"});
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("no cable named tow in the scene (cables: main, tether)"),
              std::string::npos)
        << e.what();
  }
  try {
    LoadScene(two_part, {"cables.main.lenght=3"});
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("cables.main: unknown key; did you mean length?"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(SceneLoaderTest, OverrideOfFileValueIsLocatedAtSet) {
  try {
    LoadScene(kCatenary, {"cable.elements=0"});
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "cable.elements = 0 (--set): must be >= 1");
  }
}

// Changes the working directory for the life of the object.
class ScopedCwd {
 public:
  explicit ScopedCwd(const fs::path& dir) : saved_(fs::current_path()) { fs::current_path(dir); }
  ~ScopedCwd() { fs::current_path(saved_); }

 private:
  fs::path saved_;
};

TEST_F(SceneLoaderTest, ModelPathResolvesAgainstTheSceneFolder) {
  {
    // an absolute scene path from an unrelated working directory
    const ScopedCwd cwd(dir_);
    EXPECT_EQ(LoadScene(kSteadyTow).spheres.at(0).mass, 416.0);
  }
  {
    // a relative scene path: its folder is relative to the working directory
    const ScopedCwd cwd(kConfigDir);
    EXPECT_EQ(LoadScene("scenes/steady_tow.yaml").spheres.at(0).mass, 416.0);
  }
  {
    // from text: against base_dir
    const ScopedCwd cwd(dir_);
    std::ifstream in(kSteadyTow);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(
        LoadSceneFromString(text, "steady_tow.yaml", kConfigDir + "/scenes").spheres.at(0).mass,
        416.0);
    EXPECT_THROW(LoadSceneFromString(text, "steady_tow.yaml", dir_.string()), ConfigError);
  }
}

}  // namespace
}  // namespace towsim::scene
