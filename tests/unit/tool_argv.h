#pragma once
// Test helper: argv for a tool's command line, pointing into `args` (which must outlive it;
// ToolFlags does not write to it). args[0] is the program name.

#include <string>
#include <vector>

namespace towsim::test {

inline std::vector<char*> Argv(std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  return argv;
}

}  // namespace towsim::test
