// app/sweep/sweep_slurm: the --array indices of the cases to run. (The Slurm runner itself runs
// against a real cluster in tests/integration/sweep_slurm_test.sh.)

#include "app/sweep/sweep_slurm.h"

#include <gtest/gtest.h>

namespace towsim::app {
namespace {

TEST(SweepArrayIndices, RunsOfConsecutiveCasesBecomeRanges) {
  EXPECT_EQ(ArrayIndices({0, 1, 2, 3, 4, 5, 6, 7}), "0-7");
  EXPECT_EQ(ArrayIndices({3}), "3");
  EXPECT_EQ(ArrayIndices({0, 2, 3, 4, 9, 11, 12}), "0,2-4,9,11-12");
  EXPECT_EQ(ArrayIndices({}), "");
}

}  // namespace
}  // namespace towsim::app
