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
  EXPECT_EQ(
      Error("scene: steady_tow.yaml\nparameter:\n  cable.elements: [1]\n"),
      "parameter = {cable.elements: [1]} (sweep.yaml:2): unknown key; did you mean "
      "parameters? (allowed: scene, duration, combine, parameters, results, controllers, domain, "
      "lockstep_timeout)");
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

// controllers (docs/sweeps.md "Controllers"): programs and arguments as written, a plain
// parameter named by an argument goes to the controllers only, every controller is told the
// domain, domain and lockstep_timeout read
TEST(SweepFile, ControllersTheirParametersAndTheDomain) {
  const SweepSpec s = Load(R"(scene: case1_forward.yaml
duration: 10
domain: 206
lockstep_timeout: 2.5
controllers:
  - program: maneuver_runner
    args: [--maneuver, case1, --thrust, "${thrust}"]
  - {program: ../bin/towfish_depth, name: depth, args: [--depth, 25, --domain, "${domain}",
                                                       --log, "${case_dir}/depth.log"]}
parameters:
  thrust: [0, 4165]
  cable.elements: [10, 20]
results:
  d: {signal: towfish.depth, settled: {window: 5, tolerance: 0.05}}
  n: {signal: newton_iterations_max}
)");
  ASSERT_EQ(s.controllers.size(), 2u);
  EXPECT_EQ(s.controllers[0].name, "maneuver_runner");  // the program's name
  EXPECT_EQ(s.controllers[0].program, "maneuver_runner");
  // no ${domain}: --domain ${domain} appended
  EXPECT_EQ(s.controllers[0].args,
            (std::vector<std::string>{"--maneuver", "case1", "--thrust", "${thrust}", "--domain",
                                      "${domain}"}));
  EXPECT_EQ(s.controllers[0].location, "sweep.yaml:6");
  EXPECT_EQ(s.controllers[1].name, "depth");
  EXPECT_EQ(s.controllers[1].program, "../bin/towfish_depth");
  // ${domain} named: nothing appended
  EXPECT_EQ(s.controllers[1].args,
            (std::vector<std::string>{"--depth", "25", "--domain", "${domain}", "--log",
                                      "${case_dir}/depth.log"}));
  EXPECT_EQ(s.domain, 206);
  EXPECT_EQ(s.domain_location, "sweep.yaml:3");
  ASSERT_TRUE(s.lockstep_timeout);
  EXPECT_EQ(*s.lockstep_timeout, 2.5);
  EXPECT_EQ(s.base_dir, kScenes);
  ASSERT_EQ(s.parameters.size(), 2u);
  EXPECT_TRUE(s.parameters[0].controllers_only);   // thrust: not a scene key, named ${thrust}
  EXPECT_FALSE(s.parameters[1].controllers_only);  // cable.elements: a scene key path
  ASSERT_TRUE(s.results[0].settled);
  EXPECT_EQ(s.results[0].settled->window, 5.0);
  EXPECT_EQ(s.results[0].settled->tolerance, 0.05);
  EXPECT_FALSE(s.results[1].settled);

  // without controllers: the defaults
  const SweepSpec plain = Load("scene: steady_tow.yaml\nparameters:\n  cable.elements: [1]\n");
  EXPECT_TRUE(plain.controllers.empty());
  EXPECT_EQ(plain.domain, kDefaultSweepDomain);
  EXPECT_FALSE(plain.lockstep_timeout);
}

TEST(SweepFile, BrokenControllersAndSettled) {
  const std::string head = "scene: case1_forward.yaml\nduration: 5\n";
  const std::string params = "parameters:\n  cable.elements: [10]\n";
  EXPECT_EQ(Error("scene: case1_forward.yaml\ncontrollers:\n  - {program: a}\n" + params),
            "controllers = [{program: a}] (sweep.yaml:2): need duration: (a DDS node runs until "
            "stopped; a case runs `duration` seconds of simulated time)");
  EXPECT_EQ(Error(head + "domain: 7\n" + params),
            "domain = 7 (sweep.yaml:3): needs controllers: (cases without controllers run "
            "offline, without DDS)");
  EXPECT_EQ(Error(head + "lockstep_timeout: 2\n" + params),
            "lockstep_timeout = 2 (sweep.yaml:3): needs controllers: (cases without controllers "
            "run offline, without DDS)");
  const std::string one = "controllers:\n  - {program: a}\n";
  EXPECT_EQ(Error(head + one + "domain: 232\n" + params),
            "domain = 232 (sweep.yaml:5): must be <= 231");
  EXPECT_EQ(Error(head + one + "lockstep_timeout: -1\n" + params),
            "lockstep_timeout = -1 (sweep.yaml:5): must be >= 0");
  EXPECT_EQ(Error(head + "controllers: []\n" + params),
            "controllers = [] (sweep.yaml:3): must be a list of controllers, each {program: P, "
            "args: [...], name: N}");
  EXPECT_EQ(Error(head + "controllers:\n  - {args: [x]}\n" + params),
            "controllers[0].program = <missing> (sweep.yaml:4): is required: the controller's "
            "executable");
  EXPECT_EQ(Error(head + "controllers:\n  - {program: a, arg: [x]}\n" + params),
            "controllers[0].arg = [x] (sweep.yaml:4): unknown key; did you mean args? (allowed: "
            "program, args, name)");
  EXPECT_EQ(Error(head + "controllers:\n  - {program: bin/a}\n  - {program: a}\n" + params),
            "controllers[1].program = a (sweep.yaml:5): a second controller named a (first at "
            "sweep.yaml:4); give each its own name:");
  EXPECT_EQ(Error(head + "controllers:\n  - {program: a, name: sim_node}\n" + params),
            "controllers[0].name = sim_node (sweep.yaml:4): sim_node's logs have this name; give "
            "another name:");
  EXPECT_EQ(Error(head + "controllers:\n  - {program: a, args: [[1, 2]]}\n" + params),
            "controllers[0].args[0] = [1, 2] (sweep.yaml:4): an argument must be a scalar "
            "(quote it)");
  EXPECT_EQ(
      Error(head + "controllers:\n  - {program: a, args: [\"${gain\"]}\n" + params),
      "controllers[0].args[0] = \"${gain\" (sweep.yaml:4): \"${\" without its \"}\" in ${gain");
  EXPECT_EQ(Error(head + "controllers:\n  - {program: a, args: [\"${gian}\"]}\n" +
                  "parameters:\n  gain: [1, 2]\n"),
            "controllers[0].args[0] = \"${gian}\" (sweep.yaml:4): ${gian} names no parameter; the "
            "placeholders are the parameters (gain, ...) and domain, case, case_dir");
  // a plain parameter no argument names is a scene key path, and says how to name it
  EXPECT_EQ(Error(head + one + "parameters:\n  gain: [1, 2]\n"),
            "parameters.gain = [1, 2] (sweep.yaml:6): the scene: unknown key (allowed: name, time, "
            "environment, line_types, cable, cables, bodies, integrator, script, publish, security) (a "
            "parameter of the controllers only is named in their args as ${gain})");
  EXPECT_EQ(Error(head + "controllers:\n  - {program: a, args: [\"${domain}\"]}\n" +
                  "parameters:\n  domain: [1, 2]\n"),
            "parameters.domain = [1, 2] (sweep.yaml:6): is a placeholder of its own (${domain}); "
            "choose another name");
  // settled
  EXPECT_EQ(Error(head + params + "results:\n  d: {signal: towfish.z, settled: 0.1}\n"),
            "results.d.settled = 0.1 (sweep.yaml:6): must be a map {window: W, tolerance: T}: "
            "the signal settled when its change (max - min) over the final W seconds is below T");
  EXPECT_EQ(Error(head + params +
                  "results:\n  d: {signal: towfish.z, settled: {window: 0, tolerance: 1}}\n"),
            "results.d.settled.window = 0 (sweep.yaml:6): must be > 0");
  EXPECT_EQ(Error(head + params + "results:\n  d: {signal: towfish.z, settled: {window: 2}}\n"),
            "results.d.settled.tolerance = <missing> (sweep.yaml:6): is required");
  EXPECT_EQ(
      Error(head + params + "results:\n  d: {signal: towfish.z, settled: {window: 2, tol: 1}}\n"),
      "results.d.settled.tol = 1 (sweep.yaml:6): unknown key (allowed: window, "
      "tolerance)");
}

}  // namespace
}  // namespace towsim::app
