#include "network_models.h"

#include "core/state.h"
#include "scene/scene_loader.h"

namespace towsim::reference {
namespace {

const char kLine[] =
    "diameter: 0.041, density: 1300, youngs_modulus: 7.0e8, "
    "loads: [gravity, buoyancy, drag, added_mass]";

}  // namespace

core::Model NetworkModel(const std::string& yaml) {
  return scene::LoadSceneFromString(yaml, "network.yaml", ".");
}

std::string SplitCatenaryYaml(bool split, int factor) {
  const std::string head =
      "name: catenary\n"
      "time: {step: 0.05, duration: 1, output_rate: 10}\n"
      "environment: {current: [0, 0, 0]}\n";
  if (!split) {
    return head + "cable: {length: 120, elements: " + std::to_string(20 * factor) + ", " + kLine +
           ", initial: static, start: {fixed: [0, 0, 0]}, end: {fixed: [100, 0, 20]}}\n";
  }
  const std::string els = std::to_string(10 * factor);
  return head +
         "bodies: {junction: {type: sphere, mass: 0, volume: 0, position: [50, 0, 40]}}\n"
         "cables:\n"
         "  upper: {length: 60, elements: " +
         els + ", " + kLine +
         ", initial: static, start: {fixed: [0, 0, 0]}, end: {body: junction}}\n"
         "  lower: {length: 60, elements: " +
         els + ", " + kLine +
         ", initial: static, start: {body: junction}, end: {fixed: [100, 0, 20]}}\n";
}

std::string TwoPartTowYaml(double speed, int factor) {
  const std::string v = std::to_string(speed);
  const std::string els = std::to_string(20 * factor);
  return "name: two_part_tow\n"
         "time: {step: 0.05, duration: 1, output_rate: 10}\n"
         "environment: {current: [0, 0, 0]}\n"
         "bodies:\n"
         "  depressor: {type: sphere, mass: 1500, volume: 0.25, drag_coefficient: 0.8,\n"
         "              added_mass_coefficient: 0.5, position: [0, 0, 300]}\n"
         "  towfish: {type: sphere, mass: 400, volume: 0.3, drag_coefficient: 0.5,\n"
         "            added_mass_coefficient: 0.5, position: [0, 0, 360]}\n"
         "cables:\n"
         "  main: {length: 300, elements: " +
         els +
         ", diameter: 0.035, mass_per_length: 4.5,\n"
         "         axial_stiffness: 1.0e8, bending_stiffness: 300,\n"
         "         loads: [gravity, buoyancy, drag, added_mass, bending], initial: static,\n"
         "         initial_velocity: [" +
         v +
         ", 0, 0],\n"
         "         start: {driven: {position: [0, 0, 0], velocity: [" +
         v +
         ", 0, 0]}},\n"
         "         end: {body: depressor}}\n"
         "  tether: {length: 60, elements: " +
         els +
         ", diameter: 0.03, mass_per_length: 0.8,\n"
         "           axial_stiffness: 2.0e6, bending_stiffness: 5,\n"
         "           loads: [gravity, buoyancy, drag, added_mass, bending], initial: static,\n"
         "           initial_velocity: [" +
         v +
         ", 0, 0],\n"
         "           start: {body: depressor}, end: {body: towfish}}\n";
}

std::string BridleYaml(int factor) {
  const std::string els = std::to_string(10 * factor);
  return "name: bridle\n"
         "time: {step: 0.05, duration: 1, output_rate: 10}\n"
         "environment: {current: [0, 0, 0]}\n"
         "bodies: {ring: {type: sphere, mass: 2000, volume: 0.2, position: [0, 0, 15]}}\n"
         "cables:\n"
         "  port: {length: 25, elements: " +
         els +
         ", diameter: 0.03, mass_per_length: 0.72452,\n"
         "         axial_stiffness: 2.0e6, bending_stiffness: 0, loads: [gravity, buoyancy],\n"
         "         initial: static, start: {fixed: [0, -20, 0]}, end: {body: ring}}\n"
         "  starboard: {length: 25, elements: " +
         els +
         ", diameter: 0.03, mass_per_length: 0.72452,\n"
         "              axial_stiffness: 2.0e6, bending_stiffness: 0, loads: [gravity, buoyancy],\n"
         "              initial: static, start: {fixed: [0, 20, 0]}, end: {body: ring}}\n";
}

core::Model KickedNetwork(int factor) {
  core::Model m = NetworkModel(SplitCatenaryYaml(true, factor));
  for (core::CableParams& c : m.cables) {
    c.loads.drag = false;
    c.loads.added_mass = false;
  }
  m.spheres[0].mass = 50.0;  // a clump weight at the junction
  m.integrator.scheme = core::Scheme::kTrapezoidal;
  m.integrator.rho_inf = 1.0;
  m.integrator.tolerance = 1e-10;
  return m;
}

void KickTheClump(core::Simulation* sim) {
  core::State s = sim->state();
  // a sideways kick of the clump and the cables near it
  s.v.segment<3>(sim->sphere_dof(0)) = core::Vec3(0.0, 2.0, 0.0);
  sim->StartFrom(s);
}

}  // namespace towsim::reference
