// scene/: YAML scene -> core::Model. Broken scenes must fail with the key path, the value,
// file:line and the rule in the message; the shipped scenes must load with the right numbers.

#include "scene/scene_loader.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace towsim::scene {
namespace {

namespace fs = std::filesystem;
using Model = core::Model;

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
  EXPECT_EQ(m.cable.elements, 10);
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_EQ(m.cable.end.kind, core::EndKind::kBody);
  EXPECT_EQ(m.cable.end.body, 0);
  EXPECT_TRUE(m.cable.loads.drag);
  EXPECT_FALSE(m.cable.loads.added_mass);
  EXPECT_FALSE(m.cable.loads.bending);
  // no driven end, no initial_velocity: bodies start at rest
  EXPECT_EQ(m.bodies[0].velocity, core::Vec3::Zero());
  // defaults
  EXPECT_EQ(m.environment.water_density, 1025.0);
  EXPECT_EQ(m.integrator.max_iterations, 20);
  EXPECT_EQ(m.cable.axial_damping, 0.0);
  EXPECT_EQ(m.cable.added_mass_coefficient, 1.0);
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
        BrokenCase{"staggered", Edit("rho_inf: 0.8", "coupling: staggered"), "integrator.coupling",
                   "staggered scheme comes with the 6-DOF vehicles", ""},
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
            "cable.end", "would stretch the 100 m cable by 10% (at most 1%)", ""},
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
        BrokenCase{"negative_mass", Edit("mass: 10", "mass: -1"), "bodies.fish.mass", "must be > 0",
                   ""},
        BrokenCase{"body_without_position", Edit(", position: [0, 0, 100]", ""),
                   "bodies.fish.position", "is required", "t.yaml:14"},
        BrokenCase{"not_a_sphere", Edit("type: sphere", "type: box"), "bodies.fish.type",
                   "only type: sphere is supported by this build", ""},
        BrokenCase{"missing_model_file",
                   Edit(kFishLine, "fish: {model: nope.yaml, position: [0, 0, 100]}"),
                   "bodies.fish.model", "cannot read the model file", "t.yaml:14"},
        BrokenCase{"model_file_unknown_key",
                   Edit(kFishLine, "fish: {model: bad_fish.yaml, position: [0, 0, 100]}"),
                   "bodies.fish.colour", "unknown key", "bad_fish.yaml:3"},
        BrokenCase{"model_file_not_a_sphere",
                   Edit(kFishLine, "fish: {model: box_fish.yaml, position: [0, 0, 100]}"),
                   "bodies.fish.type", "only type: sphere", "box_fish.yaml:1"},
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
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_EQ(m.bodies[0].mass, 15.0);
  EXPECT_EQ(m.bodies[0].volume, 0.01);
  EXPECT_EQ(m.bodies[0].drag_coefficient, core::SphereBody{}.drag_coefficient);
}

TEST_F(SceneLoaderTest, LoadsAndSlopes) {
  // loads absent: all on; a clamped start gets a unit slope
  const Model m = Load(Edit("  loads: [gravity, buoyancy, drag]\n", ""));
  EXPECT_TRUE(m.cable.loads.gravity && m.cable.loads.buoyancy && m.cable.loads.drag &&
              m.cable.loads.added_mass && m.cable.loads.bending);
  const Model none = Load(Edit("[gravity, buoyancy, drag]", "[]"));
  EXPECT_FALSE(none.cable.loads.gravity || none.cable.loads.buoyancy || none.cable.loads.drag ||
               none.cable.loads.added_mass || none.cable.loads.bending);
  const Model clamped =
      Load(Edit("start: {fixed: [0, 0, 0]}", "start: {fixed: [0, 0, 0], slope: [0, 0, 2]}"));
  EXPECT_TRUE(clamped.cable.start.clamped);
  EXPECT_EQ(clamped.cable.start.slope, core::Vec3(0, 0, 1));
  EXPECT_FALSE(clamped.cable.end.clamped);
}

TEST_F(SceneLoaderTest, InitialVelocityIsTheBodiesDefault) {
  const Model m =
      Load(Edit("  initial: vertical\n", "  initial: vertical\n  initial_velocity: [1, 2, 3]\n"));
  EXPECT_EQ(m.bodies[0].velocity, core::Vec3(1, 2, 3));
  const Model given =
      Load(Edit("position: [0, 0, 100]", "position: [0, 0, 100], velocity: [0, 0, 1]"));
  EXPECT_EQ(given.bodies[0].velocity, core::Vec3(0, 0, 1));
}

TEST_F(SceneLoaderTest, StraightWithinOnePercentStretchLoads) {
  const Model m =
      Load(Edit("initial: vertical\n  start: {fixed: [0, 0, 0]}\n  end: {body: fish}",
                "initial: straight\n  start: {fixed: [0, 0, 0]}\n  end: {fixed: [100.5, 0, 0]}"));
  EXPECT_EQ(m.cable.initial, core::InitialShape::kStraight);
  EXPECT_EQ(m.cable.end.kind, core::EndKind::kFixed);
}

TEST_F(SceneLoaderTest, CatenaryScene) {
  const Model m = LoadScene(kCatenary);
  EXPECT_EQ(m.name, "catenary");
  EXPECT_EQ(m.time.step, 0.05);
  EXPECT_EQ(m.time.duration, 30.0);
  EXPECT_EQ(m.time.output_rate, 10.0);
  EXPECT_EQ(m.cable.length, 200.0);
  EXPECT_EQ(m.cable.elements, 20);
  EXPECT_EQ(m.cable.diameter, 0.041);
  EXPECT_EQ(m.cable.density, 1300.0);
  EXPECT_EQ(m.cable.youngs_modulus, 7.0e8);
  EXPECT_EQ(m.cable.initial, core::InitialShape::kStatic);
  EXPECT_EQ(m.cable.start.kind, core::EndKind::kFixed);
  EXPECT_EQ(m.cable.end.kind, core::EndKind::kFixed);
  EXPECT_EQ(m.cable.start.position, core::Vec3(0, 0, 10));
  EXPECT_EQ(m.cable.end.position, core::Vec3(150, 0, 10));
  const core::CableLoads& loads = m.cable.loads;
  EXPECT_TRUE(loads.gravity && loads.buoyancy && loads.drag && loads.added_mass && loads.bending);
  EXPECT_EQ(m.integrator.scheme, core::Scheme::kGeneralizedAlpha);
  EXPECT_EQ(m.integrator.rho_inf, 0.8);
  EXPECT_TRUE(m.bodies.empty());
  EXPECT_TRUE(m.script.empty());
}

TEST_F(SceneLoaderTest, SteadyTowScene) {
  const Model m = LoadScene(kSteadyTow);
  EXPECT_EQ(m.name, "steady_tow");
  EXPECT_EQ(m.time.step, 0.05);
  EXPECT_EQ(m.time.duration, 300.0);
  EXPECT_EQ(m.time.output_rate, 10.0);
  EXPECT_EQ(m.cable.length, 200.0);
  EXPECT_EQ(m.cable.elements, 20);
  EXPECT_EQ(m.cable.initial, core::InitialShape::kVertical);
  EXPECT_EQ(m.cable.start.kind, core::EndKind::kDriven);
  EXPECT_EQ(m.cable.start.position, core::Vec3(0, 0, 3.5));
  EXPECT_EQ(m.cable.start.velocity, core::Vec3(6, 0, 0));
  EXPECT_EQ(m.cable.end.kind, core::EndKind::kBody);
  EXPECT_EQ(m.cable.end.body, 0);
  EXPECT_EQ(m.cable.end.at_B, core::Vec3::Zero());
  ASSERT_EQ(m.bodies.size(), 1u);
  const core::SphereBody& fish = m.bodies[0];
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
  EXPECT_EQ(m.integrator.tolerance, 1e-8);
  EXPECT_EQ(m.integrator.max_iterations, 20);
}

TEST_F(SceneLoaderTest, Overrides) {
  const Model m =
      LoadScene(kSteadyTow, {"cable.elements=40", "cable.initial=static", "bodies.towfish.mass=500",
                             "environment.current=[0.5,0,0]"});
  EXPECT_EQ(m.cable.elements, 40);
  EXPECT_EQ(m.cable.initial, core::InitialShape::kStatic);
  EXPECT_EQ(m.bodies[0].mass, 500.0);
  EXPECT_EQ(m.bodies[0].volume, 0.2);  // still from the model file
  EXPECT_EQ(m.environment.current, core::Vec3(0.5, 0, 0));
  EXPECT_EQ(m.cable.length, 200.0);  // untouched
}

TEST_F(SceneLoaderTest, OverridesCreateValidKeysAndApplyInOrder) {
  // absent keys and sections may be created; the last override of a key wins
  const Model m =
      Load(kScene, {"cable.axial_damping=0.01", "environment.gravity=9.8", "cable.elements=12",
                    "cable.elements=14", "bodies.buoy={type: sphere, mass: 1, position: [5, 0, 0]}",
                    "cable.start={fixed: [0, 0, 0], slope: [0, 0, 1]}"});
  EXPECT_EQ(m.cable.axial_damping, 0.01);
  EXPECT_EQ(m.environment.gravity, 9.8);
  EXPECT_EQ(m.cable.elements, 14);
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.bodies[1].name, "buoy");
  EXPECT_TRUE(m.cable.start.clamped);
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
    EXPECT_EQ(LoadScene(kSteadyTow).bodies.at(0).mass, 416.0);
  }
  {
    // a relative scene path: its folder is relative to the working directory
    const ScopedCwd cwd(kConfigDir);
    EXPECT_EQ(LoadScene("scenes/steady_tow.yaml").bodies.at(0).mass, 416.0);
  }
  {
    // from text: against base_dir
    const ScopedCwd cwd(dir_);
    std::ifstream in(kSteadyTow);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(
        LoadSceneFromString(text, "steady_tow.yaml", kConfigDir + "/scenes").bodies.at(0).mass,
        416.0);
    EXPECT_THROW(LoadSceneFromString(text, "steady_tow.yaml", dir_.string()), ConfigError);
  }
}

}  // namespace
}  // namespace towsim::scene
