#include "swinging_cable_model.h"

#include "core/state.h"

namespace towsim::reference {

using core::Vec3;

core::Model SwingingCable(core::Scheme scheme, double rho_inf, double step, int factor) {
  core::Model m;
  m.name = "swinging_cable";
  core::CableParams& c = m.cables[0];
  c.length = kSwingLength;
  c.elements = 10 * factor;
  c.diameter = 0.01;
  c.SetSolidSection(2000.0, 1.0e8);
  c.loads.gravity = true;
  c.loads.buoyancy = false;  // vacuum
  c.loads.drag = false;
  c.loads.added_mass = false;
  c.loads.bending = true;
  c.initial = core::InitialShape::kStraight;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.start.clamped = false;
  c.end.kind = core::EndKind::kFree;
  c.end.position = Vec3(kSwingLength, 0.0, 0.0);
  m.integrator.scheme = scheme;
  m.integrator.rho_inf = rho_inf;
  // these tests measure the scheme (energy to 1e-3 and 1e-9 of dPE over 2e4-2e5 steps, the
  // order of convergence), so the Newton error must be far below what they measure: the
  // increment bound ten times below the default (docs/physics.md, "Newton convergence"; the
  // default is chosen against the shipped scenes' discretisation errors, not these)
  m.integrator.tolerance = 1e-8;
  m.time.step = step;
  return m;
}

void ReleaseStraight(core::Simulation* sim) {
  core::State s = sim->state();
  const int nodes = sim->num_nodes();
  for (int i = 0; i < nodes; ++i) {
    const int k = sim->cable_dof(i);
    s.q.segment<3>(k) = Vec3(kSwingLength * i / (nodes - 1), 0.0, 0.0);
    s.q.segment<3>(k + 3) = Vec3::UnitX();
  }
  s.v.setZero();
  s.t = 0.0;
  sim->StartFrom(s);
}

}  // namespace towsim::reference
