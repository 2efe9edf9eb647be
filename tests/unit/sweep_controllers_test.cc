// app/sweep/sweep_controllers: the placeholders of controller arguments, a case's controller
// command lines, and where a controller's program is found.

#include "app/sweep/sweep_controllers.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "temp_dir.h"

namespace towsim::app {
namespace {

TEST(SweepControllers, PlaceholdersAreFoundAndReplaced) {
  EXPECT_EQ(PlaceholderNames("--kp=${kp}/${case}"), (std::vector<std::string>{"kp", "case"}));
  EXPECT_TRUE(PlaceholderNames("plain $x {y}").empty());
  auto lookup = [](const std::string& n) -> std::optional<std::string> {
    if (n == "kp") return "0.5";
    return std::nullopt;
  };
  EXPECT_EQ(ExpandPlaceholders("a${kp}b${kp}", lookup), "a0.5b0.5");
  // unknown names stay as they are (${domain} until the case starts)
  EXPECT_EQ(ExpandPlaceholders("${domain}-${kp}", lookup), "${domain}-0.5");
  EXPECT_THROW(PlaceholderNames("${kp"), std::invalid_argument);
  EXPECT_THROW(PlaceholderNames("x${}"), std::invalid_argument);
}

TEST(SweepControllers, ACaseSubstitutesItsValuesThenItsDomain) {
  SweepSpec spec;
  SweepController k;
  k.name = "depth";
  k.args = {"--depth",  "${depth}", "--at", "${cable.length}", "--log", "${case_dir}/${case}.log",
            "--domain", "${domain}"};
  spec.controllers = {k};
  SweepCase c;
  c.name = "case_0002";
  c.values = {{"depth", "\"25\""}, {"cable.length", "[1, 2]"}};  // "25": a quoted YAML string
  const std::vector<CaseController> cs =
      CaseControllers(spec, c, "/sweep/out/./case_0002", {"/bin/towfish_depth"});
  ASSERT_EQ(cs.size(), 1u);
  EXPECT_EQ(cs[0].name, "depth");
  EXPECT_EQ(cs[0].program, "/bin/towfish_depth");
  EXPECT_EQ(cs[0].args, (std::vector<std::string>{"--depth", "25", "--at", "[1, 2]", "--log",
                                                  "/sweep/out/case_0002/case_0002.log", "--domain",
                                                  "${domain}"}));
  EXPECT_EQ(WithDomain(cs[0].args, 207).back(), "207");
  EXPECT_EQ(WithDomain({"x${domain}y"}, 0), (std::vector<std::string>{"x0y"}));
}

TEST(SweepControllers, ProgramsByPathBesideTheSweepToolOrOnThePath) {
  test::TempDir dir;
  const auto make = [&](const std::filesystem::path& p) {
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p) << "#!/bin/sh\n";
    std::filesystem::permissions(p, std::filesystem::perms::owner_all);
  };
  make(dir.path() / "sweeps" / "bin" / "ctl");
  make(dir.path() / "installed" / "bin" / "towfish_depth");
  make(dir.path() / "elsewhere" / "on_path");
  std::ofstream(dir.path() / "sweeps" / "not_executable") << "x";
  const std::string sweeps = (dir.path() / "sweeps").string();
  const std::string self = (dir.path() / "installed" / "bin").string();
  std::string why;
  // a path: relative to the sweep file's folder
  EXPECT_EQ(ResolveProgram("bin/ctl", sweeps, self, &why),
            (dir.path() / "sweeps" / "bin" / "ctl").string());
  EXPECT_EQ(ResolveProgram("./not_executable", sweeps, self, &why), "");
  EXPECT_EQ(why, "no executable file " + (dir.path() / "sweeps" / "not_executable").string() +
                     " (a path is relative to the sweep file)");
  // a bare name: beside towsim_sweep, then the PATH
  EXPECT_EQ(ResolveProgram("towfish_depth", sweeps, self, &why), self + "/towfish_depth");
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", ("/nonexistent:" + (dir.path() / "elsewhere").string()).c_str(), 1);
  EXPECT_EQ(ResolveProgram("on_path", sweeps, self, &why),
            (dir.path() / "elsewhere" / "on_path").string());
  EXPECT_EQ(ResolveProgram("nowhere", sweeps, self, &why), "");
  EXPECT_EQ(why, "not found beside towsim_sweep (" + self +
                     ") nor on the PATH (a build tree: PATH=build/controllers:$PATH, or give its "
                     "path)");
  setenv("PATH", path.c_str(), 1);
}

}  // namespace
}  // namespace towsim::app
