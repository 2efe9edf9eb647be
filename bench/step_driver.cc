// A fixed amount of work for profiling: loads a scene, runs it for a given simulated time and
// prints the step statistics. Repeatable under callgrind (the instruction count depends on the
// scene and the settings only), unlike the Google Benchmark programs whose iteration count
// adapts to the clock.
//
//   step_driver SCENE SECONDS [--skip S] [key.path=value ...]
//   valgrind --tool=callgrind --callgrind-out-file=cg.out
//       --toggle-collect='towsim::core::Simulation::Step*'
//       build/bench/step_driver config/scenes/case1_forward.yaml 10
//
// --skip S runs the first S seconds before the measured part (e.g. past a start-up transient);
// the printed wall time covers the measured part only. It also prints each body's mean depth
// (z, NED) over the measured part, sampled every step (docs/environment.md: the vehicles' mean
// depth in waves).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/script.h"
#include "core/simulation.h"
#include "scene/scene_loader.h"

namespace {

int Usage() {
  std::fprintf(stderr, "usage: step_driver SCENE SECONDS [--skip S] [key.path=value ...]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return Usage();
  const std::string scene = argv[1];
  char* end = nullptr;
  const double seconds = std::strtod(argv[2], &end);
  if (*end != '\0' || !(seconds > 0.0)) {
    std::fprintf(stderr, "step_driver: error: SECONDS = %s: must be a number > 0\n", argv[2]);
    return 2;
  }
  double skip = 0.0;
  std::vector<std::string> overrides;
  for (int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--skip" && i + 1 < argc) {
      skip = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(skip >= 0.0)) {
        std::fprintf(stderr, "step_driver: error: --skip = %s: must be a number >= 0\n", argv[i]);
        return 2;
      }
    } else {
      overrides.push_back(a);
    }
  }
  try {
    const towsim::core::Model model = towsim::scene::LoadScene(scene, overrides);
    towsim::core::Simulation sim(model);
    towsim::core::ScriptRunner script(model);
    const double h = model.time.step;
    const long skip_steps = std::lround(skip / h), steps = std::lround(seconds / h);
    long newton = 0, coupling = 0;
    std::vector<double> z_sum(sim.num_bodies(), 0.0);
    auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < skip_steps + steps; ++k) {
      if (k == skip_steps) {
        newton = coupling = 0;
        t0 = std::chrono::steady_clock::now();
      }
      script.Apply(&sim);
      const towsim::core::StepStatus s = sim.Step();
      if (!s.ok()) {
        std::fprintf(stderr, "step_driver: %s\n", s.message.c_str());
        return 3;
      }
      newton += s.iterations;
      coupling += sim.coupling_iterations();
      if (k >= skip_steps)
        for (int b = 0; b < sim.num_bodies(); ++b) z_sum[b] += sim.body_position(b).z();
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf(
        "%s: %ld steps (h = %g s), %.3f s wall, RTF %.0f, Newton/step %.3f, coupling/step %.3f\n",
        model.name.c_str(), steps, h, wall, seconds / wall, static_cast<double>(newton) / steps,
        static_cast<double>(coupling) / steps);
    for (int b = 0; b < sim.num_bodies(); ++b)
      std::printf("%s: mean depth %.4f m\n", sim.body_name(b).c_str(), z_sum[b] / steps);
    // the last body's position (the towfish in the shipped scenes): a check that two builds
    // or settings reach the same state
    const int last = sim.num_bodies() - 1;
    if (last >= 0) {
      const towsim::core::Vec3 p = sim.body_position(last);
      std::printf("%s at t = %.3f s: [%.6f, %.6f, %.6f] m\n", sim.body_name(last).c_str(),
                  sim.time(), p.x(), p.y(), p.z());
    }
  } catch (const towsim::core::SolverError& e) {
    std::fprintf(stderr, "step_driver: solver failure: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "step_driver: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
