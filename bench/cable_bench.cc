// Cost of one simulated second of the shipped cable scenes, offline, one core.
//   ./build/bench/cable_bench --benchmark_counters_tabular=true
// Reports wall time per simulated second and the real-time factor (RTF = sim s / wall s).

#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/script.h"
#include "core/simulation.h"
#include "scene/scene_loader.h"

namespace {

using towsim::core::Simulation;

void RunScene(benchmark::State& bench, const std::string& scene, double settle_s,
              std::vector<std::string> overrides = {}) {
  const int elements = static_cast<int>(bench.range(0));
  overrides.push_back("cable.elements=" + std::to_string(elements));
  const towsim::core::Model model = towsim::scene::LoadScene(
      std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/" + scene, overrides);
  Simulation sim(model);
  towsim::core::ScriptRunner script(model);
  // start from the settled state so that the measured seconds are representative
  while (sim.time() < settle_s) {
    script.Apply(&sim);
    sim.Step();
  }
  const int steps_per_second = static_cast<int>(1.0 / model.time.step + 0.5);
  long newton = 0, steps = 0;
  for (auto _ : bench) {
    for (int k = 0; k < steps_per_second; ++k) {
      script.Apply(&sim);
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

// the paper's Case 1 (two 6-DOF vehicles) with either coupling scheme, first 60 s
void BM_Case1Strong(benchmark::State& s) { RunScene(s, "case1_forward.yaml", 0.0); }
void BM_Case1Staggered(benchmark::State& s) {
  RunScene(s, "case1_forward.yaml", 0.0, {"integrator.coupling=staggered"});
}

BENCHMARK(BM_Case1Strong)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Case1Staggered)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SteadyTowTransient)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SteadyTowSettled)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Catenary)->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
