// scene/environment_reader: environment.current, .waves and .seabed from YAML and --set, and
// every broken value reported with its key path, value, file:line and rule.

#include "scene/environment_reader.h"

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace towsim::scene {
namespace {

using core::kPi;
using core::Vec3;

// A 40 m cable hanging from a fixed point with a sphere 40 m down; the environment block is
// line 3 onward. Line numbers matter to the assertions.
constexpr const char* kHead = R"(name: t
time: {step: 0.01, duration: 1, output_rate: 10}
)";
constexpr const char* kTail = R"(cable:
  length: 40
  elements: 5
  diameter: 0.04
  density: 1300
  youngs_modulus: 7.0e8
  start: {fixed: [0, 0, 0]}
  end: {body: fish}
bodies:
  fish: {type: sphere, mass: 10, volume: 0.001, position: [0, 0, 40]}
)";

class EnvironmentReaderTest : public ::testing::Test {
 protected:
  // the scene with `environment` (YAML lines, starting at line 3) between head and tail
  core::Model Load(const std::string& environment, const std::vector<std::string>& set = {}) {
    return LoadSceneFromString(kHead + environment + kTail, "t.yaml", dir_.path().string(), set);
  }
  // the message of the ConfigError that loading throws
  std::string Error(const std::string& environment, const std::vector<std::string>& set = {}) {
    try {
      Load(environment, set);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "no ConfigError";
  }
  void Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_.path() / name) << text;
  }
  test::TempDir dir_;
};

TEST_F(EnvironmentReaderTest, NothingGivenIsCalmBottomlessStill) {
  const core::Model m = Load("");
  EXPECT_TRUE(m.environment.current.IsZero());
  EXPECT_TRUE(m.environment.waves.empty());
  EXPECT_FALSE(m.environment.seabed.present());
}

TEST_F(EnvironmentReaderTest, UniformCurrentFromTheFileAndFromSet) {
  const core::Model m = Load("environment: {current: [0.5, -0.1, 0]}\n");
  EXPECT_TRUE(m.environment.current.IsUniform());
  EXPECT_EQ(m.environment.current.Velocity(30.0, 2.0), Vec3(0.5, -0.1, 0.0));
  const core::Model s = Load("", {"environment.current=[1,0,0]"});
  EXPECT_EQ(s.environment.current.Velocity(0.0, 0.0), Vec3(1.0, 0.0, 0.0));
  // a whole profile by --set
  const core::Model p =
      Load("", {"environment.current={power_law: {surface: [1, 0, 0], depth: 50}}"});
  EXPECT_EQ(p.environment.current.kind(), core::CurrentField::Kind::kPowerLaw);
  EXPECT_EQ(p.environment.current.power_law_exponent(), 7.0);
}

TEST_F(EnvironmentReaderTest, ProfilePowerLawAndTimeScale) {
  const core::Model m = Load(R"(environment:
  current:
    profile: [[0, [1, 0, 0]], [20, [0.5, 0.5, 0]], [100, [0, 0, 0]]]
    time_scale: [[0, 0], [60, 1]]
)");
  const core::CurrentField& c = m.environment.current;
  EXPECT_EQ(c.kind(), core::CurrentField::Kind::kProfile);
  EXPECT_FALSE(c.IsSteady());
  EXPECT_LT((c.Velocity(10.0, 60.0) - Vec3(0.75, 0.25, 0.0)).norm(), 1e-15);
  EXPECT_LT((c.Velocity(10.0, 30.0) - Vec3(0.375, 0.125, 0.0)).norm(), 1e-15);
  const core::Model p = Load(R"(environment:
  current: {power_law: {surface: [1.5, 0, 0], depth: 80, exponent: 5}}
)");
  EXPECT_NEAR(p.environment.current.Velocity(40.0, 0.0).x(), 1.5 * std::pow(0.5, 0.2), 1e-15);
}

TEST_F(EnvironmentReaderTest, RegularWavesOverDeepOrFiniteWater) {
  const core::Model m = Load(R"(environment:
  waves: {regular: {height: 2, period: 8, direction_deg: 90, phase_deg: 30}, ramp: 10}
)");
  const core::WaveField& w = m.environment.waves;
  ASSERT_EQ(w.components().size(), 1u);
  const core::WaveComponent& c = w.components()[0];
  EXPECT_EQ(c.amplitude, 1.0);
  EXPECT_DOUBLE_EQ(c.omega, 2.0 * kPi / 8.0);
  EXPECT_DOUBLE_EQ(c.k, c.omega * c.omega / 9.81);  // no seabed: deep water
  EXPECT_DOUBLE_EQ(c.direction, kPi / 2.0);
  EXPECT_DOUBLE_EQ(c.phase, kPi / 6.0);
  EXPECT_EQ(w.ramp(), 10.0);
  EXPECT_TRUE(std::isinf(w.depth()));
  // over a 60 m seabed the 8 s wave (L = 100 m) feels the bottom: the finite-depth k
  const core::Model f = Load(R"(environment:
  waves: {regular: {height: 1, period: 8}}
  seabed: {depth: 60}
)");
  EXPECT_EQ(f.environment.waves.depth(), 60.0);
  const double k = f.environment.waves.components()[0].k;
  EXPECT_NEAR(9.81 * k * std::tanh(60.0 * k), std::pow(2.0 * kPi / 8.0, 2), 1e-12);
}

TEST_F(EnvironmentReaderTest, JonswapAndPiersonMoskowitzSeas) {
  const core::Model m = Load(R"(environment:
  waves: {jonswap: {hs: 2, tp: 8, gamma: 3.3, direction_deg: 0, components: 50, seed: 7}}
)");
  const core::WaveField& w = m.environment.waves;
  ASSERT_EQ(w.components().size(), 50u);
  // equal energy: a = sqrt(2 m0 / N), m0 = Hs^2 / 16
  EXPECT_NEAR(w.components()[0].amplitude, std::sqrt(2.0 * 0.25 / 50.0), 1e-15);
  // the same seed gives the same sea; another seed another one
  const core::Model again = Load("", {"environment.waves.jonswap={hs: 2, tp: 8, components: "
                                      "50, seed: 7}"});
  EXPECT_EQ(again.environment.waves.components()[13].phase, w.components()[13].phase);
  const core::Model other = Load(R"(environment:
  waves: {jonswap: {hs: 2, tp: 8, components: 50, seed: 7}}
)",
                                 {"environment.waves.jonswap.seed=8"});
  EXPECT_NE(other.environment.waves.components()[13].phase, w.components()[13].phase);
  const core::Model pm = Load(R"(environment:
  waves: {pierson_moskowitz: {hs: 3, tp: 10}}
)");
  EXPECT_EQ(pm.environment.waves.components().size(), 100u);  // the default
}

TEST_F(EnvironmentReaderTest, FlatPlaneAndGridSeabeds) {
  const core::Model flat = Load(R"(environment:
  seabed: {depth: 60, stiffness: 1.0e5, damping: 100, friction: 0.3}
)");
  const core::Seabed& s = flat.environment.seabed;
  EXPECT_EQ(s.kind(), core::Seabed::Kind::kFlat);
  EXPECT_EQ(s.Depth(100.0, -5.0), 60.0);
  EXPECT_EQ(s.contact().stiffness, 1.0e5);
  EXPECT_EQ(s.contact().damping, 100.0);
  EXPECT_EQ(s.contact().friction, 0.3);
  EXPECT_EQ(s.contact().lateral_friction(), 0.3);  // not given: the axial coefficient
  const core::Model lateral = Load(R"(environment:
  seabed: {depth: 60, friction: 0.3, friction_lateral: 0.8}
)");
  EXPECT_EQ(lateral.environment.seabed.contact().lateral_friction(), 0.8);
  const core::Model plane = Load(R"(environment:
  seabed: {depth: 60, slope_deg: 45, slope_direction_deg: 180}
)");
  EXPECT_EQ(plane.environment.seabed.kind(), core::Seabed::Kind::kPlane);
  EXPECT_NEAR(plane.environment.seabed.Depth(-10.0, 3.0), 70.0, 1e-12);
  // --set reaches into the seabed map
  const core::Model set =
      Load("environment: {seabed: {depth: 60}}\n", {"environment.seabed.depth=80"});
  EXPECT_EQ(set.environment.seabed.Depth(0.0, 0.0), 80.0);
  Write("bed.txt", R"(# a 3 x 2 grid
3 2
-100 0 100
-50 50
-100 -50 70
0 -50 60   # the origin's row
100 -50 50
-100 50 70
0 50 60
100 50 50
)");
  const core::Model grid = Load(R"(environment:
  seabed: {grid: bed.txt}
)");
  EXPECT_EQ(grid.environment.seabed.kind(), core::Seabed::Kind::kGrid);
  EXPECT_NEAR(grid.environment.seabed.Depth(50.0, 0.0), 55.0, 1e-12);
}

struct BadCase {
  const char* name;
  std::string environment;  // YAML from line 3
  std::string message;      // the whole what()
};
std::ostream& operator<<(std::ostream& out, const BadCase& c) { return out << c.name; }

class BadEnvironmentTest : public EnvironmentReaderTest,
                           public ::testing::WithParamInterface<BadCase> {};

TEST_P(BadEnvironmentTest, NamesKeyValueLineAndRule) {
  Write("short.txt", "2 2\n0 10\n0 10\n0 0 50\n10 0 50\n0 10 50\n");
  Write("bad_line.txt", "2 2\n0 10\n0 10\n0 0 50\n10 0 50\n0 10\n10 10 50\n");
  Write("unsorted.txt", "2 2\n10 0\n0 10\n");
  Write("negative.txt", "2 2\n0 10\n0 10\n0 0 -50\n10 0 50\n0 10 50\n10 10 50\n");
  Write("off_grid.txt", "2 2\n0 10\n0 10\n0 0 50\n10 0 50\n0 5 50\n10 10 50\n");
  Write("twice.txt", "2 2\n0 10\n0 10\n0 0 50\n10 0 50\n0 10 50\n0 0 50\n");
  EXPECT_EQ(Error(GetParam().environment), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Table, BadEnvironmentTest,
    ::testing::Values(
        // current
        BadCase{"current_not_a_vector_or_map", "environment: {current: 1}\n",
                "environment.current = 1 (t.yaml:3): must be [u, v, w], {profile: [[depth, [u, "
                "v, w]], ...]} or {power_law: {surface: [u, v, w], depth: D, exponent: 7}}"},
        BadCase{"unsorted_profile",
                "environment:\n  current: {profile: [[0, [1, 0, 0]], [40, [0, 0, 0]], [30, [0, "
                "0, 0]]]}\n",
                "environment.current.profile[2][0] = 30 (t.yaml:4): depths must increase "
                "strictly down the table (the row before has 40)"},
        BadCase{"negative_profile_depth", "environment:\n  current: {profile: [[-5, [1, 0, 0]]]}\n",
                "environment.current.profile[0][0] = -5 (t.yaml:4): must be >= 0"},
        BadCase{"profile_row_shape", "environment:\n  current: {profile: [[0, 1, 0]]}\n",
                "environment.current.profile[0] = [0, 1, 0] (t.yaml:4): must be a row [depth, "
                "value]"},
        BadCase{"profile_and_power_law",
                "environment:\n  current:\n    profile: [[0, [1, 0, 0]]]\n    power_law: "
                "{surface: [1, 0, 0], depth: 9}\n",
                "environment.current.power_law = {surface: [1, 0, 0], depth: 9} (t.yaml:6): give "
                "one of profile and power_law, not both"},
        BadCase{"power_law_depth",
                "environment:\n  current: {power_law: {surface: [1, 0, 0], "
                "depth: 0}}\n",
                "environment.current.power_law.depth = 0 (t.yaml:4): must be > 0"},
        BadCase{"time_scale_unsorted",
                "environment:\n  current: {profile: [[0, [1, 0, 0]]], time_scale: [[5, 1], [5, "
                "2]]}\n",
                "environment.current.time_scale[1][0] = 5 (t.yaml:4): times must increase "
                "strictly down the table (the row before has 5)"},
        // waves
        BadCase{"negative_hs", "environment:\n  waves: {jonswap: {hs: -1, tp: 8}}\n",
                "environment.waves.jonswap.hs = -1 (t.yaml:4): must be > 0"},
        BadCase{"gamma_below_one", "environment:\n  waves: {jonswap: {hs: 2, tp: 8, gamma: 0.5}}\n",
                "environment.waves.jonswap.gamma = 0.5 (t.yaml:4): must be >= 1"},
        BadCase{"no_components",
                "environment:\n  waves: {jonswap: {hs: 2, tp: 8, components: 0}}\n",
                "environment.waves.jonswap.components = 0 (t.yaml:4): must be >= 1"},
        BadCase{"gamma_in_pierson_moskowitz",
                "environment:\n  waves: {pierson_moskowitz: {hs: 2, tp: 8, gamma: 2}}\n",
                "environment.waves.pierson_moskowitz.gamma = 2 (t.yaml:4): unknown key (allowed: "
                "hs, tp, direction_deg, components, seed)"},
        BadCase{"regular_period_too_short",
                "environment:\n  waves: {regular: {height: 0.01, period: 0.1}}\n",
                "environment.waves.regular.period = 0.1 (t.yaml:4): must be >= 20 time steps "
                "(0.2 s) for the integrator to resolve it"},
        BadCase{"jonswap_components_too_short",
                "environment:\n  waves: {jonswap: {hs: 0.1, tp: 0.5, components: 20, seed: "
                "3}}\n",
                "environment.waves.jonswap.tp = 0.5 (t.yaml:4): gives components as short as "
                "0.0998468 s; each must be >= 20 time steps (0.2 s) for the integrator to "
                "resolve it (raise tp or lower time.step)"},
        BadCase{"breaking_wave", "environment:\n  waves: {regular: {height: 20, period: 8}}\n",
                "environment.waves.regular.height = 20 (t.yaml:4): must be <= the breaking "
                "height 0.142 L tanh(k h) = 14.1892 m (wavelength L = 99.9238 m): linear theory "
                "needs an unbroken wave"},
        BadCase{"no_wave_kind", "environment:\n  waves: {ramp: 5}\n",
                "environment.waves = {ramp: 5} (t.yaml:4): must hold one of regular, jonswap, "
                "pierson_moskowitz"},
        BadCase{"negative_ramp",
                "environment:\n  waves: {regular: {height: 1, period: 8}, ramp: -1}\n",
                "environment.waves.ramp = -1 (t.yaml:4): must be >= 0"},
        // seabed
        BadCase{"seabed_without_depth", "environment:\n  seabed: {friction: 0.5}\n",
                "environment.seabed.depth = <missing> (t.yaml:4): is required"},
        BadCase{"vertical_slope", "environment:\n  seabed: {depth: 60, slope_deg: 90}\n",
                "environment.seabed.slope_deg = 90 (t.yaml:4): must be < 90"},
        BadCase{"negative_friction", "environment:\n  seabed: {depth: 60, friction: -0.1}\n",
                "environment.seabed.friction = -0.1 (t.yaml:4): must be >= 0"},
        BadCase{"body_below_the_seabed", "environment:\n  seabed: {depth: 30}\n",
                "bodies.fish.position = [0, 0, 40] (t.yaml:14): is below the seabed (depth 30 m "
                "at x = 0, y = 0)"},
        BadCase{"grid_and_depth", "environment:\n  seabed: {grid: short.txt, depth: 3}\n",
                "environment.seabed.depth = 3 (t.yaml:4): the grid file gives the depths; leave "
                "out depth, slope_deg and slope_direction_deg"},
        BadCase{"grid_node_missing", "environment:\n  seabed: {grid: short.txt}\n",
                "environment.seabed.grid = short.txt (t.yaml:4): short.txt: node (10, 10) has no "
                "depth line (4 nodes needed)"},
        BadCase{"grid_bad_line", "environment:\n  seabed: {grid: bad_line.txt}\n",
                "environment.seabed.grid = bad_line.txt (t.yaml:4): bad_line.txt:6: must be 'x y "
                "depth', three finite numbers"},
        BadCase{"grid_unsorted", "environment:\n  seabed: {grid: unsorted.txt}\n",
                "environment.seabed.grid = unsorted.txt (t.yaml:4): unsorted.txt:2: x "
                "coordinates must increase strictly (0 after 10)"},
        BadCase{"grid_negative_depth", "environment:\n  seabed: {grid: negative.txt}\n",
                "environment.seabed.grid = negative.txt (t.yaml:4): negative.txt:4: depth -50 "
                "must be > 0 (positive down, below the mean surface)"},
        BadCase{"grid_off_node", "environment:\n  seabed: {grid: off_grid.txt}\n",
                "environment.seabed.grid = off_grid.txt (t.yaml:4): off_grid.txt:6: (0, 5) is not "
                "a node of the grid (its x and y must be among the coordinates of lines 2 and 3)"},
        BadCase{"grid_twice", "environment:\n  seabed: {grid: twice.txt}\n",
                "environment.seabed.grid = twice.txt (t.yaml:4): twice.txt:7: node (0, 0) given "
                "twice (first at line 4)"},
        BadCase{"unknown_seabed_key", "environment:\n  seabed: {depht: 60}\n",
                "environment.seabed.depht = 60 (t.yaml:4): unknown key; did you mean depth? "
                "(allowed: depth, slope_deg, slope_direction_deg, grid, stiffness, damping, "
                "friction, friction_lateral)"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

// the file that is not there: named with its path
TEST_F(EnvironmentReaderTest, MissingGridFileNamesThePath) {
  const std::string what = Error("environment:\n  seabed: {grid: nowhere.txt}\n");
  EXPECT_EQ(what,
            "environment.seabed.grid = nowhere.txt (t.yaml:4): cannot read the bathymetry "
            "file " +
                (dir_.path() / "nowhere.txt").string() + ": no such file");
}

// --set paths into the wave maps are checked against the schema
TEST_F(EnvironmentReaderTest, SetIntoWavesIsValidated) {
  EXPECT_EQ(Error("", {"environment.waves.jonswap.hz=2"}),
            "environment.waves.jonswap.hz = 2 (--set): environment.waves.jonswap: unknown key; "
            "did you mean hs? (allowed: hs, tp, gamma, direction_deg, components, seed)");
  EXPECT_EQ(Error("environment: {waves: {jonswap: {hs: 2, tp: 8}}}\n",
                  {"environment.waves.jonswap.hs=-2"}),
            "environment.waves.jonswap.hs = -2 (--set): must be > 0");
}

// the shipped waves scene: Case 1's system in a JONSWAP sea (Hs 2 m, Tp 8 s) over 60 m of water
TEST(ShippedScene, Case3WavesLoads) {
  const core::Model m =
      LoadScene(std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case3_waves.yaml");
  const core::WaveField& w = m.environment.waves;
  ASSERT_EQ(w.components().size(), 100u);
  double m0 = 0.0;
  for (const core::WaveComponent& c : w.components()) m0 += 0.5 * c.amplitude * c.amplitude;
  EXPECT_NEAR(4.0 * std::sqrt(m0), 2.0, 1e-12);  // Hs
  EXPECT_EQ(w.depth(), 60.0);
  EXPECT_EQ(w.ramp(), 20.0);
  EXPECT_DOUBLE_EQ(w.components()[0].direction, kPi);  // head sea: toward -x
  EXPECT_EQ(m.environment.seabed.kind(), core::Seabed::Kind::kFlat);
  EXPECT_EQ(m.environment.seabed.Depth(0.0, 0.0), 60.0);
  ASSERT_EQ(m.vehicles.size(), 2u);
  EXPECT_EQ(m.cables[0].initial, core::InitialShape::kStatic);
}

}  // namespace
}  // namespace towsim::scene
