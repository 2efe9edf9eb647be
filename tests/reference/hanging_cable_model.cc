#include "hanging_cable_model.h"

namespace towsim::reference {

using core::Vec3;

core::Model HangingCable(int elements, bool bending) {
  core::Model m;
  m.name = "catenary";
  core::CableParams& c = m.cables[0];
  c.length = 200.0;
  c.elements = elements;
  c.diameter = 0.041;
  c.SetSolidSection(1300.0, 7.0e8);
  c.loads.gravity = true;
  c.loads.buoyancy = true;
  c.loads.drag = false;        // static: no velocity
  c.loads.added_mass = false;  // static: no acceleration
  c.loads.bending = bending;
  c.initial = core::InitialShape::kStatic;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.end.kind = core::EndKind::kFixed;
  c.end.position = Vec3(kHangingCableSpan, 0.0, 0.0);
  return m;
}

}  // namespace towsim::reference
