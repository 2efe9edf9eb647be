#include "vehicle_file.h"

#include <stdexcept>

#include "scene/scene_loader.h"

namespace towsim::test {

core::VehicleParams ReadVehicleFile(const std::string& path) {
  // the scene loader reads the file exactly as a scene would: a one-body scene that names it
  const std::string scene =
      "name: vehicle_file\n"
      "time: {step: 0.01, duration: 1, output_rate: 10}\n"
      "cable: {length: 10, elements: 1, diameter: 0.01, density: 1300, youngs_modulus: 1e9,\n"
      "        initial: vertical, start: {body: v}, end: {free: true}}\n"
      "bodies:\n"
      "  v: {model: '" + path + "', position: [0, 0, 0]}\n";
  const core::Model model = scene::LoadSceneFromString(scene, "vehicle_file", "/", {});
  if (model.vehicles.size() != 1) throw std::runtime_error(path + ": not a vehicle file");
  return model.vehicles[0].params;
}

core::VehicleParams ReadProjectVehicle(const std::string& name) {
  return ReadVehicleFile(std::string(TOWSIM_SOURCE_DIR) + "/config/vehicles/" + name + ".yaml");
}

}  // namespace towsim::test
