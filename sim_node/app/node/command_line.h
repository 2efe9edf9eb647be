#pragma once
// The sim_node command line (docs/contract.md §5):
//
//   sim_node --scene FILE [--mode realtime|fast|lockstep|offline] [--duration S] [--rate R]
//            [--set key.path=value ...] [--csv DIR] [--record FILE.mcap [--record-wall-time]]
//            [--help] [--version]
//            [--security DIR/NAME] [--lockstep-timeout S] [--fail-on-failsafe]
//
// Every option also accepts the --name=value form. Parsing only checks the syntax and the
// ranges of the values; the scene is loaded (and --set applied) by the scene layer.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace towsim::app {

enum class Mode { kRealtime, kFast, kLockstep, kOffline };

const char* ModeName(Mode mode);

struct Options {
  std::string scene;                   // --scene FILE (required unless --help / --version)
  Mode mode = Mode::kRealtime;         // --mode
  std::optional<double> duration;      // --duration S [s]; default: the scene's time.duration
  std::optional<double> rate;          // --rate R: wall-clock pacing factor (realtime mode)
  std::vector<std::string> overrides;  // --set key.path=value, in command-line order
  std::string csv_dir;                 // --csv DIR; empty: no CSV
  std::string record_file;             // --record FILE.mcap; empty: no recording
  bool record_wall_time = false;       // --record-wall-time: log time = wall clock, not sim time
  bool overwrite = false;              // --overwrite: --record may replace an existing file
  bool allow_another_node = false;     // --allow-another-node: run beside another node
  std::optional<uint32_t> domain;      // --domain N: DDS domain id (DDS modes; default 0)
  std::optional<int> foxglove_port;    // --foxglove PORT: a Foxglove server (docs/foxglove.md)
  std::string ns = "/towsim";          // --namespace NS: ROS 2 namespace of the topics
  bool paused = false;                 // --paused: start paused (SimControl RESUME / STEP)
  bool wait_for_controllers = false;   // --wait-for-controllers: first step once all commanded
  // --winch dds|script: the winch (cable.winch) commanded over DDS (default), or following the
  // scene's script, neither waited for nor failsafed (docs/winch_dds.md)
  std::optional<std::string> winch;
  std::string security;                // --security DIR/NAME: DDS Security identity (DDS modes)
  // --lockstep-timeout S: wall time a lockstep step waits for its commands [s], >= 0; 0: wait
  // forever (debugging). Lockstep only; default: DdsNodeOptions::lockstep_timeout
  std::optional<double> lockstep_timeout;
  // --fail-on-failsafe: a run in which a body entered failsafe or a lockstep step timed out
  // ends with exit code 5 (kExitFailsafe); offline has no failsafe, the option is harmless
  bool fail_on_failsafe = false;
  bool help = false;                   // --help / -h
  bool version = false;                // --version
};

struct ParseResult {
  Options options;
  std::string error;  // empty on success, else what is wrong ("unknown option '--foo'")
  bool ok() const { return error.empty(); }
};

// parses argv[1..argc-1]
ParseResult ParseCommandLine(int argc, const char* const* argv);

// the usage text printed by --help and after a command-line error
std::string Usage();

}  // namespace towsim::app
