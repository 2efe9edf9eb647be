#pragma once
// Assertions a controller engineer needs (docs/testing_controllers.md), as GoogleTest
// predicates: EXPECT_TRUE(StaysWithin(...)) prints what went wrong, where and when.

#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testing/sim_node.h"

namespace towsim::testing {

// a signal of a body's odometry, e.g. [](const OdometrySample& s) { return s.z; }
using Signal = std::function<double(const OdometrySample&)>;

// every sample at t >= `after` [s] (of run `run`, see SimNode) has lo <= signal <= hi; there
// must be at least one such sample
::testing::AssertionResult StaysWithin(const std::vector<OdometrySample>& samples, double after,
                                       const Signal& signal, double lo, double hi,
                                       const std::string& what, int run = 0);

// no status says a body is in failsafe, and the last one counts no failsafe entry
::testing::AssertionResult NoFailsafe(const std::vector<StatusSample>& statuses);

// the largest cable tension of every cable state received is <= max_tension [N]
::testing::AssertionResult TensionBelow(const std::vector<SimNode::TensionSample>& tensions,
                                        double max_tension);

// the yaw of a body as a signal, the error to `target` [rad] wrapped into (-pi, pi]
Signal HeadingError(double target);

}  // namespace towsim::testing
