// The ROS 2 graph (docs/ros2_graph.md) as processes over loopback: sim_node (lockstep, waiting
// for a controller) and the manoeuvre runner (controllers/common), and this test as a third
// DDS participant that reads `ros_discovery_info` back and checks it against what DDS
// discovery itself says: the built-in topics DCPSParticipant (USER_DATA "enclave=/;"),
// DCPSPublication and DCPSSubscription (every endpoint's GUID, its participant and its topic).
// Reference: rmw_cyclonedds (ROS 2 Jazzy) lists a node's endpoints by their 16-byte DDS GUIDs;
// `ros2 node info` joins them with the discovered endpoints exactly as this test does.

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "dds/dds.h"
#include "rmw_dds_common.h"
#include "testing/process.h"

namespace towsim::testing {
namespace {

using Clock = std::chrono::steady_clock;
using Gid = std::vector<uint8_t>;

const std::string kSource = TOWSIM_SOURCE_DIR;
constexpr double kDiscoveryTimeout = 20.0;  // [s] until both nodes and their endpoints are seen
constexpr double kStopTimeout = 10.0;       // [s] for a process to end after SIGTERM

Gid FromGuid(const dds_guid_t& g) { return Gid(g.v, g.v + sizeof g.v); }
Gid FromMsg(const rmw_dds_common_msg_dds__Gid_& g) { return Gid(g.data, g.data + 16); }

struct NodeEntry {
  Gid participant;
  std::string ns, name;
  std::vector<Gid> readers, writers;
};

struct Endpoint {
  Gid participant;
  std::string topic, type;
};

// this test's participant: ros_discovery_info and the DDS built-in topics
class GraphObserver {
 public:
  explicit GraphObserver(int domain) {
    participant_ = dds_create_participant(static_cast<dds_domainid_t>(domain), nullptr, nullptr);
    EXPECT_GT(participant_, 0) << dds_strretcode(participant_);
    const dds_entity_t topic =
        dds_create_topic(participant_, &rmw_dds_common_msg_dds__ParticipantEntitiesInfo__desc,
                         "ros_discovery_info", nullptr, nullptr);
    dds_qos_t* qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
    dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);  // keyless: one instance for every writer
    const dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
    dds_qset_data_representation(qos, 1, &xcdr1);
    info_reader_ = dds_create_reader(participant_, topic, qos, nullptr);
    dds_delete_qos(qos);
    EXPECT_GT(info_reader_, 0);
    participants_ =
        dds_create_reader(participant_, DDS_BUILTIN_TOPIC_DCPSPARTICIPANT, nullptr, nullptr);
    publications_ =
        dds_create_reader(participant_, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, nullptr, nullptr);
    subscriptions_ =
        dds_create_reader(participant_, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr);
  }
  ~GraphObserver() { dds_delete(participant_); }

  void Poll() {
    void* samples[16];
    dds_sample_info_t infos[16];
    for (;;) {
      std::memset(samples, 0, sizeof samples);
      const dds_return_t n = dds_take(info_reader_, samples, infos, 16, 16);
      if (n <= 0) break;
      for (int i = 0; i < n; ++i) {
        if (!infos[i].valid_data) continue;
        const auto* m =
            static_cast<const rmw_dds_common_msg_dds__ParticipantEntitiesInfo_*>(samples[i]);
        for (uint32_t k = 0; k < m->node_entities_info_seq._length; ++k) {
          const auto& e = m->node_entities_info_seq._buffer[k];
          NodeEntry entry{FromMsg(m->gid), e.node_namespace, e.node_name, {}, {}};
          for (uint32_t j = 0; j < e.reader_gid_seq._length; ++j)
            entry.readers.push_back(FromMsg(e.reader_gid_seq._buffer[j]));
          for (uint32_t j = 0; j < e.writer_gid_seq._length; ++j)
            entry.writers.push_back(FromMsg(e.writer_gid_seq._buffer[j]));
          nodes_[entry.ns + "/" + entry.name] = entry;
        }
      }
      dds_return_loan(info_reader_, samples, n);
    }
    for (;;) {
      std::memset(samples, 0, sizeof samples);
      const dds_return_t n = dds_read(participants_, samples, infos, 16, 16);
      if (n <= 0) break;
      for (int i = 0; i < n; ++i) {
        if (!infos[i].valid_data) continue;
        const auto* p = static_cast<const dds_builtintopic_participant_t*>(samples[i]);
        void* data = nullptr;
        size_t size = 0;
        std::string user_data;
        if (dds_qget_userdata(p->qos, &data, &size) && data != nullptr) {
          user_data.assign(static_cast<const char*>(data), size);
          dds_free(data);
        }
        user_data_[FromGuid(p->key)] = user_data;
      }
      dds_return_loan(participants_, samples, n);
      if (n < 16) break;
    }
    for (auto [reader, out] :
         {std::pair{publications_, &publications}, {subscriptions_, &subscriptions}}) {
      for (;;) {
        std::memset(samples, 0, sizeof samples);
        const dds_return_t n = dds_take(reader, samples, infos, 16, 16);
        if (n <= 0) break;
        for (int i = 0; i < n; ++i) {
          if (!infos[i].valid_data) continue;
          const auto* e = static_cast<const dds_builtintopic_endpoint_t*>(samples[i]);
          (*out)[FromGuid(e->key)] = {FromGuid(e->participant_key), e->topic_name, e->type_name};
        }
        dds_return_loan(reader, samples, n);
      }
    }
  }

  std::map<std::string, NodeEntry> nodes_;  // "<ns>/<name>"
  std::map<Gid, std::string> user_data_;    // participant GUID -> USER_DATA
  std::map<Gid, Endpoint> publications, subscriptions;

 private:
  dds_entity_t participant_ = 0, info_reader_ = 0, participants_ = 0, publications_ = 0,
               subscriptions_ = 0;
};

// every GID of `gids` is a discovered endpoint of `participant`, and every discovered endpoint
// of it but ros_discovery_info's writer is in `gids`; returns the topics (DDS names)
std::set<std::string> CheckEndpoints(const std::vector<Gid>& gids, const Gid& participant,
                                     const std::map<Gid, Endpoint>& discovered,
                                     const std::string& what) {
  std::set<std::string> topics;
  for (const Gid& g : gids) {
    const auto it = discovered.find(g);
    if (it == discovered.end()) {
      ADD_FAILURE() << what << ": a GID that no discovered endpoint has";
      continue;
    }
    EXPECT_EQ(it->second.participant, participant) << what << " " << it->second.topic;
    topics.insert(it->second.topic);
  }
  for (const auto& [g, e] : discovered) {
    if (e.participant != participant || e.topic == "ros_discovery_info") continue;
    EXPECT_TRUE(std::find(gids.begin(), gids.end(), g) != gids.end())
        << what << ": endpoint on " << e.topic << " not listed in ros_discovery_info";
  }
  return topics;
}

bool Complete(const GraphObserver& o, const std::string& key) {
  const auto it = o.nodes_.find(key);
  if (it == o.nodes_.end()) return false;
  for (const Gid& g : it->second.writers)
    if (!o.publications.count(g)) return false;
  for (const Gid& g : it->second.readers)
    if (!o.subscriptions.count(g)) return false;
  return o.user_data_.count(it->second.participant) > 0;
}

TEST(RosGraph, NodeAndControllerListTheirDiscoveredEndpoints) {
  setenv("CYCLONEDDS_URI", TOWSIM_DDS_URI, 1);
  constexpr int kDomain = 180;
  Process node({TOWSIM_SIM_NODE, "--scene", kSource + "/config/scenes/case1_forward.yaml", "--mode",
                "lockstep", "--domain", std::to_string(kDomain)},
               LogPrefix("sim_node"));
  Process runner({TOWSIM_MANEUVER_RUNNER, "--body", "tow_vehicle", "--thrust", "4165",
                  "--rudder-deg", "0", "--domain", std::to_string(kDomain)},
                 LogPrefix("maneuver_runner"));
  GraphObserver o(kDomain);
  const Clock::time_point start = Clock::now();
  while (!(Complete(o, "/towsim/sim_node") && Complete(o, "/towsim/maneuver_runner")) &&
         std::chrono::duration<double>(Clock::now() - start).count() < kDiscoveryTimeout) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    o.Poll();
  }
  ASSERT_TRUE(Complete(o, "/towsim/sim_node")) << node.err();
  ASSERT_TRUE(Complete(o, "/towsim/maneuver_runner")) << runner.err();

  const NodeEntry& sim = o.nodes_.at("/towsim/sim_node");
  EXPECT_EQ(sim.ns, "/towsim");
  EXPECT_EQ(sim.name, "sim_node");
  EXPECT_EQ(o.user_data_.at(sim.participant), "enclave=/;");
  const std::set<std::string> written =
      CheckEndpoints(sim.writers, sim.participant, o.publications, "sim_node writers");
  const std::set<std::string> expected_written = {"rt/clock",
                                                  "rt/tf",
                                                  "rt/tf_static",
                                                  "rt/towsim/status",
                                                  "rt/towsim/scene_info",
                                                  "rt/towsim/cable/state",
                                                  "rt/towsim/markers",
                                                  "rt/towsim/tow_vehicle/odom",
                                                  "rt/towsim/tow_vehicle/cable_force",
                                                  "rt/towsim/towfish/odom",
                                                  "rt/towsim/towfish/cable_force",
                                                  "rt/towsim/tow_vehicle/altitude",
                                                  "rt/towsim/tow_vehicle/pressure",
                                                  "rt/towsim/towfish/altitude",
                                                  "rt/towsim/towfish/pressure",
                                                  // both vehicles take commands
                                                  "rt/towsim/tow_vehicle/actuator_state",
                                                  "rt/towsim/towfish/actuator_state"};
  EXPECT_EQ(written, expected_written);
  const std::set<std::string> read =
      CheckEndpoints(sim.readers, sim.participant, o.subscriptions, "sim_node readers");
  // scene_info: the node watches for another node in its namespace (docs/topics.md)
  const std::set<std::string> expected_read = {"rt/towsim/scene_info", "rt/towsim/sim_control",
                                               "rt/towsim/tow_vehicle/command",
                                               "rt/towsim/towfish/command"};
  EXPECT_EQ(read, expected_read);
  // the types as ROS 2 names them on DDS
  for (const Gid& g : sim.writers) {
    const Endpoint& e = o.publications.at(g);
    if (e.topic == "rt/tf") {
      EXPECT_EQ(e.type, "tf2_msgs::msg::dds_::TFMessage_");
    } else if (e.topic == "rt/towsim/markers") {
      EXPECT_EQ(e.type, "visualization_msgs::msg::dds_::MarkerArray_");
    }
  }

  const NodeEntry& ctl = o.nodes_.at("/towsim/maneuver_runner");
  EXPECT_EQ(o.user_data_.at(ctl.participant), "enclave=/;");
  EXPECT_NE(ctl.participant, sim.participant);
  EXPECT_EQ(CheckEndpoints(ctl.writers, ctl.participant, o.publications, "runner writers"),
            std::set<std::string>{"rt/towsim/tow_vehicle/command"});
  EXPECT_EQ(CheckEndpoints(ctl.readers, ctl.participant, o.subscriptions, "runner readers"),
            (std::set<std::string>{"rt/towsim/scene_info", "rt/towsim/status",
                                   "rt/towsim/tow_vehicle/odom"}));

  runner.Signal(SIGTERM);
  node.Signal(SIGTERM);
  EXPECT_TRUE(runner.Wait(kStopTimeout));
  EXPECT_TRUE(node.Wait(kStopTimeout));
  EXPECT_EQ(node.exit_code(), 0) << node.err();
}

}  // namespace
}  // namespace towsim::testing
