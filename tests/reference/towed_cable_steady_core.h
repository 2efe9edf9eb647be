#pragma once
// The steady towed-cable reference (towed_cable_steady.h) posed from a core model, and the
// quantities it predicts measured on a core simulation. Header-only, so that the reference
// library stays free of the core: its users (steady_tow_core_test, tests/stress,
// bench/work_precision) link the core themselves.
//
// The model: a driven tow point at cable.start and one sphere, bodies[0], at the lower end
// (config/scenes/steady_tow.yaml).

#include "core/model.h"
#include "core/simulation.h"
#include "towed_cable_steady.h"

namespace towsim::reference {

// the reference problem of the model, under the core's stretch law
inline TowedCableProblem SteadyTowProblem(const core::Model& m) {
  TowedCableProblem p;
  const core::CableParams& c = m.cables[0];
  p.length = c.length;
  p.diameter = c.diameter;
  // the line as the solid section of its diameter with the same m and EA
  p.density = c.mass_per_length / c.area();
  p.youngs_modulus = c.axial_stiffness / c.area();
  if (c.drag.kind == core::CableDragLaw::kConstant)
    p.drag_coefficients = ConstantDragCoefficients{c.drag.normal, c.drag.tangential};
  const core::SphereBody& b = m.spheres.at(0);
  p.sphere_mass = b.mass;
  p.sphere_volume = b.volume;
  p.sphere_cd = b.drag_coefficient;
  p.fluid.density = m.environment.water_density;
  p.fluid.dynamic_viscosity = m.environment.dynamic_viscosity;
  p.gravity = m.environment.gravity;
  p.current = m.environment.current.Velocity(0.0, 0.0);
  if (!m.environment.current.IsUniform()) {
    // U(z) of the (steady) profile; the driven tow point fixes the cable's depth
    p.current_profile = [current = m.environment.current](double z) {
      return current.Velocity(z, 0.0);
    };
    p.tow_depth = c.start.position.z();
  }
  p.tow_velocity = c.start.velocity;
  p.stretch_law = StretchLaw::kGreenTrueTension;  // the core's law
  return p;
}

// what the reference predicts, as the simulation has it now
struct SteadyTowSample {
  double t;        // sim time [s]
  double layback;  // x_top - x_sphere [m]
  double depth;    // z_sphere - z_top [m]
  double tension;  // |force on the tow point| [N]
};

inline SteadyTowSample MeasureSteadyTow(const core::Simulation& sim) {
  const core::CableEnd& top = sim.model().cables[0].start;
  const core::Vec3 p_top = top.position + top.velocity * sim.time();
  const core::Vec3 p_sphere = sim.body_position(0);
  return {sim.time(), p_top.x() - p_sphere.x(), p_sphere.z() - p_top.z(), sim.end_force(0).norm()};
}

}  // namespace towsim::reference
