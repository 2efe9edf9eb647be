// sim_node_dds: sim_node with its DDS modes (docs/contract.md §3-4, app/node/node_main.h): the program that
// sim_node becomes for --mode realtime, fast and lockstep. It runs every mode, offline too,
// and prints as sim_node.

#include <limits>
#include <vector>

#include "app/node/dds_node.h"
#include "app/node/node_main.h"

namespace {

// the command line and the scene's publishing settings -> the DDS node (app/node/dds_node.h)
int RunDdsModes(const towsim::core::Model& model, const towsim::app::Options& options,
                towsim::io::CsvWriter* csv) {
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
  dds.record_wall_time = options.record_wall_time;
  dds.allow_another_node = options.allow_another_node;
  dds.start_paused = options.paused;
  dds.wait_for_controllers = options.wait_for_controllers;
  dds.winch_script = options.winch == "script";
  if (options.lockstep_timeout) dds.lockstep_timeout = *options.lockstep_timeout;
  dds.fail_on_failsafe = options.fail_on_failsafe;
  if (csv != nullptr) {
    dds.output = [csv](const towsim::core::Simulation& s, const towsim::core::StepStatus& st,
                       long us, const std::vector<bool>& failsafe,
                       const std::vector<bool>& winch_failsafe) {
      csv->Write(s, st, us, failsafe, winch_failsafe);
    };
  }
  return towsim::app::RunDdsNode(model, dds);
}

}  // namespace

int main(int argc, char** argv) { return towsim::app::NodeMain(argc, argv, &RunDdsModes); }
