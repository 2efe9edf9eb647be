// What the documentation states about the code, checked against the code where a page states a
// limit or a table that the code also holds:
//   - the highest DDS domain id with config/cyclonedds.xml, as every page with a `--domain N`
//     option row states it, is dds::PortMappingOf(config/cyclonedds.xml).MaxDomain();
//   - docs/testing_controllers.md's table of installed paths names every program of
//     TOWSIM_INSTALLED_PROGRAMS and every file and folder cmake/install.cmake puts in
//     P/share/towsim.

#include <algorithm>
#include <cctype>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dds/port_mapping.h"

namespace towsim::docs {
namespace {

std::string Read(const std::string& relative) {
  std::ifstream in(std::string(TOWSIM_SOURCE_DIR) + "/" + relative);
  EXPECT_TRUE(in.good()) << relative;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// the names in backticks of a markdown table row: "| `a`, `b/` | x |" -> {a, b/}
std::set<std::string> CodeSpans(const std::string& text) {
  static const std::regex kSpan("`([^`]+)`");
  std::set<std::string> spans;
  for (std::sregex_iterator it(text.begin(), text.end(), kSpan), end; it != end; ++it) {
    spans.insert((*it)[1]);
  }
  return spans;
}

// the table rows whose first cell starts with `prefix`
std::vector<std::string> Rows(const std::string& page, const std::string& prefix) {
  std::vector<std::string> rows;
  for (const std::string& line : Lines(page)) {
    if (line.rfind("| `" + prefix, 0) == 0) rows.push_back(line);
  }
  return rows;
}

// the commands `name(...)` of a CMake file, each as its words (comments dropped, one line)
std::vector<std::vector<std::string>> CMakeCommands(const std::string& text,
                                                    const std::string& name) {
  std::string code;
  for (const std::string& line : Lines(text)) code += line.substr(0, line.find('#')) + "\n";
  std::vector<std::vector<std::string>> commands;
  for (size_t at = code.find(name + "("); at != std::string::npos;
       at = code.find(name + "(", at + 1)) {
    const char before = at > 0 ? code[at - 1] : ' ';
    if (std::isalnum(static_cast<unsigned char>(before)) || before == '_') continue;
    const size_t open = at + name.size() + 1, close = code.find(')', open);
    std::istringstream words(code.substr(open, close - open));
    std::vector<std::string> command;
    for (std::string word; words >> word;) command.push_back(word);
    commands.push_back(command);
  }
  return commands;
}

TEST(DocFacts, RowsCodeSpansAndCMakeCommands) {
  const std::string page =
      "| path | what |\n|---|---|\n| `bin/` | `a`, `b` |\n| `share/x/`, `y/` | z |\n";
  EXPECT_EQ(Rows(page, "share/"), std::vector<std::string>{"| `share/x/`, `y/` | z |"});
  EXPECT_EQ(CodeSpans("`share/x/`, `y/`"), (std::set<std::string>{"share/x/", "y/"}));
  const auto commands = CMakeCommands("set(A\n  x  # c\n  y)\nfoo_set(B z)\n", "set");
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0], (std::vector<std::string>{"A", "x", "y"}));
}

TEST(DocFacts, HighestDomainIdIsTheProjectConfigurations) {
  const long max_domain =
      dds::PortMappingOf("file://" + std::string(TOWSIM_SOURCE_DIR) + "/config/cyclonedds.xml")
          .MaxDomain();
  EXPECT_EQ(max_domain, 231);  // 7400 + 250 * 231 + 11 + 2 * 120 = 65401 <= 65535
  const std::string stated = "0 to " + std::to_string(max_domain) + " with `config/cyclonedds.xml`";
  int rows = 0;
  for (const char* page : {"docs/command_line.md", "docs/foxglove.md"}) {
    for (const std::string& line : Lines(Read(page))) {
      if (line.rfind("| `--domain N` |", 0) != 0) continue;
      ++rows;
      EXPECT_NE(line.find(stated), std::string::npos)
          << page << ": the --domain row does not state \"" << stated << "\": " << line;
    }
  }
  EXPECT_EQ(rows, 2);
}

TEST(DocFacts, InstalledPathsTableIsInstallCmakes) {
  const std::string install = Read("cmake/install.cmake");
  const std::string page = Read("docs/testing_controllers.md");

  // bin/: exactly TOWSIM_INSTALLED_PROGRAMS
  std::set<std::string> programs;
  for (const auto& command : CMakeCommands(install, "set")) {
    if (!command.empty() && command[0] == "TOWSIM_INSTALLED_PROGRAMS") {
      programs.insert(command.begin() + 1, command.end());
    }
  }
  ASSERT_EQ(programs.size(), 11u);
  std::set<std::string> documented;
  for (const std::string& line : Lines(page)) {
    if (line.rfind("| `bin/` |", 0) != 0) continue;
    const std::string what = line.substr(std::string("| `bin/` |").size());
    const std::string names = what.substr(0, what.find(';'));
    documented = CodeSpans(names);
  }
  EXPECT_EQ(documented, programs) << "docs/testing_controllers.md, the row `bin/`";

  // share/towsim/: the rows name every installed folder (DIRECTORY, as "name/") and file
  // (FILES, PROGRAMS, by name) or, for a list variable, the folder it goes to
  std::string share_rows;
  for (const std::string& row : Rows(page, "share/towsim/")) share_rows += row + "\n";
  const std::set<std::string> spans = CodeSpans(share_rows);
  const std::string data_destination = "${TOWSIM_DATA_DESTINATION}";
  int installed = 0;
  for (const auto& command : CMakeCommands(install, "install")) {
    if (command.size() < 3) continue;
    const auto dest = std::find(command.begin(), command.end(), "DESTINATION");
    if (dest == command.end() || dest + 1 == command.end() ||
        dest[1].rfind(data_destination, 0) != 0) {
      continue;
    }
    const std::string subdir = dest[1].substr(data_destination.size());  // "" or "/idl"
    const std::string place = "share/towsim" + subdir + "/";
    const bool directory = command[0] == "DIRECTORY";
    for (auto word = command.begin() + 1; word != dest; ++word) {
      ++installed;
      const std::string name = word->substr(word->rfind('/') + 1) + (directory ? "/" : "");
      const bool found =
          word->rfind("${", 0) == 0
              ? std::any_of(spans.begin(), spans.end(),
                            [&](const std::string& s) { return s.rfind(place, 0) == 0; })
              : std::any_of(spans.begin(), spans.end(), [&](const std::string& s) {
                  return s == name || s == place + name ||
                         (s.size() > name.size() &&
                          s.compare(s.size() - name.size(), name.size(), name) == 0 &&
                          s[s.size() - name.size() - 1] == '/');
                });
      EXPECT_TRUE(found) << "docs/testing_controllers.md names no installed " << place << name
                         << " (cmake/install.cmake: " << *word << ")";
    }
  }
  EXPECT_GE(installed, 12);
}

}  // namespace
}  // namespace towsim::docs
