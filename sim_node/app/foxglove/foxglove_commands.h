#pragma once
// What Foxglove clients may publish (clientPublish; docs/foxglove.md), shared by the bridge
// towsim_foxglove and sim_node --foxglove: on `<ns>/<b>/command` a towsim_msgs/msg/
// ActuatorCommand, or a geometry_msgs/msg/Twist from Foxglove's Teleop panel (TwistToCommand);
// on `<ns>/winch/command` (a scene with a winch, docs/winch_dds.md) a towsim_msgs/msg/
// WinchCommand; on `<ns>/sim_control` a towsim_msgs/msg/SimControl; encoding cdr. A message
// is checked to be a valid CDR sample of its type (Cyclone's deserializer) and written on DDS
// as it is, from a writer in the given participant, so that the node validates it exactly like
// any DDS command (the node's own readers take the samples of a writer in the node's
// participant too). A malformed message is rejected here: the verdict says so (the server
// sends the reason to the client, counts it and notes it on stderr, throttled) and it is
// counted here too.
//
// Foxglove's 3D panel advertises the topics of its publish tools (PanelTopics) as soon as it
// opens; those are taken and their messages ignored, so the panel raises no error (docs/
// foxglove.md "Publishing from Foxglove").
//
// Thread safety: Advertise, Publish and SetStatusStep may come from different threads.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "app/foxglove/foxglove_protocol.h"
#include "app/foxglove/foxglove_server.h"
#include "dds/entities.h"
#include "dds/messages.h"
#include "dds/raw_cdr.h"
#include "wire/topic_names.h"

namespace towsim::app {

// Foxglove's Teleop panel: a Twist as the actuator command answering `step`: thrust =
// linear.x [N] when non-zero, else *thrust (the thrust the panel set last, so turning keeps the
// speed); rudder = -angular.z [rad] (the panel's "left" is a positive angular.z, a positive
// rudder turns to starboard); elevator = linear.z [rad]; an all-zero Twist stops (thrust 0,
// fins centred). Updates *thrust. header.frame_id is left null.
dds::ActuatorCommandMsg TwistToCommand(const geometry_msgs_msg_dds__Twist_& twist, uint64_t step,
                                       double* thrust);

// "" if every field of a Teleop Twist is finite, else the first that is not ("linear.x is not
// finite (nan)"): a NaN linear.x would become the kept thrust and poison every later Twist
std::string NonFiniteTwistField(const geometry_msgs_msg_dds__Twist_& twist);

// "" if a message of `size` bytes whose sample takes `sample_size` bytes (both with the
// encapsulation header) holds nothing after it but padding to a multiple of 4 (XCDR), else
// "8 bytes after the 36-byte sample (only padding to a multiple of 4 may follow)"
std::string TrailingBytes(std::size_t size, std::size_t sample_size);

// A topic the 3D panel's publish tools advertise (its standard ROS topics, at the root)
struct PanelTopic {
  const char* topic;   // "/clicked_point"
  const char* schema;  // "geometry_msgs/msg/PointStamped"
};
// the 3D panel's pose goal, clicked point and pose estimate
inline constexpr PanelTopic kPanelTopics[] = {
    {"/move_base_simple/goal", "geometry_msgs/msg/PoseStamped"},
    {"/clicked_point", "geometry_msgs/msg/PointStamped"},
    {"/initialpose", "geometry_msgs/msg/PoseWithCovarianceStamped"},
};

class FoxgloveCommands {
 public:
  // `winches`: the scene's winches by name (SceneInfo.winches; the one winch: "winch"), so
  // clients may command each on its rt/<ns>/<winch>/command
  FoxgloveCommands(const dds::Participant& participant, const wire::TopicNames& names,
                   const std::vector<std::string>& bodies,
                   const std::vector<std::string>& winches);
  FoxgloveCommands(const FoxgloveCommands&) = delete;
  FoxgloveCommands& operator=(const FoxgloveCommands&) = delete;

  // hands Advertise and Publish to `server`
  void Attach(FoxgloveServer* server);
  // "" if clients may publish on the channel (its writer then exists), else why not
  std::string Advertise(const foxglove::ClientChannel& channel);
  // error "" if written on DDS, else why not (malformed: not a valid sample of its type)
  FoxgloveServer::Verdict Publish(const foxglove::ClientChannel& channel, const uint8_t* data,
                                  std::size_t size);
  // the step of the newest status: what a Teleop Twist answers
  void SetStatusStep(uint64_t step) { status_step_ = step; }
  uint64_t malformed() const { return malformed_.load(); }
  // messages taken on a PanelTopic and ignored
  uint64_t ignored() const { return ignored_.load(); }

 private:
  struct Inbound {
    std::string schema_name;     // "towsim_msgs/msg/ActuatorCommand"
    bool teleop = false;         // a command topic: also takes geometry_msgs/msg/Twist
    double teleop_thrust = 0.0;  // the thrust the Teleop panel set last [N]
    const dds_topic_descriptor_t* descriptor = nullptr;
    const dds::RawType* type = nullptr;
    dds::Entity topic, writer;
    bool control = false;  // sim_control (ControlQos)
  };

  const dds::Participant& participant_;
  dds::RawType command_type_, control_type_, twist_type_, winch_type_;
  std::mutex mutex_;                        // inbound_
  std::map<std::string, Inbound> inbound_;  // ROS topic -> writer
  std::atomic<uint64_t> status_step_{0};
  std::atomic<uint64_t> malformed_{0};
  std::atomic<uint64_t> ignored_{0};
};

}  // namespace towsim::app
