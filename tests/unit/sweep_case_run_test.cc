// app/sweep/sweep_case_run, wire/domain_lock: how a case with controllers ends (the
// policy alone, then with stand-in processes: bash scripts for sim_node and the controllers),
// and the DDS domain ids the cases take.

#include "app/sweep/sweep_case_run.h"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "app/common/text_file.h"
#include "wire/domain_lock.h"
#include "temp_dir.h"

namespace towsim::app {
namespace {

TEST(CaseJudge, TheFirstFailureWins) {
  {  // all well
    CaseJudge j({"a", "b"});
    j.ControllerEnded(0, 0, "");
    j.NodeEnded(0);
    j.ControllerEnded(1, 0, "");
    EXPECT_FALSE(j.failed());
    EXPECT_EQ(j.Outcome().exit_code, 0);
    EXPECT_EQ(j.Outcome().message, "");
  }
  {  // a controller fails during the run: its code and its last words
    CaseJudge j({"a", "depth"});
    j.ControllerEnded(1, 2, "towfish_depth: --kp nan: must be a finite number");
    j.NodeEnded(5);  // then the node, missing its commands
    EXPECT_TRUE(j.failed());
    EXPECT_EQ(j.Outcome().exit_code, 2);
    EXPECT_EQ(j.Outcome().message,
              "controller depth exited with code 2: towfish_depth: --kp nan: must be a finite "
              "number");
  }
  {  // the node fails first (exit 5: --fail-on-failsafe): its stderr says why
    CaseJudge j({"a"});
    j.NodeEnded(5);
    j.ControllerEnded(0, 1, "a: timeout");
    EXPECT_EQ(j.Outcome().exit_code, 5);
    EXPECT_EQ(j.Outcome().message, "");
  }
  {  // a controller killed by a signal, after a good run
    CaseJudge j({"a"});
    j.NodeEnded(0);
    j.ControllerEnded(0, 139, "");
    EXPECT_EQ(j.Outcome().exit_code, 139);
    EXPECT_EQ(j.Outcome().message, "controller a ended by signal 11");
  }
}

class SweepCaseRun : public ::testing::Test {
 protected:
  // an executable bash script
  std::string Script(const std::string& name, const std::string& body) {
    const std::string path = (dir_.path() / name).string();
    std::ofstream(path) << "#!/bin/bash\n" << body;
    std::filesystem::permissions(path, std::filesystem::perms::owner_all);
    return path;
  }
  // runs `c` to its end with `node` as sim_node; the outcome and the wall time
  std::optional<CaseOutcome> Run(const std::string& node, const LocalCase& c, double* wall) {
    CaseRun run(node, c);
    while (!run.Poll()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    *wall = run.wall_s();
    domain_ = run.domain();
    return run.outcome();
  }
  void SetUp() override {
    setenv("TOWSIM_DOMAIN_LOCK_DIR", dir_.path().c_str(), 1);
    case_.dir = (dir_.path() / "case").string();
    std::filesystem::create_directories(case_.dir);
    // ids of this test's own (docs: the brief's range), locks in the test's folder
    case_.domain_first = 209;
    case_.domain_last = 211;
    case_.grace = 0.2;
  }
  void TearDown() override { unsetenv("TOWSIM_DOMAIN_LOCK_DIR"); }
  test::TempDir dir_;
  LocalCase case_;
  int domain_ = -1;
};

// the controllers are given the domain (${domain} and ROS_DOMAIN_ID), the node --domain; a
// controller still running after the node's grace is stopped and not judged
TEST_F(SweepCaseRun, AGoodRunOnADomainOfItsOwn) {
  const std::string node = Script("node", "printf '%s\\n' \"$@\"; echo \"$ROS_DOMAIN_ID\"\n");
  const std::string ctl =
      Script("ctl", "printf '%s\\n' \"$@\"; echo \"$ROS_DOMAIN_ID\"; exec sleep 30\n");
  case_.arguments = {"--mode", "lockstep"};
  case_.controllers = {{"ctl", ctl, {"--domain", "${domain}", "--x", "1"}}};
  double wall = 0;
  const std::optional<CaseOutcome> o = Run(node, case_, &wall);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->exit_code, 0);
  EXPECT_EQ(o->message, "");
  EXPECT_EQ(domain_, 209);
  EXPECT_EQ(ReadTextFile(case_.dir + "/sim_node.out"), "--mode\nlockstep\n--domain\n209\n209\n");
  EXPECT_EQ(ReadTextFile(case_.dir + "/ctl.out"), "--domain\n209\n--x\n1\n209\n");
  EXPECT_LT(wall, 10.0);  // the sleeping controller was stopped after the grace
}

// a controller that fails stops the node at once: the case failed with the controller's words
TEST_F(SweepCaseRun, AControllerThatFailsEndsTheCase) {
  const std::string node = Script("node", "exec sleep 30\n");
  const std::string bad = Script("bad", "echo 'bad: --kp nan: must be finite' >&2; exit 2\n");
  const std::string good = Script("good", "exec sleep 30\n");
  case_.controllers = {{"good", good, {}}, {"bad", bad, {}}};
  double wall = 0;
  const std::optional<CaseOutcome> o = Run(node, case_, &wall);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->exit_code, 2);
  EXPECT_EQ(o->message, "controller bad exited with code 2: bad: --kp nan: must be finite");
  EXPECT_LT(wall, 10.0);
}

// the node's failure (exit 5) is the case's; a case of sim_node alone (offline) takes no domain
TEST_F(SweepCaseRun, TheNodesExitCodeAndOfflineCases) {
  const std::string node = Script("node", "echo 'sim_node: error: lockstep timeout' >&2; exit 5\n");
  const std::string ctl = Script("ctl", "exit 0\n");
  case_.controllers = {{"ctl", ctl, {}}};
  double wall = 0;
  std::optional<CaseOutcome> o = Run(node, case_, &wall);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->exit_code, 5);
  EXPECT_EQ(o->message, "");
  case_.controllers.clear();
  o = Run(Script("offline", "exit 3\n"), case_, &wall);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->exit_code, 3);
  EXPECT_EQ(domain_, -1);
  // sim_node stopped by SIGTERM (offline it exits 143): not finished
  o = Run(Script("stopped", "exit 143\n"), case_, &wall);
  EXPECT_FALSE(o);
}

// each taker gets its own id; when every id is held the case fails at once, saying so
TEST_F(SweepCaseRun, DomainIdsAreLockedOneEach) {
  std::optional<wire::DomainLock> a = wire::DomainLock::Take(209, 210);
  std::optional<wire::DomainLock> b = wire::DomainLock::Take(209, 210);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->id(), 209);
  EXPECT_EQ(b->id(), 210);
  EXPECT_FALSE(wire::DomainLock::Take(209, 210));
  EXPECT_EQ(wire::DomainLock::LockPath(209), (dir_.path() / "towsim-dds-domain-209.lock").string());

  case_.domain_last = 210;
  case_.controllers = {{"ctl", Script("ctl", "exit 0\n"), {}}};
  double wall = 0;
  const std::optional<CaseOutcome> o = Run(Script("node", "exit 0\n"), case_, &wall);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->exit_code, 1);
  EXPECT_EQ(o->message, "no free DDS domain id in 209-210: other sweeps or tests hold them all (" +
                            wire::DomainLock::LockPath(209) + ", ...)");
  a.reset();  // released: taken again
  std::optional<wire::DomainLock> c = wire::DomainLock::Take(209, 210);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->id(), 209);
}

}  // namespace
}  // namespace towsim::app
