// The Newton tolerance against the discretisation error on the reference tests' cases that a
// scene file cannot express: bench/tolerance_accuracy.py's rule and tables
// (docs/benchmarks.md, "Newton tolerance against discretisation error" and "The reference
// tests' cases") for the core::Models the tests build in C++ and start with
// Simulation::StartFrom, and for the static-only tests.
//
//   tolerance_accuracy_core [--cases a,b,...] [--tolerances 1e-4,1e-5,1e-6,1e-7,1e-8]
//                           [--truth 1e-12] [--factor 4] [--ratio 0.1] [--list]
//
// Each case builds its model exactly as the test named beside it does (the small
// model-building functions are copied from tests/reference/), with every cable's elements
// multiplied by `factor`:
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

#include "core/constants.h"
#include "core/model.h"
#include "core/simulation.h"
#include "core/state.h"
#include "scene/scene_loader.h"
#include "taut_string.h"

namespace towsim::bench {
namespace {

using core::Vec3;

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

// --- tests/reference/swinging_cable_core_test.cc --------------------------------------------
constexpr double kSwingLength = 10.0;

core::Model SwingingCable(core::Scheme scheme, double rho_inf, double step, int factor) {
  core::Model m;
  m.name = "swinging_cable";
  core::CableParams& c = m.cables[0];
  c.length = kSwingLength;
  c.elements = 10 * factor;
  c.diameter = 0.01;
  c.SetSolidSection(2000.0, 1.0e8);
  c.loads.gravity = true;
  c.loads.buoyancy = false;  // vacuum
  c.loads.drag = false;
  c.loads.added_mass = false;
  c.loads.bending = true;
  c.initial = core::InitialShape::kStraight;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.start.clamped = false;
  c.end.kind = core::EndKind::kFree;
  c.end.position = Vec3(kSwingLength, 0.0, 0.0);
  m.integrator.scheme = scheme;
  m.integrator.rho_inf = rho_inf;
  m.integrator.tolerance = 1e-8;  // the test's (overridden by every run here)
  m.time.step = step;
  return m;
}

// Released: straight along +x, at rest
void Released(core::Simulation* sim) {
  core::State s = sim->state();
  const int nodes = sim->num_nodes();
  for (int i = 0; i < nodes; ++i) {
    const int k = sim->cable_dof(i);
    s.q.segment<3>(k) = Vec3(kSwingLength * i / (nodes - 1), 0.0, 0.0);
    s.q.segment<3>(k + 3) = Vec3::UnitX();
  }
  s.v.setZero();
  s.t = 0.0;
  sim->StartFrom(s);
}

// --- tests/reference/taut_string_core_test.cc -----------------------------------------------
constexpr double kStringLength = 10.0, kStringSpan = 10.1, kStringEA = 1.0e4, kStringRhoA = 0.1;

core::Model String(int factor) {
  core::Model m;
  m.name = "taut_string";
  core::CableParams& c = m.cables[0];
  c.length = kStringLength;
  c.elements = 10 * factor;
  c.diameter = 0.01;
  c.SetSolidSection(kStringRhoA / c.area(), kStringEA / c.area());
  c.loads = {false, false, false, false, false};
  c.initial = core::InitialShape::kStraight;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.end.kind = core::EndKind::kFixed;
  c.end.position = Vec3(kStringSpan, 0.0, 0.0);
  m.integrator.scheme = core::Scheme::kTrapezoidal;
  m.integrator.rho_inf = 1.0;
  m.time.step = 1e-3;
  return m;
}

// the test's reference frequency f1 (taut_string.h)
double StringFirstFrequency() {
  reference::TautString s;
  s.length = kStringLength;
  s.span = kStringSpan;
  s.ea = kStringEA;
  s.rho_a = kStringRhoA;
  return reference::TautStringFirstFrequency(s);
}

void HalfSineVelocity(core::Simulation* sim) {
  const double omega = 2.0 * core::kPi * StringFirstFrequency();
  const double v0 = 1e-3 * omega;
  const int nodes = sim->num_nodes();
  core::State s = sim->state();
  for (int i = 0; i < nodes; ++i) {
    const double x = kStringLength * i / (nodes - 1);
    const int k = sim->cable_dof(i);
    s.v.segment<3>(k) = v0 * std::sin(core::kPi * x / kStringLength) * Vec3::UnitZ();
    s.v.segment<3>(k + 3) =
        v0 * (core::kPi / kStringLength) * std::cos(core::kPi * x / kStringLength) * Vec3::UnitZ();
  }
  sim->StartFrom(s);
}

// --- tests/reference/seabed_core_test.cc, DraggedAlongTheBedItFeelsMuTimesItsGroundedWeight ---
core::Model Dragged(int factor) {
  return scene::LoadScene(
      kCatenaryScene,
      {"cable.length=100", "cable.elements=" + std::to_string(20 * factor),
       "cable.loads=[gravity, buoyancy]", "cable.initial=vertical", "cable.axial_damping=0.01",
       "cable.start={driven: {position: [0, 0, 60], velocity: [0.1, 0, 0]}}",
       "cable.end={free: true}", "cable.initial_velocity=[0.1, 0, 0]",
       "environment.seabed={depth: 60, stiffness: 3.0e6, damping: 3.0e4, friction: 0.5}"});
}

void LaidOnTheBed(core::Simulation* sim) {
  constexpr double kSpeed = 0.1;
  const core::Model& m = sim->model();
  core::State laid = sim->state();
  const double l = m.cables[0].length / m.cables[0].elements;
  for (int n = 0; n < sim->num_nodes(); ++n) {
    laid.q.segment<3>(sim->cable_dof(n)) = Vec3(-n * l, 0.0, 60.0);
    laid.q.segment<3>(sim->cable_dof(n) + 3) = Vec3(-1.0, 0.0, 0.0);
    laid.v.segment<3>(sim->cable_dof(n)) = Vec3(kSpeed, 0.0, 0.0);
    laid.v.segment<3>(sim->cable_dof(n) + 3).setZero();
  }
  sim->StartFrom(laid);
}

// --- tests/reference/cantilever_core_test.cc ------------------------------------------------
constexpr double kCantileverLength = 2.0;

core::Model Cantilever(int elements, double alpha) {
  core::Model m;
  m.name = "cantilever";
  core::CableParams& c = m.cables[0];
  c.length = kCantileverLength;
  c.elements = elements;
  c.diameter = 0.02;
  c.SetSolidSection(7850.0, 2.0e11);  // steel
  c.loads.gravity = false;
  c.loads.buoyancy = false;
  c.loads.drag = false;
  c.loads.added_mass = false;
  c.loads.bending = true;
  c.initial = core::InitialShape::kStatic;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.start.clamped = true;
  c.start.slope = Vec3::UnitX();
  c.end.kind = core::EndKind::kSphere;
  c.end.body = 0;
  c.end.at_B = Vec3::Zero();
  core::SphereBody tip;
  tip.name = "tip_mass";
  const double ei = c.bending_stiffness;
  tip.mass = alpha * ei / (kCantileverLength * kCantileverLength) / m.environment.gravity;
  tip.volume = 0.0;
  tip.position = Vec3(kCantileverLength, 0.0, 0.0);
  m.spheres.push_back(tip);
  return m;
}

double TipDeflection(const core::Simulation& sim) {  // z of the last node [m]
  return sim.node_position(sim.num_nodes() - 1).z();
}

// --- tests/reference/catenary_core_test.cc --------------------------------------------------
core::Model HangingCable(int elements, bool bending) {
  core::Model m;
  m.name = "catenary";
  core::CableParams& c = m.cables[0];
  c.length = 200.0;
  c.elements = elements;
  c.diameter = 0.041;
  c.SetSolidSection(1300.0, 7.0e8);
  c.loads.gravity = true;
  c.loads.buoyancy = true;
  c.loads.drag = false;
  c.loads.added_mass = false;
  c.loads.bending = bending;
  c.initial = core::InitialShape::kStatic;
  c.start.kind = core::EndKind::kFixed;
  c.start.position = Vec3::Zero();
  c.end.kind = core::EndKind::kFixed;
  c.end.position = Vec3(150.0, 0.0, 0.0);
  return m;
}

// --- tests/reference/line_types_core_test.cc ------------------------------------------------
core::Model LoadString(const std::string& yaml, const std::string& file,
                       const std::vector<std::string>& overrides = {}) {
  return scene::LoadSceneFromString(yaml, file, kScenesDir, overrides);
}

core::Model ConstantDragTow(double speed, int factor) {
  const std::string v = "[" + std::to_string(speed) + ", 0, 0]";
  return scene::LoadScene(
      kSteadyTowScene,
      {"cable.initial=static", "cable.drag={normal: 1.5, tangential: 0.01}",
       "cable.start.driven.velocity=" + v, "cable.initial_velocity=" + v,
       "bodies.towfish.velocity=" + v, "cable.elements=" + std::to_string(20 * factor)});
}

core::Model RopeCatenary(int factor) {
  return LoadString(
      "name: rope_catenary\n"
      "time: {step: 0.05, duration: 1, output_rate: 10}\n"
      "line_types:\n"
      "  rope: {diameter: 0.03, mass_per_length: 2.5, axial_stiffness: 2.0e5,\n"
      "         bending_stiffness: 0, drag: {normal: 1.2, tangential: 0.01}}\n"
      "cable:\n"
      "  line_type: rope\n"
      "  length: 200\n"
      "  elements: " +
          std::to_string(20 * factor) +
          "\n"
          "  initial: static\n"
          "  start: {fixed: [0, 0, 10]}\n"
          "  end: {fixed: [150, 0, 10]}\n",
      "line_types_core_test.yaml");
}

core::Model OwnBendingCantilever(int factor) {
  constexpr double kLength = 10.0, kMass = 1.0, kGravity = 9.81;
  const double ei = kMass * kGravity * kLength * kLength * kLength / (8.0 * 1e-3);
  char yaml[1024];
  std::snprintf(yaml, sizeof yaml,
                "name: cantilever\n"
                "time: {step: 0.05, duration: 1, output_rate: 10}\n"
                "environment: {gravity: %g}\n"
                "line_types:\n"
                "  beam: {diameter: 0.2, mass_per_length: %g, axial_stiffness: 1.0e10,\n"
                "         bending_stiffness: %.17g}\n"
                "cable:\n"
                "  line_type: beam\n"
                "  length: %g\n"
                "  elements: %d\n"
                "  loads: [gravity, bending]\n"
                "  initial: static\n"
                "  start: {fixed: [0, 0, 0], slope: [1, 0, 0]}\n"
                "  end: {body: tip}\n"
                "bodies:\n"
                "  tip: {type: sphere, mass: 1.0e-9, volume: 0, position: [%g, 0, 0]}\n",
                kGravity, kMass, ei, kLength, 10 * factor, kLength);
  return LoadString(yaml, "line_types_core_test.yaml");
}

// the jumper of line_types_core_test.cc and static_solve_core_test.cc (the same YAML)
core::Model Jumper(int elements, const std::vector<std::string>& overrides = {}) {
  return LoadString(
      "name: jumper\n"
      "time: {step: 0.01, duration: 1, output_rate: 10}\n"
      "environment: {water_density: 1000, gravity: 9.807}\n"
      "cable:\n"
      "  line_type: lowe_langley_jumper\n"
      "  length: 170\n"
      "  elements: " +
          std::to_string(elements) +
          "\n"
          "  loads: [gravity, buoyancy, bending]\n"
          "  initial: static\n"
          "  start: {fixed: [-100, 0, 55]}\n"
          "  end: {fixed: [0, 0, 5]}\n",
      "line_types_core_test.yaml", overrides);
}

// --- tests/reference/network_core_test.cc ---------------------------------------------------
const char kNetworkLine[] =
    "diameter: 0.041, density: 1300, youngs_modulus: 7.0e8, "
    "loads: [gravity, buoyancy, drag, added_mass]";

std::string SplitCatenaryYaml(bool split, int factor) {
  const std::string head =
      "name: catenary\n"
      "time: {step: 0.05, duration: 1, output_rate: 10}\n"
      "environment: {current: [0, 0, 0]}\n";
  if (!split) {
    return head + "cable: {length: 120, elements: " + std::to_string(20 * factor) + ", " +
           kNetworkLine +
           ", initial: static, start: {fixed: [0, 0, 0]}, end: {fixed: [100, 0, 20]}}\n";
  }
  const std::string els = std::to_string(10 * factor);
  return head +
         "bodies: {junction: {type: sphere, mass: 0, volume: 0, position: [50, 0, 40]}}\n"
         "cables:\n"
         "  upper: {length: 60, elements: " +
         els + ", " + kNetworkLine +
         ", initial: static, start: {fixed: [0, 0, 0]}, end: {body: junction}}\n"
         "  lower: {length: 60, elements: " +
         els + ", " + kNetworkLine +
         ", initial: static, start: {body: junction}, end: {fixed: [100, 0, 20]}}\n";
}

// NetworkWithoutDragConservesEnergy: the split catenary without drag and added mass, a 50 kg
// clump at the junction, trapezoidal, h 0.01 s (its StepBy), kicked sideways by StartFrom
core::Model KickedNetwork(int factor) {
  core::Model m = scene::LoadSceneFromString(SplitCatenaryYaml(true, factor), "network.yaml", ".");
  for (core::CableParams& c : m.cables) {
    c.loads.drag = false;
    c.loads.added_mass = false;
  }
  m.spheres[0].mass = 50.0;
  m.integrator.scheme = core::Scheme::kTrapezoidal;
  m.integrator.rho_inf = 1.0;
  m.integrator.tolerance = 1e-10;  // the test's (overridden by every run here)
  m.time.step = 0.01;
  return m;
}

void KickTheClump(core::Simulation* sim) {
  core::State s = sim->state();
  s.v.segment<3>(sim->sphere_dof(0)) = Vec3(0.0, 2.0, 0.0);
  sim->StartFrom(s);
}

std::string TwoPartTowYaml(double speed, int factor) {
  const std::string v = std::to_string(speed);
  const std::string els = std::to_string(20 * factor);
  return "name: two_part_tow\n"
         "time: {step: 0.05, duration: 1, output_rate: 10}\n"
         "environment: {current: [0, 0, 0]}\n"
         "bodies:\n"
         "  depressor: {type: sphere, mass: 1500, volume: 0.25, drag_coefficient: 0.8,\n"
         "              added_mass_coefficient: 0.5, position: [0, 0, 300]}\n"
         "  towfish: {type: sphere, mass: 400, volume: 0.3, drag_coefficient: 0.5,\n"
         "            added_mass_coefficient: 0.5, position: [0, 0, 360]}\n"
         "cables:\n"
         "  main: {length: 300, elements: " +
         els +
         ", diameter: 0.035, mass_per_length: 4.5,\n"
         "         axial_stiffness: 1.0e8, bending_stiffness: 300,\n"
         "         loads: [gravity, buoyancy, drag, added_mass, bending], initial: static,\n"
         "         initial_velocity: [" +
         v +
         ", 0, 0],\n"
         "         start: {driven: {position: [0, 0, 0], velocity: [" +
         v +
         ", 0, 0]}},\n"
         "         end: {body: depressor}}\n"
         "  tether: {length: 60, elements: " +
         els +
         ", diameter: 0.03, mass_per_length: 0.8,\n"
         "           axial_stiffness: 2.0e6, bending_stiffness: 5,\n"
         "           loads: [gravity, buoyancy, drag, added_mass, bending], initial: static,\n"
         "           initial_velocity: [" +
         v +
         ", 0, 0],\n"
         "           start: {body: depressor}, end: {body: towfish}}\n";
}

std::string BridleYaml(int factor) {
  const std::string els = std::to_string(10 * factor);
  return "name: bridle\n"
         "time: {step: 0.05, duration: 1, output_rate: 10}\n"
         "environment: {current: [0, 0, 0]}\n"
         "bodies: {ring: {type: sphere, mass: 2000, volume: 0.2, position: [0, 0, 15]}}\n"
         "cables:\n"
         "  port: {length: 25, elements: " +
         els +
         ", diameter: 0.03, mass_per_length: 0.72452,\n"
         "         axial_stiffness: 2.0e6, bending_stiffness: 0, loads: [gravity, buoyancy],\n"
         "         initial: static, start: {fixed: [0, -20, 0]}, end: {body: ring}}\n"
         "  starboard: {length: 25, elements: " +
         els +
         ", diameter: 0.03, mass_per_length: 0.72452,\n"
         "              axial_stiffness: 2.0e6, bending_stiffness: 0, loads: [gravity, buoyancy],\n"
         "              initial: static, start: {fixed: [0, 20, 0]}, end: {body: ring}}\n";
}

core::Model Network(const std::string& yaml) {
  return scene::LoadSceneFromString(yaml, "network.yaml", kScenesDir);
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
      [](int f) { return SwingingCable(core::Scheme::kTrapezoidal, 1.0, 1e-4, f); }, Released);
  dynamic(
      "swinging_ga06_h1e-3", "SwingingCableCore.GeneralizedAlphaDissipates", 20.0,
      [](int f) { return SwingingCable(core::Scheme::kGeneralizedAlpha, 0.6, 1e-3, f); }, Released);
  for (const double h : {1e-3, 1.25e-4}) {
    dynamic(
        "swinging_order_trapezoidal_h" + Num(h), "SwingingCableCore.TrapezoidalIsSecondOrder", 1.0,
        [h](int f) { return SwingingCable(core::Scheme::kTrapezoidal, 1.0, h, f); }, Released);
  }
  for (const double h : {1e-3, 1.25e-4}) {
    dynamic(
        "swinging_order_ga08_h" + Num(h), "SwingingCableCore.GeneralizedAlphaIsSecondOrder", 1.0,
        [h](int f) { return SwingingCable(core::Scheme::kGeneralizedAlpha, 0.8, h, f); }, Released);
  }
  // taut string: a bit over 5 periods
  dynamic("taut_string", "TautStringCore.FirstFrequency", 5.2 / StringFirstFrequency(), String,
          HalfSineVelocity);
  // the cable dragged along the bed: 400 steps of 0.05 s
  dynamic("seabed_dragged", "SeabedCore.DraggedAlongTheBedItFeelsMuTimesItsGroundedWeight", 20.0,
          Dragged, LaidOnTheBed);

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
          [](int f) { return Network(SplitCatenaryYaml(false, f)); });
  statics("split_catenary_split", "NetworkCore.SplitCatenaryReproducesTheOneCable (split)",
          [](int f) { return Network(SplitCatenaryYaml(true, f)); });
  for (const double speed : {2.5, 5.0}) {
    statics("two_part_tow_static_" + Num(speed) + "ms",
            "NetworkCore.TwoPartTowSteadyStateMatchesTheChainedReference",
            [speed](int f) { return Network(TwoPartTowYaml(speed, f)); });
  }
  statics("bridle", "NetworkCore.BridleMatchesTheStaticSolution",
          [](int f) { return Network(BridleYaml(f)); });
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
