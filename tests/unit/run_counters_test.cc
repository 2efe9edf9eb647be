// RunCounters (app/node/run_counters): the sum over a RESET, and the summary line's exact text.
#include "app/node/run_counters.h"

#include <optional>
#include <string>

#include <gtest/gtest.h>

namespace towsim::app {
namespace {

TEST(RunCountersTest, SumCoversBothRuns) {
  RunCounters before;
  before.steps = 400;
  before.sim_time = 20.0;
  before.received = 800;
  before.rejected = 3;
  before.clamped = 5;
  before.failsafes = 1;
  before.lockstep_timeouts = 2;
  before.resets = 1;
  RunCounters run;
  run.steps = 150;
  run.sim_time = 7.5;
  run.overruns = 4;
  run.received = 300;
  run.rejected = 1;
  run.clamped = 2;
  run.failsafes = 6;
  run.lockstep_timeouts = 7;
  run.unknown_commands = 9;
  before += run;
  EXPECT_EQ(before.steps, 550);
  EXPECT_EQ(before.sim_time, 27.5);
  EXPECT_EQ(before.overruns, 4u);
  EXPECT_EQ(before.received, 1100u);
  EXPECT_EQ(before.rejected, 4u);
  EXPECT_EQ(before.clamped, 7u);
  EXPECT_EQ(before.failsafes, 7u);
  EXPECT_EQ(before.lockstep_timeouts, 9u);
  EXPECT_EQ(before.unknown_commands, 9u);
  EXPECT_EQ(before.resets, 1);
}

TEST(RunCountersTest, LockstepLine) {
  RunCounters c;
  c.steps = 2000;
  c.sim_time = 100.0;
  c.received = 4000;
  // RTF 100 / 1.52 = 65.8: no decimals from 10 on
  EXPECT_EQ(NodeSummaryLine("case1_forward", "lockstep", c, 1.52, "", std::nullopt, std::nullopt),
            "sim_node: case1_forward: lockstep, 2000 steps, 100 s simulated in 1.520 s (RTF 66), "
            "overruns 0, failsafes 0, commands 4000 (rejected 0, clamped 0), lockstep timeouts 0, "
            "resets 0");
}

TEST(RunCountersTest, RealtimeLineWithEveryPart) {
  RunCounters c;
  c.steps = 24691;
  c.sim_time = 1234.5678;
  c.overruns = 3;
  c.received = 100;
  c.rejected = 4;
  c.clamped = 7;
  c.failsafes = 1;
  c.lockstep_timeouts = 0;
  c.unknown_commands = 2;  // counted as received and rejected
  c.resets = 2;
  const SummaryLateness lateness{12e-6, 400e-6, 2.1e-3};
  // RTF 1234.5678 / 1000 = 1.23: two decimals below 10
  EXPECT_EQ(NodeSummaryLine("steady_tow", "realtime", c, 1000.0,
                            ", max cable strain 0.0123 at node 5 (t = 12.5 s): extreme (> 0.01)",
                            std::string("towsim-1a2b (case2)"), lateness),
            "sim_node: steady_tow: realtime, 24691 steps, 1234.57 s simulated in 1000.000 s "
            "(RTF 1.23), overruns 3, failsafes 1, commands 102 (rejected 6, clamped 7), lockstep "
            "timeouts 0, resets 2, max cable strain 0.0123 at node 5 (t = 12.5 s): extreme "
            "(> 0.01), other nodes in the namespace: towsim-1a2b (case2), lateness p50 12 us p99 "
            "400 us max 2100 us");
}

TEST(RunCountersTest, NoWallTimeIsRtfZeroAndALongLineIsCut) {
  const RunCounters c;
  EXPECT_EQ(NodeSummaryLine("s", "fast", c, 0.0, "", std::nullopt, std::nullopt),
            "sim_node: s: fast, 0 steps, 0 s simulated in 0.000 s (RTF 0.00), overruns 0, "
            "failsafes 0, commands 0 (rejected 0, clamped 0), lockstep timeouts 0, resets 0");
  // 639 characters at most; what does not fit (here the lateness) is left off
  const std::string line = NodeSummaryLine("s", "realtime", c, 1.0, "", std::string(700, 'n'),
                                           SummaryLateness{1e-6, 2e-6, 3e-6});
  EXPECT_EQ(line.size(), 639u);
  EXPECT_EQ(line.back(), 'n');
}

}  // namespace
}  // namespace towsim::app
