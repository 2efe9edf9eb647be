// Cost of one simulated second of the shipped cable scenes, offline, one core.
//   ./build/bench/cable_bench --benchmark_counters_tabular=true
// Reports wall time per simulated second and the real-time factor (RTF = sim s / wall s).

#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/simulation.h"
#include "scene/scene_loader.h"

namespace {

using towsim::core::Simulation;

void RunScene(benchmark::State& bench, const std::string& scene, double settle_s) {
  const int elements = static_cast<int>(bench.range(0));
  const std::vector<std::string> overrides = {"cable.elements=" + std::to_string(elements)};
  const towsim::core::Model model = towsim::scene::LoadScene(
      std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/" + scene, overrides);
  Simulation sim(model);
  // start from the settled state so that the measured seconds are representative
  while (sim.time() < settle_s) sim.Step();
  const int steps_per_second = static_cast<int>(1.0 / model.time.step + 0.5);
  long newton = 0, steps = 0;
  for (auto _ : bench) {
    for (int k = 0; k < steps_per_second; ++k) {
      const towsim::core::StepStatus s = sim.Step();
      newton += s.iterations;
      ++steps;
      if (!s.ok()) bench.SkipWithError(s.message.c_str());
    }
  }
  bench.counters["RTF"] =
      benchmark::Counter(static_cast<double>(bench.iterations()), benchmark::Counter::kIsRate);
  bench.counters["newton/step"] = static_cast<double>(newton) / steps;
  bench.SetLabel(scene + ", h = " + std::to_string(model.time.step) + " s");
}

// the steady-tow scene during its transient (first 60 s) and at steady state
void BM_SteadyTowTransient(benchmark::State& s) { RunScene(s, "steady_tow.yaml", 0.0); }
void BM_SteadyTowSettled(benchmark::State& s) { RunScene(s, "steady_tow.yaml", 200.0); }
void BM_Catenary(benchmark::State& s) { RunScene(s, "catenary.yaml", 0.0); }

BENCHMARK(BM_SteadyTowTransient)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SteadyTowSettled)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Catenary)->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
