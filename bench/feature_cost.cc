// Cost of each feature of a scene: a scene pays only for what it uses.
//   ./build/bench/feature_cost                    # benchmarks, then a Markdown table of ratios
//   ./build/bench/feature_cost --profile NAME N   # N steps of variant NAME, no timing, then N
//                                                 # residual + Newton-matrix evaluations and N
//                                                 # residual-only ones at the state reached
//                                                 # (callgrind: bench/feature_cost_callgrind.sh)
//
// Every variant is the steady-tow scene (20 elements, h = 0.05 s, starting vertical: the first
// 20 s of its transient, where drag and added mass work hardest) with one feature taken out,
// or a scene with other bodies. Each benchmark iteration builds the simulation (not timed) and
// runs the same 400 steps, so every iteration does the same work. Reported per step and per
// Newton iteration: the variants' dynamics differ (without drag the cable swings freely), so
// the iteration count differs; the cost per Newton iteration (one residual and Jacobian
// evaluation, one block-tridiagonal factorization and solve) is what the term itself costs.

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/script.h"
#include "core/simulation.h"
#include "core/state.h"
#include "core/step_sampler.h"
#include "core/system.h"
#include "scene/scene_loader.h"

namespace {

using towsim::core::Simulation;

struct Variant {
  std::string name;   // benchmark and --profile name
  std::string scene;  // config/scenes/<scene>
  std::vector<std::string> overrides;
  std::string what;  // for the table
  // an edit of the loaded model that --set cannot express (taking the waves out)
  std::function<void(towsim::core::Model*)> edit = nullptr;
};

void Calm(towsim::core::Model* m) { m->environment.waves = towsim::core::WaveField(); }
void CalmBottomless(towsim::core::Model* m) {
  Calm(m);
  m->environment.seabed = towsim::core::Seabed();
}
void WavesPerIteration(towsim::core::Model* m) { m->integrator.waves_per_iteration = true; }
// a winch at the steady tow's driven top (docs/winch.md): 150 m to 300 m, 1 m/s, 0.2 m/s^2
void Winch(towsim::core::Model* m) {
  // min_length, max_length [m], max_speed [m/s], max_acceleration [m/s^2]
  towsim::core::WinchParams w{150.0, 300.0, 1.0, 0.2};
  m->cables[0].winch = w;
}
// and paying out at 1 m/s from t = 0 (20 s: two element splits)
void WinchPayout(towsim::core::Model* m) {
  Winch(m);
  towsim::core::ScriptEntry e;
  e.set_winch = true;
  e.winch = {towsim::core::WinchCommand::Mode::kSpeed, 1.0};
  m->script.push_back(e);
}

const std::vector<Variant>& Variants() {
  static const std::vector<Variant> v = {
      {"all_loads", "steady_tow.yaml", {}, "steady tow, all five loads (baseline)"},
      {"winch_held", "steady_tow.yaml", {}, "with a winch, held", Winch},
      {"winch_payout", "steady_tow.yaml", {}, "with a winch paying out at 1 m/s", WinchPayout},
      {"no_gravity",
       "steady_tow.yaml",
       {"cable.loads=[buoyancy, drag, added_mass, bending]"},
       "without gravity"},
      {"no_buoyancy",
       "steady_tow.yaml",
       {"cable.loads=[gravity, drag, added_mass, bending]"},
       "without buoyancy"},
      {"no_drag",
       "steady_tow.yaml",
       {"cable.loads=[gravity, buoyancy, added_mass, bending]"},
       "without drag"},
      {"no_added_mass",
       "steady_tow.yaml",
       {"cable.loads=[gravity, buoyancy, drag, bending]"},
       "without added mass"},
      {"no_bending",
       "steady_tow.yaml",
       {"cable.loads=[gravity, buoyancy, drag, added_mass]"},
       "without bending"},
      {"no_loads", "steady_tow.yaml", {"cable.loads=[]"}, "no load term at all (elasticity only)"},
      {"no_body",
       "steady_tow.yaml",
       {"cable.end={free: true}", "bodies={}"},
       "no body: the lower end free (sphere removed)"},
      {"two_vehicles_staggered",
       "case1_forward.yaml",
       {"integrator.coupling=staggered"},
       "Case 1: two 6-DOF vehicles instead of driven point + sphere, staggered"},
      {"two_vehicles_strong", "case1_forward.yaml", {}, "Case 1, strong coupling (shipped)"},
      {"case1_waves",
       "case1_forward.yaml",
       {"environment.waves={jonswap: {hs: 2, tp: 8, gamma: 3.3, direction_deg: 180, components: "
        "100, seed: 1}, ramp: 20}"},
       "Case 1 in a JONSWAP sea (Hs 2 m, Tp 8 s, 100 components, 20 s ramp), deep water"},
      {"current_profile",
       "steady_tow.yaml",
       {"environment.current={profile: [[0, [0.8, 0, 0]], [60, [0.2, 0.4, 0]], [180, [-0.3, 0, "
        "0]]]}"},
       "steady tow in a depth profile of the current (docs/environment.md)"},
      {"case3_calm_bottomless",
       "case3_waves.yaml",
       {},
       "Case 3's system in calm, bottomless water (the baseline of the sea variants)",
       CalmBottomless},
      {"case3_calm",
       "case3_waves.yaml",
       {},
       "Case 3 without its waves (the 60 m seabed kept)",
       Calm},
      {"case3_waves",
       "case3_waves.yaml",
       {},
       "Case 3 (shipped): JONSWAP Hs 2 m, Tp 8 s, 100 components"},
      {"case3_waves_per_iteration",
       "case3_waves.yaml",
       {},
       "Case 3, the waves resampled at every Newton iteration",
       WavesPerIteration},
  };
  return v;
}

const Variant* FindVariant(const std::string& name) {
  for (const Variant& v : Variants())
    if (v.name == name) return &v;
  return nullptr;
}

towsim::core::Model Load(const Variant& v) {
  towsim::core::Model m = towsim::scene::LoadScene(
      std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/" + v.scene, v.overrides);
  if (v.edit) v.edit(&m);
  return m;
}

constexpr int kSteps = 400;  // 20 s at h = 0.05 s

struct Measured {
  double us_per_step = 0.0;
  double newton_per_step = 0.0;
  double us_per_newton = 0.0;
};
std::map<std::string, Measured>& Results() {
  static std::map<std::string, Measured> m;
  return m;
}

void BM_Feature(benchmark::State& bench, const Variant* v) {
  const towsim::core::Model model = Load(*v);
  long newton = 0, steps = 0;
  for (auto _ : bench) {
    bench.PauseTiming();
    Simulation sim(model);
    towsim::core::ScriptRunner script(model);
    bench.ResumeTiming();
    for (int k = 0; k < kSteps; ++k) {
      script.Apply(&sim);
      const towsim::core::StepStatus s = sim.Step();
      newton += s.iterations;
      ++steps;
      if (!s.ok()) bench.SkipWithError(s.message.c_str());
    }
  }
  bench.counters["us/step"] = benchmark::Counter(
      static_cast<double>(steps) * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bench.counters["newton/step"] = static_cast<double>(newton) / steps;
  bench.counters["us/newton"] =
      benchmark::Counter(static_cast<double>(newton) * 1e-6,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bench.SetLabel(v->what);
}

// collects the counters of every run for the ratio table
class TableReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred || r.run_type != Run::RT_Iteration) continue;
      const std::string name = r.run_name.function_name;
      const std::string variant = name.substr(name.find('/') + 1);
      Measured m;
      m.us_per_step = r.counters.at("us/step");
      m.newton_per_step = r.counters.at("newton/step");
      m.us_per_newton = r.counters.at("us/newton");
      Results()[variant] = m;
    }
  }
};

void PrintTable() {
  const auto& res = Results();
  const auto base = res.find("all_loads");
  if (base == res.end()) return;
  const Measured& b = base->second;
  std::printf(
      "\n| variant | us/step | ratio | Newton/step | us/Newton iteration | ratio |\n"
      "|---|---|---|---|---|---|\n");
  for (const Variant& v : Variants()) {
    const auto it = res.find(v.name);
    if (it == res.end()) continue;
    const Measured& m = it->second;
    std::printf("| %s | %.1f | %.3f | %.2f | %.1f | %.3f |\n", v.what.c_str(), m.us_per_step,
                m.us_per_step / b.us_per_step, m.newton_per_step, m.us_per_newton,
                m.us_per_newton / b.us_per_newton);
  }
}

// --profile NAME N: N steps, nothing else (the callgrind driver); the stepping is in its own
// function so callgrind can collect it alone (--toggle-collect=*ProfileSteps*)
__attribute__((noinline)) long ProfileSteps(Simulation* sim, towsim::core::ScriptRunner* script,
                                            int steps) {
  long newton = 0;
  for (int k = 0; k < steps; ++k) {
    script->Apply(sim);
    newton += sim->Step().iterations;
  }
  return newton;
}

// the inputs of an evaluation at the simulation's state: calm water (the waves are sampled
// once per step, not per evaluation), the supports and the drum as the state holds them
towsim::core::StepInputs CalmInputs(const Simulation& sim) {
  towsim::core::StepInputs in;
  towsim::core::StepSampler(sim.system()).TakeMotions(sim.state(), &in);
  return in;
}

// the options of an evaluation at the scene's step h (trapezoidal coefficients)
towsim::core::EvaluateOptions ProfileOptions(const Simulation& sim) {
  const double h = sim.model().time.step;
  return {1.0, {1.0, 0.5 / h, 1.0 / (0.25 * h * h)}};
}

// N evaluations of the residual and the Newton matrix (jac) or of the residual alone, at one
// fixed state: the per-evaluation cost of a variant without its dynamics mixed in
__attribute__((noinline)) void ProfileEvaluateJacobian(const Simulation& sim, int n) {
  const towsim::core::System& sys = sim.system();
  const towsim::core::State& s = sim.state();
  const towsim::core::StepInputs in = CalmInputs(sim);
  const towsim::core::EvaluateOptions options = ProfileOptions(sim);
  towsim::core::NetworkMatrix jac = sys.MakeMatrix();
  Eigen::VectorXd r, phi;
  for (int i = 0; i < n; ++i)
    sys.Evaluate({s.q, s.v, s.a, s.lambda, s.t}, in, options, {&r, &phi, &jac});
  benchmark::DoNotOptimize(r.data());
}

__attribute__((noinline)) void ProfileEvaluateResidual(const Simulation& sim, int n) {
  const towsim::core::System& sys = sim.system();
  const towsim::core::State& s = sim.state();
  const towsim::core::StepInputs in = CalmInputs(sim);
  const towsim::core::EvaluateOptions options = ProfileOptions(sim);
  Eigen::VectorXd r, phi;
  for (int i = 0; i < n; ++i) sys.Evaluate({s.q, s.v, s.a, s.lambda, s.t}, in, options, {&r, &phi});
  benchmark::DoNotOptimize(r.data());
}

int Profile(const std::string& name, int steps) {
  const Variant* v = FindVariant(name);
  if (v == nullptr) {
    std::fprintf(stderr, "feature_cost: --profile %s: unknown variant; one of:", name.c_str());
    for (const Variant& x : Variants()) std::fprintf(stderr, " %s", x.name.c_str());
    std::fprintf(stderr, "\n");
    return 2;
  }
  const towsim::core::Model model = Load(*v);
  Simulation sim(model);
  towsim::core::ScriptRunner script(model);
  const long newton = ProfileSteps(&sim, &script, steps);
  ProfileEvaluateJacobian(sim, steps);
  ProfileEvaluateResidual(sim, steps);
  std::printf("%s: %d steps, %ld Newton iterations\n", name.c_str(), steps, newton);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::strcmp(argv[1], "--profile") == 0) {
    if (argc != 4 || std::atoi(argv[3]) <= 0) {
      std::fprintf(stderr, "usage: feature_cost --profile VARIANT STEPS (STEPS > 0)\n");
      return 2;
    }
    return Profile(argv[2], std::atoi(argv[3]));
  }
  for (const Variant& v : Variants())
    benchmark::RegisterBenchmark(("BM_Feature/" + v.name).c_str(), BM_Feature, &v)
        ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  PrintTable();
  return 0;
}
