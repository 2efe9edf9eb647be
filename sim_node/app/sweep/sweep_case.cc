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
  auto number = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return std::string(text);
  };
  const bool lockstep = !spec.controllers.empty();
  std::vector<std::string> args = {"--scene", fs::absolute(spec.scene).lexically_normal().string(),
                                   "--mode", lockstep ? "lockstep" : "offline",
                                   "--fail-on-failsafe"};
  if (spec.lockstep_timeout) {
    args.insert(args.end(), {"--lockstep-timeout", number(*spec.lockstep_timeout)});
  }
  if (spec.duration) args.insert(args.end(), {"--duration", number(*spec.duration)});
  for (size_t i = 0; i < c.values.size(); ++i) {
    if (i < spec.parameters.size() && spec.parameters[i].controllers_only) continue;
    args.insert(args.end(), {"--set", c.values[i].first + "=" + c.values[i].second});
  }
  args.insert(args.end(), {"--csv", fs::absolute(case_dir).lexically_normal().string()});
  return args;
}

std::string ControllersText(const std::vector<CaseController>& controllers) {
  std::string text;
  for (const CaseController& k : controllers) {
    text +=
        "controller " + k.name + " " + std::to_string(1 + k.args.size()) + "\n" + k.program + "\n";
    for (const std::string& a : k.args) text += a + "\n";
  }
  return text;
}

std::vector<CaseController> ParseControllersText(const std::string& text) {
  std::vector<CaseController> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream head(line);
    std::string word, name;
    long n = -1;
    if (!(head >> word >> name >> n) || word != "controller" || n < 1) {
      throw std::runtime_error("controllers.txt: a malformed line: " + line);
    }
    CaseController k;
    k.name = name;
    for (long i = 0; i < n; ++i) {
      if (!std::getline(in, line)) throw std::runtime_error("controllers.txt: cut short");
      (i == 0 ? k.program : k.args.emplace_back()) = line;
    }
    out.push_back(std::move(k));
  }
  return out;
}

void PrepareCase(const std::string& case_dir, const CaseRunner& runner,
                 const std::vector<std::string>& arguments,
                 const std::vector<CaseController>& controllers) {
  std::error_code ec;
  fs::create_directories(case_dir, ec);
  if (ec) throw std::runtime_error(case_dir + ": cannot be created: " + ec.message());
  std::string args_text;
  for (const std::string& a : arguments) args_text += a + "\n";
  WriteTextFileAtomically((fs::path(case_dir) / "case_args.txt").string(), args_text);
  const std::string dir = ShellWord(fs::absolute(case_dir).lexically_normal().string());
  if (!controllers.empty()) {
    WriteTextFileAtomically((fs::path(case_dir) / "controllers.txt").string(),
                            ControllersText(controllers));
    // the case's processes and its status by towsim_sweep itself (sweep_case_run.h)
    const std::string script =
        "#!/bin/bash\n"
        "# one case of a towsim sweep with controllers (docs/sweeps.md): sim_node in lockstep\n"
        "# beside the controllers of controllers.txt on a free DDS domain id, then\n"
        "# case_status.txt\n"
        "exec " +
        ShellWord(runner.sweep) + " --run-case " + dir + " --sim-node " +
        ShellWord(runner.sim_node) + " --domain " + std::to_string(runner.domain_first) +
        " --domain-last " + std::to_string(runner.domain_last) + "\n";
    WriteTextFileAtomically((fs::path(case_dir) / "command.sh").string(), script);
    fs::permissions(fs::path(case_dir) / "command.sh",
                    fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add, ec);
    return;
  }
  const std::string& sim_node = runner.sim_node;

  // the same run as the local runner's, timed by the shell (a Slurm task runs this)
  std::string command = ShellWord(sim_node);
  for (const std::string& a : arguments) command += " " + ShellWord(a);
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

bool SameArguments(const std::string& case_dir, const std::vector<std::string>& arguments,
                   const std::vector<CaseController>& controllers) {
  std::string expected;
  for (const std::string& a : arguments) expected += a + "\n";
  return ReadTextFile((fs::path(case_dir) / "case_args.txt").string()) == expected &&
         ReadTextFile((fs::path(case_dir) / "controllers.txt").string()) ==
             ControllersText(controllers);
}

void WriteCaseStatus(const std::string& case_dir, const CaseStatus& status) {
  char text[96];
  std::snprintf(text, sizeof text, "exit_code=%d\nwall_s=%.3f\n", status.exit_code, status.wall_s);
  std::string all = text;
  if (status.domain >= 0) all += "domain=" + std::to_string(status.domain) + "\n";
  if (!status.message.empty()) {
    std::string line = status.message;
    for (char& ch : line) ch = ch == '\n' || ch == '\r' ? ' ' : ch;
    all += "message=" + line + "\n";
  }
  WriteTextFileAtomically((fs::path(case_dir) / "case_status.txt").string(), all);
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
    } else if (line.rfind("domain=", 0) == 0) {
      s.domain = std::atoi(line.c_str() + 7);
    } else if (line.rfind("message=", 0) == 0) {
      s.message = line.substr(8);
    }
  }
  if (!code || !wall) return std::nullopt;
  return s;
}

void ClearCaseStatus(const std::string& case_dir) {
  std::error_code ec;
  fs::remove(fs::path(case_dir) / "case_status.txt", ec);
}

std::vector<std::string> SweepRow::Unsettled(const SweepSpec& spec) const {
  std::vector<std::string> names;
  if (!ok) return names;
  for (size_t i = 0; i < settled.size() && i < spec.results.size(); ++i) {
    if (settled[i].asked && !settled[i].settled) names.push_back(spec.results[i].name);
  }
  return names;
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
  if (!status->message.empty()) {
    row.message = status->message;
    return row;
  }
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
                                      ReadTextFile((fs::path(case_dir) / "sim_node.out").string()),
                                      &row.settled);
    row.ok = true;
  } catch (const std::exception& e) {
    row.message = std::string("results: ") + e.what();
  }
  return row;
}

}  // namespace towsim::app
