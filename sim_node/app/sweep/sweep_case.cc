#include "app/sweep/sweep_case.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/common/text_file.h"
#include "app/sweep/sweep_signals.h"

namespace towsim::app {
namespace {

namespace fs = std::filesystem;

}  // namespace

std::string ShellWord(const std::string& s) {
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::vector<std::string> CaseArguments(const SweepSpec& spec, const SweepCase& c,
                                       const std::string& case_dir) {
  std::vector<std::string> args = {"--scene", fs::absolute(spec.scene).lexically_normal().string(),
                                   "--mode", "offline", "--fail-on-failsafe"};
  if (spec.duration) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", *spec.duration);
    args.insert(args.end(), {"--duration", text});
  }
  for (const std::string& set : c.Overrides()) args.insert(args.end(), {"--set", set});
  args.insert(args.end(), {"--csv", fs::absolute(case_dir).lexically_normal().string()});
  return args;
}

void PrepareCase(const std::string& case_dir, const std::string& sim_node,
                 const std::vector<std::string>& arguments) {
  std::error_code ec;
  fs::create_directories(case_dir, ec);
  if (ec) throw std::runtime_error(case_dir + ": cannot be created: " + ec.message());
  std::string args_text;
  for (const std::string& a : arguments) args_text += a + "\n";
  WriteTextFileAtomically((fs::path(case_dir) / "case_args.txt").string(), args_text);

  // the same run as the local runner's, timed by the shell (a Slurm task runs this)
  std::string command = ShellWord(sim_node);
  for (const std::string& a : arguments) command += " " + ShellWord(a);
  const std::string dir = ShellWord(fs::absolute(case_dir).lexically_normal().string());
  std::string script =
      "#!/bin/bash\n"
      "# one case of a towsim sweep (docs/sweeps.md): sim_node offline, then case_status.txt\n"
      "cd " +
      dir +
      " || exit 1\n"
      "rm -f case_status.txt\n"
      "start=$(date +%s.%N)\n" +
      command + " </dev/null >sim_node.out 2>sim_node.err\n" +
      "code=$?\n"
      "end=$(date +%s.%N)\n"
      "awk -v c=\"$code\" -v s=\"$start\" -v e=\"$end\" "
      "'BEGIN { printf \"exit_code=%d\\nwall_s=%.3f\\n\", c, e - s }' >case_status.txt.tmp &&\n"
      "  mv case_status.txt.tmp case_status.txt\n"
      "exit \"$code\"\n";
  WriteTextFileAtomically((fs::path(case_dir) / "command.sh").string(), script);
  fs::permissions(fs::path(case_dir) / "command.sh", fs::perms::owner_exec | fs::perms::group_exec,
                  fs::perm_options::add, ec);
}

bool SameArguments(const std::string& case_dir, const std::vector<std::string>& arguments) {
  std::string expected;
  for (const std::string& a : arguments) expected += a + "\n";
  return ReadTextFile((fs::path(case_dir) / "case_args.txt").string()) == expected;
}

void WriteCaseStatus(const std::string& case_dir, const CaseStatus& status) {
  char text[96];
  std::snprintf(text, sizeof text, "exit_code=%d\nwall_s=%.3f\n", status.exit_code, status.wall_s);
  WriteTextFileAtomically((fs::path(case_dir) / "case_status.txt").string(), text);
}

std::optional<CaseStatus> ReadCaseStatus(const std::string& case_dir) {
  std::ifstream in(fs::path(case_dir) / "case_status.txt");
  if (!in) return std::nullopt;
  CaseStatus s;
  bool code = false, wall = false;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("exit_code=", 0) == 0) {
      s.exit_code = std::atoi(line.c_str() + 10);
      code = true;
    } else if (line.rfind("wall_s=", 0) == 0) {
      s.wall_s = std::atof(line.c_str() + 7);
      wall = true;
    }
  }
  if (!code || !wall) return std::nullopt;
  return s;
}

void ClearCaseStatus(const std::string& case_dir) {
  std::error_code ec;
  fs::remove(fs::path(case_dir) / "case_status.txt", ec);
}

std::string LastLine(const std::string& text) {
  size_t end = text.size();
  while (end > 0) {
    const size_t begin = text.find_last_of("\r\n", end - 1);
    const size_t from = begin == std::string::npos ? 0 : begin + 1;
    std::string line = text.substr(from, end - from);
    const size_t last = line.find_last_not_of(" \t");
    if (last != std::string::npos) return line.substr(0, last + 1);
    if (begin == std::string::npos) break;
    end = begin;
  }
  return {};
}

std::optional<SweepRow> CollectCase(const SweepSpec& spec, const SweepCase& c,
                                    const std::string& case_dir) {
  const std::optional<CaseStatus> status = ReadCaseStatus(case_dir);
  // stopped by SIGINT / SIGTERM (the sweep stopped, the Slurm job cancelled): not finished
  if (!status || status->exit_code == 130 || status->exit_code == 143) return std::nullopt;
  SweepRow row;
  row.case_name = c.name;
  row.exit_code = status->exit_code;
  row.wall_s = status->wall_s;
  for (const auto& [path, value] : c.values) row.parameters.push_back(value);
  if (status->exit_code != 0) {
    row.message = LastLine(ReadTextFile((fs::path(case_dir) / "sim_node.err").string()));
    if (row.message.empty()) {
      row.message = status->exit_code > 128
                        ? "sim_node ended by signal " + std::to_string(status->exit_code - 128)
                        : "sim_node exited with code " + std::to_string(status->exit_code);
    }
    return row;
  }
  try {
    row.results = ComputeSweepResults(spec.results, case_dir,
                                      ReadTextFile((fs::path(case_dir) / "sim_node.out").string()));
    row.ok = true;
  } catch (const std::exception& e) {
    row.message = std::string("results: ") + e.what();
  }
  return row;
}

}  // namespace towsim::app
