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
// minimum. Start-up alone: `--duration 0` (everything but the steps) and `--version` (exec,
// dynamic loading and exit only), minimum of N each. The same loop in a fresh process (this
// program run again as `startup_cost --loop-once FILE S`, which loads the scene, steps it once
// and prints the loop's CPU and wall time) tells a new process's cold caches from what
// sim_node does beside its steps: `whole - start-up - fresh loop` is sim_node's own cost per
// run outside start-up and steps. The floor of any process linked like sim_node (libstdc++,
// yaml-cpp, libm, libc): `startup_cost --noop`, which returns at once.
//
// The last line reads `whole process / in process RTF = R` (wall times; 1 = no overhead).

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

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

// the stepping loop of sim_node offline (app/node/offline_run.cc) without its output; false if a
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

// runs `argv` to its end with stderr to /dev/null and stdout to /dev/null, or into `out` when
// it is not null; false unless it exits 0
bool RunProcess(const std::vector<std::string>& argv, Cost* cost, std::string* out = nullptr) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int pipe_fds[2] = {-1, -1};
  if (out != nullptr && pipe(pipe_fds) != 0) return false;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (out != nullptr) {
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
    posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
    posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);
  } else {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  }
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto w0 = std::chrono::steady_clock::now();
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (out != nullptr) {
    close(pipe_fds[1]);
    if (spawned == 0) {
      char buffer[256];
      ssize_t n = 0;
      while ((n = read(pipe_fds[0], buffer, sizeof buffer)) > 0) out->append(buffer, n);
    }
    close(pipe_fds[0]);
  }
  if (spawned != 0) return false;
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return false;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  cost->Add(wall, Seconds(usage.ru_utime) + Seconds(usage.ru_stime));
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// `startup_cost --loop-once FILE S`: the stepping loop once in this new process; prints
// "<wall s> <cpu s>" of the loop alone
int LoopOnce(const std::string& scene, const char* duration_text) {
  char* end = nullptr;
  const double duration = std::strtod(duration_text, &end);
  if (*end != '\0' || !(duration > 0.0)) return 2;
  try {
    Cost cost;
    if (!StepInProcess(towsim::scene::LoadScene(scene), duration, &cost)) return 3;
    std::printf("%.9g %.9g\n", cost.wall, cost.cpu);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "startup_cost: error: %s\n", e.what());
    return 2;
  }
  return 0;
}

// runs `argv` (a --loop-once child) and adds the loop's own times it prints to `cost`
bool RunFreshLoop(const std::vector<std::string>& argv, Cost* cost) {
  Cost process;
  std::string out;
  if (!RunProcess(argv, &process, &out)) return false;
  double wall = 0.0, cpu = 0.0;
  if (std::sscanf(out.c_str(), "%lf %lf", &wall, &cpu) != 2) return false;
  cost->Add(wall, cpu);
  return true;
}

int Usage() {
  std::fprintf(stderr,
               "usage: startup_cost SIM_NODE [--scene FILE] [--duration S] [--repeats N]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--noop") return 0;
  if (argc == 4 && std::string(argv[1]) == "--loop-once") return LoopOnce(argv[2], argv[3]);
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
  // this program again, in a new process (/proc/self/exe: whatever argv[0] was)
  const std::vector<std::string> fresh = {"/proc/self/exe", "--loop-once", scene, duration_text};
  const std::vector<std::string> noop = {"/proc/self/exe", "--noop"};

  Cost in_process, whole, startup, loading, fresh_loop, floor;
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
    if (!RunFreshLoop(fresh, &fresh_loop) || !RunProcess(noop, &floor)) {
      std::fprintf(stderr, "startup_cost: error: startup_cost --loop-once or --noop failed\n");
      return 3;
    }
  }
  const double rtf_in = duration / in_process.wall;
  const double rtf_whole = duration / whole.wall;
  std::printf("scene %s, %g s, %ld steps, %d pairs (minimum of each)\n", scene.c_str(), duration,
              std::lround(duration / model.time.step), repeats);
  std::printf("in process (stepping loop):       RTF %.0f (wall %.1f ms; CPU %.1f ms, RTF %.0f)\n",
              rtf_in, 1e3 * in_process.wall, 1e3 * in_process.cpu, duration / in_process.cpu);
  std::printf("whole process (sim_node):         RTF %.0f (wall %.1f ms; CPU %.1f ms, RTF %.0f)\n",
              rtf_whole, 1e3 * whole.wall, 1e3 * whole.cpu, duration / whole.cpu);
  std::printf("start-up (--duration 0):          wall %.2f ms, CPU %.2f ms\n", 1e3 * startup.wall,
              1e3 * startup.cpu);
  std::printf("exec and loading (--version):     wall %.2f ms, CPU %.2f ms\n", 1e3 * loading.wall,
              1e3 * loading.cpu);
  std::printf("no work, same libraries (--noop): wall %.2f ms, CPU %.2f ms\n", 1e3 * floor.wall,
              1e3 * floor.cpu);
  std::printf(
      "the loop in a fresh process:      wall %.1f ms, CPU %.1f ms (%+.1f %% against in "
      "process)\n",
      1e3 * fresh_loop.wall, 1e3 * fresh_loop.cpu, 100.0 * (fresh_loop.cpu / in_process.cpu - 1.0));
  // what sim_node costs beside its start-up and the loop a fresh process runs as fast
  std::printf("CPU: whole - start-up - fresh loop = %.2f ms (%+.1f %% of in process)\n",
              1e3 * (whole.cpu - startup.cpu - fresh_loop.cpu),
              100.0 * (whole.cpu - startup.cpu - fresh_loop.cpu) / in_process.cpu);
  // the ratio if reading the scene and building the initial state cost nothing
  std::printf("CPU: in process / (in process + exec and loading) = %.3f\n",
              in_process.cpu / (in_process.cpu + loading.cpu));
  std::printf("CPU: whole process / in process RTF = %.3f\n", in_process.cpu / whole.cpu);
  std::printf("whole process / in process RTF = %.3f\n", rtf_whole / rtf_in);
  return 0;
}
