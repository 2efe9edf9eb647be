// The installed-file lookup of every program (installed/installed_data.h): a path that exists
// wins, a bare name finds <data>/<folder>/NAME[.yaml], anything else is passed on unchanged;
// the prefix of an installed program (P/bin, P/libexec/towsim).

#include "installed/installed_data.h"

#include <fstream>

#include <gtest/gtest.h>

#include "temp_dir.h"

namespace towsim::installed {
namespace {

namespace fs = std::filesystem;

void Touch(const fs::path& p) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << "name: x\n";
}

TEST(ResolveInstalled, BareNamesFindTheInstalledScenes) {
  const test::TempDir tmp;
  const fs::path data = tmp.path() / "share" / "towsim";
  Touch(data / "scenes" / "case1_forward.yaml");
  EXPECT_EQ(ResolveInstalled("case1_forward", kScenes, data),
            (data / "scenes" / "case1_forward.yaml").string());
  EXPECT_EQ(ResolveInstalled("case1_forward.yaml", kScenes, data),
            (data / "scenes" / "case1_forward.yaml").string());
  // not installed, or with a directory: unchanged (the loader names the missing file)
  EXPECT_EQ(ResolveInstalled("nope", kScenes, data), "nope");
  EXPECT_EQ(ResolveInstalled("scenes/case1_forward.yaml", kScenes, data),
            "scenes/case1_forward.yaml");
  EXPECT_EQ(ResolveInstalled("case1_forward", kScenes, std::nullopt), "case1_forward");
  EXPECT_EQ(ResolveInstalled("", kScenes, data), "");
}

// the controllers' --config NAME: each program looks in its own folder only
TEST(ResolveInstalled, EachFolderHoldsItsProgramsFiles) {
  const test::TempDir tmp;
  const fs::path data = tmp.path() / "share" / "towsim";
  Touch(data / "maneuvers" / "zigzag_10_10.yaml");
  Touch(data / "autopilot" / "heading_step.yaml");
  EXPECT_EQ(ResolveInstalled("zigzag_10_10", kManeuvers, data),
            (data / "maneuvers" / "zigzag_10_10.yaml").string());
  EXPECT_EQ(ResolveInstalled("heading_step", kAutopilot, data),
            (data / "autopilot" / "heading_step.yaml").string());
  EXPECT_EQ(ResolveInstalled("zigzag_10_10", kAutopilot, data), "zigzag_10_10");
  EXPECT_EQ(ResolveInstalled("heading_step", kScenes, data), "heading_step");
}

TEST(ResolveInstalled, AnExistingPathWins) {
  const test::TempDir tmp;
  const fs::path data = tmp.path() / "share" / "towsim";
  Touch(data / "scenes" / "mine.yaml");
  const fs::path own = tmp.path() / "mine.yaml";
  Touch(own);
  EXPECT_EQ(ResolveInstalled(own.string(), kScenes, data), own.string());
}

// P/bin/<program> and P/libexec/towsim/<program> (sim_node's DDS program) are installed
TEST(InstallPrefix, BinAndPrivateProgramDir) {
  EXPECT_EQ(InstallPrefix("/usr/bin/sim_node"), fs::path("/usr"));
  EXPECT_EQ(InstallPrefix("/opt/p/libexec/towsim/sim_node_dds"), fs::path("/opt/p"));
  EXPECT_EQ(InstallPrefix("/tmp/x/root/usr/libexec/towsim/sim_node_dds"),
            fs::path("/tmp/x/root/usr"));
  // anywhere else: a build tree
  EXPECT_FALSE(InstallPrefix("/work/build/sim_node/app/sim_node").has_value());
  EXPECT_FALSE(InstallPrefix("/opt/p/libexec/sim_node_dds").has_value());
  EXPECT_FALSE(InstallPrefix("/opt/p/lib/towsim/sim_node_dds").has_value());
  EXPECT_FALSE(InstallPrefix("/towsim/sim_node_dds").has_value());
}

TEST(InstalledDataDir, NoneInABuildTree) {
  // this test runs from the build tree (build/tests/unit/), not from P/bin
  EXPECT_FALSE(InstalledDataDir().has_value());
  EXPECT_EQ(ResolveInstalled("case1_forward", kScenes), "case1_forward");
}

}  // namespace
}  // namespace towsim::installed
