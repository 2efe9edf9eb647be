#pragma once
// Other nodes in this node's domain and namespace (docs/topics.md): a reader of
// <ns>/scene_info (transient local, so a node that started earlier is seen at once) that
// ignores this participant's own writer. Every other writer of scene_info is another sim_node
// (or a replay of one) whose controllers and status would mix with this node's. sim_node
// waits kStartWindow for one at start and refuses to run (exit 2, naming its run id) unless
// --allow-another-node; one that appears later is reported in the status and the summary.

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dds/entities.h"
#include "dds/messages.h"
#include "wire/topic_names.h"

namespace towsim::app {

class PeerNodes {
 public:
  // wall time given at start to discover a node that runs already [s]
  static constexpr double kStartWindow = 0.3;

  PeerNodes(const dds::Participant& participant, const wire::TopicNames& names);

  // takes what arrived; true if a node not seen before is among it
  bool Poll();
  // waits up to `timeout` [s] (in slices, returning early on `stop()`) for another node;
  // true if one was seen
  template <class Stop>
  bool WaitForAny(double timeout, Stop stop) {
    constexpr double kSlice = 0.02;  // [s]
    for (double waited = 0.0; waited < timeout && !stop(); waited += kSlice) {
      if (Poll() || !run_ids_.empty()) return true;
      waitset_.Wait(static_cast<int64_t>(kSlice * 1e9));
    }
    return Poll() || !run_ids_.empty();
  }
  // the run ids of the other nodes seen (the latest of each writer), in order of discovery
  std::vector<std::string> run_ids() const;
  // "run id a, run id b" for messages
  std::string Names() const;
  // the scene_info reader (listed in the node's ROS 2 graph entry, wire/ros_graph.h)
  dds_entity_t reader() const { return reader_.get(); }

 private:
  dds::Topic topic_;
  dds::Reader<dds::SceneInfoMsg> reader_;
  dds::WaitSet waitset_;
  std::map<dds_instance_handle_t, size_t> writer_index_;  // publication handle -> run_ids_
  std::vector<std::string> run_ids_;
};

}  // namespace towsim::app
