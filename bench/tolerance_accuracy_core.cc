// The Newton tolerance against the discretisation error on the reference tests' cases that a
// scene file cannot express: bench/tolerance_accuracy.py's rule and tables
// (docs/benchmarks.md, "Newton tolerance against discretisation error" and "The reference
// tests' cases") for the core::Models the tests build in C++ and start with
// Simulation::StartFrom, and for the static-only tests.
//
//   tolerance_accuracy_core [--cases a,b,...] [--tolerances 1e-4,1e-5,1e-6,1e-7,1e-8]
//                           [--truth 1e-12] [--factor 4] [--ratio 0.1] [--list]
//
// Each case builds its model exactly as the test named beside it does (with the
// model-building functions the tests call, tests/reference/*_model.h and *_models.h), with
// every cable's elements multiplied by `factor`:
//
//   truth       the test's own elements (and step h) at integrator.tolerance = --truth (1e-12);
//               if it fails (a static solve that cannot reach it in double precision, a step
//               that does not converge), at 10x that, up to 1e-10 (static cases: up to 1e-8,
//               the tightest their static solve reaches), said in the table
//   reference   --factor (4) x the elements (and h / 4) at truth's tolerance; if it fails, 2x
//               the elements and h / 2; a static reference first tries 4x at 10x looser
//               tolerances up to 1e-8, then 2x from truth's; said in the table
//   T           the test's own elements and h at each tolerance of --tolerances
//
// (integrator.force_tolerance stays the model's: the shipped 3e-4.) Dynamic cases run the
// test's own steps (its duration, or 60 s if longer), all runs in lockstep, and are compared at
// every step of the coarser run (the reference's every 4th); static cases compare the initial
// state the static solve gives. The two measures:
//
//   track       max over the bodies (spheres, vehicles, vessels) and the compared times of
//               |p - p_other| [m]; without bodies: max over the first cable's nodes at the
//               same arc length (node i of the run, node factor x i of the reference)
//   tension     max over time of |T_top - T_top_other| / max over time of |T_top_other|, T_top
//               the tension of node 0 of the first cable (Simulation::NodeTension(0), what
//               cable.csv writes); for the cantilevers, whose axial tension is not what their
//               tests measure, the tip deflection (z of the last node) in its place, said in
//               the table
//
// solver error at T = run T against truth; discretisation error = truth against reference; the
// ratio per measure is the solver's share. Tables on stdout (the same Markdown tables as
// bench/tolerance_accuracy.py), one line per run on stderr.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cantilever_model.h"
#include "core/constants.h"
#include "core/model.h"
#include "core/simulation.h"
#include "core/state.h"
#include "hanging_cable_model.h"
#include "jumper_model.h"
#include "line_types_models.h"
#include "network_models.h"
#include "scene/scene_loader.h"
#include "seabed_drag_model.h"
#include "swinging_cable_model.h"
#include "taut_string.h"
#include "taut_string_model.h"

namespace towsim::bench {
namespace {

using core::Vec3;
using reference::BridleYaml;
using reference::Cantilever;
using reference::ConstantDragTow;
using reference::HangingCable;
using reference::Jumper;
using reference::KickTheClump;
using reference::NetworkModel;
using reference::OwnBendingCantilever;
using reference::ReleaseStraight;
using reference::RopeCatenary;
using reference::SplitCatenaryYaml;
using reference::String;
using reference::SwingingCable;
using reference::TwoPartTowYaml;

const std::string kScenesDir = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes";
const std::string kCatenaryScene = kScenesDir + "/catenary.yaml";
const std::string kSteadyTowScene = kScenesDir + "/steady_tow.yaml";

// ---------------------------------------------------------------------------------------------
// The cases

struct Case {
  std::string name;
  std::string test;  // the test it reproduces
  bool dynamic = false;
  double duration = 0.0;  // dynamic: simulated seconds (the test's)
  // the model with every cable's elements x factor (the step is set by the runner)
  std::function<core::Model(int factor)> build;
  // after construction: the test's StartFrom (empty: none)
  std::function<void(core::Simulation*)> start;
  // the second measure (empty: the top node's tension) and its name
  std::function<double(const core::Simulation&)> quantity;
  std::string quantity_name = "top tension";
};

// The tests' models (tests/reference/*_model.h, *_models.h), built by the functions the tests
// themselves call; `factor` (or elements x factor) scales every cable's elements

// the taut string's reference frequency f1 (taut_string.h)
double StringFirstFrequency() {
  return reference::TautStringFirstFrequency(reference::StringReference());
}

void HalfSineVelocity(core::Simulation* sim) {
  reference::StartHalfSine(sim, StringFirstFrequency());
}

double TipDeflection(const core::Simulation& sim) {  // z of the last node [m]
  return sim.node_position(sim.num_nodes() - 1).z();
}

// NetworkWithoutDragConservesEnergy steps by 0.01 s (its StepBy): the runs' step
core::Model KickedNetwork(int factor) {
  core::Model m = reference::KickedNetwork(factor);
  m.time.step = 0.01;
  return m;
}

std::string Num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", x);
  return b;
}

std::vector<Case> AllCases() {
  std::vector<Case> cases;
  auto dynamic = [&](std::string name, std::string test, double duration,
                     std::function<core::Model(int)> build,
                     std::function<void(core::Simulation*)> start) {
    Case c;
    c.name = std::move(name);
    c.test = std::move(test);
    c.dynamic = true;
    c.duration = duration;
    c.build = std::move(build);
    c.start = std::move(start);
    cases.push_back(std::move(c));
  };
  auto statics = [&](std::string name, std::string test, std::function<core::Model(int)> build) {
    Case c;
    c.name = std::move(name);
    c.test = std::move(test);
    c.build = std::move(build);
    cases.push_back(std::move(c));
  };

  // swinging cable: the energy tests (20 s) and the order tests (1 s) at their coarsest and
  // finest steps
  dynamic(
      "swinging_trapezoidal_h1e-4", "SwingingCableCore.TrapezoidalConservesEnergy", 20.0,
      [](int f) { return SwingingCable(core::Scheme::kTrapezoidal, 1.0, 1e-4, f); },
      ReleaseStraight);
  dynamic(
      "swinging_ga06_h1e-3", "SwingingCableCore.GeneralizedAlphaDissipates", 20.0,
      [](int f) { return SwingingCable(core::Scheme::kGeneralizedAlpha, 0.6, 1e-3, f); },
      ReleaseStraight);
  for (const double h : {1e-3, 1.25e-4}) {
    dynamic(
        "swinging_order_trapezoidal_h" + Num(h), "SwingingCableCore.TrapezoidalIsSecondOrder", 1.0,
        [h](int f) { return SwingingCable(core::Scheme::kTrapezoidal, 1.0, h, f); },
        ReleaseStraight);
  }
  for (const double h : {1e-3, 1.25e-4}) {
    dynamic(
        "swinging_order_ga08_h" + Num(h), "SwingingCableCore.GeneralizedAlphaIsSecondOrder", 1.0,
        [h](int f) { return SwingingCable(core::Scheme::kGeneralizedAlpha, 0.8, h, f); },
        ReleaseStraight);
  }
  // taut string: a bit over 5 periods
  dynamic("taut_string", "TautStringCore.FirstFrequency", 5.2 / StringFirstFrequency(), String,
          HalfSineVelocity);
  // the cable dragged along the bed: 400 steps of 0.05 s
  dynamic("seabed_dragged", "SeabedCore.DraggedAlongTheBedItFeelsMuTimesItsGroundedWeight", 20.0,
          reference::DraggedOnTheBed, reference::LayOnTheBed);

  // the kicked split catenary: 20 s of 0.01 s
  dynamic("network_kicked", "NetworkCore.NetworkWithoutDragConservesEnergy", 20.0, KickedNetwork,
          KickTheClump);

  // statics
  auto cantilever = [&](std::string name, std::string test, int elements, double alpha) {
    statics(std::move(name), std::move(test),
            [elements, alpha](int f) { return Cantilever(elements * f, alpha); });
    cases.back().quantity = TipDeflection;
    cases.back().quantity_name = "tip deflection";
  };
  cantilever("cantilever_small_10", "CantileverCore.SmallLoadIsEulerBernoulli", 10, 3e-3);
  cantilever("cantilever_large_20", "CantileverCore.LargeLoadIsElastica", 20, 5.0);
  cantilever("cantilever_large_10", "CantileverCore.LargeLoadTenElementsReported", 10, 5.0);
  statics("catenary_20", "CatenaryCore.TwentyElementsMatchIrvine",
          [](int f) { return HangingCable(20 * f, true); });
  statics("catenary_20_no_bending", "CatenaryCore.BendingIsNegligible",
          [](int f) { return HangingCable(20 * f, false); });
  statics("catenary_10", "CatenaryCore.TenElementsReported",
          [](int f) { return HangingCable(10 * f, true); });

  statics("constant_drag_static_6ms", "LineTypesCore.ConstantDragSteadyTowSixMetresPerSecond",
          [](int f) { return ConstantDragTow(6.0, f); });
  statics("constant_drag_static_3ms", "LineTypesCore.ConstantDragSteadyTowThreeMetresPerSecond",
          [](int f) { return ConstantDragTow(3.0, f); });
  statics("constant_drag_default_law", "LineTypesCore.ConstantDragIsNotTheDefaultLaw", [](int f) {
    core::Model m = scene::LoadScene(
        kSteadyTowScene, {"cable.initial=static", "cable.elements=" + std::to_string(20 * f)});
    m.cables[0].drag = {core::CableDragLaw::kConstant, 1.5, 0.01};
    return m;
  });
  statics("rope_catenary_ei0", "LineTypesCore.NoBendingStiffnessIsTheElasticCatenary",
          RopeCatenary);
  statics("own_ei_cantilever", "LineTypesCore.OwnBendingStiffnessCantileverUnderItsOwnWeight",
          OwnBendingCantilever);
  cases.back().quantity = TipDeflection;
  cases.back().quantity_name = "tip deflection";
  statics("jumper_68", "LineTypesCore.LoweLangleyJumperStaticEndForces",
          [](int f) { return Jumper(68 * f); });
  statics("jumper_68_no_ei", "LineTypesCore.LoweLangleyJumperStaticEndForces (EI 0)",
          [](int f) { return Jumper(68 * f, {"cable.bending_stiffness=0"}); });

  for (const int n : {5, 10, 20, 30, 50, 80, 120, 160, 200}) {
    statics("jumper_" + std::to_string(n),
            "StaticSolveCore.StiffHangingLineOneAnswerAtEveryElementCount",
            [n](int f) { return Jumper(n * f); });
  }
  for (const int n : {5, 10, 20, 30, 50, 80, 120, 160, 200}) {
    statics("paper_cable_" + std::to_string(n),
            "StaticSolveCore.PaperCableHangingOneAnswerAtEveryElementCount", [n](int f) {
              return scene::LoadScene(kCatenaryScene, {"cable.elements=" + std::to_string(n * f),
                                                       "cable.loads=[gravity, buoyancy]"});
            });
  }
  for (const int n : {5, 10, 20, 30, 50, 80, 120, 160, 200}) {
    statics("steady_tow_static_" + std::to_string(n),
            "StaticSolveCore.SteadyTowOneAnswerAtEveryElementCount", [n](int f) {
              return scene::LoadScene(kSteadyTowScene, {"cable.initial=static",
                                                        "cable.elements=" + std::to_string(n * f)});
            });
  }
  for (const double speed : {2.0, 3.0, 6.0}) {
    statics("sphere_swings_back_" + Num(speed) + "ms",
            "StaticSolveCore.ASphereSwingsBackToItsTowedPosition...", [speed](int f) {
              const std::string v = std::to_string(speed);
              return scene::LoadScene(
                  kSteadyTowScene,
                  {"cable.initial=static", "cable.initial_velocity=[" + v + ", 0, 0]",
                   "cable.start.driven.velocity=[" + v + ", 0, 0]",
                   "cable.elements=" + std::to_string(20 * f)});
            });
  }
  statics("tow_without_cable_drag", "StaticSolveCore.ATowWithoutCableDragIsFound", [](int f) {
    return scene::LoadScene(
        kSteadyTowScene,
        {"cable.initial=static", "cable.loads=[gravity, buoyancy, added_mass, bending]",
         "cable.elements=" + std::to_string(20 * f)});
  });

  statics("split_catenary_one", "NetworkCore.SplitCatenaryReproducesTheOneCable (one cable)",
          [](int f) { return NetworkModel(SplitCatenaryYaml(false, f)); });
  statics("split_catenary_split", "NetworkCore.SplitCatenaryReproducesTheOneCable (split)",
          [](int f) { return NetworkModel(SplitCatenaryYaml(true, f)); });
  for (const double speed : {2.5, 5.0}) {
    statics("two_part_tow_static_" + Num(speed) + "ms",
            "NetworkCore.TwoPartTowSteadyStateMatchesTheChainedReference",
            [speed](int f) { return NetworkModel(TwoPartTowYaml(speed, f)); });
  }
  statics("bridle", "NetworkCore.BridleMatchesTheStaticSolution",
          [](int f) { return NetworkModel(BridleYaml(f)); });
  return cases;
}

// ---------------------------------------------------------------------------------------------
// Runs in lockstep

struct Run {
  double tolerance = 0.0;
  int factor = 1;
  std::unique_ptr<core::Simulation> sim;
  bool ok = true;
  std::string why;  // failure
  long iterations = 0;
  long steps = 0;
  double wall = 0.0;
  double newton() const {
    return steps > 0 ? static_cast<double>(iterations) / steps
                     : std::numeric_limits<double>::quiet_NaN();
  }
};

// one pair's two measures, accumulated over the compared times
struct Pair {
  double track = 0.0;
  double diff = 0.0;   // max |q_a - q_b|
  double scale = 0.0;  // max |q_b|
  double tension() const {
    return scale > 0.0 ? diff / scale : diff > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  }
};

double Quantity(const Case& c, const core::Simulation& sim) {
  return c.quantity ? c.quantity(sim) : sim.NodeTension(0, 0);
}

// run a against b (node i of a is node factor x i of b)
void Compare(const Case& c, const core::Simulation& a, const core::Simulation& b, int factor,
             Pair* p) {
  if (a.num_bodies() > 0) {
    for (int k = 0; k < a.num_bodies(); ++k)
      p->track = std::max(p->track, (a.body_position(k) - b.body_position(k)).norm());
  } else {
    for (int i = 0; i < a.num_nodes(0); ++i)
      p->track = std::max(p->track, (a.node_position(i) - b.node_position(factor * i)).norm());
  }
  const double qa = Quantity(c, a), qb = Quantity(c, b);
  p->diff = std::max(p->diff, std::abs(qa - qb));
  p->scale = std::max(p->scale, std::abs(qb));
}

using Clock = std::chrono::steady_clock;

// a failure's message for the tables: the static solve's first "residual R N (tolerance T N)"
// (its full message names both guesses and the worst node: on stderr only)
std::string Short(const std::string& why) {
  const size_t at = why.find("residual ");
  if (why.rfind("static equilibrium not found", 0) != 0 || at == std::string::npos) return why;
  const size_t end = why.find(')', at);
  return "static solve: " + why.substr(at, end == std::string::npos ? end : end + 1 - at);
}

Run Make(const Case& c, double tolerance, int factor, double h) {
  Run r;
  r.tolerance = tolerance;
  r.factor = factor;
  const auto t0 = Clock::now();
  try {
    core::Model m = c.build(factor);
    m.integrator.tolerance = tolerance;
    if (c.dynamic) m.time.step = h / factor;
    r.sim = std::make_unique<core::Simulation>(m);
    if (c.start) c.start(r.sim.get());
  } catch (const std::exception& e) {
    r.ok = false;
    r.why = e.what();
    r.sim.reset();
  }
  r.wall = std::chrono::duration<double>(Clock::now() - t0).count();
  return r;
}

void Advance(Run* r, int substeps) {
  if (!r->ok) return;
  const auto t0 = Clock::now();
  for (int i = 0; i < substeps; ++i) {
    const core::StepStatus st = r->sim->Step();
    r->iterations += st.iterations;
    ++r->steps;
    if (!st.ok()) {
      r->ok = false;
      char b[64];
      std::snprintf(b, sizeof b, "step failed at t = %.6g s: ", r->sim->time());
      r->why = b + st.message;
      break;
    }
  }
  r->wall += std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Pass {
  Run truth, ref;
  std::vector<Run> runs;
  Pair disc;
  std::vector<Pair> solver;
};

// truth (tolerance truth_tol), the reference (factor x elements, h / factor, truth_tol) and the
// runs at `tolerances`, stepped together; every pair compared at every step of the coarse runs
Pass RunPass(const Case& c, double truth_tol, int factor, double ref_tol,
             const std::vector<double>& tolerances) {
  const double h = c.build(1).time.step;
  constexpr double kLongest = 60.0;  // [s]: the first 60 s of a longer test
  const double duration = std::min(c.duration, kLongest);
  const long steps = c.dynamic ? static_cast<long>(std::ceil(duration / h - 1e-9)) : 0;
  Pass p;
  p.truth = Make(c, truth_tol, 1, h);
  p.ref = Make(c, ref_tol, factor, h);
  for (double t : tolerances) p.runs.push_back(Make(c, t, 1, h));
  p.solver.resize(tolerances.size());
  auto compare_all = [&] {
    if (!p.truth.ok) return;
    if (p.ref.ok) Compare(c, *p.truth.sim, *p.ref.sim, factor, &p.disc);
    for (size_t i = 0; i < p.runs.size(); ++i)
      if (p.runs[i].ok) Compare(c, *p.runs[i].sim, *p.truth.sim, 1, &p.solver[i]);
  };
  compare_all();
  for (long k = 0; k < steps && p.truth.ok; ++k) {
    Advance(&p.truth, 1);
    Advance(&p.ref, factor);
    for (Run& r : p.runs) Advance(&r, 1);
    compare_all();
  }
  auto log = [&](const char* label, const Run& r) {
    std::fprintf(stderr, "  %18s: %s, %6.2f s, Newton %.2f%s%s\n", label, r.ok ? "ok" : "FAILED",
                 r.wall, r.newton(), r.ok ? "" : ": ", r.why.c_str());
  };
  char label[64];
  std::snprintf(label, sizeof label, "truth %g", truth_tol);
  log(label, p.truth);
  std::snprintf(label, sizeof label, "ref %dx %g", factor, ref_tol);
  log(label, p.ref);
  for (const Run& r : p.runs) {
    std::snprintf(label, sizeof label, "tol %g", r.tolerance);
    log(label, r);
  }
  return p;
}

// ---------------------------------------------------------------------------------------------
// Tables (the layout of bench/tolerance_accuracy.py)

std::string Fmt(double x) {
  if (std::isnan(x)) return "nan";
  char b[32];
  std::snprintf(b, sizeof b, "%.2e", x);
  return b;
}

std::string Fmt(const char* format, double x) {
  char b[64];
  std::snprintf(b, sizeof b, format, x);
  return b;
}

std::vector<std::string> Split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

struct Result {
  const Case* c;
  std::string disc_text, ref_note;
  bool disc_ok = false;
  std::string disc_fail;
  double disc_track = 0.0, disc_tension = 0.0;
  double truth_newton = 0.0, ref_newton = 0.0, truth_wall = 0.0, ref_wall = 0.0;
  double loosest = 0.0;  // 0: none
  double truth_tol = 0.0;
  struct Row {
    double tolerance;
    bool run_ok;
    std::string why;
    bool has_solver = false;
    double track = 0.0, tension = 0.0;
    bool has_ratio = false;
    double r_track = 0.0, r_tension = 0.0;
    bool ok = false;
    double newton = 0.0, wall = 0.0;
  };
  std::vector<Row> rows;
};

int Main(int argc, char** argv) {
  std::vector<double> tolerances = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  double truth = 1e-12, ratio_limit = 0.1;
  int factor = 4;
  std::vector<std::string> only;
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "tolerance_accuracy_core: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--cases") {
      only = Split(value());
    } else if (a == "--tolerances") {
      tolerances.clear();
      for (const std::string& t : Split(value())) tolerances.push_back(std::stod(t));
    } else if (a == "--truth") {
      truth = std::stod(value());
    } else if (a == "--factor") {
      factor = std::stoi(value());
    } else if (a == "--ratio") {
      ratio_limit = std::stod(value());
    } else if (a == "--list") {
      list = true;
    } else {
      std::fprintf(stderr,
                   "usage: tolerance_accuracy_core [--cases a,b,...] [--tolerances 1e-4,...] "
                   "[--truth 1e-12] [--factor 4] [--ratio 0.1] [--list]\n");
      return 2;
    }
  }
  const std::vector<Case> all = AllCases();
  std::vector<const Case*> cases;
  for (const Case& c : all) {
    if (list) std::printf("%-34s %s\n", c.name.c_str(), c.test.c_str());
    if (only.empty() || std::find(only.begin(), only.end(), c.name) != only.end())
      cases.push_back(&c);
  }
  if (list) return 0;
  if (cases.empty()) {
    std::fprintf(stderr, "tolerance_accuracy_core: no such case (--list)\n");
    return 2;
  }

  std::vector<Result> results;
  std::vector<bool> passing(tolerances.size(), true);
  for (const Case* c : cases) {
    const double h = c->build(1).time.step;
    std::fprintf(stderr, "%s (%s):\n", c->name.c_str(),
                 c->dynamic ? Fmt("%g s", c->duration).c_str() : "static");
    // truth: --truth, else 10x looser up to 1e-10 (dynamic, as bench/tolerance_accuracy.py) or
    // up to 1e-8 (static: the tightest the static solve reaches); the reference at the same
    // tolerance, else 2x the elements (and h / 2) at it; a static reference that fails also
    // tries its own tightest tolerance up to 1e-8 (4x first, then 2x)
    const double loosest_truth = c->dynamic ? 1e-10 : 1e-8;
    double truth_tol = truth;
    std::string truth_note;
    Pass p = RunPass(*c, truth_tol, factor, truth_tol, tolerances);
    while (!p.truth.ok && truth_tol < loosest_truth / 1.001) {
      truth_note = " (truth at " + Fmt("%g", truth_tol) + ": " + Short(p.truth.why) + ")";
      truth_tol *= 10;
      p = RunPass(*c, truth_tol, factor, truth_tol, tolerances);
    }
    auto ref_text = [&](int f) {
      return std::to_string(f) + "x el." + (c->dynamic ? ", h/" + std::to_string(f) : "");
    };
    std::string ref_note = ref_text(factor);
    Pair disc = p.disc;
    Run* ref = &p.ref;
    Pass fallback;
    if (p.truth.ok && !p.ref.ok) {
      std::vector<std::pair<int, double>> tries;  // (factor, tolerance)
      if (c->dynamic) {
        if (factor > 2) tries.push_back({2, truth_tol});
      } else {
        for (double t = 10 * truth_tol; t < 1e-8 * 1.001; t *= 10) tries.push_back({factor, t});
        if (factor > 2)
          for (double t = truth_tol; t < 1e-8 * 1.001; t *= 10) tries.push_back({2, t});
      }
      std::string why = ref_text(factor) + " at " + Fmt("%g", truth_tol) + ": " + Short(p.ref.why);
      bool found = false;
      for (const auto& [f, t] : tries) {
        fallback = RunPass(*c, truth_tol, f, t, {});
        if (fallback.ref.ok) {
          found = true;
          ref_note = ref_text(f) + " at " + Fmt("%g", t) + " (" + why + ")";
          break;
        }
        why += "; " + ref_text(f) + " at " + Fmt("%g", t) + ": " + Short(fallback.ref.why);
      }
      if (!tries.empty()) {
        disc = fallback.disc;
        ref = &fallback.ref;
      }
      if (!found) ref_note += " (" + why + ")";
    }
    ref_note += "; truth tolerance " + Fmt("%g", truth_tol) + truth_note;
    Result res;
    res.c = c;
    res.ref_note = ref_note;
    res.truth_tol = truth_tol;
    const core::Model m = c->build(1);
    std::string els;
    for (size_t k = 0; k < m.cables.size(); ++k)
      els += (k ? "+" : "") + std::to_string(m.cables[k].elements);
    const char* scheme = m.integrator.scheme == core::Scheme::kTrapezoidal ? "trapezoidal" : "GA";
    res.disc_text = els + " el.";
    if (c->dynamic) {
      res.disc_text += ", h " + Fmt("%g", h) + " s, " + scheme;
      if (m.integrator.scheme == core::Scheme::kGeneralizedAlpha)
        res.disc_text += " " + Fmt("%g", m.integrator.rho_inf);
    } else {
      res.disc_text += ", static";
    }
    res.disc_ok = p.truth.ok && ref->ok;
    if (!p.truth.ok)
      res.disc_fail = "truth failed";
    else if (!ref->ok)
      res.disc_fail = "reference failed";
    res.disc_track = disc.track;
    res.disc_tension = disc.tension();
    res.truth_newton = p.truth.newton();
    res.ref_newton = ref->newton();
    res.truth_wall = p.truth.wall;
    res.ref_wall = ref->wall;
    for (size_t i = 0; i < tolerances.size(); ++i) {
      Result::Row row;
      const Run& r = p.runs[i];
      row.tolerance = tolerances[i];
      row.run_ok = r.ok;
      row.why = Short(r.why);
      row.newton = r.newton();
      row.wall = r.wall;
      if (r.ok && p.truth.ok) {
        row.has_solver = true;
        row.track = p.solver[i].track;
        row.tension = p.solver[i].tension();
        if (res.disc_ok) {
          auto div = [](double s, double d) {
            return d > 0 ? s / d : std::numeric_limits<double>::infinity();
          };
          row.has_ratio = true;
          row.r_track = div(row.track, res.disc_track);
          row.r_tension = div(row.tension, res.disc_tension);
          row.ok = row.r_track <= ratio_limit && row.r_tension <= ratio_limit;
        }
      }
      if (!row.ok)
        passing[i] = false;
      else if (res.loosest == 0.0)
        res.loosest = row.tolerance;
      res.rows.push_back(row);
    }
    results.push_back(std::move(res));
  }

  std::printf(
      "tolerance_accuracy_core; truth and reference at tolerance %g; ratio limit %g; "
      "force_tolerance the model's (%g)\n\n",
      truth, ratio_limit, core::IntegratorSettings{}.force_tolerance);
  std::printf(
      "| case | test | duration [s] | discretisation | reference | track [m] | second "
      "measure | Newton/step truth, ref | wall [s] truth, ref | loosest T with both ratios "
      "<= %g |\n",
      ratio_limit);
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Result& r : results) {
    const std::string measure =
        r.c->quantity_name == "top tension" ? "" : " (" + r.c->quantity_name + ")";
    std::string track = r.disc_ok ? Fmt(r.disc_track) : r.disc_fail;
    std::string tension = r.disc_ok ? Fmt(r.disc_tension) + measure : r.disc_fail;
    const std::string newton =
        r.c->dynamic ? Fmt("%.2f", r.truth_newton) + ", " + Fmt("%.2f", r.ref_newton) : "-";
    std::printf("| `%s` | `%s` | %s | %s | %s | %s | %s | %s | %.2f, %.2f | %s |\n",
                r.c->name.c_str(), r.c->test.c_str(),
                r.c->dynamic ? Fmt("%.4g", r.c->duration).c_str() : "static", r.disc_text.c_str(),
                r.ref_note.c_str(), track.c_str(), tension.c_str(), newton.c_str(), r.truth_wall,
                r.ref_wall, r.loosest > 0 ? Fmt("%.0e", r.loosest).c_str() : "none");
  }
  std::printf(
      "\n| case | tolerance | solver track [m] | solver tension | ratio track | ratio "
      "tension | Newton/step | wall [s] |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  auto mark = [&](double x) {
    return x > ratio_limit ? "**" + Fmt("%.3f", x) + "**" : Fmt("%.3f", x);
  };
  for (const Result& r : results) {
    for (const Result::Row& row : r.rows) {
      std::string cells;
      if (!row.run_ok) {
        cells = "failed | failed | failed | failed";
      } else if (!row.has_solver) {
        cells = "- | - | - | -";
      } else {
        cells = Fmt(row.track) + " | " + Fmt(row.tension) + " | " +
                (row.has_ratio ? mark(row.r_track) : "-") + " | " +
                (row.has_ratio ? mark(row.r_tension) : "-");
      }
      std::printf("| `%s` | %g | %s | %s | %.2f |\n", r.c->name.c_str(), row.tolerance,
                  cells.c_str(), r.c->dynamic ? Fmt("%.2f", row.newton).c_str() : "-", row.wall);
    }
  }
  std::printf("\n| ratio solver / discretisation (track / second measure) |");
  for (double t : tolerances) std::printf(" %g |", t);
  std::printf("\n|---|");
  for (size_t i = 0; i < tolerances.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (const Result& r : results) {
    std::printf("| `%s` |", r.c->name.c_str());
    for (const Result::Row& row : r.rows) {
      std::string cell;
      if (!row.run_ok)
        cell = "failed";
      else if (!row.has_ratio)
        cell = "-";
      else {
        cell = Fmt("%.2g", row.r_track) + " / " + Fmt("%.2g", row.r_tension);
        if (!row.ok) cell = "**" + cell + "**";
        if (row.tolerance <= r.truth_tol * 1.001) cell += " (not above truth's tolerance)";
      }
      std::printf(" %s |", cell.c_str());
    }
    std::printf("\n");
  }
  std::printf("\n");
  double loosest = 0.0;
  for (size_t i = 0; i < tolerances.size(); ++i)
    if (passing[i]) loosest = std::max(loosest, tolerances[i]);
  if (loosest > 0.0) {
    std::string tighter;
    for (size_t i = 0; i < tolerances.size(); ++i)
      if (tolerances[i] < loosest && !passing[i])
        tighter += (tighter.empty() ? "" : ", ") + Fmt("%g", tolerances[i]);
    std::printf("Loosest tolerance with every case's ratio <= %g on both measures: **%g**%s\n",
                ratio_limit, loosest,
                tighter.empty() ? "" : (" (but not at " + tighter + ")").c_str());
  } else {
    std::printf("No tolerance of the list keeps every case's ratio <= %g.\n", ratio_limit);
  }
  // cases that fail at some tolerance: the failures' messages
  for (const Result& r : results)
    for (const Result::Row& row : r.rows)
      if (!row.run_ok)
        std::printf("\n- `%s` at %g: %s", r.c->name.c_str(), row.tolerance, row.why.c_str());
  std::printf("\n");
  return 0;
}

}  // namespace
}  // namespace towsim::bench

int main(int argc, char** argv) { return towsim::bench::Main(argc, argv); }
