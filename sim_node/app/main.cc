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
#include "app/offline_run.h"
#include "app/stop_signal.h"
#include "core/model.h"
#include "io/csv_writer.h"
#include "scene/scene_loader.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;  // unexpected (e.g. a CSV write failed: disk full)
constexpr int kExitBadInput = 2;

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
  try {
    model = towsim::scene::LoadScene(options.scene, options.overrides);
  } catch (const std::exception& e) {  // scene::ConfigError: what() is the full message
    std::fprintf(stderr, "sim_node: error: %s\n", e.what());
    return kExitBadInput;
  }
  if (model.name.empty()) model.name = std::filesystem::path(options.scene).stem().string();
  const double duration = options.duration.value_or(model.time.duration);
  model.time.duration = duration;

  std::unique_ptr<towsim::io::CsvWriter> csv;
  if (!options.csv_dir.empty()) {
    try {
      csv = std::make_unique<towsim::io::CsvWriter>(options.csv_dir);
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
    const towsim::core::Publishing& pub = model.publishing;
    dds.rates = {pub.clock, pub.odom, pub.cable_force, pub.status, pub.cable_state, pub.markers};
    dds.command_timeout = pub.command_timeout;
    dds.record_file = options.record_file;
    dds.foxglove_port = options.foxglove_port.value_or(-1);
    dds.start_paused = options.paused;
    dds.wait_for_controllers = options.wait_for_controllers;
    if (csv) {
      dds.output = [&](const towsim::core::Simulation& s, const towsim::core::StepStatus& st,
                       long us) { csv->Write(s, st, us); };
    }
    const int code = towsim::app::RunDdsNode(model, dds);
    if (csv) csv->Close();
    return code;
  }
  const int code = towsim::app::RunOffline(model, duration, csv.get());
  if (csv) csv->Close();
  return code;
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
