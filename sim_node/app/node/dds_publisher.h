#pragma once
// The DDS endpoints of the node (docs/contract.md §3): the writers of the per-step state topics of
// app/common/node_topics.h (odometry, cable force, altitude and pressure of each body, actuator
// state of each vehicle that takes commands; cable state,
// /tf, markers, /clock), of status, scene info and /tf_static (docs/frames.md); readers of the
// vehicles' commands and of sim_control. A message is built and serialized only when its
// writer has a matched reader (or a recording or a Foxglove client takes it); scene info and
// /tf_static (transient local) are always written.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/common/mcap_recording.h"
#include "app/common/node_topics.h"
#include "app/foxglove/foxglove_commands.h"
#include "app/foxglove/foxglove_server.h"
#include "core/publish_rates.h"
#include "core/simulation.h"
#include "dds/entities.h"
#include "dds/frames.h"
#include "dds/markers.h"
#include "dds/messages.h"
#include "dds/raw_cdr.h"
#include "dds/sensor_translators.h"
#include "dds/translators.h"
#include "wire/topic_names.h"

namespace towsim::app {

class NodeEndpoints {
 public:
  // topics for every body of `sim`, commands for `command_vehicles` (vehicle indices) and
  // poses for `external_vessels` (vessel indices, docs/vessels.md "External vessels"); throws
  // dds::DdsError
  NodeEndpoints(const dds::Participant& participant, const wire::TopicNames& names,
                const core::Simulation& sim, const std::vector<int>& command_vehicles,
                const std::vector<int>& external_vessels = {});

  // the state of `sim` after `step` steps: the topics whose stride divides `step` (all of
  // them when `all`); those of each body, then those of the node, /clock last
  void PublishState(const core::Simulation& sim, uint64_t step, const core::PublishStrides& strides,
                    bool all);
  // the failsafe flag and source of vehicle v's command (Model::vehicles order), for its
  // actuator_state messages from now on (docs/topics.md "Actuator state")
  void SetActuatorFlags(int vehicle, const dds::ActuatorFlags& flags) {
    vehicles_.flags[vehicle] = flags;
  }
  void PublishStatus(const dds::StatusSample& sample);
  void PublishSceneInfo(const dds::SceneInfoSample& sample);
  // from now on, every message published is also written to `recording` (one channel per
  // writer), log time = the message's simulation time (sim t = 0 at log time 0 ns, the epoch
  // of its header stamps, docs/recording_formats.md) or, with `wall_time`, the wall clock of
  // its publication; publish time = the wall clock of its publication (its DDS source
  // timestamp) either way. Throws dds::DdsError (serializer probe) or std::invalid_argument (a
  // type without ROS 2 definition).
  void StartRecording(const dds::Participant& participant, McapRecording* recording,
                      bool wall_time = false);
  // from now on, every message is also served to the Foxglove clients of `server` subscribed
  // to its channel (one channel per writer, docs/foxglove.md; scene info and /tf_static
  // latched), log time = the simulation time; clients may publish commands and sim_control
  // (app/foxglove/foxglove_commands.h) through writers of `participant`. Call before
  // server->Start().
  void StartFoxglove(const dds::Participant& participant, FoxgloveServer* server);
  // no more recording (it failed: the messages still go to DDS)
  void StopRecording() { recording_ = nullptr; }
  // waits up to `timeout` [s] until the readers acknowledged status and scene info (exit)
  void Flush(double timeout);

  // command reader i (the order of command_vehicles) and the sim_control reader
  dds::Reader<dds::ActuatorCommandMsg>& command_reader(int i) { return *command_readers_[i]; }
  int num_command_readers() const { return static_cast<int>(command_readers_.size()); }
  // pose reader i (the order of external_vessels: rt/<ns>/<vessel>/pose_command)
  dds::Reader<dds::OdometryMsg>& pose_reader(int i) { return *pose_readers_[i]; }
  int num_pose_readers() const { return static_cast<int>(pose_readers_.size()); }
  dds::Reader<dds::SimControlMsg>& control_reader() { return control_reader_; }
  // winch w's command reader (rt/<ns>/<winch name>/command: rt/<ns>/winch/command for the one
  // winch, docs/winch_dds.md), winch w on cable w; none when the scene has no winch
  int num_winch_readers() const { return static_cast<int>(winch_readers_.size()); }
  dds::Reader<dds::WinchCommandMsg>& winch_reader(int w) { return *winch_readers_[w]; }
  // blocks until a command or a control request is available, or `timeout` [s]
  void WaitForInput(double timeout);

  // every reader and writer of the node's topics (its ROS 2 graph entry, wire/ros_graph.h)
  std::vector<dds_entity_t> readers() const;
  std::vector<dds_entity_t> writers() const;

 private:
  // the recording side of one writer
  struct Recorded {
    const dds::RawType* type = nullptr;
    std::uint16_t channel = 0;
    std::uint32_t fox = 0;  // Foxglove channel; 0: none
  };
  bool Served(const Recorded& recorded) const {
    return fox_ != nullptr && recorded.fox != 0 && fox_->HasSubscribers(recorded.fox);
  }
  template <class T>
  bool Wanted(const dds::Writer<T>& writer, const Recorded& recorded) const {
    return recording_ != nullptr || writer.matched() || Served(recorded);
  }
  const dds::RawType* TypeOf(const dds::Participant& participant,
                             const dds_topic_descriptor_t* descriptor);
  // publishes `msg` (the C struct of the writer's topic) on `writer` (if matched), records it
  // (if recording) and serves it (to subscribed Foxglove clients)
  template <class T>
  void Emit(dds::Writer<T>& writer, const Recorded& recorded, const void* msg);
  // writes `msg` whether matched or not (transient local topics) and records it
  template <class T>
  void EmitAlways(dds::Writer<T>& writer, const Recorded& recorded, const void* msg);
  // the log time of a message published at wall time `now` [ns]: its simulation time, or
  // `now` with --record-wall-time
  std::uint64_t RecordLogTime(std::int64_t now) const {
    return record_wall_time_ ? static_cast<std::uint64_t>(now) : sim_ns_;
  }
  Recorded AddRecorded(const dds::Participant& participant, const std::string& topic,
                       const dds_topic_descriptor_t* descriptor, bool transient_local);

  // a per-step state topic (app/common/node_topics.h) and its recording side
  struct Published {
    std::unique_ptr<StateTopic> topic;
    Recorded recorded;
  };

  dds::Topic status_topic_, scene_topic_, control_topic_, tf_static_topic_;
  dds::Writer<dds::SimStatusMsg> status_;
  dds::Writer<dds::SceneInfoMsg> scene_;
  dds::Writer<dds::TfMsg> tf_static_;
  // the vehicles' commands (app/common/node_topics.h): read by the actuator_state topics
  VehicleCommands vehicles_;
  std::vector<Published> state_;  // in the order they are published
  std::vector<dds::Topic> command_topics_;
  std::vector<std::unique_ptr<dds::Reader<dds::ActuatorCommandMsg>>> command_readers_;
  std::vector<dds::Topic> pose_topics_;
  std::vector<std::unique_ptr<dds::Reader<dds::OdometryMsg>>> pose_readers_;
  dds::Reader<dds::SimControlMsg> control_reader_;
  std::vector<std::unique_ptr<dds::Topic>> winch_topics_;  // one per winch
  std::vector<std::unique_ptr<dds::Reader<dds::WinchCommandMsg>>> winch_readers_;
  dds::WaitSet waitset_;

  dds::SimStatusMessage status_msg_;
  dds::SceneInfoMessage scene_msg_;
  std::unique_ptr<dds::TransformsMessage> tf_static_msg_;

  McapRecording* recording_ = nullptr;
  bool record_wall_time_ = false;  // log time = wall clock (--record-wall-time)
  std::vector<std::unique_ptr<dds::RawType>> raw_types_;  // one per type recorded
  Recorded status_rec_, scene_rec_, tf_static_rec_;
  std::vector<std::uint8_t> buffer_;  // the bytes of the message being recorded
  FoxgloveServer* fox_ = nullptr;
  std::unique_ptr<FoxgloveCommands> fox_commands_;
  wire::TopicNames names_;
  std::vector<std::string> body_names_;
  std::uint64_t sim_ns_ = 0;  // simulation time of the messages being published [ns]
};

}  // namespace towsim::app
