// sim_node: the towsim simulation node (DESIGN §4-5). Parses the command line, loads the
// scene, and runs it offline (no DDS) or as a DDS node (realtime, fast, lockstep).

#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>

#include "app/command_line.h"
#include "app/dds_node.h"
#include "app/installed_data.h"
#include "app/offline_run.h"
#include "app/stop_signal.h"
#include "core/model.h"
#include "io/csv_writer.h"
#include "io/output_error.h"
#include "scene/scene_loader.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;  // unexpected (e.g. a CSV write failed: disk full)
constexpr int kExitBadInput = 2;

std::string FormatSeconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

// closes the CSV files after a run that ended with `code`; a failure to close is an output
// failure (exit 1), told once
int CloseCsv(towsim::io::CsvWriter* csv, int code) {
  if (csv == nullptr) return code;
  try {
    csv->Close();
  } catch (const std::exception& e) {
    if (code != kExitError) std::fprintf(stderr, "sim_node: error: --csv: %s\n", e.what());
    return kExitError;
  }
  return code;
}

int Run(const towsim::app::Options& options) {
  using towsim::app::Mode;
  if (!options.record_file.empty() && options.mode == Mode::kOffline) {
    // the recording holds what the node publishes on DDS; offline publishes nothing
    std::fprintf(stderr,
                 "sim_node: error: --record %s: recording needs a DDS mode (realtime, fast or "
                 "lockstep): --mode offline publishes nothing; use --mode fast, or --csv DIR\n",
                 options.record_file.c_str());
    return kExitBadInput;
  }

  towsim::core::Model model;
  // a bare scene name also finds the scenes of an installed towsim (P/share/towsim/scenes)
  const std::string scene =
      towsim::app::ResolveScene(options.scene, towsim::app::InstalledDataDir());
  try {
    model = towsim::scene::LoadScene(scene, options.overrides);
  } catch (const std::exception& e) {  // scene::ConfigError: what() is the full message
    std::fprintf(stderr, "sim_node: error: %s\n", e.what());
    return kExitBadInput;
  }
  if (model.name.empty()) model.name = std::filesystem::path(scene).stem().string();
  const double duration = options.duration.value_or(model.time.duration);
  model.time.duration = duration;
  if (!(duration / model.time.step <= towsim::core::kMaxSteps)) {
    std::fprintf(stderr,
                 "sim_node: error: --duration %s: must be <= 1e12 steps of time.step = %g s "
                 "(%g s)\n",
                 FormatSeconds(duration).c_str(), model.time.step,
                 towsim::core::kMaxSteps * model.time.step);
    return kExitBadInput;
  }

  std::unique_ptr<towsim::io::CsvWriter> csv;
  if (!options.csv_dir.empty()) {
    try {
      csv = std::make_unique<towsim::io::CsvWriter>(options.csv_dir,
                                                    towsim::io::HasSea(model.environment));
    } catch (const towsim::io::OutputError& e) {  // opened, not written: disk full
      std::fprintf(stderr, "sim_node: error: --csv %s: %s\n", options.csv_dir.c_str(), e.what());
      return kExitError;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sim_node: error: --csv %s: %s\n", options.csv_dir.c_str(), e.what());
      return kExitBadInput;
    }
  }

  towsim::app::InstallStopHandlers();
  if (options.mode != Mode::kOffline) {
    towsim::app::DdsNodeOptions dds;
    dds.mode = options.mode;
    dds.duration = options.duration.value_or(std::numeric_limits<double>::infinity());
    dds.rate = options.rate.value_or(1.0);
    dds.domain = options.domain.value_or(0);
    dds.ns = options.ns;
    dds.security = options.security;
    dds.open_outputs = model.publishing.open_outputs;
    const towsim::core::Publishing& pub = model.publishing;
    dds.rates = pub.rates;
    dds.command_timeout = pub.command_timeout;
    dds.record_file = options.record_file;
    dds.foxglove_port = options.foxglove_port.value_or(-1);
    dds.overwrite = options.overwrite;
    dds.allow_another_node = options.allow_another_node;
    dds.start_paused = options.paused;
    dds.wait_for_controllers = options.wait_for_controllers;
    if (csv) {
      dds.output = [&](const towsim::core::Simulation& s, const towsim::core::StepStatus& st,
                       long us) { csv->Write(s, st, us); };
    }
    return CloseCsv(csv.get(), towsim::app::RunDdsNode(model, dds));
  }
  return CloseCsv(csv.get(), towsim::app::RunOffline(model, duration, csv.get()));
}

}  // namespace

int main(int argc, char** argv) {
  const towsim::app::ParseResult parsed = towsim::app::ParseCommandLine(argc, argv);
  if (!parsed.ok()) {
    std::fprintf(stderr, "sim_node: error: %s\n\n%s", parsed.error.c_str(),
                 towsim::app::Usage().c_str());
    return kExitBadInput;
  }
  if (parsed.options.help) {
    std::fputs(towsim::app::Usage().c_str(), stdout);
    return kExitOk;
  }
  if (parsed.options.version) {
    std::printf("sim_node (towsim) %s\n", TOWSIM_VERSION);
    return kExitOk;
  }
  try {
    return Run(parsed.options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sim_node: error: %s\n", e.what());
    return kExitError;
  }
}
