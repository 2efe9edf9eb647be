// Step does not allocate (docs/contract.md §1: a preallocated Workspace). Built against a core
// compiled with EIGEN_RUNTIME_NO_MALLOC and asserts on, so any Eigen heap allocation while
// allocation is forbidden aborts; std containers are caught by counting the global operator new.
// The first steps may size work space (the sub-stepping backups, the first copies); after them
// a step of the cable alone, of a sphere-ended tow and of vehicles with either coupling must
// not allocate at all, also after a state was restored with SetState.

#include <algorithm>
#include <cstdlib>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "core/simulation.h"
#include "core/state.h"
#include "steady_tow_model.h"
#include "counting_new.h"

namespace towsim::core {
namespace {

using test::InASea;
using test::SteadyTowModel;
using test::SteadyTowWithVehicle;

// the next 100 steps of `sim` call no operator new and no Eigen allocation
void ExpectNextStepsDoNotAllocate(Simulation& sim) {
  Eigen::internal::set_is_malloc_allowed(false);
  g_news = 0;
  g_counting = true;
  bool ok = true;
  for (int k = 0; k < 100 && ok; ++k) ok = sim.Step().ok();
  g_counting = false;
  Eigen::internal::set_is_malloc_allowed(true);
  ASSERT_TRUE(ok);
  EXPECT_EQ(g_news.load(), 0) << "operator new called during Step";
}

// restored: the steps after Simulation::SetState (docs/state.md) must not allocate either
void ExpectStepsDoNotAllocate(const Model& model, bool restored = false) {
  Simulation sim(model);
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(sim.Step().ok());  // warm-up: work space sized
  if (restored) {
    const State taken = sim.GetState();
    for (int k = 0; k < 5; ++k) ASSERT_TRUE(sim.Step().ok());
    sim.SetState(taken);  // may allocate (a copy); the steps after it may not
  }
  ExpectNextStepsDoNotAllocate(sim);
}

TEST(NoAllocation, CableWithASphere) { ExpectStepsDoNotAllocate(SteadyTowModel()); }
TEST(NoAllocation, VehicleStrongCoupling) {
  ExpectStepsDoNotAllocate(SteadyTowWithVehicle(Coupling::kStrong));
}
TEST(NoAllocation, VehicleStaggeredCoupling) {
  ExpectStepsDoNotAllocate(SteadyTowWithVehicle(Coupling::kStaggered));
}

TEST(NoAllocation, VehicleAfterSetState) {
  ExpectStepsDoNotAllocate(SteadyTowWithVehicle(Coupling::kStrong), true);
}
TEST(NoAllocation, VehicleInASeaAfterSetState) {
  ExpectStepsDoNotAllocate(InASea(SteadyTowWithVehicle(Coupling::kStrong)), true);
}

TEST(NoAllocation, CableWithASphereInASea) { ExpectStepsDoNotAllocate(InASea(SteadyTowModel())); }
// the winch paying out across element splits, then reeling in across merges (docs/winch.md)
TEST(NoAllocation, WinchPayoutAndReelIn) {
  Simulation sim(test::SteadyTowWithWinch());
  sim.SetWinchCommand({WinchCommand::Mode::kSpeed, 5.0});
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(sim.Step().ok());  // warm-up: work space sized
  const int nodes = sim.num_nodes();
  Eigen::internal::set_is_malloc_allowed(false);
  g_news = 0;
  g_counting = true;
  bool ok = true;
  int most = nodes;
  for (int k = 0; k < 100 && ok; ++k) {
    ok = sim.Step().ok();
    most = std::max(most, sim.num_nodes());
  }
  sim.SetWinchCommand({WinchCommand::Mode::kLength, 150.0});
  for (int k = 0; k < 200 && ok; ++k) ok = sim.Step().ok();
  g_counting = false;
  Eigen::internal::set_is_malloc_allowed(true);
  ASSERT_TRUE(ok);
  EXPECT_GE(most, nodes + 2);              // split at least twice
  EXPECT_LE(sim.num_nodes(), nodes - 1);  // and merged back below the start
  EXPECT_EQ(g_news.load(), 0) << "operator new called during Step";
}

// a slipping brake repeats its steps from a copy of the step's start (winch.h): the copies
// reuse their storage
TEST(NoAllocation, BrakeSlipping) {
  Model model = test::SteadyTowWithWinch();
  model.cables[0].winch->brake_tension = 0.7 * Simulation(model).DrumTension();
  Simulation sim(model);
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(sim.Step().ok());  // warm-up: work space sized
  ASSERT_TRUE(sim.state().winches[0].slipping);
  const double length = sim.cable_length();
  ExpectNextStepsDoNotAllocate(sim);
  EXPECT_GT(sim.cable_length(), length);  // it slipped
}

TEST(NoAllocation, VehicleInASea) {
  ExpectStepsDoNotAllocate(InASea(SteadyTowWithVehicle(Coupling::kStrong)));
}

}  // namespace
}  // namespace towsim::core
