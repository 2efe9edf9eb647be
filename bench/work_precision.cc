// Accuracy against run time: sweeps the time step, the number of elements, the
// integrator (generalized-alpha with several rho_inf, trapezoidal) and, with vehicles, the
// coupling scheme (staggered, strong) on the steady-tow, Case 1, Case 3 (waves) and winch-payout
// scenes, and writes one CSV row per run.
//
//   work_precision [--out FILE.csv] [--scenes steady_tow,case1_forward,case3_waves,winch_payout]
//                  [--quick]
//   work_precision --targets      the shipped scenes at their own settings: RTF, and the
//                                 towfish-track error against a run 4x finer in time and space
//
// Errors (all relative):
//   pos_err_ref      max over time of |p_fish(t) - p_fish_ref(t)| / L, sampled every 0.2 s,
//                    against the scene's finest run (kRefStep, kRefElements, strong, rho 0.8),
//                    itself shown converged by the same error of the two runs next to it
//                    (2 x its step, 1/2 x its elements)
//   tension_err_ref  RMS over time of T_top - T_top_ref, divided by the RMS of T_top_ref (the
//                    force on the tow point or the towing vehicle)
//   pos_err_steady, tension_err_steady (steady tow only)
//                    the final state against the independent steady towed-cable solution
//                    (tests/reference/towed_cable_steady.h): |(p_top - p_fish) - r_ref| / L and
//                    |T_top - T_ref| / T_ref
// Cost: wall time per simulated second on one core, the minimum over repeats (and the thread
// CPU time, likewise, which a loaded machine disturbs less).

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/script.h"
#include "core/simulation.h"
#include "scene/scene_loader.h"
#include "towed_cable_steady_core.h"

namespace {

using towsim::core::Vec3;

constexpr double kSampleInterval = 0.2;  // [s]; every swept step divides it
constexpr double kRefStep = 0.0125;      // [s]
constexpr int kRefElements = 40;
constexpr double kMinRepeatTime = 3.0;  // [s] of wall time: repeat up to 3 runs within it
constexpr int kMaxRepeats = 3;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Method {
  std::string scheme;  // generalized_alpha | trapezoidal
  double rho_inf;      // generalized-alpha only
  std::string name() const {
    if (scheme == "trapezoidal") return "trapezoidal";
    char b[32];
    std::snprintf(b, sizeof b, "ga%.1f", rho_inf);
    return b;
  }
};

struct Spec {
  std::string scene;  // file stem in config/scenes
  int elements;
  double step;
  Method method;
  std::string coupling;  // strong | staggered | "" (scene without vehicles)
  double duration;
};

struct Run {
  Spec spec;
  bool ok = false;
  std::string message;
  std::vector<Vec3> fish;               // towfish position every kSampleInterval
  std::vector<double> tension;          // top tension every kSampleInterval
  Vec3 final_offset;                    // p_top - p_fish at the end
  double final_tension = 0.0;           // [N]
  double wall = 0.0, cpu = 0.0;         // [s] of the stepping loop, min over repeats
  double newton = 0.0, coupling = 0.0;  // per step
  towsim::core::Model model;
};

std::string ScenePath(const std::string& stem) {
  return std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/" + stem + ".yaml";
}

double ThreadCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

std::vector<std::string> Overrides(const Spec& s) {
  std::vector<std::string> o = {"cable.elements=" + std::to_string(s.elements),
                                "integrator.scheme=" + s.method.scheme};
  char b[64];
  std::snprintf(b, sizeof b, "time.step=%.17g", s.step);
  o.push_back(b);
  if (s.method.scheme == "generalized_alpha") {
    std::snprintf(b, sizeof b, "integrator.rho_inf=%.17g", s.method.rho_inf);
    o.push_back(b);
  }
  if (!s.coupling.empty()) o.push_back("integrator.coupling=" + s.coupling);
  return o;
}

int FindBody(const towsim::core::Simulation& sim, const std::string& name) {
  for (int b = 0; b < sim.num_bodies(); ++b)
    if (sim.body_name(b) == name) return b;
  return -1;
}

// one run: samples, final state, cost
bool RunOnce(const towsim::core::Model& model, double duration, Run* out, double* wall,
             double* cpu) {
  towsim::core::Simulation sim(model);
  towsim::core::ScriptRunner script(model);
  const int fish = FindBody(sim, "towfish");
  if (fish < 0) {
    out->message = "scene has no body named towfish";
    return false;
  }
  const double h = model.time.step;
  const long steps = std::lround(duration / h);
  const long every = std::max(1L, std::lround(kSampleInterval / h));
  const bool driven = model.cables[0].start.kind == towsim::core::EndKind::kDriven;
  auto top = [&] {
    return driven ? Vec3(model.cables[0].start.position + sim.time() * model.cables[0].start.velocity)
                  : sim.node_position(0);
  };
  out->fish.clear();
  out->tension.clear();
  long newton = 0, coupling = 0;
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = ThreadCpuSeconds();
  for (long k = 0; k <= steps; ++k) {
    if (k % every == 0) {
      out->fish.push_back(sim.body_position(fish));
      out->tension.push_back(sim.end_force(0).norm());
    }
    if (k == steps) break;
    script.Apply(&sim);
    const towsim::core::StepStatus s = sim.Step();
    if (!s.ok()) {
      out->message = s.message;
      return false;
    }
    newton += s.iterations;
    coupling += sim.coupling_iterations();
  }
  *cpu = ThreadCpuSeconds() - c0;
  *wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  out->final_offset = top() - sim.body_position(fish);
  out->final_tension = sim.end_force(0).norm();
  out->newton = static_cast<double>(newton) / steps;
  out->coupling = static_cast<double>(coupling) / steps;
  return true;
}

Run Execute(const Spec& spec, int max_repeats = kMaxRepeats) {
  Run r;
  r.spec = spec;
  try {
    r.model = towsim::scene::LoadScene(ScenePath(spec.scene), Overrides(spec));
    r.wall = r.cpu = std::numeric_limits<double>::infinity();
    double spent = 0.0;
    for (int k = 0; k < max_repeats && (k == 0 || spent < kMinRepeatTime); ++k) {
      double wall = 0.0, cpu = 0.0;
      r.ok = RunOnce(r.model, spec.duration, &r, &wall, &cpu);
      if (!r.ok) break;
      r.wall = std::min(r.wall, wall);
      r.cpu = std::min(r.cpu, cpu);
      spent += wall;
    }
  } catch (const std::exception& e) {
    r.ok = false;
    r.message = e.what();
  }
  return r;
}

// max over time of |p - p_ref| / L
double PositionError(const Run& r, const Run& ref) {
  const size_t n = std::min(r.fish.size(), ref.fish.size());
  double e = 0.0;
  for (size_t i = 0; i < n; ++i) e = std::max(e, (r.fish[i] - ref.fish[i]).norm());
  return e / ref.model.cables[0].length;
}

// RMS(T - T_ref) / RMS(T_ref)
double TensionError(const Run& r, const Run& ref) {
  const size_t n = std::min(r.tension.size(), ref.tension.size());
  double num = 0.0, den = 0.0;
  for (size_t i = 0; i < n; ++i) {
    num += (r.tension[i] - ref.tension[i]) * (r.tension[i] - ref.tension[i]);
    den += ref.tension[i] * ref.tension[i];
  }
  return std::sqrt(num / den);
}

std::string Num(double x) {
  if (!std::isfinite(x)) return "nan";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

struct SceneSweep {
  std::string scene;
  double duration;
  bool vehicles;
};

int Sweep(const std::string& out_path, const std::vector<SceneSweep>& scenes, bool quick) {
  const std::vector<double> steps =
      quick ? std::vector<double>{0.1, 0.05} : std::vector<double>{0.2, 0.1, 0.05, 0.025, 0.0125};
  const std::vector<int> elements = quick ? std::vector<int>{10, 20} : std::vector<int>{10, 20, 40};
  const std::vector<Method> methods = {{"generalized_alpha", 0.6},
                                       {"generalized_alpha", 0.8},
                                       {"generalized_alpha", 0.9},
                                       {"trapezoidal", 1.0}};
  std::ofstream csv(out_path);
  if (!csv) {
    std::fprintf(stderr, "work_precision: error: --out = %s: cannot be written\n",
                 out_path.c_str());
    return 2;
  }
  csv << "scene,elements,step,method,coupling,ok,wall_per_sim_s,cpu_per_sim_s,rtf,"
         "newton_per_step,coupling_per_step,pos_err_ref,tension_err_ref,pos_err_steady,"
         "tension_err_steady,note\n";
  const auto started = std::chrono::steady_clock::now();
  for (const SceneSweep& sc : scenes) {
    const std::string ref_coupling = sc.vehicles ? "strong" : "";
    const Method ref_method{"generalized_alpha", 0.8};
    const Run ref =
        Execute({sc.scene, kRefElements, kRefStep, ref_method, ref_coupling, sc.duration}, 1);
    if (!ref.ok) {
      std::fprintf(stderr, "work_precision: reference run of %s failed: %s\n", sc.scene.c_str(),
                   ref.message.c_str());
      return 3;
    }
    const bool steady = !sc.vehicles;
    towsim::reference::TowedCableSolution analytic;
    if (steady) {
      analytic =
          towsim::reference::SolveTowedCableSteady(towsim::reference::SteadyTowProblem(ref.model));
    }
    // the reference's own convergence in space: twice its elements (in time: the sweep's run at
    // twice its step, 40 elements, ga0.8, in the rows below)
    const Run finer =
        Execute({sc.scene, 2 * kRefElements, kRefStep, ref_method, ref_coupling, sc.duration}, 1);
    if (finer.ok) {
      std::printf(
          "%s: reference (%d elements, h = %g s) against %d elements: towfish position %.3g "
          "of L, top tension %.3g (RMS relative)\n",
          sc.scene.c_str(), kRefElements, kRefStep, 2 * kRefElements, PositionError(ref, finer),
          TensionError(ref, finer));
      csv << sc.scene << ',' << 2 * kRefElements << ',' << kRefStep << ',' << ref_method.name()
          << ',' << (ref_coupling.empty() ? "none" : ref_coupling) << ",1,"
          << Num(finer.wall / sc.duration) << ',' << Num(finer.cpu / sc.duration) << ','
          << Num(sc.duration / finer.wall) << ',' << Num(finer.newton) << ',' << Num(finer.coupling)
          << ',' << Num(PositionError(ref, finer)) << ',' << Num(TensionError(ref, finer))
          << ",nan,nan,space check of the reference\n";
    }
    std::vector<std::string> couplings = {""};
    if (sc.vehicles) couplings = {"strong", "staggered"};
    for (const std::string& coupling : couplings)
      for (const Method& m : methods)
        for (int n : elements)
          for (double h : steps) {
            const bool is_ref = n == kRefElements && h == kRefStep && m.name() == "ga0.8" &&
                                coupling == ref_coupling;
            const Run r =
                is_ref ? Execute(ref.spec) : Execute({sc.scene, n, h, m, coupling, sc.duration});
            std::ostringstream row;
            row << sc.scene << ',' << n << ',' << h << ',' << m.name() << ','
                << (coupling.empty() ? "none" : coupling) << ',' << (r.ok ? 1 : 0) << ',';
            if (r.ok) {
              const double wall = r.wall / sc.duration, cpu = r.cpu / sc.duration;
              row << Num(wall) << ',' << Num(cpu) << ',' << Num(1.0 / wall) << ',' << Num(r.newton)
                  << ',' << Num(r.coupling) << ',' << Num(PositionError(r, ref)) << ','
                  << Num(TensionError(r, ref)) << ',';
              if (steady) {
                const Vec3 d = r.final_offset - analytic.top_minus_sphere;
                row << Num(d.norm() / r.model.cables[0].length) << ','
                    << Num(std::abs(r.final_tension / analytic.top_tension - 1.0)) << ',';
              } else {
                row << "nan,nan,";
              }
              row << (is_ref ? "reference" : "");
            } else {
              std::string msg = r.message.substr(0, r.message.find(';'));
              std::replace(msg.begin(), msg.end(), ',', ' ');
              row << "nan,nan,nan,nan,nan,nan,nan,nan,nan," << msg;
            }
            csv << row.str() << '\n' << std::flush;
            std::printf("%s\n", row.str().c_str());
            std::fflush(stdout);
          }
  }
  std::printf("sweep: %.0f s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  return 0;
}

// the shipped scenes at their own settings: RTF (min over repeats) and the towfish-track error
// against the same scene run 4x finer in time and in space
int Targets() {
  struct Target {
    std::string scene;
    double rtf_target;
  };
  for (const Target& t : {Target{"steady_tow", 2000.0}, Target{"case1_forward", 1000.0},
                          Target{"case2_uturn", 0.0}}) {
    const towsim::core::Model m = towsim::scene::LoadScene(ScenePath(t.scene));
    const Method method{m.integrator.scheme == towsim::core::Scheme::kTrapezoidal
                            ? "trapezoidal"
                            : "generalized_alpha",
                        m.integrator.rho_inf};
    const std::string coupling =
        m.vehicles.empty()
            ? ""
            : (m.integrator.coupling == towsim::core::Coupling::kStrong ? "strong" : "staggered");
    const Spec spec{t.scene, m.cables[0].elements, m.time.step, method, coupling, m.time.duration};
    const Run r = Execute(spec, 5);
    Spec fine = spec;
    fine.step /= 4.0;
    fine.elements *= 4;
    const Run f = Execute(fine, 1);
    Spec fine_t = spec;
    fine_t.step /= 4.0;
    const Run ft = Execute(fine_t, 1);
    if (!r.ok || !f.ok || !ft.ok) {
      std::fprintf(stderr, "work_precision: %s failed: %s%s%s\n", t.scene.c_str(),
                   r.message.c_str(), f.message.c_str(), ft.message.c_str());
      return 3;
    }
    const double rtf = spec.duration / r.wall;
    std::printf(
        "%s (%d elements, h = %g s, %s%s%s, %g s): RTF %.0f (wall, min of repeats; CPU %.0f)%s; "
        "Newton/step %.2f, coupling/step %.2f; towfish track vs 4x finer (h/4, 4N): max %.3f%% "
        "of L, top tension RMS %.3f%%; vs h/4 (same N): max %.3f%% of L\n",
        t.scene.c_str(), spec.elements, spec.step, method.name().c_str(),
        coupling.empty() ? "" : ", ", coupling.c_str(), spec.duration, rtf, spec.duration / r.cpu,
        t.rtf_target > 0.0 ? (rtf >= t.rtf_target ? " >= target" : " < target") : "", r.newton,
        r.coupling, 100.0 * PositionError(r, f), 100.0 * TensionError(r, f),
        100.0 * PositionError(r, ft));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = std::string(TOWSIM_SOURCE_DIR) + "/bench/results/work_precision.csv";
  // case3_waves: Case 1's system in the JONSWAP sea (docs/environment.md), its first 100 s;
  // winch_payout: the winch paying out 150 -> 250 m under way, holding and reeling in
  // (docs/winch.md), 330 s
  std::vector<SceneSweep> scenes = {{"steady_tow", 300.0, false},
                                    {"case1_forward", 100.0, true},
                                    {"case3_waves", 100.0, true},
                                    {"winch_payout", 330.0, false}};
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--targets") return Targets();
    if (a == "--quick") {
      quick = true;
    } else if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (a == "--scenes" && i + 1 < argc) {
      const std::string list = argv[++i];
      std::vector<SceneSweep> chosen;
      for (const SceneSweep& s : scenes)
        if (list.find(s.scene) != std::string::npos) chosen.push_back(s);
      if (chosen.empty()) {
        std::fprintf(stderr,
                     "work_precision: error: --scenes = %s: must name steady_tow, "
                     "case1_forward, case3_waves and/or winch_payout\n",
                     list.c_str());
        return 2;
      }
      scenes = chosen;
    } else {
      std::fprintf(stderr,
                   "usage: work_precision [--out FILE.csv] [--scenes LIST] [--quick] | "
                   "--targets\n");
      return 2;
    }
  }
  return Sweep(out, scenes, quick);
}
