#pragma once
// One stress run through the public core API: a scene (with --set style overrides) stepped for
// a given time, its script applied as sim_node applies it, an optional command policy on top,
// and everything that must stay sane watched at every step:
//
//   - every StepStatus converged (Newton, sub-stepping and coupling included);
//   - the state finite (q, v, a, lambda and every vehicle state);
//   - the mechanical energy E = kinetic + potential (gravity, buoyancy, waterplane) + strain
//     bounded by the work put in. With P_in the power of the propeller thrust (T u: thrust
//     along body x through the origin, current 0) and of the driven supports
//     (-lambda_end . v_support), every other force either dissipates (drag, numerical damping
//     of generalized-alpha) or is conservative and in E, so
//         E(t) - E(0) <= W_in(t) = int_0^t P_in dt      (energy balance)
//     up to the slack of terms that do neither (see kEnergySlack* in stress_test.cc).
//
// No I/O, no clocks: the caller asserts on the result.

#include <functional>
#include <string>
#include <vector>

#include "core/model.h"
#include "core/simulation.h"

namespace towsim::stress {

// path of a shipped scene by file name (config/scenes/<name>)
std::string ScenePath(const std::string& name);

// loads config/scenes/<name> with overrides (key.path=value, as --set)
core::Model LoadShippedScene(const std::string& name, const std::vector<std::string>& overrides);

// called before every step, after the scene's script (which runs as in sim_node): may change
// vehicle commands; `step` counts from 1
using CommandPolicy = std::function<void(core::Simulation* sim, long step)>;

struct StressResult {
  bool ok = true;                // every step converged and stayed finite
  std::string failure;           // first failing step's diagnosis (StepStatus::message)
  bool nonfinite_state = false;  // a step reported ok but left a non-finite state (silent NaN)
  long steps = 0;                // steps completed
  double t_end = 0.0;            // time reached [s]
  // Newton and coupling
  int max_iterations = 0;      // largest StepStatus::iterations of one step
  double mean_iterations = 0;  // per step
  long substepped_steps = 0;   // steps that needed sub-stepping (substeps > 1)
  int max_coupling_iterations = 0;
  // energy balance [J]
  double energy0 = 0.0;          // E(0)
  double energy_end = 0.0;       // E(t_end)
  double work_in = 0.0;          // W_in(t_end)
  double work_abs = 0.0;         // int |P_in| dt
  double max_energy_gain = 0.0;  // max_t E(t) - E(0)
  double max_excess = 0.0;       // max_t E(t) - E(0) - W_in(t) (> 0: more energy than put in)
  double max_excess_time = 0.0;  // where [s]
  // top of the cable: TopTension [N] (<= 0: slack)
  double min_top_tension = 0.0;
  double max_top_tension = 0.0;
};

// mechanical energy E = kinetic + potential + strain [J]
double MechanicalEnergy(const core::Simulation& sim);

// power put into the system by propellers and driven supports [W]
double InputPower(const core::Simulation& sim);

// force of the cable on its start support along the cable's direction there [N]: the
// tension, <= 0 when the cable is slack (or pushes)
double TopTension(const core::Simulation& sim);

// the whole state finite
bool StateFinite(const core::Simulation& sim);

// Steps `sim` for round(duration / h) steps of h = model().time.step (or `h` > 0: StepBy(h)),
// applying the scene's script (a fresh ScriptRunner: in a second call on the same sim its
// due entries fire again) and then `policy` before each step. Stops at the first failed
// step. `observe`, if given, is called after every completed step.
StressResult RunStress(core::Simulation* sim, double duration, const CommandPolicy& policy = {},
                       double h = 0.0,
                       const std::function<void(const core::Simulation&)>& observe = {});

}  // namespace towsim::stress
