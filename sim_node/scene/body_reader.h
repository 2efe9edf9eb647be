#pragma once
// bodies: name -> a sphere {type: sphere, mass, volume, drag_coefficient,
// added_mass_coefficient, position, velocity}, a 6-DOF vehicle {type: vehicle, <VehicleParams
// keys>, position, euler_deg, velocity, command} or a vessel {type: vessel, ...} (vessel_reader.h);
// with `model: <file>` the body's keys come from
// that file, and keys given in the scene override the file's (maps such as damping key by key).
// A vehicle with `scale: lambda` is its model file's vehicle lambda times the size
// (core/vehicle_scaling.h), its model keys all from the file.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// The keys of one body: its scene entry over its model file. Map-valued keys (added_mass,
// damping, rudder, elevator, propeller) merge key by key; any other key is taken whole.
class BodyKeys {
 public:
  BodyKeys(MapReader scene, std::optional<MapReader> file)
      : scene_(std::move(scene)), file_(std::move(file)) {}

  // the scene entry (initial state, messages about the body as a whole)
  const MapReader& scene() const { return scene_; }
  bool Has(const std::string& key) const;
  // the scene's value, else the file's, else Field::Missing located at the scene entry
  Field Get(const std::string& key) const;
  Field Require(const std::string& key) const;  // throws "is required" when absent

  // a map-valued key of kind `kind`, its keys checked in both places
  class Map {
   public:
    bool present() const { return scene_ || file_; }
    bool Has(const std::string& key) const;
    // the scene's value, else the file's, else Field::Missing located at the body
    Field Get(const std::string& key) const;
    // the map as a whole, for messages: the scene's if given, else the file's
    const Field& field() const { return field_; }
    double Number(const std::string& key, const Range& range, double fallback) const {
      return Has(key) ? Get(key).Number(range) : fallback;
    }

   private:
    friend class BodyKeys;
    Map(std::optional<MapReader> scene, std::optional<MapReader> file, Field field)
        : scene_(std::move(scene)), file_(std::move(file)), field_(std::move(field)) {}
    std::optional<MapReader> scene_, file_;
    Field field_;  // the map's path, and where a missing key is reported
  };
  Map GetMap(const std::string& key, MapKind kind) const;

 private:
  MapReader scene_;
  std::optional<MapReader> file_;
};

// The model file named by `model` (a path relative to `base_dir`): its root map, as a Field
// whose keys carry `body_path` (bodies.<name>.mass) and whose locations name the file. Its keys
// are checked later, against the type of the body. An unreadable file, one that is not YAML or
// not a map is reported at `model`.
Field LoadModelFile(const Field& model, const std::string& body_path, const std::string& base_dir);

// the `type` of a model file's root map, or Field::Missing located at the root
Field FileType(const Field& root);

struct SphereInput {
  core::SphereBody body;
  bool velocity_given = false;  // false: the body starts with the cable's initial velocity
};

struct VehicleInput {
  core::Vehicle vehicle;
  bool velocity_given = false;  // false: the cable's initial velocity, in the body frame
};

struct BodiesInput {
  std::vector<SphereInput> spheres;    // -> Model::spheres, in document order
  std::vector<VehicleInput> vehicles;  // -> Model::vehicles, in document order
  std::vector<core::Vessel> vessels;   // -> Model::vessels, in document order
};

// Reads the bodies map (absent: no bodies). Model paths are relative to `base_dir`; errors
// inside a model file name that file and line.
BodiesInput ReadBodies(const Field& bodies, const std::string& base_dir);

// a body's `euler_deg` in the scene entry ([roll, pitch, yaw] in degrees, ZYX, pitch within
// (-90, 90)) in radians; zero when absent
core::Vec3 ReadEulerDeg(const MapReader& scene);

// A body of the scene by name: a sphere (index into Model::spheres), a vehicle (index into
// Model::vehicles) or a vessel (index into Model::vessels).
struct BodyRef {
  enum Kind { kNone, kSphere, kVehicle, kVessel };
  Kind kind = kNone;
  int index = -1;
};
BodyRef FindBody(const core::Model& model, const std::string& name);

// "towfish, tow_vehicle" for messages: spheres, vehicles, then vessels ("none" when empty)
std::string BodyNames(const core::Model& model);

}  // namespace towsim::scene::internal
