// Largest stable step per scene.
//   ./build/bench/stress_max_step            # Markdown table on stdout, ~1 min
//
// For each scene, the step h runs over a grid (0.05 ... 1.0 s) for the scene's duration
// through the stress harness (tests/stress/stress_run.h). A run is *stable* when every step
// converges (sub-stepping allowed, counted), the state stays finite and the mechanical energy
// never exceeds the work put in by more than the stress tests' slack. The largest stable step
// is the largest grid value below which every grid value is stable, refined by bisection
// towards the first unstable grid value (to 0.01 s). Accuracy is reported, not judged: the
// towfish's largest distance from its track at h = 0.05 s, relative to the cable length.

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/simulation.h"
#include "stress_run.h"

namespace {

using towsim::core::Simulation;
using towsim::core::Vec3;
using towsim::stress::RunStress;
using towsim::stress::StressResult;

// the stress tests' energy bound (tests/stress/stress_test.cc)
constexpr double kEnergySlackRel = 1e-3;
constexpr double kEnergySlackAbs = 1e3;  // [J]

struct Scene {
  std::string label, file;
  std::vector<std::string> overrides;
  int towfish = 0;  // body index of the towfish (spheres first, then vehicles); -1: mid node
};

struct Outcome {
  bool stable = false;
  StressResult r;
  std::vector<double> t;    // after every step [s]
  std::vector<Vec3> track;  // the towfish (or the mid node) at t
  std::string why;
};

Outcome Run(const Scene& s, double h) {
  std::vector<std::string> o = s.overrides;
  o.push_back("time.step=" + std::to_string(h));
  Outcome out;
  try {
    const towsim::core::Model model = towsim::stress::LoadShippedScene(s.file, o);
    Simulation sim(model);
    auto probe = [&](const Simulation& sm) {
      out.t.push_back(sm.time());
      out.track.push_back(s.towfish >= 0 ? sm.body_position(s.towfish)
                                         : sm.node_position(sm.num_nodes() / 2));
    };
    probe(sim);
    out.r = RunStress(&sim, model.time.duration, {}, 0.0, probe);
  } catch (const std::exception& e) {
    out.why = e.what();
    return out;
  }
  const bool energy_ok = out.r.max_excess <= kEnergySlackRel * out.r.work_abs + kEnergySlackAbs;
  out.stable = out.r.ok && energy_ok;
  if (!out.r.ok) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "fails at t = %.2f s", out.r.t_end);
    out.why = buf;
  } else if (!energy_ok) {
    out.why = "energy above the work put in";
  }
  return out;
}

// position on a track at time t, linear between the samples
Vec3 At(const Outcome& o, double t) {
  size_t i = 1;
  while (i + 1 < o.t.size() && o.t[i] < t) ++i;
  const double w = (t - o.t[i - 1]) / (o.t[i] - o.t[i - 1]);
  return (1.0 - w) * o.track[i - 1] + w * o.track[i];
}

// largest distance between two tracks at whole seconds, relative to `length`
double TrackError(const Outcome& a, const Outcome& ref, double length) {
  double worst = 0.0;
  const double end = std::min(a.t.back(), ref.t.back());
  for (double t = 0.0; t <= end + 1e-9; t += 1.0)
    worst = std::max(worst, (At(a, t) - At(ref, t)).norm());
  return worst / length;
}

}  // namespace

int main() {
  const std::vector<Scene> scenes = {
      {"steady tow", "steady_tow.yaml", {}, 0},
      {"catenary (no body)", "catenary.yaml", {}, -1},
      {"Case 1, strong", "case1_forward.yaml", {}, 1},
      {"Case 1, staggered", "case1_forward.yaml", {"integrator.coupling=staggered"}, 1},
      {"Case 2, strong", "case2_uturn.yaml", {}, 1},
      {"Case 2, staggered", "case2_uturn.yaml", {"integrator.coupling=staggered"}, 1},
      {"Case 1, E x 10, strong", "case1_forward.yaml", {"cable.youngs_modulus=7e9"}, 1},
      {"Case 1, E x 10, staggered",
       "case1_forward.yaml",
       {"cable.youngs_modulus=7e9", "integrator.coupling=staggered"},
       1},
  };
  const std::vector<double> grid = {0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.75, 1.0};
  std::printf(
      "| scene | largest stable h [s] | first unstable h [s] | at the largest stable h: "
      "Newton/step, sub-stepped steps, towfish track error vs h = 0.05 s (of L) |\n"
      "|---|---|---|---|\n");
  for (const Scene& s : scenes) {
    Outcome ref = Run(s, grid[0]);
    double stable_h = 0.0, unstable_h = 0.0;
    Outcome best;
    for (size_t i = 0; i < grid.size(); ++i) {
      Outcome o = i == 0 ? ref : Run(s, grid[i]);
      std::fprintf(stderr, "  %-28s h %.3f: %s\n", s.label.c_str(), grid[i],
                   o.stable ? "stable" : o.why.c_str());
      if (!o.stable) {
        unstable_h = grid[i];
        break;
      }
      stable_h = grid[i];
      best = o;
    }
    // bisection between the last stable and the first unstable grid value, to 0.01 s
    if (stable_h > 0.0 && unstable_h > 0.0) {
      double lo = stable_h, hi = unstable_h;
      while (hi - lo > 0.01 + 1e-12) {
        const double mid = 0.5 * (lo + hi);
        Outcome o = Run(s, mid);
        std::fprintf(stderr, "  %-28s h %.3f: %s\n", s.label.c_str(), mid,
                     o.stable ? "stable" : o.why.c_str());
        if (o.stable) {
          lo = mid;
          best = o;
        } else {
          hi = mid;
          unstable_h = mid;
        }
      }
      stable_h = lo;
    }
    char unstable[64];
    if (unstable_h > 0.0)
      std::snprintf(unstable, sizeof unstable, "%.3f", unstable_h);
    else
      std::snprintf(unstable, sizeof unstable, "none up to %.2f", grid.back());
    if (stable_h > 0.0) {
      // the cable length of every scene here is 200 m
      const double err = TrackError(best, ref, 200.0);
      std::printf("| %s | %.3f | %s | %.2f, %ld, %.2e%s |\n", s.label.c_str(), stable_h, unstable,
                  best.r.mean_iterations, best.r.substepped_steps, err,
                  s.towfish < 0 ? " (mid node)" : "");
    } else {
      std::printf("| %s | below %.2f | %.3f | %s |\n", s.label.c_str(), grid[0], unstable_h,
                  ref.why.c_str());
    }
    std::fflush(stdout);
  }
  return 0;
}
