#include "scene/scene_loader.h"

#include <filesystem>
#include <memory>
#include <new>

#include <yaml-cpp/yaml.h>

#include "scene/body_reader.h"
#include "scene/cable_reader.h"
#include "scene/environment_reader.h"
#include "scene/network_reader.h"
#include "scene/overrides.h"
#include "scene/rao_coverage.h"
#include "scene/rao_file.h"
#include "scene/time_history_file.h"
#include "scene/script_reader.h"
#include "scene/sensor_reader.h"
#include "scene/vehicle_reader.h"
#include "scene/yaml_reader.h"

namespace towsim::scene {
namespace {

using internal::Field;
using internal::MapKind;
using internal::MapReader;
using internal::Range;

core::TimeSettings ReadTime(const Field& field) {
  const MapReader time(field, MapKind::kTime);
  core::TimeSettings t;
  // all > 0 and finite
  t.step = time.Number("step", Range::Above(0.0));
  t.duration = time.Number("duration", Range::Above(0.0));
  t.output_rate = time.Number("output_rate", Range::Above(0.0));
  // at least one step
  if (t.step > t.duration) {
    time.Get("step").Fail("must be <= time.duration (" + internal::FormatNumber(t.duration) + ")");
  }
  // a countable number of steps
  if (!(t.duration / t.step <= core::kMaxSteps)) {
    time.Get("step").Fail("must be >= time.duration / 1e12 (" +
                          internal::FormatNumber(t.duration / core::kMaxSteps) +
                          "): at most 1e12 steps");
  }
  return t;
}

core::IntegratorSettings ReadIntegrator(const Field& field) {
  const MapReader integrator(field, MapKind::kIntegrator);
  core::IntegratorSettings s;
  if (integrator.Has("scheme")) {
    const size_t scheme = integrator.Get("scheme").Choice({"generalized_alpha", "trapezoidal"});
    s.scheme = scheme == 0 ? core::Scheme::kGeneralizedAlpha : core::Scheme::kTrapezoidal;
  }
  s.rho_inf = integrator.Number("rho_inf", Range::Closed(0.0, 1.0), s.rho_inf);
  if (integrator.Has("coupling")) {
    const size_t coupling = integrator.Get("coupling").Choice({"strong", "staggered"});
    s.coupling = coupling == 0 ? core::Coupling::kStrong : core::Coupling::kStaggered;
  }
  s.tolerance = integrator.Number("tolerance", Range::LeftOpen(0.0, 1e-2), s.tolerance);
  s.force_tolerance =
      integrator.Number("force_tolerance", Range::Open(0.0, 1.0), s.force_tolerance);
  s.max_iterations = integrator.Integer("max_iterations", Range::Closed(1, 1000), s.max_iterations);
  s.max_substep_level =
      integrator.Integer("max_substep_level", Range::Closed(0, 20), s.max_substep_level);
  s.max_coupling_iterations = integrator.Integer("max_coupling_iterations", Range::Closed(1, 1000),
                                                 s.max_coupling_iterations);
  return s;
}

// publish: per-topic rates of a DDS node [Hz] (0: every step) and the command timeout [s]
core::Publishing ReadPublish(const Field& field) {
  const MapReader publish(field, MapKind::kPublish);
  core::Publishing p;
  // every rate key (core/publish_rates.h): >= 0; absent: the default
  for (const core::PublishRateKey& k : core::kPublishRateKeys) {
    if (publish.Has(k.key)) p.rates[k.rate] = publish.Get(k.key).Number(Range::AtLeast(0.0));
  }
  p.command_timeout = publish.Number("command_timeout", Range::Above(0.0), p.command_timeout);
  return p;
}

// a vessel's RAOs cover the scene's sea and its time history the run (docs/vessels.md): else
// the error names the key, what is not covered and the rule
void CheckVesselCoverage(const Field& bodies_field, const core::Model& model) {
  const MapReader bodies(bodies_field, MapKind::kBodies);
  for (const core::Vessel& v : model.vessels) {
    const MapReader body(bodies.Get(v.name), MapKind::kBody);
    const auto at = [&](const std::string& key) {
      return body.Has(key) ? body.Get(key) : body.field();
    };
    if (v.raos && !v.raos->extrapolate) {
      bool turns = false;
      for (const core::CourseChange& c : v.course) turns |= c.set_heading || c.set_turn_rate;
      const std::string problem = RaoCoverageProblem(
          *v.raos, model.environment.waves.components(), turns, v.euler.z());
      if (!problem.empty()) {
        at("raos").Fail(problem +
                        "; give RAOs that cover the sea, or rao_extrapolation: hold to hold "
                        "the nearest entry");
      }
    }
    if (v.time_history) {
      const std::string problem = TimeHistoryCoverageProblem(*v.time_history, model.time.duration);
      if (!problem.empty()) at("time_history").Fail(problem);
    }
  }
}

core::Model BuildModel(const Field& root, const std::string& base_dir) {
  const MapReader scene(root, MapKind::kScene);
  core::Model model;
  // name: a non-empty string
  const Field name = scene.Require("name");
  model.name = name.String();
  if (model.name.empty()) name.Fail("must not be empty");
  model.time = ReadTime(scene.Require("time"));
  model.environment = internal::ReadEnvironment(scene.Get("environment"), model.time, base_dir);

  // bodies first: cable ends and script entries refer to them
  const internal::BodiesInput bodies = internal::ReadBodies(scene.Get("bodies"), base_dir);
  for (const internal::SphereInput& sphere : bodies.spheres) model.spheres.push_back(sphere.body);
  for (const internal::VehicleInput& v : bodies.vehicles) model.vehicles.push_back(v.vehicle);
  model.vessels = bodies.vessels;
  internal::CheckBodiesAboveSeabed(scene.Get("bodies"), model);
  model.sensors = internal::ReadSensors(scene.Get("bodies"), model.time.step);
  // cable: the one-cable form (a cable named `cable`); cables: a network (network_reader.h)
  if (scene.Has("cable") && scene.Has("cables")) {
    scene.Get("cables").Fail(
        "give either cable (one cable) or cables (a network of named cables), not both");
  }
  if (scene.Has("cables")) {
    model.cables =
        internal::ReadCables(scene.Get("cables"), scene.Get("line_types"), base_dir, model);
  } else {
    model.cables = {
        internal::ReadCable(scene.Require("cable"), scene.Get("line_types"), base_dir, model)};
    // the one cable's winch is `winch` (its topic <ns>/winch/command, winch.csv)
    if (std::optional<core::WinchParams>& w = model.cables[0].winch) {
      if (!w->name.empty() && w->name != "winch") {
        internal::MapReader(internal::MapReader(scene.Get("cable"), internal::MapKind::kCable)
                                .Get("winch"),
                            internal::MapKind::kWinch)
            .Get("name")
            .Fail("the winch of the one-cable form is named winch (rt/<ns>/winch/command, "
                  "winch.csv); name: applies to the winches of cables:");
      }
      w->name = "winch";
    }
  }
  // a sphere without mass (nor added mass) is a junction: its position is set by the cable
  // ends that meet there, two or more (one alone would leave it undetermined)
  for (size_t i = 0; i < model.spheres.size(); ++i) {
    const core::SphereBody& b = model.spheres[i];
    if (b.mass > 0.0 || b.added_mass_coefficient * b.volume > 0.0) continue;
    int ends = 0;
    for (const core::CableParams& c : model.cables)
      for (const core::CableEnd* e : {&c.start, &c.end})
        ends += e->kind == core::EndKind::kSphere && e->body == static_cast<int>(i);
    if (ends >= 2) continue;
    const Field entry = MapReader(scene.Get("bodies"), MapKind::kBodies).Get(b.name);
    const MapReader body(entry, MapKind::kBody);
    (body.Has("mass") ? body.Get("mass") : entry)
        .Fail("a sphere without mass is a junction of cables: hold it by two or more cable ends "
              "(" + std::to_string(ends) + " hold" + (ends == 1 ? "s" : "") +
              " it), or give it a mass");
  }
  // bodies that give no velocity start with the first cable that holds them, else the first
  // cable (vehicles: in their body frame)
  const auto start_velocity = [&](core::EndKind kind, int body) {
    for (const core::CableParams& c : model.cables)
      for (const core::CableEnd* e : {&c.start, &c.end})
        if (e->kind == kind && e->body == body) return c.initial_velocity;
    return model.cables.front().initial_velocity;
  };
  for (size_t i = 0; i < bodies.spheres.size(); ++i) {
    if (!bodies.spheres[i].velocity_given)
      model.spheres[i].velocity = start_velocity(core::EndKind::kSphere, static_cast<int>(i));
  }
  for (size_t i = 0; i < bodies.vehicles.size(); ++i) {
    core::Vehicle& v = model.vehicles[i];
    if (!bodies.vehicles[i].velocity_given) {
      v.nu.head<3>() = core::QuaternionFromEulerZYX(v.euler).conjugate() *
                       start_velocity(core::EndKind::kVehicle, static_cast<int>(i));
    }
  }

  model.integrator = ReadIntegrator(scene.Get("integrator"));
  model.publishing = ReadPublish(scene.Get("publish"));
  // security: what a node run with --security admits (docs/security.md)
  const MapReader security(scene.Get("security"), MapKind::kSecurity);
  if (security.Has("open_outputs")) {
    model.publishing.open_outputs = security.Get("open_outputs").Boolean();
  }
  model.script = internal::ReadScript(scene.Get("script"), &model);
  CheckVesselCoverage(scene.Get("bodies"), model);
  return model;
}

}  // namespace

core::Model LoadScene(const std::string& path, const std::vector<std::string>& overrides) {
  std::string text;
  std::string why;
  if (!internal::ReadTextFile(path, &text, &why)) {
    throw ConfigError("scene", path, path, "cannot read the scene file (" + why + ")");
  }
  // messages name the file by its basename; model paths are relative to its folder
  const std::filesystem::path file(path);
  const std::string base_dir = file.has_parent_path() ? file.parent_path().string() : ".";
  try {
    return LoadSceneFromString(text, file.filename().string(), base_dir, overrides);
  } catch (const std::bad_alloc&) {
    // a tree too large for the memory left: the file is named, not a bare std::bad_alloc
    throw ConfigError("scene", path, path, "out of memory while reading the scene file");
  }
}

core::Model LoadSceneFromString(const std::string& yaml, const std::string& name_for_messages,
                                const std::string& base_dir,
                                const std::vector<std::string>& overrides) {
  auto source = std::make_shared<internal::Source>();
  source->name = name_for_messages;

  // the text is YAML, a map of keys
  YAML::Node root = internal::LoadYamlMap(
      yaml, name_for_messages,
      "a scene must be a map of keys (name, time, environment, cable or cables, bodies, "
      "integrator, script)");

  internal::ApplyOverrides(overrides, root, source.get());
  return BuildModel(Field(root, root.Mark(), "", source), base_dir);
}

std::vector<std::string> SceneWarnings(const core::Model& model) {
  std::vector<std::string> warnings;
  const auto held = [&](core::EndKind kind, int body) {
    for (const core::CableParams& c : model.cables)
      for (const core::CableEnd* e : {&c.start, &c.end})
        if (e->kind == kind && e->body == body) return true;
    return false;
  };
  for (size_t i = 0; i < model.spheres.size(); ++i)
    if (!held(core::EndKind::kSphere, static_cast<int>(i)))
      warnings.push_back("bodies." + model.spheres[i].name +
                         ": no cable end holds this body; it moves on its own");
  for (size_t i = 0; i < model.vehicles.size(); ++i)
    if (!held(core::EndKind::kVehicle, static_cast<int>(i)))
      warnings.push_back("bodies." + model.vehicles[i].name +
                         ": no cable end holds this body; it moves on its own");
  for (size_t i = 0; i < model.vessels.size(); ++i)
    if (!held(core::EndKind::kVessel, static_cast<int>(i)))
      warnings.push_back("bodies." + model.vessels[i].name +
                         ": no cable end holds this body; it moves on its own");
  return warnings;
}

core::VehicleParams LoadVehicleFile(const std::string& path) {
  // the path stands in for the scene key that would name the file
  auto source = std::make_shared<internal::Source>();
  source->name = path;
  const Field named(YAML::Node(path), YAML::Mark::null_mark(), "model", source);
  const Field root = internal::LoadModelFile(named, "", ".");
  const Field type = internal::FileType(root);
  if (type.Choice({"sphere", "vehicle"}) != 1) {
    type.Fail("must be vehicle (this reads the model files of 6-DOF vehicles)");
  }
  // no scene entry: every key from the file
  const MapReader no_scene(Field::Missing("", root), MapKind::kBody);
  return internal::ReadVehicleParams(
      internal::BodyKeys(no_scene, MapReader(root, MapKind::kVehicleFile)));
}

}  // namespace towsim::scene
