// app/sweep/sweep_case: a case's folder: its arguments, command.sh (run by bash), case_status.txt,
// and the row collected from it.

#include "app/sweep/sweep_case.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include "app/common/text_file.h"
#include "temp_dir.h"

namespace towsim::app {
namespace {

TEST(SweepCase, LastLineIsTheLastNonEmptyOneAfterProgressRedraws) {
  EXPECT_EQ(LastLine("a\nb\n\n"), "b");
  EXPECT_EQ(LastLine("\r[sim_node] t = 1/2 s   \r[sim_node] t = 2/2 s   \nsim_node: error: x\n"),
            "sim_node: error: x");
  EXPECT_EQ(LastLine(""), "");
  EXPECT_EQ(LastLine("only"), "only");
}

TEST(SweepCase, ArgumentsRunOfflineFailingOnFailsafe) {
  SweepSpec spec;
  spec.scene = "/scenes/case1_forward.yaml";
  spec.duration = 2.5;
  SweepCase c;
  c.name = "case_0003";
  c.values = {{"cable.length", "300"}};
  EXPECT_EQ(CaseArguments(spec, c, "/out/case_0003"),
            (std::vector<std::string>{"--scene", "/scenes/case1_forward.yaml", "--mode", "offline",
                                      "--fail-on-failsafe", "--duration", "2.5", "--set",
                                      "cable.length=300", "--csv", "/out/case_0003"}));
}

TEST(SweepCase, CommandShRunsTheCaseAndWritesItsStatus) {
  test::TempDir dir;
  const std::string case_dir = (dir.path() / "case_0000").string();
  // a stand-in for sim_node: prints its arguments, one a line, and exits 3
  const std::string fake = (dir.path() / "fake_sim_node").string();
  std::ofstream(fake) << "#!/bin/bash\nprintf '%s\\n' \"$@\"\necho 'last words' >&2\nexit 3\n";
  ASSERT_EQ(std::system(("chmod +x '" + fake + "'").c_str()), 0);
  const std::vector<std::string> args = {"--set", "script=[{at: 0, thrust: 1}]", "--set",
                                         "name=it's"};
  CaseRunner runner;
  runner.sim_node = fake;
  PrepareCase(case_dir, runner, args);
  EXPECT_TRUE(SameArguments(case_dir, args));
  EXPECT_FALSE(SameArguments(case_dir, {"--set", "other"}));
  EXPECT_FALSE(ReadCaseStatus(case_dir));  // not run yet
  const int status = std::system(("bash '" + case_dir + "/command.sh'").c_str());
  EXPECT_EQ(WEXITSTATUS(status), 3);
  // the arguments arrived unchanged through the shell quoting
  EXPECT_EQ(ReadTextFile(case_dir + "/sim_node.out"),
            "--set\nscript=[{at: 0, thrust: 1}]\n--set\nname=it's\n");
  const std::optional<CaseStatus> s = ReadCaseStatus(case_dir);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->exit_code, 3);
  EXPECT_GE(s->wall_s, 0.0);

  SweepSpec spec;
  SweepCase c;
  c.name = "case_0000";
  c.values = {{"script", "[{at: 0, thrust: 1}]"}};
  const std::optional<SweepRow> row = CollectCase(spec, c, case_dir);
  ASSERT_TRUE(row);
  EXPECT_FALSE(row->ok);
  EXPECT_EQ(row->exit_code, 3);
  EXPECT_EQ(row->message, "last words");
  EXPECT_EQ(row->parameters, (std::vector<std::string>{"[{at: 0, thrust: 1}]"}));

  ClearCaseStatus(case_dir);
  EXPECT_FALSE(CollectCase(spec, c, case_dir));
  WriteCaseStatus(case_dir, {0, 1.5});
  EXPECT_EQ(ReadTextFile(case_dir + "/case_status.txt"), "exit_code=0\nwall_s=1.500\n");
}

// with controllers: lockstep, the sweep's lockstep timeout, no --set for the parameters of the
// controllers only (the domain is added when the case starts)
TEST(SweepCase, ArgumentsWithControllersRunInLockstep) {
  SweepSpec spec;
  spec.scene = "/scenes/case1_forward.yaml";
  spec.duration = 10;
  spec.lockstep_timeout = 2.5;
  spec.controllers = {SweepController{"depth", "towfish_depth", {}, ""}};
  spec.parameters = {{"kp", {"1"}, "", true}, {"cable.length", {"300"}, "", false}};
  SweepCase c;
  c.values = {{"kp", "1"}, {"cable.length", "300"}};
  EXPECT_EQ(
      CaseArguments(spec, c, "/out/case_0000"),
      (std::vector<std::string>{"--scene", "/scenes/case1_forward.yaml", "--mode", "lockstep",
                                "--fail-on-failsafe", "--lockstep-timeout", "2.5", "--duration",
                                "10", "--set", "cable.length=300", "--csv", "/out/case_0000"}));
}

// controllers.txt and case_status.txt's domain and message, read back; --resume sees a changed
// controller argument; command.sh runs towsim_sweep --run-case
TEST(SweepCase, ControllersFileStatusMessageAndCommand) {
  const std::vector<CaseController> ks = {{"a", "/bin/a", {"--x", "", "${domain}"}},
                                          {"depth", "/bin/depth", {}}};
  const std::string text = ControllersText(ks);
  EXPECT_EQ(text, "controller a 4\n/bin/a\n--x\n\n${domain}\ncontroller depth 1\n/bin/depth\n");
  const std::vector<CaseController> back = ParseControllersText(text);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].name, "a");
  EXPECT_EQ(back[0].program, "/bin/a");
  EXPECT_EQ(back[0].args, ks[0].args);
  EXPECT_TRUE(back[1].args.empty());
  EXPECT_THROW(ParseControllersText("controller a 3\n/bin/a\n"), std::runtime_error);

  test::TempDir dir;
  const std::string case_dir = (dir.path() / "case_0001").string();
  CaseRunner runner{"/opt/bin/towsim_sweep", "/opt/bin/sim_node", 206, 231};
  PrepareCase(case_dir, runner, {"--mode", "lockstep"}, ks);
  EXPECT_TRUE(SameArguments(case_dir, {"--mode", "lockstep"}, ks));
  std::vector<CaseController> changed = ks;
  changed[0].args[0] = "--y";
  EXPECT_FALSE(SameArguments(case_dir, {"--mode", "lockstep"}, changed));
  EXPECT_FALSE(SameArguments(case_dir, {"--mode", "lockstep"}));
  EXPECT_EQ(ReadTextFile(case_dir + "/command.sh")
                .substr(ReadTextFile(case_dir + "/command.sh").find("exec ")),
            "exec '/opt/bin/towsim_sweep' --run-case '" + case_dir +
                "' --sim-node '/opt/bin/sim_node' --domain 206 --domain-last 231\n");

  WriteCaseStatus(case_dir, {2, 1.25, "controller depth exited with code 2: no\nluck", 207});
  EXPECT_EQ(ReadTextFile(case_dir + "/case_status.txt"),
            "exit_code=2\nwall_s=1.250\ndomain=207\nmessage=controller depth exited with code "
            "2: no luck\n");
  const std::optional<CaseStatus> s = ReadCaseStatus(case_dir);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->domain, 207);
  EXPECT_EQ(s->message, "controller depth exited with code 2: no luck");
  // the row's message is the controller's (sim_node's stderr is not read)
  std::ofstream(case_dir + "/sim_node.err") << "sim_node: something else\n";
  SweepSpec spec;
  SweepCase c;
  c.name = "case_0001";
  const std::optional<SweepRow> row = CollectCase(spec, c, case_dir);
  ASSERT_TRUE(row);
  EXPECT_FALSE(row->ok);
  EXPECT_EQ(row->exit_code, 2);
  EXPECT_EQ(row->message, "controller depth exited with code 2: no luck");
}

}  // namespace
}  // namespace towsim::app
