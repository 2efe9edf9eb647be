#include "app/node/node_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "app/common/dds_uri.h"
#include "app/common/stop_signal.h"
#include "dds/port_mapping.h"
#include "dds/translators.h"
#include "io/output_error.h"
#include "wire/topic_names.h"

namespace towsim::app {
namespace {

// On exit, Cyclone keeps each writer with unacknowledged samples alive for WriterLingerDuration
// (default 1 s): with a subscriber that vanished without a goodbye (killed; its lease has not
// expired), stopping would take a second per writer. The node's exit waits 10 ms per writer.
constexpr const char* kLingerConfig =
    "<Internal><WriterLingerDuration>10ms</WriterLingerDuration></Internal>";
constexpr const char* kNodeName = "sim_node";  // its ROS 2 node name (wire/ros_graph.h)

}  // namespace

int SetUpNode(const core::Model& model, const DdsNodeOptions& opt, NodeParts* parts) {
  NodeParts& n = *parts;
  const bool lockstep = opt.mode == Mode::kLockstep;
  const double h = model.time.step;
  auto bad = [](const std::string& message) {
    std::fprintf(stderr, "sim_node: error: %s\n", message.c_str());
    return kExitBadInput;
  };
  if (opt.mode == Mode::kOffline) return bad("RunDdsNode: --mode offline has no DDS");
  if (!(std::isfinite(opt.rate) && opt.rate > 0.0)) return bad("--rate must be a number > 0");
  if (const std::string e = wire::CheckNamespace(opt.ns); !e.empty()) {
    return bad("--namespace " + opt.ns + ": " + e);
  }
  if (!(opt.command_timeout > 0.0)) return bad("command_timeout must be > 0 s");
  if (!(opt.lockstep_timeout >= 0.0)) {
    return bad("--lockstep-timeout: must be a number of seconds >= 0 (0: wait forever)");
  }
  for (const core::SphereBody& b : model.spheres) {
    if (const std::string e = wire::CheckBodyName(b.name); !e.empty()) {
      return bad("body " + b.name + ": " + e + " (it names DDS topics)");
    }
  }
  for (const core::Vehicle& v : model.vehicles) {
    if (const std::string e = wire::CheckBodyName(v.name); !e.empty()) {
      return bad("body " + v.name + ": " + e + " (it names DDS topics)");
    }
  }
  for (const core::Vessel& v : model.vessels) {
    if (const std::string e = wire::CheckBodyName(v.name); !e.empty()) {
      return bad("body " + v.name + ": " + e + " (it names DDS topics)");
    }
  }

  // the vehicles that take commands, and those lockstep waits for
  std::vector<dds::CommandArbiter::Vehicle> vehicles;
  for (size_t v = 0; v < model.vehicles.size(); ++v) {
    const core::Vehicle& vehicle = model.vehicles[v];
    if (!dds::IsCommandable(vehicle.params)) continue;
    n.command_vehicles.push_back(static_cast<int>(v));
    const bool waited = opt.lockstep_bodies.empty() ||
                        std::find(opt.lockstep_bodies.begin(), opt.lockstep_bodies.end(),
                                  vehicle.name) != opt.lockstep_bodies.end();
    vehicles.push_back({vehicle.name, dds::LimitsOf(vehicle.params), lockstep && waited});
    n.has_lockstep_vehicles = n.has_lockstep_vehicles || (lockstep && waited);
  }
  // the winches (docs/winch_dds.md): one more entry each, after the vehicles, named by the
  // winch (winch w on cable w, core/model.h), waited for in lockstep like a commanded body;
  // none with --winch script (the scene's script drives them)
  n.winch_script = model.cables[0].winch.has_value() && opt.winch_script;
  for (const core::CableParams& c : model.cables) {
    if (!c.winch) continue;
    for (const auto& v : vehicles) {
      if (v.name == c.winch->name) {
        return bad("body " + v.name + ": the name is taken by the winch's topic rt/<ns>/" +
                   v.name + "/command (rename the vehicle)");
      }
    }
  }
  if (model.cables[0].winch && !opt.winch_script) {
    n.winch_entry = static_cast<int>(vehicles.size());
    for (const core::CableParams& c : model.cables) {
      if (!c.winch) continue;
      const bool waited = opt.lockstep_bodies.empty() ||
                          std::find(opt.lockstep_bodies.begin(), opt.lockstep_bodies.end(),
                                    c.winch->name) != opt.lockstep_bodies.end();
      vehicles.push_back(dds::CommandArbiter::Vehicle::Winch(*c.winch, lockstep && waited));
      ++n.num_winch_entries;
      n.has_lockstep_vehicles = n.has_lockstep_vehicles || (lockstep && waited);
    }
  }
  // the external vessels (docs/vessels.md "External vessels"): one entry each, their poses
  // waited for in lockstep like a vehicle's commands
  for (size_t v = 0; v < model.vessels.size(); ++v) {
    const core::Vessel& vessel = model.vessels[v];
    if (!vessel.external) continue;
    const bool waited = opt.lockstep_bodies.empty() ||
                        std::find(opt.lockstep_bodies.begin(), opt.lockstep_bodies.end(),
                                  vessel.name) != opt.lockstep_bodies.end();
    n.external_vessels.push_back(static_cast<int>(v));
    n.vessel_entries.push_back(static_cast<int>(vehicles.size()));
    vehicles.push_back(dds::CommandArbiter::Vehicle::Vessel(vessel.name, lockstep && waited));
    n.has_lockstep_vehicles = n.has_lockstep_vehicles || (lockstep && waited);
  }
  for (const std::string& name : opt.lockstep_bodies) {
    bool found = false;
    for (const auto& v : vehicles) found = found || v.name == name;
    if (!found) {
      return bad("lockstep body " + name +
                 ": not a vehicle of the scene that takes commands nor an external vessel" +
                 (n.winch_entry >= 0 ? " nor a winch" : "") +
                 (n.winch_script ? " (--winch script: the winches are not waited for)" : ""));
    }
  }
  n.arbiter.emplace(std::move(vehicles), opt.command_timeout);

  // the initial state (may solve statics)
  try {
    n.sim.emplace(model, [] { return StopRequested() != 0; });  // Ctrl-C in the static solve
  } catch (const core::StopRequestedError& e) {
    std::fprintf(stderr, "sim_node: %s (no DDS participant yet)\n", e.what());
    return kExitStoppedInSetup;
  } catch (const core::SolverError& e) {
    std::fprintf(stderr, "sim_node: solver failure while building the initial state: %s\n",
                 e.what());
    return kExitSolver;
  }
  if (!n.sim->initial_report().empty())
    std::fprintf(stderr, "sim_node: initial: static: %s\n", n.sim->initial_report().c_str());
  n.script.emplace(model);

  // DDS: the configuration given, else $CYCLONEDDS_URI, plus the node's exit behaviour
  std::string config = opt.dds_config;
  if (config.empty()) config = DdsUriFromEnvironment("sim_node");
  config += config.empty() ? kLingerConfig : std::string(",") + kLingerConfig;
  if (const std::string e = dds::CheckDomainPorts(opt.domain, config); !e.empty()) {
    return bad("DDS setup failed: " + e);
  }
  try {
    n.participant = std::make_unique<dds::Participant>(
        opt.domain, config, opt.security,
        opt.open_outputs ? wire::Admit::kOpenOutputs : wire::Admit::kAuthenticated);
    n.endpoints = std::make_unique<NodeEndpoints>(*n.participant, wire::TopicNames(opt.ns), *n.sim,
                                                  n.command_vehicles, n.external_vessels);
    std::vector<std::string> commanded;
    // the vehicles' names (the winch's topic carries another type)
    for (size_t i = 0; i < n.command_vehicles.size(); ++i) {
      commanded.push_back(n.arbiter->vehicle(static_cast<int>(i)).name);
    }
    n.unknown = std::make_unique<UnknownCommands>(*n.participant, opt.ns, commanded);
    // another node in this domain and namespace: refused (docs/topics.md); nothing of
    // this node is published yet
    n.peers = std::make_unique<PeerNodes>(*n.participant, wire::TopicNames(opt.ns));
    if (n.peers->WaitForAny(PeerNodes::kStartWindow, [] { return StopRequested() != 0; })) {
      const std::string where = "DDS domain " + std::to_string(opt.domain) + ", namespace " +
                                opt.ns + " (" + n.peers->Names() + ")";
      if (!opt.allow_another_node) {
        return bad("another sim_node runs on " + where +
                   ": controllers would drive both; stop it, pick another --domain or "
                   "--namespace, or pass --allow-another-node");
      }
      n.peer_note = "warning: another node runs on " + where;
      std::fprintf(stderr, "sim_node: %s\n", n.peer_note.c_str());
    }
    // every reader and writer the node has now (the readers UnknownCommands makes later for
    // commands on topics of no commandable body are not listed)
    std::vector<dds_entity_t> readers = n.endpoints->readers();
    readers.push_back(n.peers->reader());
    n.graph = std::make_unique<wire::RosGraphNode>(n.participant->get(), opt.ns, kNodeName, readers,
                                                   n.endpoints->writers());
  } catch (const wire::SecurityError& e) {
    return bad(e.what());
  } catch (const std::runtime_error& e) {  // dds::DdsError, the ROS 2 graph entry
    std::fprintf(stderr, "sim_node: error: DDS setup failed: %s\n", e.what());
    return kExitBadInput;
  }
  if (!opt.record_file.empty()) {
    try {
      n.recording = std::make_unique<McapRecording>(opt.record_file, opt.overwrite);
      n.endpoints->StartRecording(*n.participant, n.recording.get(), opt.record_wall_time);
    } catch (const io::OutputError& e) {  // created, not written: disk full
      std::fprintf(stderr, "sim_node: error: --record %s: %s\n", opt.record_file.c_str(), e.what());
      return kExitError;
    } catch (const std::exception& e) {
      return bad("--record " + opt.record_file + ": " + e.what());
    }
  }

  // after the recording: its channels are the recording's too
  if (opt.foxglove_port >= 0) {
    try {
      FoxgloveServer::Options fox;
      fox.port = static_cast<uint16_t>(opt.foxglove_port);
      fox.name = "sim_node " + opt.ns;
      fox.program = "sim_node";
      n.foxglove = std::make_unique<FoxgloveServer>(fox);
      n.endpoints->StartFoxglove(*n.participant, n.foxglove.get());
      n.foxglove->Start();
    } catch (const std::exception& e) {
      return bad("--foxglove " + std::to_string(opt.foxglove_port) + ": " + e.what());
    }
    std::printf("sim_node: Foxglove at ws://127.0.0.1:%u\n",
                static_cast<unsigned>(n.foxglove->port()));
    std::fflush(stdout);
  }

  n.strides = core::PublishStrides(opt.rates, h, model.time.output_rate);
  if (lockstep) n.strides.Set(core::PublishRate::kStatus, 1);  // lockstep: every step
  n.output_stride = core::StepsPer(model.time.output_rate, h);
  if (std::isfinite(opt.duration)) n.steps_to_run = std::max(0L, std::lround(opt.duration / h));
  return kExitOk;
}

}  // namespace towsim::app
