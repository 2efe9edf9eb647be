#pragma once
// The logs the fixture writes for the running test (SimNode's log folder, the files of
// LogPrefix): at the end of the test, after TearDown, they are removed if it passed, and kept,
// their paths printed ("[towsim] the logs of the failed test are kept in PATH"), if it failed
// (docs/testing_controllers.md). Outside a test nothing is registered and everything is kept.

#include <string>

namespace towsim::testing {

// removes `path` (a file or a folder; nothing if it does not exist) at the end of the running
// test if it passed; keeps it and prints its path if it failed
void RemoveAfterPassingTest(const std::string& path);

}  // namespace towsim::testing
