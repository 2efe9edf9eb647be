#pragma once
// Test helper: runs the sim_node binary (TOWSIM_SIM_NODE, set by towsim_add_test) as a process
// through the shell, stdin from /dev/null, stdout and stderr captured in files of a directory
// of the test's own, and returns its exit code and both outputs.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace towsim::test {

// the whole file; empty if it cannot be read
inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// `s` as one shell word: single-quoted, a ' inside written '\''
inline std::string ShellQuote(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

struct SimNodeResult {
  int exit_code = -1;  // -1 if the process did not exit normally
  std::string out;     // stdout
  std::string err;     // stderr
};

// runs sim_node with `args`, stdout and stderr captured in tmp/stdout.txt and tmp/stderr.txt
inline SimNodeResult RunSimNode(const std::vector<std::string>& args,
                                const std::filesystem::path& tmp) {
  std::string command = ShellQuote(TOWSIM_SIM_NODE);
  for (const std::string& arg : args) command += " " + ShellQuote(arg);
  const std::filesystem::path out = tmp / "stdout.txt";
  const std::filesystem::path err = tmp / "stderr.txt";
  command += " </dev/null >" + ShellQuote(out.string()) + " 2>" + ShellQuote(err.string());
  const int status = std::system(command.c_str());
  SimNodeResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = ReadFile(out);
  result.err = ReadFile(err);
  return result;
}

}  // namespace towsim::test
