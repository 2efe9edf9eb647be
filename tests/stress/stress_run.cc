#include "stress_run.h"

#include <algorithm>
#include <cmath>

#include "core/script.h"
#include "core/state.h"
#include "scene/scene_loader.h"

namespace towsim::stress {

std::string ScenePath(const std::string& name) {
  return std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/" + name;
}

core::Model LoadShippedScene(const std::string& name, const std::vector<std::string>& overrides) {
  return scene::LoadScene(ScenePath(name), overrides);
}

double MechanicalEnergy(const core::Simulation& sim) {
  return sim.KineticEnergy() + sim.PotentialEnergy() + sim.StrainEnergy();
}

double InputPower(const core::Simulation& sim) {
  double p = 0.0;
  // propeller: thrust T along body x through O, power T u (u: surge over ground, no current)
  for (int v = 0; v < sim.num_vehicles(); ++v) {
    const core::VehicleState& vs = sim.vehicle_state(v);
    p += vs.actuator[core::kThrust] * vs.nu(0);
  }
  // driven support: it exerts -lambda on the cable and moves with v_support
  const core::CableParams& c = sim.model().cables[0];
  const core::CableEnd* ends[2] = {&c.start, &c.end};
  for (int e = 0; e < 2; ++e)
    if (ends[e]->kind == core::EndKind::kDriven) p -= sim.end_force(e).dot(ends[e]->velocity);
  return p;
}

double TopTension(const core::Simulation& sim) {
  // the cable pulls its support along its own direction r'_0 (tension > 0) or pushes it
  const Eigen::Vector3d slope = sim.state().q.segment<3>(sim.cable_dof(0) + 3);
  return sim.end_force(0).dot(slope.normalized());
}

bool StateFinite(const core::Simulation& sim) {
  const core::State& s = sim.state();
  bool finite = std::isfinite(s.t) && s.q.allFinite() && s.v.allFinite() && s.a.allFinite() &&
                s.lambda.allFinite();
  for (const core::VehicleState& vs : s.vehicles)
    finite = finite && vs.p_W.allFinite() && vs.q_WB.coeffs().allFinite() && vs.nu.allFinite() &&
             std::isfinite(vs.actuator[core::kThrust]);
  return finite;
}

StressResult RunStress(core::Simulation* sim, double duration, const CommandPolicy& policy,
                       double h, const std::function<void(const core::Simulation&)>& observe) {
  const core::Model& model = sim->model();
  const double step = h > 0.0 ? h : model.time.step;
  const long steps = std::lround(duration / step);
  core::ScriptRunner script(model);

  StressResult r;
  r.energy0 = MechanicalEnergy(*sim);
  r.min_top_tension = r.max_top_tension = TopTension(*sim);
  double p_prev = InputPower(*sim);
  long iterations = 0;
  for (long k = 1; k <= steps; ++k) {
    script.Apply(sim);
    if (policy) policy(sim, k);
    const core::StepStatus s = h > 0.0 ? sim->StepBy(h) : sim->Step();
    if (!s.ok()) {
      r.ok = false;
      r.failure = s.message;
      break;
    }
    if (!StateFinite(*sim)) {
      r.ok = false;
      r.nonfinite_state = true;
      r.failure =
          "step reported ok but the state is not finite at t = " + std::to_string(sim->time());
      break;
    }
    ++r.steps;
    iterations += s.iterations;
    r.max_iterations = std::max(r.max_iterations, s.iterations);
    if (s.substeps > 1) ++r.substepped_steps;
    r.max_coupling_iterations = std::max(r.max_coupling_iterations, sim->coupling_iterations());

    // W_in by the trapezoidal rule over the step (the power is linear in the state)
    const double p = InputPower(*sim);
    r.work_in += 0.5 * step * (p_prev + p);
    r.work_abs += 0.5 * step * (std::abs(p_prev) + std::abs(p));
    p_prev = p;
    const double gain = MechanicalEnergy(*sim) - r.energy0;
    r.max_energy_gain = std::max(r.max_energy_gain, gain);
    if (gain - r.work_in > r.max_excess) {
      r.max_excess = gain - r.work_in;
      r.max_excess_time = sim->time();
    }
    const double top = TopTension(*sim);
    r.min_top_tension = std::min(r.min_top_tension, top);
    r.max_top_tension = std::max(r.max_top_tension, top);
    if (observe) observe(*sim);
  }
  r.t_end = sim->time();
  r.energy_end = MechanicalEnergy(*sim);
  r.mean_iterations = r.steps > 0 ? static_cast<double>(iterations) / r.steps : 0.0;
  return r;
}

}  // namespace towsim::stress
