// towsim_sweep: runs every case of a sweep file (offline, or in lockstep beside the sweep's
// controllers), locally with N workers or on Slurm as one job array, and tabulates the
// results (docs/sweeps.md).
//
//   towsim_sweep FILE --out DIR [--workers N] [--domain N] [--slurm] [--resume] [--no-wait]
//                [--collect]
//   towsim_sweep --run-case DIR/<case> --sim-node PATH --domain N [--domain-last M]
//                (one case with controllers: its command.sh runs this)

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/common/exit_codes.h"
#include "app/common/stop_signal.h"
#include "app/common/text_file.h"
#include "app/common/tool_command_line.h"
#include "app/sweep/sweep_case.h"
#include "app/sweep/sweep_case_run.h"
#include "app/sweep/sweep_combinator.h"
#include "app/sweep/sweep_controllers.h"
#include "app/sweep/sweep_file.h"
#include "app/sweep/sweep_local.h"
#include "app/sweep/sweep_lock.h"
#include "app/sweep/sweep_plot.h"
#include "app/sweep/sweep_signals.h"
#include "app/sweep/sweep_slurm.h"
#include "app/sweep/sweep_table.h"
#include "core/model.h"
#include "scene/config_error.h"
#include "scene/scene_loader.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

using towsim::app::kExitBadInput;
using towsim::app::kExitError;
using towsim::app::kExitIncomplete;  // the sweep ran; some cases failed (see results.csv)
using towsim::app::kExitOk;

constexpr long kMaxWorkers = 4096;  // --workers: processes at once, locally or on Slurm

struct Options {
  std::string file, out;
  int workers = 0;  // 0: the number of cores (locally); no limit on Slurm
  int domain = -1;  // -1: the sweep file's `domain`
  int domain_last = towsim::app::kMaxSweepDomain;
  bool slurm = false, resume = false, no_wait = false, collect = false;
  std::string run_case, sim_node;  // --run-case DIR --sim-node PATH
};

std::string Usage() {
  return "usage: towsim_sweep FILE --out DIR [--workers N] [--domain N] [--slurm] [--resume]\n"
         "\n"
         "Runs every case of the sweep file FILE (docs/sweeps.md) with sim_node --mode offline\n"
         "(with controllers: lockstep, beside the controller processes, each case on a DDS\n"
         "domain of its own), one folder per case under DIR, and writes DIR/results.csv,\n"
         "DIR/columns.json, DIR/summary.txt and DIR/results.svg. Plots of two parameters (PNG and\n"
         "SVG): python3 scripts/plot_sweep.py DIR.\n"
         "\n"
         "options:\n"
         "  --out DIR      the sweep's folder (required)\n"
         "  --workers N    cases at once (default: the number of cores); with --slurm, Slurm\n"
         "                 array tasks at once (default: as Slurm schedules)\n"
         "  --domain N     with controllers: the first DDS domain id of the cases (default the\n"
         "                 sweep file's domain:, else 100); they use N up to 231\n"
         "  --slurm        run the cases as one Slurm job array (sbatch --array) and wait\n"
         "  --no-wait      with --slurm: submit and return; --collect later\n"
         "  --resume       run only the cases that are missing or failed in DIR\n"
         "  --collect      run nothing: tabulate the cases finished in DIR\n"
         "  --run-case DIR/CASE --sim-node PATH --domain N [--domain-last M]\n"
         "                 run one case with controllers from its folder (its command.sh)\n"
         "  --help         print this and exit\n"
         "\n"
         "exit codes: 0 every case ok, 4 some cases failed (results.csv), 2 bad input,\n"
         "1 unexpected error (e.g. sbatch failed), 130 / 143 stopped by SIGINT / SIGTERM\n";
}

// the options, read into `o`; "--slurm=1" is not --slurm, as before
towsim::app::ToolCommandLine CommandLine(Options* o) {
  towsim::app::ToolCommandLine line("towsim_sweep", Usage());
  line.FlagsTakeNoValue()
      .Value("--out", &o->out)
      .Value("--workers",
             [o](const std::string& v) -> std::string {
               char* end = nullptr;
               const long n = std::strtol(v.c_str(), &end, 10);
               // at most kMaxWorkers sim_node processes (each with its pipes and files)
               if (v.empty() || *end != '\0' || n < 1 || n > kMaxWorkers) {
                 return "--workers " + v + ": must be an integer from 1 to " +
                        std::to_string(kMaxWorkers);
               }
               o->workers = static_cast<int>(n);
               return "";
             })
      .Value("--domain",
             [o](const std::string& v) -> std::string {
               char* end = nullptr;
               const long n = std::strtol(v.c_str(), &end, 10);
               if (v.empty() || *end != '\0' || n < 0 || n > towsim::app::kMaxSweepDomain) {
                 return "--domain " + v + ": must be an integer from 0 to " +
                        std::to_string(towsim::app::kMaxSweepDomain);
               }
               o->domain = static_cast<int>(n);
               return "";
             })
      .Value("--domain-last",
             [o](const std::string& v) -> std::string {
               char* end = nullptr;
               const long n = std::strtol(v.c_str(), &end, 10);
               if (v.empty() || *end != '\0' || n < 0 || n > towsim::app::kMaxSweepDomain) {
                 return "--domain-last " + v + ": must be an integer from 0 to " +
                        std::to_string(towsim::app::kMaxSweepDomain);
               }
               o->domain_last = static_cast<int>(n);
               return "";
             })
      .Value("--run-case", &o->run_case)
      .Value("--sim-node", &o->sim_node)
      .Flag("--slurm", &o->slurm)
      .Flag("--resume", &o->resume)
      .Flag("--no-wait", &o->no_wait)
      .Flag("--collect", &o->collect)
      .Others([o](const towsim::app::ToolFlags& flags) -> std::string {
        const std::string& arg = flags.raw();
        if (arg.rfind("-", 0) == 0) return "unknown option " + arg;
        if (!o->file.empty()) return "one sweep file only (" + o->file + ", then " + arg + ")";
        o->file = arg;
        return "";
      })
      .Require([o]() -> std::string {
        if (o->run_case.empty()) return "";
        if (!o->file.empty() || !o->out.empty() || o->slurm || o->resume || o->collect) {
          return "--run-case runs one case of a sweep folder: no FILE, --out, --slurm, "
                 "--resume or --collect";
        }
        if (o->sim_node.empty() || o->domain < 0) {
          return "--run-case needs --sim-node PATH and --domain N";
        }
        return o->domain_last < o->domain ? "--domain-last must be >= --domain" : "";
      })
      .Require([o]() -> std::string {
        return o->file.empty() && o->run_case.empty() ? "the sweep file FILE is required" : "";
      })
      .Require([o]() -> std::string {
        return o->out.empty() && o->run_case.empty() ? "--out DIR is required" : "";
      })
      .Require(
          [o]() -> std::string { return o->no_wait && !o->slurm ? "--no-wait needs --slurm" : ""; })
      .Require([o]() -> std::string {
        return o->collect && (o->slurm || o->resume)
                   ? "--collect runs nothing: not with --slurm or --resume"
                   : "";
      });
  return line;
}

// this executable's folder and path
fs::path SelfPath() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : self;
}

// one case of a sweep with controllers, from its folder (its command.sh runs this): exits
// with the case's exit code, 128 + signal if stopped
int RunOneCase(const Options& o) {
  towsim::app::LocalCase c;
  c.dir = fs::absolute(o.run_case).lexically_normal().string();
  const std::string args = towsim::app::ReadTextFile(c.dir + "/case_args.txt");
  if (args.empty()) {
    std::fprintf(stderr, "towsim_sweep: error: --run-case %s: no case_args.txt\n", c.dir.c_str());
    return kExitBadInput;
  }
  for (size_t at = 0; at < args.size();) {
    const size_t end = args.find('\n', at);
    c.arguments.push_back(args.substr(at, end - at));
    at = end == std::string::npos ? args.size() : end + 1;
  }
  c.controllers =
      towsim::app::ParseControllersText(towsim::app::ReadTextFile(c.dir + "/controllers.txt"));
  c.domain_first = o.domain;
  c.domain_last = o.domain_last;
  std::FILE* quiet = std::fopen("/dev/null", "w");
  int code = 0;
  {
    towsim::app::SweepProgress progress(1, 0, quiet != nullptr ? quiet : stderr);
    towsim::app::InstallStopHandlers();
    code = towsim::app::RunLocal(
        o.sim_node, {c}, 1, [](size_t) { return true; }, &progress);
  }
  if (quiet != nullptr) std::fclose(quiet);
  if (code != 0) return code;
  const std::optional<towsim::app::CaseStatus> status = towsim::app::ReadCaseStatus(c.dir);
  if (!status) return kExitError;
  if (!status->message.empty()) std::fprintf(stderr, "towsim_sweep: %s\n", status->message.c_str());
  return status->exit_code;
}

// sim_node: TOWSIM_SIM_NODE, else beside this executable, else on the PATH
std::string FindSimNode() {
  if (const char* env = std::getenv("TOWSIM_SIM_NODE"); env != nullptr && *env != '\0') {
    return env;
  }
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = self.parent_path() / "sim_node";
    if (fs::exists(beside)) return beside.string();
  }
  if (const char* path = std::getenv("PATH")) {
    std::string dirs = path;
    size_t begin = 0;
    while (begin <= dirs.size()) {
      const size_t end = std::min(dirs.find(':', begin), dirs.size());
      const fs::path candidate = fs::path(dirs.substr(begin, end - begin)) / "sim_node";
      if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
      begin = end + 1;
    }
  }
  return {};
}

int Run(const Options& o) {
  if (!o.run_case.empty()) return RunOneCase(o);
  // the sweep file, its scene, its results (exit 2 for any rule broken)
  towsim::app::SweepSpec spec;
  std::vector<towsim::app::SweepCase> cases;
  std::vector<std::string> programs;  // the controllers', found
  try {
    spec = towsim::app::LoadSweepFile(o.file);
    const towsim::core::Model model = towsim::scene::LoadScene(spec.scene);
    std::vector<std::string> bodies;
    for (const auto& s : model.spheres) bodies.push_back(s.name);
    for (const auto& v : model.vehicles) bodies.push_back(v.name);
    std::vector<std::string> cables;  // Model::cables order: the one cable is "cable"
    for (const auto& c : model.cables) cables.push_back(c.name);
    towsim::app::CheckSweepResults(&spec.results, bodies, cables);
    cases = towsim::app::CombineParameters(spec.parameters, spec.combine);
    for (const towsim::app::SweepController& k : spec.controllers) {
      std::string why;
      programs.push_back(towsim::app::ResolveProgram(k.program, spec.base_dir,
                                                     SelfPath().parent_path().string(), &why));
      if (programs.back().empty()) {
        throw towsim::scene::ConfigError(
            "controllers[" + std::to_string(programs.size() - 1) + "].program", k.program,
            k.location, why);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "towsim_sweep: error: %s\n", e.what());
    return kExitBadInput;
  }

  if (o.domain >= 0 && spec.controllers.empty()) {
    std::fprintf(stderr,
                 "towsim_sweep: error: --domain %d: %s has no controllers: (its cases run "
                 "offline, without DDS)\n",
                 o.domain, spec.name.c_str());
    return kExitBadInput;
  }
  if (o.domain >= 0) spec.domain = o.domain;
  // the cases' sim_node and controllers talk DDS: the loopback configuration, as they require
  const char* uri = std::getenv("CYCLONEDDS_URI");
  if (!spec.controllers.empty() && !o.collect && (uri == nullptr || *uri == '\0')) {
    std::fprintf(stderr,
                 "towsim_sweep: error: %s has controllers: and CYCLONEDDS_URI is not set: export "
                 "CYCLONEDDS_URI=file://<towsim>/config/cyclonedds.xml, or for an installed "
                 "towsim file://<prefix>/share/towsim/cyclonedds.xml (the loopback DDS "
                 "configuration every case's processes use)\n",
                 spec.name.c_str());
    return kExitBadInput;
  }
  // the cases running at once each need a domain id of their own, from `domain` to 231
  const int local_workers =
      o.workers > 0 ? o.workers
                    : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (!spec.controllers.empty() && !o.slurm && !o.collect &&
      spec.domain + local_workers - 1 > towsim::app::kMaxSweepDomain) {
    std::fprintf(stderr,
                 "towsim_sweep: error: domain = %d with %d workers: the cases running at once "
                 "each take a DDS domain id from %d up, and the highest is %d "
                 "(config/cyclonedds.xml); choose a lower domain (--domain, or domain: in %s) or "
                 "fewer --workers\n",
                 spec.domain, local_workers, spec.domain, towsim::app::kMaxSweepDomain,
                 spec.name.c_str());
    return kExitBadInput;
  }

  const fs::path out(o.out);
  const fs::path table = out / "results.csv";
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) {
    std::fprintf(stderr, "towsim_sweep: error: --out %s: cannot be created: %s\n", o.out.c_str(),
                 ec.message().c_str());
    return kExitBadInput;
  }
  // one sweep at a time in a folder, for this process's life
  const towsim::app::SweepLock lock(o.out);
  if (!lock.locked()) {
    std::fprintf(stderr, "towsim_sweep: error: %s\n", lock.error().c_str());
    return kExitBadInput;
  }
  if (!o.resume && !o.collect && (fs::exists(table) || fs::exists(out / "slurm"))) {
    std::fprintf(stderr,
                 "towsim_sweep: error: --out %s: holds an earlier sweep (results.csv); pass "
                 "--resume to continue it, --collect to tabulate it, or choose another folder\n",
                 o.out.c_str());
    return kExitBadInput;
  }
  // the folder belongs to one sweep file (by absolute path): another one would replace its table
  const std::string file_path = fs::absolute(o.file, ec).lexically_normal().string();
  const fs::path made_by = out / "sweep_file.txt";
  if (o.resume || o.collect) {
    std::string recorded = towsim::app::ReadTextFile(made_by.string());
    if (!recorded.empty() && recorded.back() == '\n') recorded.pop_back();
    if (!recorded.empty() && recorded != file_path) {
      std::fprintf(stderr,
                   "towsim_sweep: error: %s: --out %s was made by the sweep file %s, not %s; "
                   "pass that file, or choose another folder\n",
                   o.resume ? "--resume" : "--collect", o.out.c_str(), recorded.c_str(),
                   file_path.c_str());
      return kExitBadInput;
    }
  }
  if (!o.collect) towsim::app::WriteTextFileAtomically(made_by.string(), file_path + "\n");
  const std::string sim_node = FindSimNode();
  if (sim_node.empty() && !o.collect) {
    std::fprintf(stderr,
                 "towsim_sweep: error: sim_node not found (beside towsim_sweep, on the PATH, or "
                 "TOWSIM_SIM_NODE)\n");
    return kExitError;
  }

  // each case's folder, arguments and state; --resume keeps the ok cases with the same args
  towsim::app::CaseRunner runner;
  runner.sweep = SelfPath().string();
  runner.sim_node = sim_node;
  runner.domain_first = spec.domain;
  runner.domain_last = towsim::app::kMaxSweepDomain;
  std::vector<std::string> dirs;
  std::vector<std::vector<std::string>> arguments;
  std::vector<std::vector<towsim::app::CaseController>> controllers;
  std::vector<std::optional<towsim::app::SweepRow>> rows(cases.size());
  std::vector<size_t> todo;
  int already = 0;
  for (const towsim::app::SweepCase& c : cases) {
    dirs.push_back((out / c.name).string());
    arguments.push_back(towsim::app::CaseArguments(spec, c, dirs.back()));
    controllers.push_back(towsim::app::CaseControllers(spec, c, dirs.back(), programs));
    const bool same = towsim::app::SameArguments(dirs.back(), arguments.back(), controllers.back());
    if (o.resume || o.collect) {
      if (same) rows[c.index] = towsim::app::CollectCase(spec, c, dirs.back());
      if (o.collect) continue;
      if (rows[c.index] && rows[c.index]->ok) {
        ++already;
        continue;
      }
      rows[c.index].reset();
    }
    towsim::app::PrepareCase(dirs.back(), runner, arguments.back(), controllers.back());
    todo.push_back(static_cast<size_t>(c.index));
  }
  towsim::app::WriteResultsTable(table.string(), spec, rows);
  towsim::app::WriteTextFileAtomically((out / "columns.json").string(),
                                       towsim::app::ColumnsJson(spec));

  // run: each finished case goes into the table at once
  const Clock::time_point start = Clock::now();
  auto on_finished = [&](size_t index) {
    rows[index] = towsim::app::CollectCase(spec, cases[index], dirs[index]);
    towsim::app::WriteResultsTable(table.string(), spec, rows);
    return rows[index] && rows[index]->ok;
  };
  towsim::app::SweepProgress progress(static_cast<int>(cases.size()), already);
  towsim::app::InstallStopHandlers();
  int code = 0;
  towsim::app::SweepTiming timing;
  timing.slurm = o.slurm;
  if (o.collect || todo.empty()) {
    // nothing to run
  } else if (o.slurm) {
    towsim::app::SlurmRun run;
    run.out_dir = o.out;
    run.case_dirs = dirs;
    run.todo = todo;
    run.max_parallel = o.workers;
    run.wait = !o.no_wait;
    timing.workers = o.workers;
    code = towsim::app::RunOnSlurm(run, on_finished, &progress);
    if (code == 1) return kExitError;
    if (o.no_wait) {
      std::printf(
          "towsim_sweep: %zu cases submitted; when the job has ended: towsim_sweep %s "
          "--out %s --collect\n",
          todo.size(), o.file.c_str(), o.out.c_str());
      return kExitOk;
    }
  } else {
    const int workers = local_workers;
    timing.workers = workers;
    std::vector<towsim::app::LocalCase> local;
    for (size_t i : todo) {
      local.push_back(
          {dirs[i], arguments[i], controllers[i], runner.domain_first, runner.domain_last});
    }
    code = towsim::app::RunLocal(
        sim_node, local, workers, [&](size_t k) { return on_finished(todo[k]); }, &progress);
  }
  timing.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  for (size_t i : todo) timing.ran += rows[i] ? 1 : 0;

  // the table (complete), the summary, the plot
  towsim::app::WriteResultsTable(table.string(), spec, rows);
  const std::string summary = towsim::app::SweepSummary(spec, cases, rows, timing);
  towsim::app::WriteTextFileAtomically((out / "summary.txt").string(), summary);
  towsim::app::WriteTextFileAtomically((out / "results.svg").string(),
                                       towsim::app::SweepPlotSvg(spec, rows));
  std::fputs(summary.c_str(), stdout);
  std::fflush(stdout);
  if (code != 0) return code;  // stopped by a signal
  for (const auto& row : rows) {
    if (!row || !row->ok) return kExitIncomplete;
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const std::optional<int> exit = CommandLine(&options).Read(argc, argv)) return *exit;
  try {
    return Run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "towsim_sweep: error: %s\n", e.what());
    return kExitError;
  }
}
