#include "cantilever_model.h"

namespace towsim::reference {

using core::Vec3;

core::Model Cantilever(int elements, double alpha) {
  core::Model m;
  m.name = "cantilever";
  core::CableParams& c = m.cables[0];
  c.length = kCantileverLength;
  c.elements = elements;
  c.diameter = 0.02;
  c.SetSolidSection(7850.0, 2.0e11);  // steel
  c.loads.gravity = false;
  c.loads.buoyancy = false;
  c.loads.drag = false;
  c.loads.added_mass = false;
  c.loads.bending = true;
  c.initial = core::InitialShape::kStatic;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.start.clamped = true;
  c.start.slope = Vec3::UnitX();
  c.end.kind = core::EndKind::kSphere;
  c.end.body = 0;
  c.end.at_B = Vec3::Zero();
  core::SphereBody tip;
  tip.name = "tip_mass";
  const double ei = c.bending_stiffness;
  // P = m g
  tip.mass = alpha * ei / (kCantileverLength * kCantileverLength) / m.environment.gravity;
  tip.volume = 0.0;
  tip.position = Vec3(kCantileverLength, 0.0, 0.0);
  m.spheres.push_back(tip);
  return m;
}

}  // namespace towsim::reference
