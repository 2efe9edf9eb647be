#include "taut_string_model.h"

#include <cmath>

#include "core/constants.h"
#include "core/state.h"

namespace towsim::reference {

using core::kPi;
using core::Vec3;

core::Model String(int factor) {
  core::Model m;
  m.name = "taut_string";
  core::CableParams& c = m.cables[0];
  c.length = kStringLength;
  c.elements = 10 * factor;
  c.diameter = 0.01;
  c.SetSolidSection(kStringRhoA / c.area(), kStringEA / c.area());
  c.loads = {false, false, false, false, false};
  c.initial = core::InitialShape::kStraight;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.end.kind = core::EndKind::kFixed;
  c.end.position = Vec3(kStringSpan, 0.0, 0.0);
  m.integrator.scheme = core::Scheme::kTrapezoidal;
  m.integrator.rho_inf = 1.0;
  m.time.step = 1e-3;
  return m;
}

TautString StringReference() {
  TautString s;
  s.length = kStringLength;
  s.span = kStringSpan;
  s.ea = kStringEA;
  s.rho_a = kStringRhoA;
  return s;
}

void StartHalfSine(core::Simulation* sim, double f_ref) {
  const double omega = 2.0 * kPi * f_ref;
  const double v0 = 1e-3 * omega;
  const int nodes = sim->num_nodes();
  core::State s = sim->state();
  for (int i = 0; i < nodes; ++i) {
    const double x = kStringLength * i / (nodes - 1);
    const int k = sim->cable_dof(i);
    s.v.segment<3>(k) = v0 * std::sin(kPi * x / kStringLength) * Vec3::UnitZ();
    s.v.segment<3>(k + 3) =
        v0 * (kPi / kStringLength) * std::cos(kPi * x / kStringLength) * Vec3::UnitZ();
  }
  sim->StartFrom(s);
}

}  // namespace towsim::reference
