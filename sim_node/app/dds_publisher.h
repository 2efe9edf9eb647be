#pragma once
// The DDS endpoints of the node (DESIGN §3): writers of odometry, cable force, cable state,
// /clock, status, scene info, /tf, /tf_static and the markers (docs/frames.md); readers of the
// vehicles' commands and of sim_control. A message is built and serialized only when its
// writer has a matched reader (or a recording takes it); scene info and /tf_static (transient
// local) are always written.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "app/foxglove_commands.h"
#include "app/foxglove_server.h"
#include "app/mcap_recording.h"
#include "core/simulation.h"
#include "dds/entities.h"
#include "dds/frames.h"
#include "dds/markers.h"
#include "dds/messages.h"
#include "dds/raw_cdr.h"
#include "dds/sensor_translators.h"
#include "dds/topic_names.h"
#include "dds/translators.h"

namespace towsim::app {

// publishing strides of the per-step topics [steps], >= 1
struct PublishStrides {
  long clock = 1;
  long odom = 1;
  long cable_force = 1;
  long cable_state = 1;
  long status = 1;
  long sensors = 1;
  long markers = 1;  // /tf goes with odom (the same state as the odometry)
};

class NodeEndpoints {
 public:
  // topics for every body of `sim` and commands for `command_vehicles` (vehicle indices);
  // throws dds::DdsError
  NodeEndpoints(const dds::Participant& participant, const dds::TopicNames& names,
                const core::Simulation& sim, const std::vector<int>& command_vehicles);

  // the state of `sim` after `step` steps: the topics whose stride divides `step` (all of
  // them when `all`); odometry, cable force and cable state before the clock
  void PublishState(const core::Simulation& sim, uint64_t step, const PublishStrides& strides,
                    bool all);
  void PublishStatus(const dds::StatusSample& sample);
  void PublishSceneInfo(const dds::SceneInfoSample& sample);
  // from now on, every message published is also written to `recording` (one channel per
  // writer); throws dds::DdsError (serializer probe) or std::invalid_argument (a type without
  // ROS 2 definition)
  void StartRecording(const dds::Participant& participant, McapRecording* recording);
  // from now on, every message is also served to the Foxglove clients of `server` subscribed
  // to its channel (one channel per writer, docs/foxglove.md; scene info and /tf_static
  // latched), log time = the simulation time; clients may publish commands and sim_control
  // (app/foxglove_commands.h) through writers of `participant`. Call before server->Start().
  void StartFoxglove(const dds::Participant& participant, FoxgloveServer* server);
  // no more recording (it failed: the messages still go to DDS)
  void StopRecording() { recording_ = nullptr; }
  // waits up to `timeout` [s] until the readers acknowledged status and scene info (exit)
  void Flush(double timeout);

  // command reader i (the order of command_vehicles) and the sim_control reader
  dds::Reader<dds::ActuatorCommandMsg>& command_reader(int i) { return *command_readers_[i]; }
  int num_command_readers() const { return static_cast<int>(command_readers_.size()); }
  dds::Reader<dds::SimControlMsg>& control_reader() { return control_reader_; }
  // the winch's command reader (rt/<ns>/winch/command, docs/winch_dds.md); nullptr when the
  // scene has no winch
  dds::Reader<dds::WinchCommandMsg>* winch_reader() { return winch_reader_.get(); }
  // blocks until a command or a control request is available, or `timeout` [s]
  void WaitForInput(double timeout);

  // every reader and writer of the node's topics (its ROS 2 graph entry, dds/ros_graph.h)
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
  // publishes `msg` on `writer` (if matched) and records it (if recording)
  template <class T>
  void Emit(dds::Writer<T>& writer, const Recorded& recorded, const T& msg);
  // writes `msg` whether matched or not (transient local topics) and records it
  template <class T>
  void EmitAlways(dds::Writer<T>& writer, const Recorded& recorded, const T& msg);
  Recorded AddRecorded(const dds::Participant& participant, const std::string& topic,
                       const dds_topic_descriptor_t* descriptor, bool transient_local);

  struct BodyEndpoints {
    dds::Topic odom_topic, force_topic;
    dds::Writer<dds::OdometryMsg> odom;
    dds::Writer<dds::WrenchStampedMsg> force;
    std::unique_ptr<dds::OdometryMessage> odom_msg;
    std::unique_ptr<dds::WrenchStampedMessage> force_msg;
    Recorded odom_rec, force_rec;
  };
  // a body's altimeter and pressure sensor (dds/sensor_translators.h)
  struct SensorEndpoints {
    SensorEndpoints(const dds::Participant& participant, const dds::TopicNames& names,
                    const std::string& body);
    dds::Topic altitude_topic, pressure_topic;
    dds::Writer<dds::RangeMsg> altitude;
    dds::Writer<dds::FluidPressureMsg> pressure;
    dds::RangeMessage altitude_msg;
    dds::FluidPressureMessage pressure_msg;
    Recorded altitude_rec, pressure_rec;
  };

  dds::Topic clock_topic_, cable_topic_, status_topic_, scene_topic_, control_topic_, tf_topic_,
      tf_static_topic_, markers_topic_;
  dds::Writer<dds::ClockMsg> clock_;
  dds::Writer<dds::CableStateMsg> cable_;
  dds::Writer<dds::SimStatusMsg> status_;
  dds::Writer<dds::SceneInfoMsg> scene_;
  dds::Writer<dds::TfMsg> tf_, tf_static_;
  dds::Writer<dds::MarkerArrayMsg> markers_;
  std::vector<std::unique_ptr<BodyEndpoints>> bodies_;
  std::vector<std::unique_ptr<SensorEndpoints>> sensors_;  // one per body, same order
  std::vector<dds::Topic> command_topics_;
  std::vector<std::unique_ptr<dds::Reader<dds::ActuatorCommandMsg>>> command_readers_;
  dds::Reader<dds::SimControlMsg> control_reader_;
  std::unique_ptr<dds::Topic> winch_topic_;
  std::unique_ptr<dds::Reader<dds::WinchCommandMsg>> winch_reader_;
  dds::WaitSet waitset_;

  dds::ClockMsg clock_msg_{};
  std::unique_ptr<dds::CableStateMessage> cable_msg_;
  dds::SimStatusMessage status_msg_;
  dds::SceneInfoMessage scene_msg_;
  std::unique_ptr<dds::TransformsMessage> tf_msg_, tf_static_msg_;
  std::unique_ptr<dds::SceneMarkers> markers_msg_;

  McapRecording* recording_ = nullptr;
  std::vector<std::unique_ptr<dds::RawType>> raw_types_;  // one per type recorded
  Recorded clock_rec_, cable_rec_, status_rec_, scene_rec_, tf_rec_, tf_static_rec_, markers_rec_;
  std::vector<std::uint8_t> buffer_;  // the bytes of the message being recorded
  FoxgloveServer* fox_ = nullptr;
  std::unique_ptr<FoxgloveCommands> fox_commands_;
  dds::TopicNames names_;
  std::vector<std::string> body_names_;
  std::uint64_t sim_ns_ = 0;  // simulation time of the messages being published [ns]
};

}  // namespace towsim::app
