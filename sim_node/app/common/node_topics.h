#pragma once
// The node's per-step state topics in one table (docs/contract.md §3, docs/frames.md, docs/app_layer.md):
// one row per topic with its wire row (wire/topic_table.h: name, type, QoS, direction), its rate
// key (core/publish_rates.h) and the translator that fills its message from the simulation. The
// node's state writers (app/node/dds_publisher.h) with their recording and Foxglove channels read
// this table; the tools that subscribe to a node by name (towsim_record, towsim_foxglove:
// NodeTopics) read the wire's. A new state topic is one row there, one row here, its rate key
// and its translator.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/publish_rates.h"
#include "core/simulation.h"
#include "dds/actuator_state_translator.h"
#include "dds/entities.h"
#include "dds/qos.h"
#include "wire/topic_table.h"

namespace towsim::app {

// one per-step state topic of a running node: its writer and the message its translator fills
class StateTopic {
 public:
  StateTopic(const dds::Participant& participant, const dds_topic_descriptor_t* type,
             const std::string& name, const dds::Qos& qos, core::PublishRate rate);
  virtual ~StateTopic() = default;
  StateTopic(const StateTopic&) = delete;
  StateTopic& operator=(const StateTopic&) = delete;

  // fills the message from `sim` after `step` steps; returns it (the C struct of type())
  virtual const void* Fill(const core::Simulation& sim, uint64_t step) = 0;
  // a sensor with errors (docs/sensors.md "Sensor models") is stepped at every step, whether
  // anyone listens or not, so that its errors do not depend on the subscribers: Sample is
  // called once per step instead of Fill (again for the same step: the same answer), `due`
  // whether the topic's publish stride divides the step; returns the message to publish, or
  // nullptr when the sensor publishes nothing at this step
  virtual bool sampled() const { return false; }
  virtual const void* Sample(const core::Simulation&, uint64_t, bool) { return nullptr; }

  core::PublishRate rate() const { return rate_; }
  const dds_topic_descriptor_t* type() const { return type_; }
  dds::Writer<void>& writer() { return writer_; }
  const dds::Writer<void>& writer() const { return writer_; }

 private:
  const dds_topic_descriptor_t* type_;
  core::PublishRate rate_;
  dds::Topic topic_;
  dds::Writer<void> writer_;
};

// what the node knows of its vehicles beyond the simulation, by vehicle (Model::vehicles
// order): whether it takes commands (has a command topic), and the failsafe flag and source
// of the command it holds (the command arbiter's, kept by app/node/dds_node.cc)
struct VehicleCommands {
  std::vector<bool> commanded;
  std::vector<dds::ActuatorFlags> flags;
};

struct TopicRow {
  wire::Topic topic;  // its name, type and QoS: wire/topic_table.h
  core::PublishRate rate;
  // its writer with its translator (owner: the body index of a per-body row, the cable index
  // (Model::cables order) of a per-cable row, else -1); nullptr where the scene has no such
  // topic (the environment of a calm scene, the actuator state of a vehicle without
  // commands). `vehicles` outlives the topic; its flags are read at every Fill.
  std::unique_ptr<StateTopic> (*make)(const dds::Participant& participant, const TopicRow& row,
                                      const std::string& name, const core::Simulation& sim,
                                      int owner, const VehicleCommands& vehicles);
  const wire::TopicSpec& spec() const { return wire::SpecOf(topic); }
  bool per_body() const { return spec().scope == wire::Scope::kBody; }
  bool per_cable() const { return spec().scope == wire::Scope::kCable; }
};

// every per-step state topic of a node: those of the node (per-cable rows once per cable),
// then those of each body
const std::vector<TopicRow>& NodeTopicTable();

}  // namespace towsim::app
