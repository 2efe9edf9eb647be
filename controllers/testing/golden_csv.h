#pragma once
// A trajectory held to a golden CSV file (docs/testing_controllers.md, "Golden trajectories"):
// typically the node's bodies.csv (t,body,x,y,z,roll,pitch,yaw,u,v,w,p,q,r, docs/contract.md §5) of a run
// against a copy checked into the user's repository.
//
// The files must have the same header and the same rows; the first `key_columns` columns
// (t, body) must match exactly as text, every other column as numbers within
//   |actual - golden| <= tolerance.abs + tolerance.rel * |golden|.
// To rewrite the golden file on purpose (after a change of the controller that is meant to
// change the trajectory), run the test with TOWSIM_UPDATE_GOLDEN=1 in the environment: the
// actual file is copied over the golden one (directories created) and the check passes with a
// note; review the diff and commit it.

#include <string>

#include <gtest/gtest.h>

namespace towsim::testing {

struct CsvTolerance {
  double abs = 0.0;
  double rel = 0.0;
};

// true if TOWSIM_UPDATE_GOLDEN=1
bool UpdateGoldenRequested();

::testing::AssertionResult MatchesGoldenCsv(const std::string& actual_path,
                                            const std::string& golden_path, CsvTolerance tolerance,
                                            int key_columns = 2);

}  // namespace towsim::testing
