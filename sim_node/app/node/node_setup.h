#pragma once
// Setting up the DDS node (docs/topics.md): the options checked, the vehicles that take
// commands and those lockstep waits for, the initial state, the participant and the node's
// endpoints, the second-node check, its ROS 2 graph entry, the recording and the Foxglove
// server. What the run (app/node/dds_node.cc) then steps, controls and publishes.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/common/exit_codes.h"
#include "app/common/mcap_recording.h"
#include "app/foxglove/foxglove_server.h"
#include "app/node/dds_node.h"
#include "app/node/dds_publisher.h"
#include "app/node/peer_nodes.h"
#include "app/node/unknown_commands.h"
#include "core/model.h"
#include "core/publish_rates.h"
#include "core/script.h"
#include "core/simulation.h"
#include "dds/command_arbiter.h"
#include "dds/entities.h"
#include "wire/ros_graph.h"

namespace towsim::app {

// the exit codes are app/common/exit_codes.h's; this one never leaves the node
inline constexpr int kExitStoppedInSetup = -1;  // a signal stopped the setup (the node exits 0)

// the node's parts, in the order they are built (and destroyed in reverse)
struct NodeParts {
  std::vector<int> command_vehicles;  // vehicle index of arbiter entry i
  // the first winch's arbiter entry, after the vehicles'; winch w's is winch_entry + w
  // (num_winch_entries of them); < 0: no winch, or they follow the script
  int winch_entry = -1;
  int num_winch_entries = 0;
  bool winch_script = false;  // --winch script: the scene's winches follow its script
  // the external vessels (docs/vessels.md "External vessels"): vessel_entries[i] is the
  // arbiter entry of the vessel external_vessels[i] (index into Model::vessels), after the
  // vehicles' and the winch's entries
  std::vector<int> external_vessels;
  std::vector<int> vessel_entries;
  bool has_lockstep_vehicles = false;
  std::optional<dds::CommandArbiter> arbiter;
  std::optional<core::Simulation> sim;
  std::optional<core::ScriptRunner> script;
  std::unique_ptr<dds::Participant> participant;
  std::unique_ptr<McapRecording> recording;  // declared first: outlives the endpoints
  std::unique_ptr<NodeEndpoints> endpoints;
  std::unique_ptr<wire::RosGraphNode> graph;  // the ROS 2 node /<ns>/sim_node
  std::unique_ptr<FoxgloveServer> foxglove;   // after endpoints: stops before them
  std::unique_ptr<PeerNodes> peers;           // other nodes in the namespace
  std::unique_ptr<UnknownCommands> unknown;   // commands on topics of no commandable body
  std::string peer_note;                      // the warning about them, for the status
  core::PublishStrides strides;
  long output_stride = 1;
  long steps_to_run = -1;  // < 0: no end
};

// Builds the parts of a node of `model` with `options`. Returns kExitOk, kExitStoppedInSetup,
// or the exit code of a failure (its message on stderr): kExitBadInput (bad options, DDS setup
// failure), kExitSolver (the initial state), kExitError (the recording cannot be written).
int SetUpNode(const core::Model& model, const DdsNodeOptions& options, NodeParts* parts);

}  // namespace towsim::app
