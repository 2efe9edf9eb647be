// Line types (scene/line_type_reader.h, docs/scene_format.md "Line types"): the keys, where a
// name is looked up, the cable over the type, --set, and the messages of every rule.

#include "scene/line_type_reader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/model.h"
#include "scene/config_error.h"
#include "scene/scene_loader.h"

namespace towsim::scene {
namespace {

namespace fs = std::filesystem;

const std::string kConfigDir = std::string(TOWSIM_SOURCE_DIR) + "/config";
const std::string kScenesDir = kConfigDir + "/scenes";

// a scene with one line type in its map; `cable_extra` adds keys to the cable
std::string Scene(const std::string& line_types, const std::string& cable_extra) {
  return "name: t\n"
         "time: {step: 0.05, duration: 1, output_rate: 10}\n" +
         line_types +
         "cable:\n"
         "  length: 100\n"
         "  elements: 10\n" +
         cable_extra +
         "  start: {fixed: [0, 0, 0]}\n"
         "  end: {free: true}\n";
}

const std::string kTether =
    "line_types:\n"
    "  tether:\n"
    "    diameter: 0.02\n"
    "    mass_per_length: 0.5\n"
    "    axial_stiffness: 2.0e6\n"
    "    bending_stiffness: 0.5\n"
    "    drag: {normal: 1.5, tangential: 0.01}\n"
    "    added_mass: {normal: 0.9, tangential: 0.1}\n";

core::Model Load(const std::string& yaml, const std::vector<std::string>& overrides = {},
                 const std::string& base_dir = kScenesDir) {
  return LoadSceneFromString(yaml, "t.yaml", base_dir, overrides);
}

// the message of the ConfigError `yaml` gives, or "no error"
std::string Error(const std::string& yaml, const std::vector<std::string>& overrides = {},
                  const std::string& base_dir = kScenesDir) {
  try {
    Load(yaml, overrides, base_dir);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(LineTypeReader, TheScenesTypeGivesEveryProperty) {
  const core::CableParams c = Load(Scene(kTether, "  line_type: tether\n")).cables[0];
  EXPECT_EQ(c.diameter, 0.02);
  EXPECT_EQ(c.mass_per_length, 0.5);
  EXPECT_EQ(c.axial_stiffness, 2.0e6);
  EXPECT_EQ(c.bending_stiffness, 0.5);
  EXPECT_EQ(c.drag.kind, core::CableDragLaw::kConstant);
  EXPECT_EQ(c.drag.normal, 1.5);
  EXPECT_EQ(c.drag.tangential, 0.01);
  EXPECT_EQ(c.added_mass.normal, 0.9);
  EXPECT_EQ(c.added_mass.tangential, 0.1);
  EXPECT_EQ(c.axial_damping, 0.0);
}

TEST(LineTypeReader, TodaysKeysGiveTheSolidSection) {
  const core::CableParams c =
      Load(Scene("", "  diameter: 0.041\n  density: 1300\n  youngs_modulus: 7.0e8\n")).cables[0];
  // m = rho_c A, EA = E A, EI = E I, bit for bit as before line types
  EXPECT_EQ(c.mass_per_length, 1300.0 * c.area());
  EXPECT_EQ(c.axial_stiffness, 7.0e8 * c.area());
  EXPECT_EQ(c.bending_stiffness, 7.0e8 * c.second_moment());
  EXPECT_EQ(c.drag.kind, core::CableDragLaw::kChooCasarella);
  EXPECT_EQ(c.added_mass.normal, 1.0);
  EXPECT_EQ(c.added_mass.tangential, 0.0);
  // EA without E: the solid section's EI from E = EA / A (d = 0.041 m: A = 1.3203e-3 m^2,
  // I = 1.3873e-7 m^4, EI = EA d^2 / 16)
  const core::CableParams d =
      Load(Scene("", "  diameter: 0.041\n  mass_per_length: 1.7\n  axial_stiffness: 1.0e6\n"))
          .cables[0];
  EXPECT_NEAR(d.bending_stiffness, 1.0e6 * 0.041 * 0.041 / 16.0, 1e-12);
  // 0 switches bending off
  EXPECT_EQ(Load(Scene("",
                       "  diameter: 0.041\n  density: 1300\n  youngs_modulus: 7.0e8\n"
                       "  bending_stiffness: 0\n"))
                .cables[0].bending_stiffness,
            0.0);
}

TEST(LineTypeReader, TheLibraryTypeIsTheShippedCable) {
  // config/scenes/../line_types/park_kim_tow_cable.yaml: the steady tow's cable, to the bit
  const core::Model shipped = LoadScene(kScenesDir + "/steady_tow.yaml");
  const core::Model typed = LoadScene(kScenesDir + "/steady_tow.yaml",
                                      {"cable={line_type: park_kim_tow_cable, length: 200, "
                                       "elements: 20, start: {driven: {position: [0, 0, 3.5], "
                                       "velocity: [6, 0, 0]}}, end: {body: towfish}}"});
  const core::CableParams& a = shipped.cables[0];
  const core::CableParams& b = typed.cables[0];
  EXPECT_EQ(a.diameter, b.diameter);
  EXPECT_EQ(a.mass_per_length, b.mass_per_length);
  EXPECT_EQ(a.axial_stiffness, b.axial_stiffness);
  EXPECT_EQ(a.bending_stiffness, b.bending_stiffness);
  EXPECT_EQ(b.drag.kind, core::CableDragLaw::kChooCasarella);
  EXPECT_EQ(a.added_mass.normal, b.added_mass.normal);
  EXPECT_EQ(a.added_mass.tangential, b.added_mass.tangential);
}

TEST(LineTypeReader, EveryLibraryFileLoads) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kConfigDir + "/line_types")) {
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE(name);
    const core::CableParams c = Load(Scene("", "  line_type: " + name + "\n")).cables[0];
    EXPECT_GT(c.diameter, 0.0);
    EXPECT_GT(c.mass_per_length, 0.0);
    EXPECT_GT(c.axial_stiffness, 0.0);
    ++count;
  }
  EXPECT_GE(count, 4);
  // the numbers of two of them (their sources in the files)
  const core::CableParams oc3 = Load(Scene("", "  line_type: oc3_hywind_mooring\n")).cables[0];
  EXPECT_EQ(oc3.mass_per_length, 77.7066);
  EXPECT_EQ(oc3.axial_stiffness, 384.243e6);
  EXPECT_EQ(oc3.bending_stiffness, 0.0);
  EXPECT_EQ(oc3.drag.normal, 1.6);
  EXPECT_EQ(oc3.drag.tangential, 0.1);
  const core::CableParams jumper = Load(Scene("", "  line_type: lowe_langley_jumper\n")).cables[0];
  EXPECT_EQ(jumper.bending_stiffness, 120.8e3);
  EXPECT_EQ(jumper.axial_stiffness, 500.0e6);
}

TEST(LineTypeReader, TheScenesMapWinsOverTheLibrary) {
  const std::string own =
      "line_types:\n"
      "  oc3_hywind_mooring: {diameter: 0.05, mass_per_length: 3, axial_stiffness: 1e7}\n";
  const core::CableParams c = Load(Scene(own, "  line_type: oc3_hywind_mooring\n")).cables[0];
  EXPECT_EQ(c.diameter, 0.05);
  EXPECT_EQ(c.mass_per_length, 3.0);
}

TEST(LineTypeReader, APathIsRelativeToTheScenesFolder) {
  const core::CableParams c =
      Load(Scene("", "  line_type: ../line_types/moordyn_nylon_rope.yaml\n")).cables[0];
  EXPECT_EQ(c.mass_per_length, 13.76);
  EXPECT_EQ(c.axial_stiffness, 2515288.0);
  EXPECT_EQ(c.drag.normal, 1.6);
  EXPECT_EQ(c.drag.tangential, 0.05);
}

TEST(LineTypeReader, ALibraryBesideTheScene) {
  // a line_types/ folder in the scene's own folder
  const fs::path dir = fs::path(::testing::TempDir()) / "line_type_reader_test";
  fs::create_directories(dir / "line_types");
  std::ofstream(dir / "line_types" / "mine.yaml")
      << "diameter: 0.03\nmass_per_length: 1.1\naxial_stiffness: 3e6\nbending_stiffness: 0\n";
  std::ofstream(dir / "scene.yaml") << Scene("", "  line_type: mine\n");
  const core::CableParams c = LoadScene((dir / "scene.yaml").string()).cables[0];
  EXPECT_EQ(c.diameter, 0.03);
  EXPECT_EQ(c.axial_stiffness, 3e6);
  fs::remove_all(dir);
}

TEST(LineTypeReader, TheCablesKeysOverrideTheTypes) {
  // a pair as a whole: youngs_modulus replaces the type's axial_stiffness; EI stays the type's
  const core::CableParams c =
      Load(Scene(kTether, "  line_type: tether\n  youngs_modulus: 1.0e10\n  diameter: 0.03\n"))
          .cables[0];
  EXPECT_EQ(c.diameter, 0.03);
  EXPECT_EQ(c.axial_stiffness, 1.0e10 * c.area());
  EXPECT_EQ(c.bending_stiffness, 0.5);
  EXPECT_EQ(c.mass_per_length, 0.5);
  // added_mass_coefficient: C_an only
  const core::CableParams d =
      Load(Scene(kTether, "  line_type: tether\n  added_mass_coefficient: 0.7\n")).cables[0];
  EXPECT_EQ(d.added_mass.normal, 0.7);
  EXPECT_EQ(d.added_mass.tangential, 0.1);
  // added_mass per coefficient
  const core::CableParams e =
      Load(Scene(kTether, "  line_type: tether\n  added_mass: {tangential: 0.3}\n")).cables[0];
  EXPECT_EQ(e.added_mass.normal, 0.9);
  EXPECT_EQ(e.added_mass.tangential, 0.3);
  // drag as a whole
  const core::CableParams f =
      Load(Scene(kTether, "  line_type: tether\n  drag: choo_casarella\n")).cables[0];
  EXPECT_EQ(f.drag.kind, core::CableDragLaw::kChooCasarella);
}

TEST(LineTypeReader, SetTakesTheNewKeys) {
  const std::string yaml = Scene(kTether, "  line_type: tether\n");
  // a coefficient over the type's drag keeps the type's other one
  const core::CableParams n = Load(yaml, {"cable.drag.normal=1.2"}).cables[0];
  EXPECT_EQ(n.drag.normal, 1.2);
  EXPECT_EQ(n.drag.tangential, 0.01);
  EXPECT_EQ(Load(yaml, {"line_types.tether.bending_stiffness=0"}).cables[0].bending_stiffness, 0.0);
  EXPECT_EQ(Load(yaml, {"cable.line_type=oc3_hywind_mooring"}).cables[0].mass_per_length, 77.7066);
  EXPECT_EQ(Load(yaml, {"cable.drag=choo_casarella"}).cables[0].drag.kind,
            core::CableDragLaw::kChooCasarella);
  const core::CableParams c =
      Load(yaml, {"cable.drag={normal: 1.1, tangential: 0.02}", "cable.mass_per_length=0.8",
                  "cable.added_mass.tangential=0.2"})
          .cables[0];
  EXPECT_EQ(c.drag.normal, 1.1);
  EXPECT_EQ(c.drag.tangential, 0.02);
  EXPECT_EQ(c.mass_per_length, 0.8);
  EXPECT_EQ(c.added_mass.tangential, 0.2);
  EXPECT_EQ(Error(yaml, {"line_types.tether.bending=1"}),
            "line_types.tether.bending = 1 (--set): line_types.tether: unknown key; did you "
            "mean bending_stiffness? (allowed: diameter, mass_per_length, density, "
            "axial_stiffness, youngs_modulus, bending_stiffness, axial_damping, drag, "
            "added_mass, source)");
}

TEST(LineTypeReader, EveryRuleNamesItsKey) {
  const std::string section = "  diameter: 0.02\n  mass_per_length: 0.5\n";
  // one of each pair
  EXPECT_EQ(Error(Scene("", section + "  axial_stiffness: 1e6\n  youngs_modulus: 1e9\n")),
            "cable.youngs_modulus = 1e9 (t.yaml:9): give one of axial_stiffness and "
            "youngs_modulus, not both");
  EXPECT_EQ(Error(Scene("", section)),
            "cable.axial_stiffness = <missing> (t.yaml:3): is required: give axial_stiffness or "
            "youngs_modulus (the line's stiffness)");
  EXPECT_EQ(Error(Scene(kTether, "  line_type: tether\n  density: 900\n  mass_per_length: 1\n")),
            "cable.density = 900 (t.yaml:15): give one of mass_per_length and density, not both");
  EXPECT_EQ(Error(Scene("line_types:\n  bare: {mass_per_length: 1, axial_stiffness: 1e6}\n",
                        "  line_type: bare\n")),
            "cable.diameter = <missing> (t.yaml:5): is required (in cable or in its line type "
            "bare)");
  // positive values, where they were written
  EXPECT_EQ(Error(Scene("line_types:\n  bad:\n    diameter: 0.02\n    mass_per_length: -1\n"
                        "    axial_stiffness: 1e6\n",
                        "  line_type: bad\n")),
            "line_types.bad.mass_per_length = -1 (t.yaml:6): must be > 0");
  EXPECT_EQ(Error(Scene("", section + "  axial_stiffness: 1e6\n  bending_stiffness: -2\n")),
            "cable.bending_stiffness = -2 (t.yaml:9): must be >= 0");
  EXPECT_EQ(Error(Scene("", section + "  axial_stiffness: 1e6\n  drag: {normal: 1.5}\n")),
            "cable.drag.tangential = <missing> (t.yaml:9): is required");
  EXPECT_EQ(Error(Scene("", section + "  axial_stiffness: 1e6\n  drag: {normal: -1, "
                                      "tangential: 0}\n")),
            "cable.drag.normal = -1 (t.yaml:9): must be >= 0");
  EXPECT_EQ(Error(Scene("", section + "  axial_stiffness: 1e6\n  drag: morison\n")),
            "cable.drag = morison (t.yaml:9): must be one of choo_casarella");
  EXPECT_EQ(Error(Scene("", section + "  axial_stiffness: 1e6\n  added_mass: {normal: 1}\n"
                                      "  added_mass_coefficient: 1\n")),
            "cable.added_mass_coefficient = 1 (t.yaml:10): give one of added_mass and "
            "added_mass_coefficient, not both");
  EXPECT_EQ(Error(Scene("", section + "  axial_stiffness: 1e6\n  added_mass: {tangential: -1}\n")),
            "cable.added_mass.tangential = -1 (t.yaml:9): must be >= 0");
  // the physical limits: EA of a Young's modulus of 1e13 Pa over the section
  EXPECT_EQ(Error(Scene("", section + "  axial_stiffness: 1e13\n")),
            "cable.axial_stiffness = 1e13 (t.yaml:8): must be <= 3.14159e+09 N (a Young's "
            "modulus of 1e13 Pa over the section of diameter 0.02 m; the stiffest material, "
            "diamond, is 1.2e12)");
}

TEST(LineTypeReader, AnUnknownNameSaysWhereItLooked) {
  const std::string dir = "/nowhere/scenes";
  EXPECT_EQ(Error(Scene(kTether, "  line_type: steel\n"), {}, dir),
            "cable.line_type = steel (t.yaml:14): no such line type: not in the scene's "
            "line_types (tether) and no file /nowhere/scenes/line_types/steel.yaml, "
            "/nowhere/line_types/steel.yaml");
  EXPECT_EQ(Error(Scene("", "  line_type: 9lives\n")),
            "cable.line_type = 9lives (t.yaml:6): line type names must match "
            "[A-Za-z_][A-Za-z0-9_]*");
}

TEST(LineTypeReader, AStiffnessTheWeightsWouldStretchBeyondHalfIsFlagged) {
  // 100 m of 0.5 kg/m (d 0.02: 0.322 kg/m displaced) in water: weight in water 174.6 N; half
  // of it, 87.3 N, on EA = 100 N is a strain of 87 %
  EXPECT_EQ(Error(Scene(kTether, "  line_type: tether\n  axial_stiffness: 100\n")),
            "cable.axial_stiffness = 100 (t.yaml:15): gives EA = 100 N, which the weights alone "
            "(87.3025 N: half the cable's weight in water and the spheres hanging on it) would "
            "stretch by 87.3025 % (at most 50 %: no cable material stretches that far)");
  // at 400 N (22 %) it runs: the run's strain watch reports what the dynamics do
  EXPECT_EQ(
      Load(Scene(kTether, "  line_type: tether\n  axial_stiffness: 400\n")).cables[0].axial_stiffness,
      400.0);
}

// T_min of the check: half the cable's weight in water plus the spheres hanging on it; on a
// seabed (which may carry the cable) the spheres only
TEST(LineTypeReader, MinimumTensionOfTheSteadyTow) {
  core::Model m = LoadScene(kScenesDir + "/steady_tow.yaml");
  // cable: (1300 - 1025) kg/m^3 x 1.32025e-3 m^2 x 9.81 x 200 m / 2 = 356.17 N;
  // sphere: (416 - 1025 x 0.2) kg x 9.81 = 2069.91 N
  constexpr double kTol = 0.01;  // [N], the hand values' rounding
  EXPECT_NEAR(internal::MinimumTension(m.cables[0], m), 356.17 + 2069.91, kTol);
  m.environment.seabed = core::Seabed::Flat(300.0);
  EXPECT_NEAR(internal::MinimumTension(m.cables[0], m), 2069.91, kTol);
  // a free end carries nothing: the cable's half only
  m.environment.seabed = core::Seabed();
  m.cables[0].end.kind = core::EndKind::kFree;
  EXPECT_NEAR(internal::MinimumTension(m.cables[0], m), 356.17, kTol);
}

}  // namespace
}  // namespace towsim::scene
