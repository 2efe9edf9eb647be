#include "app/node/node_main.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

#include "app/common/exit_codes.h"
#include "installed/installed_data.h"
#include "app/common/stop_signal.h"
#include "app/node/dds_program.h"
#include "app/node/offline_run.h"
#include "scene/time_history_file.h"
#include "io/output_error.h"
#include "scene/scene_loader.h"

namespace towsim::app {
namespace {

std::string FormatSeconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

// closes the CSV files after a run that ended with `code`; a failure to close is an output
// failure (exit 1), told once
int CloseCsv(io::CsvWriter* csv, int code) {
  if (csv == nullptr) return code;
  try {
    csv->Close();
  } catch (const std::exception& e) {
    if (code != kExitError) std::fprintf(stderr, "sim_node: error: --csv: %s\n", e.what());
    return kExitError;
  }
  return code;
}

int Run(const Options& options, DdsModeRunner run_dds) {
  if (!options.record_file.empty() && options.mode == Mode::kOffline) {
    // the recording holds what the node publishes on DDS; offline publishes nothing
    std::fprintf(stderr,
                 "sim_node: error: --record %s: recording needs a DDS mode (realtime, fast or "
                 "lockstep): --mode offline publishes nothing; use --mode fast, or --csv DIR\n",
                 options.record_file.c_str());
    return kExitBadInput;
  }

  core::Model model;
  // a bare scene name also finds the scenes of an installed towsim (P/share/towsim/scenes)
  const std::string scene = installed::ResolveInstalled(options.scene, installed::kScenes);
  try {
    model = scene::LoadScene(scene, options.overrides);
  } catch (const std::exception& e) {  // scene::ConfigError: what() is the full message
    std::fprintf(stderr, "sim_node: error: %s\n", e.what());
    return kExitBadInput;
  }
  if (model.name.empty()) model.name = std::filesystem::path(scene).stem().string();
  for (const std::string& w : scene::SceneWarnings(model))
    std::fprintf(stderr, "sim_node: warning: %s\n", w.c_str());
  if (options.winch && !model.cables[0].winch) {
    std::fprintf(stderr, "sim_node: error: --winch %s: the scene %s has no winch (cable.winch)\n",
                 options.winch->c_str(), scene.c_str());
    return kExitBadInput;
  }
  const double duration = options.duration.value_or(model.time.duration);
  model.time.duration = duration;
  if (!(duration / model.time.step <= core::kMaxSteps)) {
    std::fprintf(stderr,
                 "sim_node: error: --duration %s: must be <= 1e12 steps of time.step = %g s "
                 "(%g s)\n",
                 FormatSeconds(duration).c_str(), model.time.step,
                 core::kMaxSteps * model.time.step);
    return kExitBadInput;
  }

  // vessels (docs/vessels.md): an external one needs a DDS mode (its pose comes from another
  // program), a time history must cover the run's duration as given on the command line too
  for (const core::Vessel& v : model.vessels) {
    if (v.external && options.mode == Mode::kOffline) {
      std::fprintf(stderr,
                   "sim_node: error: bodies.%s.external = true: an external vessel takes its pose "
                   "from another program over DDS (rt/<ns>/%s/pose_command); --mode offline has "
                   "no DDS: use --mode lockstep, or give the vessel a time_history\n",
                   v.name.c_str(), v.name.c_str());
      return kExitBadInput;
    }
    if (v.time_history && options.duration) {
      const std::string problem = scene::TimeHistoryCoverageProblem(*v.time_history, duration);
      if (!problem.empty()) {
        std::fprintf(stderr, "sim_node: error: --duration %s: bodies.%s.time_history: %s\n",
                     FormatSeconds(duration).c_str(), v.name.c_str(), problem.c_str());
        return kExitBadInput;
      }
    }
  }

  std::unique_ptr<io::CsvWriter> csv;
  if (!options.csv_dir.empty()) {
    try {
      std::vector<std::string> cables, winches;
      for (const core::CableParams& c : model.cables) {
        cables.push_back(c.name);
        if (c.winch) winches.push_back(c.winch->name);  // winch w on cable w (core/model.h)
      }
      csv = std::make_unique<io::CsvWriter>(options.csv_dir, io::HasSea(model.environment),
                                            !winches.empty(), !model.vehicles.empty(), cables,
                                            winches);
    } catch (const io::OutputError& e) {  // opened, not written: disk full
      std::fprintf(stderr, "sim_node: error: --csv %s: %s\n", options.csv_dir.c_str(), e.what());
      return kExitError;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sim_node: error: --csv %s: %s\n", options.csv_dir.c_str(), e.what());
      return kExitBadInput;
    }
  }

  InstallStopHandlers();
  if (options.mode != Mode::kOffline) {
    return CloseCsv(csv.get(), run_dds(model, options, csv.get()));
  }
  return CloseCsv(csv.get(), RunOffline(model, duration, csv.get()));
}

}  // namespace

int NodeMain(int argc, char** argv, DdsModeRunner run_dds) {
  const ParseResult parsed = ParseCommandLine(argc, argv);
  if (!parsed.ok()) {
    std::fprintf(stderr, "sim_node: error: %s\n\n%s", parsed.error.c_str(), Usage().c_str());
    return kExitBadInput;
  }
  if (parsed.options.help) {
    std::fputs(Usage().c_str(), stdout);
    return kExitOk;
  }
  if (parsed.options.version) {
    std::printf("sim_node (towsim) %s\n", TOWSIM_VERSION);
    return kExitOk;
  }
  // the DDS modes run in the DDS program, which checks and loads everything again itself
  if (parsed.options.mode != Mode::kOffline && run_dds == nullptr) {
    return ExecDdsProgram(parsed.options.mode, argv);
  }
  try {
    return Run(parsed.options, run_dds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sim_node: error: %s\n", e.what());
    return kExitError;
  }
}

}  // namespace towsim::app
