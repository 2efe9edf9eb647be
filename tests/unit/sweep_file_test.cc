// app/sweep/sweep_file: a sweep file -> SweepSpec. Values written out, ranges and seeded draws;
// broken files fail with the key path, the value, file:line and the rule.

#include "app/sweep/sweep_file.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/sweep/sweep_values.h"
#include "scene/config_error.h"

namespace towsim::app {
namespace {

const std::string kScenes = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes";

SweepSpec Load(const std::string& yaml) { return LoadSweepFromString(yaml, "sweep.yaml", kScenes); }

// the message of the ConfigError that loading `yaml` throws ("" if none)
std::string Error(const std::string& yaml) {
  try {
    Load(yaml);
  } catch (const scene::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepFile, ListsRangesAndDrawsInFileOrder) {
  const SweepSpec s = Load(R"(scene: steady_tow.yaml
duration: 5
parameters:
  cable.elements: {from: 10, to: 40, step: 10}
  integrator.rho_inf: {from: 0.6, to: 0.9, count: 4}
  cable.start.driven.velocity: [[3, 0, 0], [6, 0, 0]]
  integrator.scheme: [generalized_alpha, trapezoidal]
  environment.water_density: {random: uniform, low: 1020, high: 1030, count: 3, seed: 7}
results:
  depth: {signal: towfish.depth}
  tension: {signal: top_tension, stat: rms, from: 2}
)");
  EXPECT_EQ(s.scene, kScenes + "/steady_tow.yaml");
  ASSERT_TRUE(s.duration);
  EXPECT_EQ(*s.duration, 5.0);
  ASSERT_EQ(s.parameters.size(), 5u);
  EXPECT_EQ(s.parameters[0].path, "cable.elements");
  EXPECT_EQ(s.parameters[0].values, (std::vector<std::string>{"10", "20", "30", "40"}));
  EXPECT_EQ(s.parameters[1].values, (std::vector<std::string>{"0.6", "0.7", "0.8", "0.9"}));
  EXPECT_EQ(s.parameters[2].values, (std::vector<std::string>{"[3, 0, 0]", "[6, 0, 0]"}));
  EXPECT_EQ(s.parameters[3].values, (std::vector<std::string>{"generalized_alpha", "trapezoidal"}));
  // the draws are the values of UniformDraws with that seed, as %.9g
  const std::vector<double> draws = UniformDraws(1020, 1030, 3, 7);
  ASSERT_EQ(s.parameters[4].values.size(), 3u);
  for (size_t i = 0; i < 3; ++i) EXPECT_EQ(s.parameters[4].values[i], FormatSweepNumber(draws[i]));
  EXPECT_EQ(s.parameters[0].location, "sweep.yaml:4");
  ASSERT_EQ(s.results.size(), 2u);
  EXPECT_EQ(s.results[0].name, "depth");
  EXPECT_EQ(s.results[0].signal, "towfish.depth");
  EXPECT_EQ(s.results[0].stat, "");  // the sweep tool makes it "final"
  EXPECT_EQ(s.results[1].stat, "rms");
  ASSERT_TRUE(s.results[1].from);
  EXPECT_EQ(*s.results[1].from, 2.0);
  EXPECT_EQ(s.combine, SweepCombine::kProduct);
}

// line types (docs/scene_format.md "Line types"): a sweep over the type, its drag and a
// type's key; each value is the --set value of its case
TEST(SweepFile, LineTypeKeysAreParameters) {
  const SweepSpec s = Load(R"(scene: steady_tow.yaml
parameters:
  cable.drag: [{normal: 1.2, tangential: 0.008}, {normal: 1.5, tangential: 0.01}]
  cable.bending_stiffness: [0, 9.71]
  line_types.wire.drag.normal: [1.2, 1.5]
)");
  ASSERT_EQ(s.parameters.size(), 3u);
  EXPECT_EQ(s.parameters[0].values[1], "{normal: 1.5, tangential: 0.01}");
  EXPECT_EQ(s.parameters[1].path, "cable.bending_stiffness");
  EXPECT_EQ(s.parameters[2].path, "line_types.wire.drag.normal");
  EXPECT_EQ(Error("scene: steady_tow.yaml\nparameters:\n  cable.drag.cn: [1, 2]\n"),
            "parameters.cable.drag.cn = [1, 2] (sweep.yaml:3): cable.drag: unknown key "
            "(allowed: normal, tangential)");
}

TEST(SweepFile, BadKeyPathsAreReportedWithTheSweepFilesLine) {
  // the --set rules of sim_node, located in the sweep file
  EXPECT_EQ(Error("scene: steady_tow.yaml\nparameters:\n  cable.lenght: [100, 200]\n"),
            "parameters.cable.lenght = [100, 200] (sweep.yaml:3): cable: unknown key; did you "
            "mean length? (allowed: length, elements, line_type, diameter, mass_per_length, "
            "density, axial_stiffness, youngs_modulus, bending_stiffness, axial_damping, drag, "
            "added_mass, added_mass_coefficient, loads, initial, initial_velocity, start, end, "
            "winch)");
  EXPECT_NE(Error("scene: steady_tow.yaml\nparameters:\n  bodies.fish.mass: [1, 2]\n")
                .find("parameters.bodies.fish.mass = [1, 2] (sweep.yaml:3): no body named fish "
                      "in the scene (bodies: towfish)"),
            std::string::npos);
  EXPECT_EQ(Error("scene: steady_tow.yaml\nparameters:\n  cable..length: [1]\n"),
            "parameters.cable..length = [1] (sweep.yaml:3): key path must be names joined by "
            "dots, e.g. cable.length");
}

TEST(SweepFile, BrokenValuesNameTheRule) {
  const std::string head = "scene: steady_tow.yaml\nparameters:\n";
  EXPECT_EQ(Error(head + "  cable.elements: 10\n"),
            "parameters.cable.elements = 10 (sweep.yaml:3): must be a list of values, a range "
            "{from, to, step} or {from, to, count}, or seeded draws {random: "
            "uniform|normal|integer, ..., count, seed}");
  EXPECT_EQ(Error(head + "  cable.elements: []\n"),
            "parameters.cable.elements = [] (sweep.yaml:3): must list at least one value");
  EXPECT_EQ(Error(head + "  cable.elements: {from: 10, to: 40}\n"),
            "parameters.cable.elements = {from: 10, to: 40} (sweep.yaml:3): a range needs "
            "exactly one of step and count");
  EXPECT_EQ(Error(head + "  cable.elements: {from: 10, to: 40, step: -5}\n"),
            "parameters.cable.elements.step = -5 (sweep.yaml:3): must point from `from` towards "
            "`to`");
  EXPECT_EQ(Error(head + "  cable.elements: {from: 9223372036854775800, to: "
                         "9223372036854775807, step: 1}\n"),
            "parameters.cable.elements.from = 9223372036854775800 (sweep.yaml:3): an integer "
            "range must lie within -(2^53 - 1) .. 2^53 - 1 = 9007199254740991 (exact in a "
            "double)");
  EXPECT_EQ(Error(head + "  cable.elements: {from: 1, to: 9007199254740991, step: 1}\n"),
            "parameters.cable.elements.step = 1 (sweep.yaml:3): gives more than 1e6 values");
  EXPECT_EQ(Error(head + "  cable.elements: {from: -9007199254740993, to: 1, step: "
                         "9007199254740992}\n"),
            "parameters.cable.elements.from = -9007199254740993 (sweep.yaml:3): an integer "
            "range must lie within -(2^53 - 1) .. 2^53 - 1 = 9007199254740991 (exact in a "
            "double)");
  EXPECT_EQ(Error(head + "  cable.density: {random: uniform, low: 1, high: 2, count: 3}\n"),
            "parameters.cable.density.seed = <missing> (sweep.yaml:3): is required: every draw "
            "is seeded (reproducible)");
  EXPECT_EQ(Error(head + "  cable.density: {random: normal, low: 1, stddev: 2, count: 3, "
                         "seed: 1}\n"),
            "parameters.cable.density.low = 1 (sweep.yaml:3): not a key of random: normal (it "
            "takes mean, stddev, count, seed)");
  EXPECT_EQ(Error(head + "  cable.density: {random: gauss, count: 3, seed: 1}\n"),
            "parameters.cable.density.random = gauss (sweep.yaml:3): must be one of uniform, "
            "normal, integer");
  EXPECT_EQ(Error("scene: steady_tow.yaml\ncombine: zip\nparameters:\n  cable.elements: [1, 2]\n"
                  "  cable.density: [1, 2, 3]\n"),
            "parameters.cable.density = [1, 2, 3] (sweep.yaml:5): has 3 values, cable.elements "
            "has 2: combine: zip needs lists of one length");
}

TEST(SweepFile, BrokenTopLevelAndResults) {
  EXPECT_EQ(Error("scene: steady_tow.yaml\nparameter:\n  cable.elements: [1]\n"),
            "parameter = {cable.elements: [1]} (sweep.yaml:2): unknown key; did you mean "
            "parameters? (allowed: scene, duration, combine, parameters, results)");
  EXPECT_EQ(Error("scene: nope.yaml\nparameters:\n  cable.elements: [1]\n"),
            "scene = " + kScenes +
                "/nope.yaml (sweep.yaml:1): cannot read the scene file (no "
                "such file; the path is relative to the sweep file)");
  EXPECT_EQ(Error("scene: steady_tow.yaml\n"),
            "parameters = <missing> (sweep.yaml:1): is required: a map of scene key paths to "
            "values");
  const std::string head = "scene: steady_tow.yaml\nparameters:\n  cable.elements: [1]\n";
  EXPECT_EQ(Error(head + "results:\n  wall_s: {signal: rtf}\n"),
            "results.wall_s = {signal: rtf} (sweep.yaml:5): is a column of results.csv "
            "already; choose another name");
  EXPECT_EQ(Error(head + "results:\n  d: {signal: towfish.z, stat: median}\n"),
            "results.d.stat = median (sweep.yaml:5): must be one of final, initial, min, max, "
            "max_abs, mean, rms, std");
  EXPECT_EQ(Error(head + "results:\n  d: {signal: towfish.z, from: 5, to: 2}\n"),
            "results.d.to = 2 (sweep.yaml:5): must be > 5");
}

}  // namespace
}  // namespace towsim::app
