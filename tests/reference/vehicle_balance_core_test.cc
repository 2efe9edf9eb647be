// initial: static with vehicles (docs/physics.md "Static equilibrium with vehicles"): the
// balance places a towed 6-DOF towfish at the depth, layback and trim of steady tow and gives a
// towing vehicle the thrust that holds the speed, so that the run starts in steady tow.
//
// The reference is the run itself: the dynamic equations at rest in the moving frame are the
// static ones, so a balanced start has nothing to settle. Each case runs 300 s in calm water
// and compares the start (t = 0) with the mean of the last 10 s: the top tension, the towfish's
// depth, layback and pitch, and (towing vehicle) its speed. The towfish is placed by hand far
// from its steady position (straight behind the tow point at 30 degrees), so the balance, not
// the scene's numbers, finds it. A towing vehicle asked for a speed its propeller cannot hold
// is refused with the propeller named.

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "core/state.h"
#include "scene/scene_loader.h"

namespace towsim::reference {
namespace {

using core::Vec3;

// the target: t = 0 within 2 % of the steady state at 300 s
constexpr double kSteadyRelTol = 2e-2;
// the pitch is near zero: compared absolutely [rad]
constexpr double kPitchTol = 2e-3;
constexpr double kDuration = 300.0;  // [s]
constexpr double kWindow = 10.0;     // the mean's window at the end [s]

const std::string kScenes = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes";

std::string Num(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", x);
  return b;
}

// the paper's cable from its start to the towfish's bow, 20 elements, initial: static at V:
// the start driven at V (the tow point 3.5 m deep), or on the towing vehicle (propeller, no
// thrust given) when `towing`
core::Model TowScene(double speed, double length, bool towing) {
  const double a = 30.0 * M_PI / 180.0;  // the hand-placed guess: 30 degrees down
  const std::string v = Num(speed);
  const std::string start = towing
      ? "{body: tow_vehicle, at: [0, 0, 0.2]}"
      : "{driven: {position: [0, 0, 3.5], velocity: [" + v + ", 0, 0]}}";
  const std::string tow_vehicle =
      towing ? "  tow_vehicle: {model: ../vehicles/tow_vehicle.yaml, position: [0, 0, 3.5]}\n"
             : "";
  return scene::LoadSceneFromString(
      "name: balance\n"
      "time: {step: 0.05, duration: 300, output_rate: 10}\n"
      "environment: {water_density: 1025, dynamic_viscosity: 1.0e-3, gravity: 9.81}\n"
      "cable:\n"
      "  line_type: park_kim_tow_cable\n"
      "  length: " + Num(length) + "\n"
      "  elements: 20\n"
      "  initial: static\n"
      "  initial_velocity: [" + v + ", 0, 0]\n"
      "  start: " + start + "\n"
      "  end: {body: towfish, at: [1.65, 0, 0]}\n"
      "bodies:\n" + tow_vehicle +
      "  towfish: {model: ../vehicles/towfish.yaml, position: [" +
          Num(-length * std::cos(a)) + ", 0, " + Num(3.5 + length * std::sin(a)) + "]}\n"
      "integrator: {scheme: generalized_alpha, rho_inf: 0.8, coupling: strong, "
      "tolerance: 1.0e-8, max_iterations: 20}\n",
      "vehicle_balance_core_test.yaml", kScenes, {});
}

int Body(const core::Simulation& sim, const std::string& name) {
  for (int b = 0; b < sim.num_bodies(); ++b)
    if (sim.body_name(b) == name) return b;
  ADD_FAILURE() << "no body " << name;
  return 0;
}

// what the comparison reads
struct Tow {
  double tension = 0.0;  // the cable's force on its start [N]
  double depth = 0.0;    // the towfish's z [m]
  double layback = 0.0;  // the tow point's x minus the towfish's [m]
  double pitch = 0.0;    // the towfish's pitch [rad]
  double speed = 0.0;    // the towing vehicle's forward speed dx/dt (0 without one) [m/s]
  Tow& operator+=(const Tow& o) {
    tension += o.tension, depth += o.depth, layback += o.layback, pitch += o.pitch,
        speed += o.speed;
    return *this;
  }
};

Tow Read(const core::Simulation& sim, bool towing) {
  const int fish = Body(sim, "towfish");
  Tow t;
  t.tension = sim.end_force(0).norm();
  const Vec3 p = sim.body_position(fish);
  const Vec3 top = sim.node_position(0);
  t.depth = p.z();
  t.layback = top.x() - p.x();
  const Eigen::Matrix3d r = sim.body_attitude(fish).toRotationMatrix();
  t.pitch = std::asin(-r(2, 0));
  if (towing) t.speed = sim.body_velocity(Body(sim, "tow_vehicle")).x();
  return t;
}

// the start, and the mean over the last kWindow of a kDuration run
void RunSteady(const core::Model& model, bool towing, Tow* start, Tow* end) {
  core::Simulation sim(model);
  std::printf("  %s\n", sim.initial_report().c_str());
  *start = Read(sim, towing);
  const long steps = std::lround(kDuration / model.time.step);
  const long window = std::lround(kWindow / model.time.step);
  *end = Tow();
  for (long k = 1; k <= steps; ++k) {
    const core::StepStatus s = sim.Step();
    ASSERT_TRUE(s.ok()) << "step " << k << ": " << s.message;
    if (k > steps - window) *end += Read(sim, towing);
  }
  const double n = static_cast<double>(window);
  end->tension /= n, end->depth /= n, end->layback /= n, end->pitch /= n, end->speed /= n;
}

void ExpectSteady(const Tow& a, const Tow& b, const std::string& what) {
  std::printf("%s: tension %.2f -> %.2f N (%+.2e), depth %.3f -> %.3f m (%+.2e), layback %.3f "
              "-> %.3f m (%+.2e), pitch %.5f -> %.5f rad\n",
              what.c_str(), a.tension, b.tension, a.tension / b.tension - 1, a.depth, b.depth,
              a.depth / b.depth - 1, a.layback, b.layback, a.layback / b.layback - 1, a.pitch,
              b.pitch);
  EXPECT_NEAR(a.tension, b.tension, kSteadyRelTol * b.tension) << what;
  EXPECT_NEAR(a.depth, b.depth, kSteadyRelTol * std::abs(b.depth)) << what;
  EXPECT_NEAR(a.layback, b.layback, kSteadyRelTol * std::abs(b.layback)) << what;
  EXPECT_NEAR(a.pitch, b.pitch, kPitchTol) << what;
}

TEST(VehicleBalanceCore, TowedFishStartsInSteadyTowAtThreeSpeedsAndLengths) {
  struct Case {
    double speed, length;
  };
  for (const Case c : {Case{2.0, 100.0}, Case{3.0, 200.0}, Case{6.0, 300.0}}) {
    Tow start, end;
    RunSteady(TowScene(c.speed, c.length, false), false, &start, &end);
    ExpectSteady(start, end,
                 "towed at " + Num(c.speed) + " m/s on " + Num(c.length) + " m");
  }
}

TEST(VehicleBalanceCore, TowingVehicleIsGivenTheThrustThatHoldsTheSpeed) {
  constexpr double kSpeed = 4.0;  // [m/s]
  Tow start, end;
  const core::Model model = TowScene(kSpeed, 200.0, true);
  RunSteady(model, true, &start, &end);
  ExpectSteady(start, end, "behind the towing vehicle at 4 m/s on 200 m");
  std::printf("towing vehicle's speed at the end %.5f m/s\n", end.speed);
  EXPECT_NEAR(start.speed, kSpeed, 1e-9);
  EXPECT_NEAR(end.speed, kSpeed, kSteadyRelTol * kSpeed);
}

TEST(VehicleBalanceCore, ASpeedThePropellerCannotHoldIsRefusedNamingIt) {
  // 8 m/s on 600 m of the paper's cable takes about 4165 N x (8/6)^2 x 3 = 22 kN (Case 3's
  // thrust scaled by the drag's V^2 L): more than the propeller's 12 kN
  try {
    const core::Simulation sim(TowScene(8.0, 600.0, true));
    FAIL() << "balanced: " << sim.initial_report();
  } catch (const core::SolverError& e) {
    const std::string what = e.what();
    std::printf("%s\n", what.c_str());
    EXPECT_NE(what.find("no static equilibrium of the vehicles"), std::string::npos) << what;
    EXPECT_NE(what.find("tow_vehicle's propeller"), std::string::npos) << what;
    EXPECT_NE(what.find("cannot hold the speed"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace towsim::reference
