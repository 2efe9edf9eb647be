#pragma once
// Test helper: a steady tow built in code, without the scene loader (the main numbers of
// config/scenes/steady_tow.yaml, all else at the Model defaults), starting vertical: the top end
// driven at [0, 0, 3.5] with [6, 0, 0] m/s, 200 m of cable in 20 elements, a 416 kg sphere
// (0.2 m^3) at the lower end, step 0.05 s. Header-only, so that it serves the tests linked
// against towsim::core and no_allocation_test, linked against towsim_core_nomalloc.

#include "core/model.h"

namespace towsim::test {

inline core::Model SteadyTowModel() {
  core::Model m;
  m.time.step = 0.05;
  m.cables[0].length = 200;
  m.cables[0].elements = 20;
  m.cables[0].start.kind = core::EndKind::kDriven;
  m.cables[0].start.position = core::Vec3(0, 0, 3.5);
  m.cables[0].start.velocity = core::Vec3(6, 0, 0);
  m.cables[0].end.kind = core::EndKind::kSphere;
  m.cables[0].end.body = 0;
  m.cables[0].initial_velocity = core::Vec3(6, 0, 0);
  core::SphereBody b;
  b.name = "towfish";
  b.mass = 416;
  b.volume = 0.2;
  b.position = core::Vec3(0, 0, 203.5);
  b.velocity = core::Vec3(6, 0, 0);
  m.spheres.push_back(b);
  return m;
}

// the steady tow pulled by a towing vehicle (no hydrodynamic coefficients: none are needed to
// exercise the coupling) instead of the driven point
inline core::Model SteadyTowWithVehicle(core::Coupling coupling) {
  core::Model m = SteadyTowModel();
  m.integrator.coupling = coupling;
  m.cables[0].start.kind = core::EndKind::kVehicle;
  m.cables[0].start.body = 0;
  m.cables[0].start.at_B = core::Vec3(0, 0, 0.2);
  core::Vehicle v;
  v.name = "tow_vehicle";
  v.params.mass = 6950;
  v.params.inertia = core::Vec3(397, 3970, 3069);
  v.params.r_g = core::Vec3(0, 0, 0.2);
  v.params.volume = 6950 / 1025.0;
  v.params.added_mass.diagonal() << 217, 8280, 8280, 624, 43263, 43263;
  v.params.x_uu = -35;
  v.params.has_propeller = true;
  v.params.max_thrust = 20000;
  v.position = core::Vec3(0, 0, 3.3);
  v.nu(0) = 6.0;
  v.command.thrust = 4000;
  m.vehicles.push_back(v);
  return m;
}

// the steady tow with a fast winch at the driven top (10 m elements; 150 m to 260 m at up to
// 5 m/s and 5 m/s^2), so that a few dozen steps pay out or reel in across an element split or
// merge (docs/winch.md)
inline core::Model SteadyTowWithWinch(core::Model m = SteadyTowModel()) {
  // min_length, max_length [m], max_speed [m/s], max_acceleration [m/s^2]
  core::WinchParams w{150, 260, 5, 5};
  m.cables[0].winch = w;
  return m;
}

// the whole sea around a scene: an irregular sea, a sheared current and a seabed
inline core::Model InASea(core::Model m) {
  core::Environment& env = m.environment;
  env.current = core::CurrentField::Profile(
      {{0.0, core::Vec3(0.5, 0.2, 0.0)}, {100.0, core::Vec3(0.1, 0.0, 0.0)}});
  core::WaveSpectrum spectrum;
  spectrum.hs = 2.0;
  spectrum.tp = 8.0;
  spectrum.components = 100;
  env.waves = core::WaveField::Irregular(spectrum, 250.0, env.gravity, env.water_density);
  env.seabed = core::Seabed::Flat(250.0);
  core::SeabedContact contact;
  contact.friction = 0.5;
  env.seabed.set_contact(contact);
  return m;
}

}  // namespace towsim::test
