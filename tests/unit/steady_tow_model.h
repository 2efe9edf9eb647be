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
  m.cable.length = 200;
  m.cable.elements = 20;
  m.cable.start.kind = core::EndKind::kDriven;
  m.cable.start.position = core::Vec3(0, 0, 3.5);
  m.cable.start.velocity = core::Vec3(6, 0, 0);
  m.cable.end.kind = core::EndKind::kBody;
  m.cable.end.body = 0;
  m.cable.initial_velocity = core::Vec3(6, 0, 0);
  core::SphereBody b;
  b.name = "towfish";
  b.mass = 416;
  b.volume = 0.2;
  b.position = core::Vec3(0, 0, 203.5);
  b.velocity = core::Vec3(6, 0, 0);
  m.bodies.push_back(b);
  return m;
}

}  // namespace towsim::test
