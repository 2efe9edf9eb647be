#include "scene/body_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <new>
#include <optional>

#include "core/vehicle_scaling.h"
#include "scene/config_error.h"
#include "scene/vehicle_reader.h"
#include "scene/vessel_reader.h"

namespace towsim::scene::internal {
namespace {

bool Allowed(MapKind kind, const std::string& key) {
  const std::vector<std::string>& keys = AllowedKeys(kind);
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// the body types (the values of `type`), their model files' kinds and the scene keys of their
// initial state
const std::vector<std::string> kTypes = {"sphere", "vehicle", "vessel"};
constexpr MapKind kFileKind[] = {MapKind::kModelFile, MapKind::kVehicleFile, MapKind::kVesselFile};
const std::vector<std::string> kStateKeys[] = {
    {"position", "velocity"}, {"position", "euler_deg", "velocity", "command", "scale"},
    {"position", "euler_deg"}};

// the key of the scene's body entry belongs to body type `type`
bool OfType(const std::string& key, size_t type) {
  if (key == "type" || key == "model" || key == "sensors") return true;
  const std::vector<std::string>& state = kStateKeys[type];
  return Allowed(kFileKind[type], key) ||
         std::find(state.begin(), state.end(), key) != state.end();
}

// a key of the scene's body entry that belongs to another type of body
void CheckKeysOfType(const MapReader& scene_keys, size_t type) {
  for (const auto& [key, value] : scene_keys.entries()) {
    if (OfType(key, type)) continue;
    std::string types;
    for (size_t t = 0; t < kTypes.size(); ++t)
      if (OfType(key, t)) types += (types.empty() ? "type: " : " or type: ") + kTypes[t];
    std::string why = "this body is a " + kTypes[type];
    if (type == 0) why += ", whose frame stays aligned with the world";
    value.Fail("applies only to " + types + " (" + why + ")");
  }
}

SphereInput ReadSphere(const std::string& name, const BodyKeys& keys) {
  SphereInput input;
  core::SphereBody& body = input.body;
  body.name = name;
  // 0: a junction of cables (the scene loader checks that two or more cable ends hold it)
  body.mass = keys.Get("mass").Number(Range::AtLeast(0.0));
  const auto optional_number = [&](const std::string& key, double fallback) {
    return keys.Has(key) ? keys.Get(key).Number(Range::AtLeast(0.0)) : fallback;
  };
  body.volume = optional_number("volume", body.volume);
  body.drag_coefficient = optional_number("drag_coefficient", body.drag_coefficient);
  body.added_mass_coefficient =
      optional_number("added_mass_coefficient", body.added_mass_coefficient);
  // position and velocity (world frame) belong to the scene, not to the model file
  body.position = keys.scene().Vector("position");
  input.velocity_given = keys.scene().Has("velocity");
  if (input.velocity_given) body.velocity = keys.scene().Vector("velocity");
  return input;
}

// `scale: lambda` on a vehicle of the scene: its model file's vehicle lambda times the size,
// every coefficient by Froude similarity (core/vehicle_scaling.h; docs/vehicles.md §9). The
// model is the file's alone: a model key given in the scene beside scale is refused (it would
// be ambiguous whether it is at the file's size or at the scaled one).
void ApplyScale(const MapReader& scene, bool has_model_file, core::VehicleParams* params) {
  if (!scene.Has("scale")) return;
  const Field scale = scene.Get("scale");
  const double lambda = scale.Number();  // a finite number
  if (!(lambda > 0.0)) {
    scale.Fail("must be > 0 (the ratio lambda of the body's size to its model file's)");
  }
  if (!has_model_file) {
    scale.Fail("needs a model file (model: FILE): scale sizes the vehicle of that file");
  }
  for (const auto& [key, value] : scene.entries()) {
    if (key != "type" && Allowed(MapKind::kVehicleFile, key)) {
      value.Fail(
          "cannot be given beside scale: a scaled vehicle takes every coefficient from its model "
          "file (write a model file at the size you want to change one)");
    }
  }
  *params = core::ScaleVehicle(*params, lambda);
  // lambda^5 must neither overflow nor underflow: the scaled body stays a body
  const bool finite = std::isfinite(params->length) && std::isfinite(params->inertia.sum()) &&
                      params->added_mass.allFinite() && std::isfinite(params->max_thrust);
  const bool positive = params->length > 0.0 && params->mass > 0.0 &&
                        params->inertia.minCoeff() > 0.0 && params->thrust_time_constant > 0.0;
  if (!finite || !positive) {
    scale.Fail(
        "is out of range: the scaled mass (lambda^3) and inertia (lambda^5) must be finite "
        "and > 0");
  }
}

VehicleInput ReadVehicle(const std::string& name, const BodyKeys& keys, bool has_model_file) {
  VehicleInput input;
  core::Vehicle& vehicle = input.vehicle;
  vehicle.name = name;
  vehicle.params = ReadVehicleParams(keys);
  ApplyScale(keys.scene(), has_model_file, &vehicle.params);

  // the initial state belongs to the scene: origin position, attitude, body-frame velocity
  const MapReader& scene = keys.scene();
  vehicle.position = scene.Vector("position");
  vehicle.euler = ReadEulerDeg(scene);
  input.velocity_given = scene.Has("velocity");
  if (input.velocity_given) vehicle.nu.head<3>() = scene.Vector("velocity");

  // the command held from t = 0: the fields given, each one the vehicle can carry out
  ReadCommand(MapReader(scene.Get("command"), MapKind::kCommand), vehicle, &vehicle.command);
  return input;
}

void ReadBody(const std::string& name, const Field& field, const std::string& base_dir,
              BodiesInput* out) {
  const MapReader scene_keys(field, MapKind::kBody);
  std::optional<Field> file_root;
  std::string model_dir;  // the model file's folder: files it names are relative to it
  if (scene_keys.Has("model")) {
    file_root.emplace(LoadModelFile(scene_keys.Get("model"), field.path(), base_dir));
    std::filesystem::path path(scene_keys.Get("model").String());
    if (path.is_relative()) path = std::filesystem::path(base_dir) / path;
    model_dir = path.lexically_normal().parent_path().string();
    if (model_dir.empty()) model_dir = ".";
  }
  // the type: the scene's, else the model file's
  const Field type =
      scene_keys.Has("type") || !file_root ? scene_keys.Get("type") : FileType(*file_root);
  if (!type.present()) {
    type.Fail(
        "is required (type: sphere, type: vehicle or type: vessel, here or in the model file)");
  }
  const size_t kind = type.Choice(kTypes);

  // the keys of that type, in the model file and in the scene
  std::optional<MapReader> file_keys;
  if (file_root) file_keys.emplace(*file_root, kFileKind[kind]);
  if (kind != 1 && scene_keys.Has("scale")) {
    scene_keys.Get("scale").Fail(
        kind == 0 ? "applies only to type: vehicle (a sphere is given by its own mass, volume and "
                    "coefficients: write them at the size you want)"
                  : "applies only to type: vehicle (a vessel's motion is given, not computed "
                    "from its size)");
  }
  CheckKeysOfType(scene_keys, kind);
  const bool has_model_file = file_keys.has_value();
  const BodyKeys keys(scene_keys, file_keys);
  if (kind == 2) {
    out->vessels.push_back(ReadVessel(name, keys, base_dir, model_dir));
  } else if (kind == 1) {
    out->vehicles.push_back(ReadVehicle(name, keys, has_model_file));
  } else {
    out->spheres.push_back(ReadSphere(name, keys));
  }
}

}  // namespace

Field LoadModelFile(const Field& model, const std::string& body_path, const std::string& base_dir) {
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
    root = LoadOneDocument(text, source->name, model.path(), model.text());
  } catch (const std::bad_alloc&) {
    model.Fail("out of memory while reading the model file " + path.string());
  }
  // a model file is a map of body parameters
  if (!root.IsMap()) {
    throw ConfigError(model.path(), model.text(), source->name,
                      "a model file must be a map of body parameters (type, mass, ...)");
  }
  return Field(root, root.Mark(), body_path, source);
}

Field FileType(const Field& root) {
  for (auto it = root.node().begin(); it != root.node().end(); ++it) {
    const YAML::Node key = it->first;
    if (key.IsScalar() && key.Scalar() == "type") {
      return Field(it->second, key.Mark(), JoinPath(root.path(), "type"), root.source());
    }
  }
  return Field::Missing(JoinPath(root.path(), "type"), root);
}

bool BodyKeys::Has(const std::string& key) const {
  return scene_.Has(key) || (file_ && file_->Has(key));
}

Field BodyKeys::Get(const std::string& key) const {
  // a key given in the scene overrides the model file's; one missing in both is reported at
  // the model file, where it belongs
  if (scene_.Has(key) || !file_) return scene_.Get(key);
  return file_->Get(key);
}

Field BodyKeys::Require(const std::string& key) const {
  Field value = Get(key);
  if (!value.present()) value.Fail("is required (in the model file or the scene)");
  return value;
}

BodyKeys::Map BodyKeys::GetMap(const std::string& key, MapKind kind) const {
  std::optional<MapReader> scene, file;
  if (scene_.Has(key)) scene.emplace(scene_.Get(key), kind);
  if (file_ && file_->Has(key)) file.emplace(file_->Get(key), kind);
  Field field = scene ? scene->field() : file ? file->field() : scene_.Get(key);
  return Map(std::move(scene), std::move(file), std::move(field));
}

bool BodyKeys::Map::Has(const std::string& key) const {
  return (scene_ && scene_->Has(key)) || (file_ && file_->Has(key));
}

Field BodyKeys::Map::Get(const std::string& key) const {
  if (scene_ && scene_->Has(key)) return scene_->Get(key);
  if (file_ && file_->Has(key)) return file_->Get(key);
  return Field::Missing(JoinPath(field_.path(), key), field_);
}

BodiesInput ReadBodies(const Field& bodies, const std::string& base_dir) {
  // a map name -> body; names are checked by the reader (and unique, being keys of one map)
  const MapReader map(bodies, MapKind::kBodies);
  BodiesInput inputs;
  for (const auto& [name, field] : map.entries()) ReadBody(name, field, base_dir, &inputs);
  return inputs;
}

core::Vec3 ReadEulerDeg(const MapReader& scene) {
  // [roll, pitch, yaw] in degrees, ZYX; pitch away from the +-90 deg singularity
  if (!scene.Has("euler_deg")) return core::Vec3::Zero();
  const Field euler = scene.Get("euler_deg");
  const core::Vec3 deg = euler.Vector();
  euler.Items()[1].Number(Range::Open(-90.0, 90.0));
  return kDegToRad * deg;
}

BodyRef FindBody(const core::Model& model, const std::string& name) {
  for (size_t i = 0; i < model.spheres.size(); ++i) {
    if (model.spheres[i].name == name) return {BodyRef::kSphere, static_cast<int>(i)};
  }
  for (size_t i = 0; i < model.vehicles.size(); ++i) {
    if (model.vehicles[i].name == name) return {BodyRef::kVehicle, static_cast<int>(i)};
  }
  for (size_t i = 0; i < model.vessels.size(); ++i) {
    if (model.vessels[i].name == name) return {BodyRef::kVessel, static_cast<int>(i)};
  }
  return {};
}

std::string BodyNames(const core::Model& model) {
  std::string names;
  for (const core::SphereBody& body : model.spheres)
    names += (names.empty() ? "" : ", ") + body.name;
  for (const core::Vehicle& v : model.vehicles) names += (names.empty() ? "" : ", ") + v.name;
  for (const core::Vessel& v : model.vessels) names += (names.empty() ? "" : ", ") + v.name;
  return names.empty() ? "none" : names;
}

}  // namespace towsim::scene::internal
