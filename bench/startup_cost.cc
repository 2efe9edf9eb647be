// The shipped binary against its benchmark (docs/benchmarks.md, "Start-up"): the real-time
// factor of `sim_node --scene S --mode offline --duration D` as a whole process (exec, dynamic
// loading, scene, initial state, stepping, progress and summary, exit) against the stepping
// loop alone, run in this process on the same scene and settings.
//
//   startup_cost SIM_NODE [--scene FILE] [--duration S] [--repeats N]
//       (defaults: config/scenes/case1_forward.yaml, its 100 s, 10 pairs; bench/run.sh startup)
//
// In process: LoadScene, Simulation and the script, then `script.Apply; Step` round(D / h)
// times; the wall time of that loop and the thread's CPU time (work_precision --targets
// measures the same loop). Whole process: posix_spawn of SIM_NODE with its output to
// /dev/null, the wall time from the spawn to wait4 and the child's CPU time (user + system,
// from wait4). The two alternate, N pairs, so both see the same load; each reports its
// minimum. Start-up alone: `--duration 0` (everything but the steps) and `--version` (exec and
// dynamic loading only), minimum of N each.
//
// The last line reads `whole process / in process RTF = R` (wall times; 1 = no overhead).

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <string>
#include <vector>

#include "core/script.h"
#include "core/simulation.h"
#include "scene/scene_loader.h"

extern char** environ;

namespace {

struct Cost {
  double wall = std::numeric_limits<double>::infinity();  // [s], min over repeats
  double cpu = std::numeric_limits<double>::infinity();   // [s], min over repeats
  void Add(double w, double c) {
    wall = std::min(wall, w);
    cpu = std::min(cpu, c);
  }
};

double ThreadCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double Seconds(const timeval& t) {
  return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

// the stepping loop of sim_node offline (app/offline_run.cc) without its output; false if a
// step failed
bool StepInProcess(const towsim::core::Model& model, double duration, Cost* cost) {
  towsim::core::Simulation sim(model);
  towsim::core::ScriptRunner script(model);
  const long steps = std::max(0L, std::lround(duration / model.time.step));
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = ThreadCpuSeconds();
  for (long k = 0; k < steps; ++k) {
    script.Apply(&sim);
    if (!sim.Step().ok()) return false;
  }
  cost->Add(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count(),
            ThreadCpuSeconds() - c0);
  return true;
}

// runs `argv` to its end with stdout and stderr to /dev/null; false unless it exits 0
bool RunProcess(const std::vector<std::string>& argv, Cost* cost) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto w0 = std::chrono::steady_clock::now();
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return false;
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return false;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  cost->Add(wall, Seconds(usage.ru_utime) + Seconds(usage.ru_stime));
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

int Usage() {
  std::fprintf(stderr,
               "usage: startup_cost SIM_NODE [--scene FILE] [--duration S] [--repeats N]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return Usage();
  const std::string sim_node = argv[1];
  std::string scene = std::string(TOWSIM_SOURCE_DIR) + "/config/scenes/case1_forward.yaml";
  double duration = -1.0;  // < 0: the scene's
  int repeats = 10;
  for (int i = 2; i < argc; i += 2) {
    if (i + 1 >= argc) return Usage();
    const std::string a = argv[i];
    const char* v = argv[i + 1];
    char* end = nullptr;
    if (a == "--scene") {
      scene = v;
    } else if (a == "--duration") {
      duration = std::strtod(v, &end);
      if (*end != '\0' || !(duration > 0.0)) {
        std::fprintf(stderr, "startup_cost: error: --duration %s: must be a number > 0\n", v);
        return 2;
      }
    } else if (a == "--repeats") {
      repeats = static_cast<int>(std::strtol(v, &end, 10));
      if (*end != '\0' || repeats < 1 || repeats > 1000) {
        std::fprintf(stderr, "startup_cost: error: --repeats %s: must be 1 to 1000\n", v);
        return 2;
      }
    } else {
      return Usage();
    }
  }
  towsim::core::Model model;
  try {
    model = towsim::scene::LoadScene(scene);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "startup_cost: error: %s\n", e.what());
    return 2;
  }
  if (duration < 0.0) duration = model.time.duration;
  char duration_text[32];
  std::snprintf(duration_text, sizeof duration_text, "%.17g", duration);
  const std::vector<std::string> run = {sim_node,  "--scene",    scene,        "--mode",
                                        "offline", "--duration", duration_text};
  const std::vector<std::string> start = {sim_node,  "--scene",    scene, "--mode",
                                          "offline", "--duration", "0"};
  const std::vector<std::string> version = {sim_node, "--version"};

  Cost in_process, whole, startup, loading;
  for (int k = 0; k < repeats; ++k) {
    if (!StepInProcess(model, duration, &in_process)) {
      std::fprintf(stderr, "startup_cost: error: a step failed in process\n");
      return 3;
    }
    if (!RunProcess(run, &whole) || !RunProcess(start, &startup) ||
        !RunProcess(version, &loading)) {
      std::fprintf(stderr, "startup_cost: error: %s did not run to exit code 0\n",
                   sim_node.c_str());
      return 3;
    }
  }
  const double rtf_in = duration / in_process.wall;
  const double rtf_whole = duration / whole.wall;
  std::printf("scene %s, %g s, %ld steps, %d pairs (minimum of each)\n", scene.c_str(), duration,
              std::lround(duration / model.time.step), repeats);
  std::printf("in process (stepping loop):     RTF %.0f (wall %.1f ms; CPU %.1f ms, RTF %.0f)\n",
              rtf_in, 1e3 * in_process.wall, 1e3 * in_process.cpu, duration / in_process.cpu);
  std::printf("whole process (sim_node):       RTF %.0f (wall %.1f ms; CPU %.1f ms, RTF %.0f)\n",
              rtf_whole, 1e3 * whole.wall, 1e3 * whole.cpu, duration / whole.cpu);
  std::printf("start-up (--duration 0):        wall %.2f ms, CPU %.2f ms\n", 1e3 * startup.wall,
              1e3 * startup.cpu);
  std::printf("exec and loading (--version):   wall %.2f ms, CPU %.2f ms\n", 1e3 * loading.wall,
              1e3 * loading.cpu);
  std::printf("CPU: whole process / in process RTF = %.3f\n", in_process.cpu / whole.cpu);
  std::printf("whole process / in process RTF = %.3f\n", rtf_whole / rtf_in);
  return 0;
}
