#pragma once
// A sweep file (YAML, docs/sweeps.md) -> a validated SweepSpec: the base scene, the parameters
// (scene key paths, the --set paths of sim_node, each with its list of values), how they
// combine, and the results to extract from every case. Every rule broken throws ConfigError
// in the scene's style, e.g.
//   parameters.cable.lenght = [150, 200] (sweep.yaml:7): the scene: unknown key; did you
//   mean length? ...
// A parameter's key path is checked against the scene file as sim_node's --set checks it; its
// values are checked by sim_node when a case runs (a bad value is a failed case, not a bad
// sweep file).

#include <optional>
#include <string>
#include <vector>

namespace towsim::app {

// one parameter: a scene key path and its values, each a YAML value in flow style ("200",
// "[3, 0, 0]", "trapezoidal") as it is passed to sim_node (--set path=value) and written to
// results.csv
struct SweepParameter {
  std::string path;
  std::vector<std::string> values;
  std::string location;  // "sweep.yaml:7", for messages
  // a plain name (no dot) that the controllers' arguments name as ${path}: it goes to the
  // controllers only, never to sim_node (--set); every other parameter is a scene key path
  bool controllers_only = false;
};

// `settled` of a result (docs/sweeps.md "Settled"): the signal's change over the final
// `window` seconds of the result's rows, max - min, must be below `tolerance` (the signal's
// unit); results.csv gains the column <name>.settled (1 or 0)
struct SweepSettled {
  double window = 0.0;     // [s], > 0
  double tolerance = 0.0;  // > 0
};

// a controller process beside every case's sim_node (docs/sweeps.md "Controllers")
struct SweepController {
  std::string name;               // its logs <case>/<name>.out, .err; default the program's name
  std::string program;            // as written: a path (relative to the sweep file) or a name
  std::vector<std::string> args;  // ${parameter}, ${domain}, ${case}, ${case_dir} substituted
  std::string location;           // "sweep.yaml:12"
};

// the DDS domain ids of controller cases: from the sweep's `domain` up to this one, the
// highest with config/cyclonedds.xml (docs/command_line.md, --domain)
inline constexpr int kMaxSweepDomain = 231;
inline constexpr int kDefaultSweepDomain = 100;

enum class SweepCombine {
  kProduct,  // every combination; the first parameter varies slowest
  kZip,      // the i-th values of every parameter together; lists of equal length
};

// one requested result: a statistic of a named signal of a case (docs/sweeps.md lists them);
// the signal and statistic names are checked against the scene by the sweep tool
struct SweepResult {
  std::string name;    // its column in results.csv
  std::string signal;  // e.g. towfish.z, layback, top_tension, newton_iterations
  std::string stat;    // final, initial, min, max, max_abs, mean, rms, std; empty if not given
  std::optional<double> from, to;  // time window [s]; all the run if absent
  std::optional<SweepSettled> settled;
  std::string location;  // "sweep.yaml:12"
  // a cable signal's cable (CheckSweepResults: its qualifier, `main` of main.top_tension, or
  // the scene's first cable), whose <cable>.csv it reads; empty: "cable" (cable.csv)
  std::string cable;
};

struct SweepSpec {
  std::string name;                // the sweep file's name for messages (basename)
  std::string scene;               // the scene file, resolved against the sweep file's folder
  std::optional<double> duration;  // sim_node --duration of every case [s]
  SweepCombine combine = SweepCombine::kProduct;
  std::vector<SweepParameter> parameters;  // file order; at least one
  std::vector<SweepResult> results;        // file order
  // with controllers: every case runs sim_node --mode lockstep on a DDS domain of its own
  // (the first free id from `domain` up to kMaxSweepDomain) beside these processes
  std::vector<SweepController> controllers;
  int domain = kDefaultSweepDomain;
  std::string domain_location;             // where `domain` was given (empty: the default)
  std::optional<double> lockstep_timeout;  // sim_node --lockstep-timeout [s]
  std::string base_dir;                    // the sweep file's folder (relative programs)
};

// the statistics a result may ask for, in documentation order
const std::vector<std::string>& SweepStats();

// Loads and checks the sweep file at `path`; its `scene:` resolves against the file's folder.
// Throws ConfigError.
SweepSpec LoadSweepFile(const std::string& path);

// The same from text (tests): `name_for_messages` stands in for the file name, the scene path
// resolves against `base_dir`. Throws ConfigError.
SweepSpec LoadSweepFromString(const std::string& yaml, const std::string& name_for_messages,
                              const std::string& base_dir);

}  // namespace towsim::app
