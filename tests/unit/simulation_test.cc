// Simulation's state is complete (state.h): a run continued from a state taken with GetState
// and restored with SetState, in the same or in a fresh Simulation of the same Model, is bit
// for bit the run that never stopped. The reference is that uninterrupted run itself; the
// tolerance is zero (every double compared exactly). That the history in the state matters is
// shown by StartFrom, which keeps q and v but clears the history: its continuation differs.

#include "core/simulation.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/state.h"
#include "steady_tow_model.h"

namespace towsim::core {
namespace {

using test::InASea;
using test::SteadyTowModel;
using test::SteadyTowWithVehicle;

constexpr int kBefore = 40;  // steps before the state is taken (the kept Newton matrix and
                             // the coupling predictor are in use by then)
constexpr int kAfter = 40;   // steps continued from it

void StepN(Simulation* sim, int steps) {
  for (int k = 0; k < steps; ++k) ASSERT_TRUE(sim->Step().ok()) << "step " << k;
}

// every number a step produces, compared exactly
void ExpectBitIdentical(const Simulation& a, const Simulation& b) {
  const State& x = a.state();
  const State& y = b.state();
  EXPECT_EQ(x.t, y.t);
  EXPECT_EQ(x.step, y.step);
  ASSERT_EQ(x.q.size(), y.q.size());
  for (int i = 0; i < x.q.size(); ++i) {
    ASSERT_EQ(x.q(i), y.q(i)) << "q(" << i << ")";
    ASSERT_EQ(x.v(i), y.v(i)) << "v(" << i << ")";
    ASSERT_EQ(x.a(i), y.a(i)) << "a(" << i << ")";
  }
  for (int i = 0; i < x.lambda.size(); ++i) ASSERT_EQ(x.lambda(i), y.lambda(i)) << "lambda";
  ASSERT_EQ(x.vehicles.size(), y.vehicles.size());
  for (size_t v = 0; v < x.vehicles.size(); ++v) {
    for (int i = 0; i < 3; ++i) EXPECT_EQ(x.vehicles[v].p_W(i), y.vehicles[v].p_W(i));
    for (int i = 0; i < 6; ++i) EXPECT_EQ(x.vehicles[v].nu(i), y.vehicles[v].nu(i));
    EXPECT_EQ(x.vehicles[v].q_WB.coeffs(), y.vehicles[v].q_WB.coeffs());
    EXPECT_EQ(x.vehicles[v].actuator, y.vehicles[v].actuator);
  }
  // the winch (a fixed length and no motion without one)
  EXPECT_EQ(a.cable_length(), b.cable_length());
  EXPECT_EQ(a.winch_speed(), b.winch_speed());
  EXPECT_EQ(a.num_nodes(), b.num_nodes());
  EXPECT_EQ(x.winches[0].slip_slope, y.winches[0].slip_slope);
}

// the uninterrupted run against one restored into a fresh Simulation and one restored into
// the same Simulation after it had run on
void ExpectRoundTrip(const Model& model) {
  Simulation straight(model);
  StepN(&straight, kBefore + kAfter);

  Simulation first(model);
  StepN(&first, kBefore);
  const State taken = first.GetState();
  StepN(&first, 7);  // runs on: its caches (Newton matrix, coupling history) move on

  Simulation fresh(model);
  fresh.SetState(taken);
  StepN(&fresh, kAfter);
  ExpectBitIdentical(straight, fresh);

  first.SetState(taken);
  StepN(&first, kAfter);
  ExpectBitIdentical(straight, first);
}

TEST(SimulationState, RoundTripCableWithASphere) { ExpectRoundTrip(SteadyTowModel()); }
TEST(SimulationState, RoundTripVehicleStrongCoupling) {
  ExpectRoundTrip(SteadyTowWithVehicle(Coupling::kStrong));
}
TEST(SimulationState, RoundTripVehicleStaggeredCoupling) {
  ExpectRoundTrip(SteadyTowWithVehicle(Coupling::kStaggered));
}
TEST(SimulationState, RoundTripVehicleInASea) {
  ExpectRoundTrip(InASea(SteadyTowWithVehicle(Coupling::kStrong)));
}

// the history matters: restarting from the same q, v without it (StartFrom) gives another run
TEST(SimulationState, HistoryIsPartOfTheState) {
  const Model model = SteadyTowWithVehicle(Coupling::kStrong);
  Simulation straight(model);
  StepN(&straight, kBefore + kAfter);
  Simulation restarted(model);
  StepN(&restarted, kBefore);
  restarted.StartFrom(restarted.GetState());
  StepN(&restarted, kAfter);
  EXPECT_NE((straight.state().q - restarted.state().q).lpNorm<Eigen::Infinity>(), 0.0);
}

// the winch moving (docs/winch.md): the state taken mid-payout, 5 steps before an element split,
// continues bit for bit, in a fresh Simulation (given the same winch command: an input) and in
// the one that ran on past the split and then reels in past a merge
TEST(SimulationState, RoundTripWinchMovingAcrossASplit) {
  const Model model = test::SteadyTowWithWinch();
  const WinchCommand payout{WinchCommand::Mode::kSpeed, 5.0};
  Simulation straight(model);
  straight.SetWinchCommand(payout);
  StepN(&straight, 20);
  const int nodes_before = straight.num_nodes();
  const State taken = straight.GetState();
  StepN(&straight, kAfter);
  ASSERT_GT(straight.num_nodes(), nodes_before);  // the continuation splits the drum element

  Simulation fresh(model);
  fresh.SetWinchCommand(payout);
  fresh.SetState(taken);
  StepN(&fresh, kAfter);
  ExpectBitIdentical(straight, fresh);

  // the run that went on and reeled in past a merge, set back to the state before the split
  Simulation first(model);
  first.SetWinchCommand(payout);
  StepN(&first, 20 + kAfter);
  first.SetWinchCommand({WinchCommand::Mode::kLength, 150.0});
  StepN(&first, 120);
  ASSERT_LT(first.num_nodes(), straight.num_nodes());  // merged
  first.SetWinchCommand(payout);
  first.SetState(taken);
  StepN(&first, kAfter);
  ExpectBitIdentical(straight, first);
}

// a slipping brake (winch.h): its slip solved by repeated attempts of each step, and the slope
// it carries to the next step, continue bit for bit from a restored state
TEST(SimulationState, RoundTripBrakeSlipping) {
  Model model = test::SteadyTowWithWinch();
  model.cables[0].winch->brake_tension = 0.7 * Simulation(model).DrumTension();
  Simulation straight(model);
  StepN(&straight, 20);
  ASSERT_TRUE(straight.state().winches[0].slipping);
  const State taken = straight.GetState();
  StepN(&straight, kAfter);
  ASSERT_GT(straight.cable_length(), taken.winches[0].length);  // it slipped on
  Simulation fresh(model);
  fresh.SetState(taken);
  StepN(&fresh, kAfter);
  ExpectBitIdentical(straight, fresh);
}

// the drum on a towing vehicle (strong coupling): the same round trip across a split
TEST(SimulationState, RoundTripWinchOnAVehicle) {
  const Model model = test::SteadyTowWithWinch(SteadyTowWithVehicle(Coupling::kStrong));
  const WinchCommand payout{WinchCommand::Mode::kSpeed, 5.0};
  Simulation straight(model);
  straight.SetWinchCommand(payout);
  StepN(&straight, 20);
  const int nodes_before = straight.num_nodes();
  const State taken = straight.GetState();
  StepN(&straight, kAfter);
  ASSERT_GT(straight.num_nodes(), nodes_before);
  Simulation fresh(model);
  fresh.SetWinchCommand(payout);
  fresh.SetState(taken);
  StepN(&fresh, kAfter);
  ExpectBitIdentical(straight, fresh);
}

std::string SetStateError(const Model& model, const State& s) {
  Simulation sim(model);
  try {
    sim.SetState(s);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(SimulationState, WrongShapeIsRejected) {
  const Model model = SteadyTowWithVehicle(Coupling::kStrong);
  Model longer = model;
  longer.cables[0].elements = 21;
  const State other = Simulation(longer).GetState();
  EXPECT_EQ(SetStateError(model, other),
            "SetState: q has 135 entries, this model needs 129 (3 per sphere body and 6 per cable "
            "node: 1 bodies, 21 nodes)");
  State s = Simulation(model).GetState();
  s.vehicles.clear();
  EXPECT_EQ(SetStateError(model, s),
            "SetState: vehicles has 0 entries, this model needs 1 (one per scene vehicle)");
  s = Simulation(model).GetState();
  s.lambda.resize(5);
  EXPECT_EQ(SetStateError(model, s),
            "SetState: lambda has 5 entries, this model needs 6 (3 per held cable end, 2 more "
            "per clamped end)");
  // the nodes in use are part of the shape
  s = Simulation(model).GetState();
  s.winches[0].nodes = 30;
  EXPECT_EQ(SetStateError(model, s),
            "SetState: winches[0].nodes = 30, this model needs 21 (cable.elements + 1; the cable "
            "has no winch)");
  const Model winch = test::SteadyTowWithWinch(model);
  s = Simulation(winch).GetState();
  s.winches[0].nodes = 1;
  EXPECT_EQ(SetStateError(winch, s),
            "SetState: winches[0].nodes = 1, this model needs 2 to 28 (cable nodes in use; the "
            "winch's max_length holds at most that many)");
}

// The altimeter (Simulation::BodyAltimeterRange, docs/sensors.md): a vehicle's beam runs
// along its body z axis, so over a flat bed h below its origin a pitch theta and a roll phi
// give h / (cos theta cos phi); a sphere's points straight down. Reference: the closed form;
// tolerance: round-off of the quaternion rotation and one division.
TEST(SimulationAltimeter, TiltedVehicleOverAFlatBedReadsHOverCosine) {
  constexpr double kBed = 250.0;            // [m]
  constexpr double kMaxRange = 1000.0;      // [m], beyond the bed
  constexpr double kRangeRelTol = 1e-13;    // round-off
  struct Tilt {
    double roll_deg, pitch_deg;
  };
  for (const Tilt tilt : {Tilt{0, 0}, Tilt{0, 15}, Tilt{0, -30}, Tilt{20, 0}, Tilt{-10, 25}}) {
    Model model = SteadyTowWithVehicle(Coupling::kStrong);
    model.environment.seabed = Seabed::Flat(kBed);
    const double phi = tilt.roll_deg * kPi / 180.0, theta = tilt.pitch_deg * kPi / 180.0;
    model.vehicles[0].euler = Vec3(phi, theta, 0.7);
    const Simulation sim(model);
    const int vehicle = sim.num_spheres();
    const double h = kBed - sim.body_position(vehicle).z();
    const double expected = h / (std::cos(theta) * std::cos(phi));
    EXPECT_NEAR(sim.BodyAltimeterRange(vehicle, kMaxRange), expected, kRangeRelTol * expected)
        << "roll " << tilt.roll_deg << ", pitch " << tilt.pitch_deg;
    // the vertical altitude (the environment's) is h whatever the attitude
    EXPECT_NEAR(sim.BodyAltitude(vehicle), h, kRangeRelTol * h);
    // the sphere: straight down
    const double h_sphere = kBed - sim.body_position(0).z();
    EXPECT_NEAR(sim.BodyAltimeterRange(0, kMaxRange), h_sphere, kRangeRelTol * h_sphere);
  }
  // pitched past the horizon: no return (REP 117's +inf), and beyond max_range likewise
  Model model = SteadyTowWithVehicle(Coupling::kStrong);
  model.environment.seabed = Seabed::Flat(kBed);
  model.vehicles[0].euler = Vec3(0.0, 100.0 * kPi / 180.0, 0.0);
  const Simulation up(model);
  EXPECT_EQ(up.BodyAltimeterRange(up.num_spheres(), kMaxRange),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(up.BodyAltimeterRange(0, 10.0), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace towsim::core
