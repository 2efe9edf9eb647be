#pragma once
// Plain C++ values of the messages towsim publishes (msgs/, docs/contract.md §3) and their decoders from
// XCDR1 payloads (io/cdr_reader.h) — for tools that read recordings without DDS (towsim_export).
// Field for field as msgs/idl/*.idl; the decoders read the fields in IDL order and throw
// cdr::CdrError (naming the field and byte offset) for a short or malformed payload.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace towsim::io::cdr {

struct Time {  // builtin_interfaces/Time
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  double seconds() const { return sec + 1e-9 * nanosec; }  // [s]
};

struct Header {  // std_msgs/Header
  Time stamp;
  std::string frame_id;
};

struct Vector3 {  // geometry_msgs/Point and geometry_msgs/Vector3
  double x = 0.0, y = 0.0, z = 0.0;
};

struct Quaternion {  // geometry_msgs/Quaternion (scalar last)
  double x = 0.0, y = 0.0, z = 0.0, w = 1.0;
};

struct Odometry {  // nav_msgs/Odometry
  Header header;
  std::string child_frame_id;
  Vector3 position;        // pose.pose.position
  Quaternion orientation;  // pose.pose.orientation
  std::array<double, 36> pose_covariance{};
  Vector3 linear;   // twist.twist.linear
  Vector3 angular;  // twist.twist.angular
  std::array<double, 36> twist_covariance{};
};

struct WrenchStamped {  // geometry_msgs/WrenchStamped
  Header header;
  Vector3 force;
  Vector3 torque;
};

struct Clock {  // rosgraph_msgs/Clock
  Time clock;
};

struct CableState {  // towsim_msgs/CableState
  Header header;
  std::uint64_t step = 0;
  std::vector<Vector3> positions;
  std::vector<Vector3> velocities;
  std::vector<double> tensions;
  double paid_out_length = 0.0;  // [m]
  double winch_speed = 0.0;      // [m/s]
  double drum_tension = 0.0;     // [N]
  std::uint32_t node_count = 0;
};

struct BodyEnvironment {  // towsim_msgs/BodyEnvironment
  Header header;
  std::uint64_t step = 0;
  double wave_elevation = 0.0;
  Vector3 current;
  double altitude = 0.0;  // NaN: no seabed
  double depth = 0.0;
};

struct ActuatorCommand {  // towsim_msgs/ActuatorCommand
  Header header;
  std::uint64_t step = 0;
  double thrust = 0.0, rudder = 0.0, elevator = 0.0;
};

struct ActuatorState {  // towsim_msgs/ActuatorState
  Header header;
  std::uint64_t step = 0;
  double thrust_command = 0.0, rudder_command = 0.0, elevator_command = 0.0;
  double thrust = 0.0, rudder = 0.0, elevator = 0.0;
  bool failsafe = false;
  std::uint8_t source = 0;  // SOURCE_*
};

struct WinchCommand {  // towsim_msgs/WinchCommand
  Header header;
  std::uint64_t step = 0;
  std::uint8_t mode = 0;
  double value = 0.0;
};

struct SimStatus {  // towsim_msgs/SimStatus
  Header header;
  std::string run_id;
  std::string mode;
  std::uint8_t state = 0;
  std::uint8_t health = 0;
  std::string message;
  std::uint64_t step = 0;
  double sim_time = 0.0;
  double rate = 0.0;
  double real_time_factor = 0.0;
  double step_wall_time = 0.0;
  double lateness = 0.0;
  double lateness_max = 0.0;
  std::uint64_t overruns = 0;
  std::int32_t newton_iterations = 0;
  double residual = 0.0;
  std::int32_t coupling_iterations = 0;
  std::int32_t substeps = 0;
  std::uint64_t failsafe_count = 0;
  std::vector<std::string> failsafe_bodies;
  std::uint64_t commands_received = 0;
  std::uint64_t commands_rejected = 0;
  std::uint64_t commands_clamped = 0;
  std::uint64_t lockstep_timeouts = 0;
};

struct SimControl {  // towsim_msgs/SimControl
  Header header;
  std::uint8_t command = 0;
  std::uint32_t steps = 0;
  double rate = 0.0;
};

struct SceneInfo {  // towsim_msgs/SceneInfo
  Header header;
  std::string run_id;
  std::string scene;
  std::string mode;
  double step_size = 0.0;
  double duration = 0.0;
  double command_timeout = 0.0;
  std::vector<std::string> bodies;
  std::vector<std::string> commanded_bodies;
  std::uint32_t cable_nodes = 0;
  bool has_winch = false;
  double winch_min_length = 0.0, winch_max_length = 0.0;
  double winch_max_speed = 0.0, winch_max_acceleration = 0.0;
  // the network fields (msgs/towsim_msgs/msg/SceneInfo.msg); empty in a recording of a towsim
  // that did not send them yet (the message ends after winch_max_acceleration): one cable
  std::vector<std::string> cables;
  std::vector<std::uint32_t> cable_node_counts;
  std::vector<std::string> winches, winch_cables;
};

// payload = the serialized sample with its 4-byte encapsulation header
Odometry DecodeOdometry(const std::uint8_t* data, std::size_t size);
WrenchStamped DecodeWrenchStamped(const std::uint8_t* data, std::size_t size);
Clock DecodeClock(const std::uint8_t* data, std::size_t size);
CableState DecodeCableState(const std::uint8_t* data, std::size_t size);
BodyEnvironment DecodeBodyEnvironment(const std::uint8_t* data, std::size_t size);
ActuatorCommand DecodeActuatorCommand(const std::uint8_t* data, std::size_t size);
ActuatorState DecodeActuatorState(const std::uint8_t* data, std::size_t size);
WinchCommand DecodeWinchCommand(const std::uint8_t* data, std::size_t size);
SimStatus DecodeSimStatus(const std::uint8_t* data, std::size_t size);
SimControl DecodeSimControl(const std::uint8_t* data, std::size_t size);
SceneInfo DecodeSceneInfo(const std::uint8_t* data, std::size_t size);

}  // namespace towsim::io::cdr
