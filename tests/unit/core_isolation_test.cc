// The core depends on the standard library and Eigen only (docs/contract.md §1, STYLE "the engine never
// sees the parser"): no DDS, no yaml-cpp, no threads or clocks, nothing from io/, scene/, app/.
// This test reads every file under sim_node/core/ and names the file and line of each include
// (or use of a thread / clock facility) that breaks the rule.

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

// C++17 (and later) standard library headers, plus the C headers it incorporates
const std::set<std::string>& StandardHeaders() {
  static const std::set<std::string> kHeaders = {
      // C++
      "algorithm", "any", "array", "atomic", "bit", "bitset", "charconv", "codecvt", "compare",
      "complex", "concepts", "deque", "exception", "execution", "filesystem", "forward_list",
      "fstream", "functional", "initializer_list", "iomanip", "ios", "iosfwd", "iostream",
      "istream", "iterator", "limits", "list", "locale", "map", "memory", "memory_resource", "new",
      "numbers", "numeric", "optional", "ostream", "queue", "random", "ratio", "regex",
      "scoped_allocator", "set", "span", "sstream", "stack", "stdexcept", "streambuf", "string",
      "string_view", "system_error", "tuple", "type_traits", "typeindex", "typeinfo",
      "unordered_map", "unordered_set", "utility", "valarray", "variant", "vector", "version",
      // forbidden below, but standard
      "thread", "chrono", "mutex", "shared_mutex", "future", "condition_variable", "stop_token",
      "semaphore", "latch", "barrier", "ctime",
      // C compatibility
      "cassert", "cctype", "cerrno", "cfenv", "cfloat", "cinttypes", "climits", "clocale", "cmath",
      "csetjmp", "csignal", "cstdarg", "cstddef", "cstdint", "cstdio", "cstdlib", "cstring",
      "cuchar", "cwchar", "cwctype", "assert.h", "ctype.h", "errno.h", "fenv.h", "float.h",
      "inttypes.h", "limits.h", "locale.h", "math.h", "setjmp.h", "signal.h", "stdarg.h",
      "stddef.h", "stdint.h", "stdio.h", "stdlib.h", "string.h", "time.h", "uchar.h", "wchar.h",
      "wctype.h"};
  return kHeaders;
}

// threads and clocks: the core is a pure function of (Model, State); the app owns time
const std::set<std::string>& ForbiddenStandardHeaders() {
  static const std::set<std::string> kHeaders = {
      "thread",     "chrono",    "mutex", "shared_mutex", "future", "condition_variable",
      "stop_token", "semaphore", "latch", "barrier",      "ctime",  "time.h",
      "signal.h",   "csignal"};
  return kHeaders;
}

// what is wrong with `#include <header>` / `#include "header"` in a file of core/, or "" if
// nothing. `core_files` holds the paths of core/ relative to core/ (for "ancf_element.h").
std::string CheckInclude(const std::string& header, const std::set<std::string>& core_files) {
  std::string lower = header;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* word : {"dds", "yaml", "io/", "scene/", "app/"}) {
    if (lower.find(word) != std::string::npos) {
      return std::string("includes <") + header + ">: the core must not see '" + word + "'";
    }
  }
  if (ForbiddenStandardHeaders().count(header) != 0) {
    return "includes <" + header + ">: no threads or clocks in the core";
  }
  if (StandardHeaders().count(header) != 0) return "";
  if (header.rfind("Eigen/", 0) == 0 || header.rfind("unsupported/Eigen/", 0) == 0) return "";
  if (header.rfind("core/", 0) == 0 && core_files.count(header.substr(5)) != 0) return "";
  if (core_files.count(header) != 0) return "";  // same directory, relative
  return "includes <" + header +
         ">: only the standard library, Eigen and core/ itself are allowed in the core";
}

// uses of thread / clock facilities that an indirect include could let through
std::string CheckCode(const std::string& line) {
  const std::string code = line.substr(0, line.find("//"));
  for (const char* word : {"std::chrono", "std::thread", "std::this_thread", "std::mutex",
                           "std::async", "std::time(", "std::clock(", "getenv("}) {
    if (code.find(word) != std::string::npos) {
      return std::string("uses ") + word + ": no threads, clocks or environment in the core";
    }
  }
  return "";
}

struct Violation {
  std::string where;  // file:line
  std::string what;
};

std::vector<Violation> ScanCore(const fs::path& core_dir, int* files_scanned) {
  std::set<std::string> core_files;
  std::vector<fs::path> paths;
  for (const auto& entry : fs::recursive_directory_iterator(core_dir)) {
    if (!entry.is_regular_file()) continue;
    paths.push_back(entry.path());
    core_files.insert(fs::relative(entry.path(), core_dir).generic_string());
  }
  std::sort(paths.begin(), paths.end());
  *files_scanned = static_cast<int>(paths.size());

  static const std::regex kInclude(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  std::vector<Violation> violations;
  for (const fs::path& path : paths) {
    std::ifstream in(path);
    std::string line;
    int number = 0;
    bool in_block_comment = false;
    while (std::getline(in, line)) {
      ++number;
      // skip /* ... */ comment blocks (a mention of <chrono> in prose is fine)
      if (in_block_comment) {
        if (line.find("*/") != std::string::npos) in_block_comment = false;
        continue;
      }
      if (line.find("/*") != std::string::npos && line.find("*/") == std::string::npos) {
        in_block_comment = true;
      }
      const std::string where = "sim_node/core/" + fs::relative(path, core_dir).generic_string() +
                                ":" + std::to_string(number);
      std::smatch match;
      if (std::regex_search(line, match, kInclude)) {
        const std::string problem = CheckInclude(match[2].str(), core_files);
        if (!problem.empty()) violations.push_back({where, problem});
        continue;
      }
      const std::string problem = CheckCode(line);
      if (!problem.empty()) violations.push_back({where, problem});
    }
  }
  return violations;
}

TEST(CoreIsolationTest, CoreIncludesOnlyStandardLibraryEigenAndItself) {
  const fs::path core_dir = fs::path(TOWSIM_SOURCE_DIR) / "sim_node" / "core";
  ASSERT_TRUE(fs::is_directory(core_dir)) << core_dir;
  int files = 0;
  const std::vector<Violation> violations = ScanCore(core_dir, &files);
  // guard against a vacuous pass (wrong directory, empty tree)
  ASSERT_TRUE(fs::exists(core_dir / "model.h"));
  ASSERT_GE(files, 3) << "expected the core sources under " << core_dir;
  for (const Violation& v : violations) ADD_FAILURE() << v.where << ": " << v.what;
}

// the scan names file and line, on a made-up core tree
TEST(CoreIsolationTest, ScanNamesFileAndLine) {
  const fs::path dir =
      fs::temp_directory_path() / ("towsim_core_isolation_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "sub");
  std::ofstream(dir / "ok.h") << "#pragma once\n#include <vector>\n#include <Eigen/Core>\n";
  std::ofstream(dir / "sub" / "bad.cc") << "#include \"core/ok.h\"\n"
                                           "/* #include <thread> in a comment is fine\n"
                                           "   still a comment */\n"
                                           "#include <chrono>\n"
                                           "#include \"scene/scene_loader.h\"\n";
  int files = 0;
  const std::vector<Violation> violations = ScanCore(dir, &files);
  fs::remove_all(dir);
  EXPECT_EQ(files, 2);
  ASSERT_EQ(violations.size(), 2u);
  EXPECT_EQ(violations[0].where, "sim_node/core/sub/bad.cc:4");
  EXPECT_NE(violations[0].what.find("<chrono>"), std::string::npos) << violations[0].what;
  EXPECT_EQ(violations[1].where, "sim_node/core/sub/bad.cc:5");
  EXPECT_NE(violations[1].what.find("scene/"), std::string::npos) << violations[1].what;
}

// the rule itself, on known lines
TEST(CoreIsolationTest, ClassifiesIncludes) {
  const std::set<std::string> core_files = {"model.h", "state.h"};
  for (const char* ok : {"vector", "cmath", "Eigen/Core", "Eigen/Dense",
                         "unsupported/Eigen/AutoDiff", "core/model.h", "state.h"}) {
    EXPECT_EQ(CheckInclude(ok, core_files), "") << ok;
  }
  for (const char* bad :
       {"thread", "chrono", "mutex", "future", "ctime", "dds/dds.h", "yaml-cpp/yaml.h",
        "io/csv_writer.h", "scene/load_scene.h", "app/node/progress.h", "boost/optional.hpp",
        "core/missing.h", "msgs/CableState.h"}) {
    EXPECT_NE(CheckInclude(bad, core_files), "") << bad;
  }
  EXPECT_NE(CheckCode("  auto t0 = std::chrono::steady_clock::now();"), "");
  EXPECT_EQ(CheckCode("  x = 1;  // std::chrono is for the app"), "");
}

}  // namespace
