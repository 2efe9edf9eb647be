#include "scene/body_reader.h"

#include <filesystem>
#include <memory>
#include <optional>

#include "scene/config_error.h"

namespace towsim::scene::internal {
namespace {

// The vehicle file named by bodies.<name>.model, read as a checked map whose keys carry the
// body's path (bodies.<name>.mass) and whose locations name the vehicle file.
MapReader ReadModelFile(const Field& model, const std::string& body_path,
                        const std::string& base_dir) {
  // the path is relative to the scene's folder
  std::filesystem::path path(model.String());
  if (path.is_relative()) path = std::filesystem::path(base_dir) / path;
  path = path.lexically_normal();

  std::string text;
  std::string why;
  if (!ReadTextFile(path.string(), &text, &why)) {
    model.Fail("cannot read the model file " + path.string() + " (" + why + ")");
  }
  auto source = std::make_shared<Source>();
  source->name = path.filename().string();
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    const std::string line = e.mark.is_null() ? "" : ":" + std::to_string(e.mark.line + 1);
    throw ConfigError(model.path(), model.text(), source->name + line, "not valid YAML: " + e.msg);
  }
  // a model file is a map of body parameters
  if (!root.IsMap()) {
    throw ConfigError(model.path(), model.text(), source->name,
                      "a model file must be a map of body parameters (type, mass, ...)");
  }
  return MapReader(Field(root, root.Mark(), body_path, source), MapKind::kModelFile);
}

BodyInput ReadBody(const std::string& name, const Field& field, const std::string& base_dir) {
  const MapReader scene_keys(field, MapKind::kBody);
  std::optional<MapReader> file_keys;
  if (scene_keys.Has("model")) {
    file_keys.emplace(ReadModelFile(scene_keys.Get("model"), field.path(), base_dir));
  }
  // a key given in the scene overrides the model file's
  const auto pick = [&](const std::string& key) {
    if (!scene_keys.Has(key) && file_keys && file_keys->Has(key)) return file_keys->Get(key);
    return scene_keys.Get(key);
  };

  // only spheres in this build
  const Field type = pick("type");
  if (!type.present()) type.Fail("is required (type: sphere, or a model file that gives it)");
  if (type.String() != "sphere") {
    type.Fail("only type: sphere is supported by this build (6-DOF vehicles are not built yet)");
  }

  BodyInput input;
  core::SphereBody& body = input.body;
  body.name = name;
  body.mass = pick("mass").Number(Range::Above(0.0));
  const auto optional_number = [&](const std::string& key, double fallback) {
    const Field value = pick(key);
    return value.present() ? value.Number(Range::AtLeast(0.0)) : fallback;
  };
  body.volume = optional_number("volume", body.volume);
  body.drag_coefficient = optional_number("drag_coefficient", body.drag_coefficient);
  body.added_mass_coefficient =
      optional_number("added_mass_coefficient", body.added_mass_coefficient);
  // position and velocity belong to the scene, not to the vehicle file
  body.position = scene_keys.Vector("position");
  input.velocity_given = scene_keys.Has("velocity");
  if (input.velocity_given) body.velocity = scene_keys.Vector("velocity");
  return input;
}

}  // namespace

std::vector<BodyInput> ReadBodies(const Field& bodies, const std::string& base_dir) {
  // a map name -> body; names are checked by the reader
  const MapReader map(bodies, MapKind::kBodies);
  std::vector<BodyInput> inputs;
  inputs.reserve(map.entries().size());
  for (const auto& [name, field] : map.entries()) inputs.push_back(ReadBody(name, field, base_dir));
  return inputs;
}

std::string BodyNames(const std::vector<core::SphereBody>& bodies) {
  std::string names;
  for (const core::SphereBody& body : bodies) names += (names.empty() ? "" : ", ") + body.name;
  return names.empty() ? "none" : names;
}

int FindBody(const std::vector<core::SphereBody>& bodies, const std::string& name) {
  for (size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace towsim::scene::internal
