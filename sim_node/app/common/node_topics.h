#pragma once
// The node's topics in one table (DESIGN §3, docs/frames.md): one row per topic with its name,
// type, QoS, direction, rate key (core/publish_rates.h) and, for the per-step state topics,
// the translator that fills its message from the simulation. The node's endpoints
// (app/node/dds_publisher.h), its recording and Foxglove channels, and the tools that subscribe
// to a node by name (towsim_record, towsim_foxglove: NodeTopics) all read this table, so a new
// state topic is one row here, its rate key and its translator.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/publish_rates.h"
#include "core/simulation.h"
#include "dds/entities.h"
#include "dds/qos.h"
#include "dds/topic_names.h"

namespace towsim::app {

// the QoS of a topic (dds/qos.h)
enum class TopicQos { kState, kLatched, kCommand, kControl };
dds::Qos QosOf(TopicQos qos);

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

struct TopicRow {
  bool per_body;  // one topic per body (name(names, body))
  std::string (*name)(const dds::TopicNames& names, const std::string& body);
  const dds_topic_descriptor_t* type;
  TopicQos qos;
  bool outbound;  // the node writes it (else: the node reads it)
  // the per-step state topics: their rate key and their writer with its translator (body: the
  // body index for per-body rows, else -1); the others (scene_info, status, sim_control,
  // commands, /tf_static) are written or read by the node's run itself. `make` returns
  // nullptr where the scene has no such topic (the environment of a calm scene)
  std::optional<core::PublishRate> rate = std::nullopt;
  std::unique_ptr<StateTopic> (*make)(const dds::Participant& participant, const TopicRow& row,
                                      const std::string& name, const core::Simulation& sim,
                                      int body) = nullptr;
  bool transient_local() const { return qos == TopicQos::kLatched; }
};

// every topic of a node, scene_info first, then the topics of the node, then those of each
// body
const std::vector<TopicRow>& NodeTopicTable();

}  // namespace towsim::app
