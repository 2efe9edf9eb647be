// The bodies map (scene/body_reader.h): `scale: lambda` on a vehicle with a model file. The
// scaled vehicle is core::ScaleVehicle of its model file, every number bit for bit; scale 1
// is the model itself; what is not part of the model (position, attachment points, commands)
// is the scene's, unscaled; bad values and combinations are refused with the key, the value
// and the rule.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/vehicle_scaling.h"
#include "scene/scene_loader.h"
#include "vehicle_fields.h"

namespace towsim::scene {
namespace {

const std::string kVehicles = std::string(TOWSIM_SOURCE_DIR) + "/config/vehicles/";

std::uint64_t Bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// a one-vehicle scene: `body` is the entry of bodies.v (line 6)
std::string Scene(const std::string& body) {
  return "name: s\n"
         "time: {step: 0.01, duration: 1, output_rate: 10}\n"
         "cable: {length: 10, elements: 1, diameter: 0.01, density: 1300, youngs_modulus: 1e9,\n"
         "        initial: vertical, start: {body: v, at: [1.65, 0, 0]}, end: {free: true}}\n"
         "bodies:\n"
         "  v: " +
         body + "\n";
}

std::string Model(const std::string& file) { return "model: '" + kVehicles + file + "'"; }

core::Model Load(const std::string& body, const std::vector<std::string>& overrides = {}) {
  return LoadSceneFromString(Scene(body), "s.yaml", "/", overrides);
}

// the message of the ConfigError that loading throws ("" if none)
std::string Error(const std::string& body, const std::vector<std::string>& overrides = {}) {
  try {
    Load(body, overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

void ExpectBitEqual(const core::VehicleParams& a, const core::VehicleParams& b) {
  EXPECT_TRUE(test::SameNonNumericFields(a, b));
  core::VehicleParams x = a, y = b;
  for (const test::VehicleField& f : test::VehicleFields(a)) {
    EXPECT_EQ(Bits(f.get(x)), Bits(f.get(y))) << f.name << ": " << f.get(x) << " vs " << f.get(y);
  }
}

TEST(BodyScale, ScaleOneIsTheModel) {
  for (const char* file : {"tow_vehicle.yaml", "towfish.yaml"}) {
    SCOPED_TRACE(file);
    const core::Model plain = Load("{" + Model(file) + ", position: [0, 0, 3]}");
    const core::Model one = Load("{" + Model(file) + ", scale: 1, position: [0, 0, 3]}");
    ExpectBitEqual(plain.vehicles.at(0).params, one.vehicles.at(0).params);
  }
}

TEST(BodyScale, ScaledVehicleIsScaleVehicleOfItsFile) {
  for (const char* file : {"tow_vehicle.yaml", "towfish.yaml"}) {
    for (const double lambda : {0.25, 2.0, 3.0}) {
      SCOPED_TRACE(std::string(file) + " x " + std::to_string(lambda));
      const core::VehicleParams expected =
          core::ScaleVehicle(LoadVehicleFile(kVehicles + file), lambda);
      char scale[32];
      std::snprintf(scale, sizeof scale, "%.17g", lambda);
      const core::Model m =
          Load("{" + Model(file) + ", scale: " + scale + ", position: [0, 0, 7]}");
      ExpectBitEqual(m.vehicles.at(0).params, expected);
      // the scene's own values are not scaled: the initial position and the attachment point
      // are given in the scaled body's world and frame
      EXPECT_EQ(m.vehicles[0].position, core::Vec3(0, 0, 7));
      EXPECT_EQ(m.cables.at(0).start.at_B, core::Vec3(1.65, 0, 0));
    }
  }
  // --set reaches the key like any other
  const core::Model m =
      Load("{" + Model("towfish.yaml") + ", position: [0, 0, 7]}", {"bodies.v.scale=2"});
  EXPECT_EQ(m.vehicles.at(0).params.mass, 416.0 * 8.0);
}

TEST(BodyScale, CommandsAreCheckedAgainstTheScaledVehicle) {
  // max_thrust 12000 N x 2^3: 50 kN is beyond the file's vehicle, within the scaled one
  const std::string body =
      "{" + Model("tow_vehicle.yaml") + ", position: [0, 0, 7], " + "command: {thrust: 50000}";
  EXPECT_EQ(Error(body + ", scale: 2}"), "");
  EXPECT_EQ(Error(body + "}"),
            "bodies.v.command.thrust = 50000 (s.yaml:6): must be in [-max_thrust/4, max_thrust] "
            "= [-3000, 12000] N for v");
}

TEST(BodyScale, BadScalesAreRefusedWithKeyValueAndRule) {
  const std::string fish = "{" + Model("towfish.yaml") + ", position: [0, 0, 7], scale: ";
  const std::string rule_positive =
      "must be > 0 (the ratio lambda of the body's size to its model file's)";
  EXPECT_EQ(Error(fish + "0}"), "bodies.v.scale = 0 (s.yaml:6): " + rule_positive);
  EXPECT_EQ(Error(fish + "-2}"), "bodies.v.scale = -2 (s.yaml:6): " + rule_positive);
  EXPECT_EQ(Error(fish + ".nan}"), "bodies.v.scale = .nan (s.yaml:6): must be a finite number");
  EXPECT_EQ(Error(fish + ".inf}"), "bodies.v.scale = .inf (s.yaml:6): must be a finite number");
  EXPECT_EQ(Error(fish + "two}"), "bodies.v.scale = two (s.yaml:6): must be a number");
  EXPECT_EQ(Error(fish + "1e80}"),
            "bodies.v.scale = 1e80 (s.yaml:6): is out of range: the scaled mass (lambda^3) and "
            "inertia (lambda^5) must be finite and > 0");
  EXPECT_EQ(Error(fish + "1e-80}"),
            "bodies.v.scale = 1e-80 (s.yaml:6): is out of range: the scaled mass (lambda^3) and "
            "inertia (lambda^5) must be finite and > 0");
  EXPECT_EQ(Error("{" + Model("towfish.yaml") + ", position: [0, 0, 7]}", {"bodies.v.scale=0"}),
            "bodies.v.scale = 0 (--set): " + rule_positive);
}

TEST(BodyScale, ScaleIsForVehiclesWithAModelFileAlone) {
  // a sphere is given by its own numbers
  EXPECT_EQ(Error("{" + Model("sphere_416kg.yaml") + ", position: [0, 0, 7], scale: 2}"),
            "bodies.v.scale = 2 (s.yaml:6): applies only to type: vehicle (a sphere is given by "
            "its own mass, volume and coefficients: write them at the size you want)");
  // a model key beside scale would be ambiguous (at which size?)
  EXPECT_EQ(Error("{" + Model("towfish.yaml") + ", position: [0, 0, 7], scale: 2, mass: 900}"),
            "bodies.v.mass = 900 (s.yaml:6): cannot be given beside scale: a scaled vehicle takes "
            "every coefficient from its model file (write a model file at the size you want to "
            "change one)");
  EXPECT_NE(Error("{" + Model("towfish.yaml") + ", position: [0, 0, 7], scale: 2}",
                  {"bodies.v.damping.x_uu=-3"})
                .find("bodies.v.damping = "),
            std::string::npos);
  // the type may be repeated in the scene
  EXPECT_EQ(Error("{" + Model("towfish.yaml") + ", type: vehicle, position: [0, 0, 7], scale: 2}"),
            "");
  // an inline vehicle has no model file to scale
  EXPECT_EQ(Error("{type: vehicle, source: inline, length: 1, mass: 20, inertia: [0.1, 1, 1], "
                  "r_g: [0, 0, 0], volume: 0.02, position: [0, 0, 7], scale: 2}"),
            "bodies.v.scale = 2 (s.yaml:6): needs a model file (model: FILE): scale sizes the "
            "vehicle of that file");
}

}  // namespace
}  // namespace towsim::scene
