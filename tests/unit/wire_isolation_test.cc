// The wire has one home (docs/contract.md §7, docs/app_layer.md "The wire"): sim_node/ and controllers/
// meet only in wire/ (and msgs/). This test reads every source file under sim_node/ and
// controllers/ and names the file and line of each include that crosses:
//   - a file of sim_node/ includes nothing of controllers/ ("common/...", "testing/...",
//     "controllers/...");
//   - a file of controllers/ includes no sim_node/ header ("dds/...", "core/...", "scene/...",
//     "io/...", "app/...", "sim_node/..."), but wire/ and msgs/ freely.
// Cyclone's own headers share the prefix "dds/" (dds/dds.h, dds/ddsi/..., dds/ddsrt/...): they
// are told from ours by the files that exist in sim_node/dds/.

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace {

namespace fs = std::filesystem;

// the top-level folder a quoted or bracketed include names
std::string FirstSegment(const std::string& header) { return header.substr(0, header.find('/')); }

// what is wrong with `#include "header"` in a file of sim_node/, or "" if nothing
std::string CheckSimNodeInclude(const std::string& header) {
  for (const char* folder : {"common", "testing", "controllers"}) {
    if (FirstSegment(header) == folder && header.find('/') != std::string::npos) {
      return "includes \"" + header + "\": sim_node/ must not include controllers/ (use wire/)";
    }
  }
  return "";
}

// what is wrong with `#include "header"` in a file of controllers/, or "" if nothing.
// `our_dds`: the files of sim_node/dds/ ("entities.h", ...), to tell ours from Cyclone's.
std::string CheckControllerInclude(const std::string& header,
                                   const std::set<std::string>& our_dds) {
  const std::string first = FirstSegment(header);
  if (header.find('/') == std::string::npos) return "";
  if (first == "dds") {
    if (our_dds.count(header.substr(4)) == 0) return "";  // Cyclone's
  } else if (first != "core" && first != "scene" && first != "io" && first != "app" &&
             first != "sim_node") {
    return "";
  }
  return "includes \"" + header +
         "\": a controller reaches sim_node/ only through wire/ (and msgs/)";
}

struct Violation {
  std::string where;  // file:line
  std::string what;
};

// every include of the source files under root/dir checked by `check`
template <class Check>
std::vector<Violation> Scan(const fs::path& root, const std::string& dir, Check check,
                            int* files_scanned) {
  static const std::regex kInclude(R"(^\s*#\s*include\s*[<"]([^>"]+)[>"])");
  std::vector<fs::path> paths;
  for (const auto& entry : fs::recursive_directory_iterator(root / dir)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext == ".h" || ext == ".cc" || ext == ".c") paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  *files_scanned = static_cast<int>(paths.size());
  std::vector<Violation> violations;
  for (const fs::path& path : paths) {
    std::ifstream in(path);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
      ++number;
      std::smatch match;
      if (!std::regex_search(line, match, kInclude)) continue;
      const std::string problem = check(match[1].str());
      if (!problem.empty()) {
        violations.push_back(
            {fs::relative(path, root).generic_string() + ":" + std::to_string(number), problem});
      }
    }
  }
  return violations;
}

std::set<std::string> FilesOf(const fs::path& dir) {
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    files.insert(entry.path().filename().string());
  }
  return files;
}

TEST(WireIsolationTest, SimNodeIncludesNothingOfControllers) {
  const fs::path root(TOWSIM_SOURCE_DIR);
  int files = 0;
  const auto violations = Scan(root, "sim_node", CheckSimNodeInclude, &files);
  ASSERT_GE(files, 50) << "expected the sources under " << root / "sim_node";
  for (const Violation& v : violations) ADD_FAILURE() << v.where << ": " << v.what;
}

TEST(WireIsolationTest, ControllersIncludeSimNodeOnlyThroughWire) {
  const fs::path root(TOWSIM_SOURCE_DIR);
  const std::set<std::string> our_dds = FilesOf(root / "sim_node" / "dds");
  ASSERT_EQ(our_dds.count("entities.h"), 1u);
  int files = 0;
  const auto violations = Scan(
      root, "controllers", [&](const std::string& h) { return CheckControllerInclude(h, our_dds); },
      &files);
  ASSERT_GE(files, 20) << "expected the sources under " << root / "controllers";
  for (const Violation& v : violations) ADD_FAILURE() << v.where << ": " << v.what;
}

// the rules themselves, on known lines
TEST(WireIsolationTest, ClassifiesIncludes) {
  for (const char* ok : {"dds/entities.h", "wire/qos.h", "core/model.h", "towsim_msgs.h",
                         "dds/dds.h", "testing_util.h", "app/node_topics.h"}) {
    EXPECT_EQ(CheckSimNodeInclude(ok), "") << ok;
  }
  for (const char* bad : {"common/client.h", "testing/sim_node.h", "controllers/common/laws.h"}) {
    EXPECT_NE(CheckSimNodeInclude(bad), "") << bad;
  }
  const std::set<std::string> our_dds = {"entities.h", "qos.h", "translators.h"};
  for (const char* ok : {"wire/security.h", "wire/topic_names.h", "towsim_msgs.h", "dds/dds.h",
                         "dds/ddsi/ddsi_config.h", "dds/ddsrt/log.h", "common/laws.h",
                         "testing/process.h", "gtest/gtest.h"}) {
    EXPECT_EQ(CheckControllerInclude(ok, our_dds), "") << ok;
  }
  for (const char* bad : {"dds/qos.h", "dds/entities.h", "core/model.h", "scene/scene_loader.h",
                          "io/csv_writer.h", "app/node_topics.h", "sim_node/dds/qos.h"}) {
    EXPECT_NE(CheckControllerInclude(bad, our_dds), "") << bad;
  }
}

// the scan names file and line, on a made-up tree
TEST(WireIsolationTest, ScanNamesFileAndLine) {
  const fs::path root =
      fs::temp_directory_path() / ("towsim_wire_isolation_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "sim_node" / "app");
  std::ofstream(root / "sim_node" / "app" / "a.cc") << "#include \"dds/dds.h\"\n"
                                                       "#include \"wire/qos.h\"\n"
                                                       "#include \"common/dds_qos.h\"\n";
  std::ofstream(root / "sim_node" / "app" / "notes.txt") << "#include \"common/client.h\"\n";
  int files = 0;
  const auto violations = Scan(root, "sim_node", CheckSimNodeInclude, &files);
  fs::remove_all(root);
  EXPECT_EQ(files, 1);
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].where, "sim_node/app/a.cc:3");
  EXPECT_NE(violations[0].what.find("common/dds_qos.h"), std::string::npos) << violations[0].what;
}

}  // namespace
