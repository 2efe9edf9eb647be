#include "io/cdr_messages.h"

#include "io/cdr_reader.h"

namespace towsim::io::cdr {
namespace {

// the smallest serialized sizes, for sequence-length checks [bytes]
constexpr std::size_t kVector3Size = 24;   // 3 x float64
constexpr std::size_t kStringMinSize = 5;  // u32 length + NUL

Time ReadTime(CdrReader& r) {
  Time t;
  t.sec = r.I32("stamp.sec");
  t.nanosec = r.U32("stamp.nanosec");
  return t;
}

Header ReadHeader(CdrReader& r) {
  Header h;
  h.stamp = ReadTime(r);
  h.frame_id = r.String("header.frame_id");
  return h;
}

Vector3 ReadVector3(CdrReader& r, const char* field) {
  Vector3 v;
  v.x = r.F64(field);
  v.y = r.F64(field);
  v.z = r.F64(field);
  return v;
}

std::vector<std::string> ReadStrings(CdrReader& r, const char* field) {
  const std::uint32_t n = r.SequenceLength(field, kStringMinSize);
  std::vector<std::string> out;
  out.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) out.push_back(r.String(field));
  return out;
}

}  // namespace

Odometry DecodeOdometry(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "nav_msgs/msg/Odometry");
  Odometry m;
  m.header = ReadHeader(r);
  m.child_frame_id = r.String("child_frame_id");
  m.position = ReadVector3(r, "pose.pose.position");
  m.orientation.x = r.F64("pose.pose.orientation.x");
  m.orientation.y = r.F64("pose.pose.orientation.y");
  m.orientation.z = r.F64("pose.pose.orientation.z");
  m.orientation.w = r.F64("pose.pose.orientation.w");
  for (double& c : m.pose_covariance) c = r.F64("pose.covariance");
  m.linear = ReadVector3(r, "twist.twist.linear");
  m.angular = ReadVector3(r, "twist.twist.angular");
  for (double& c : m.twist_covariance) c = r.F64("twist.covariance");
  r.Finish();
  return m;
}

WrenchStamped DecodeWrenchStamped(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "geometry_msgs/msg/WrenchStamped");
  WrenchStamped m;
  m.header = ReadHeader(r);
  m.force = ReadVector3(r, "wrench.force");
  m.torque = ReadVector3(r, "wrench.torque");
  r.Finish();
  return m;
}

Clock DecodeClock(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "rosgraph_msgs/msg/Clock");
  Clock m;
  m.clock.sec = r.I32("clock.sec");
  m.clock.nanosec = r.U32("clock.nanosec");
  r.Finish();
  return m;
}

CableState DecodeCableState(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "towsim_msgs/msg/CableState");
  CableState m;
  m.header = ReadHeader(r);
  m.step = r.U64("step");
  m.positions.resize(r.SequenceLength("positions", kVector3Size));
  for (Vector3& p : m.positions) p = ReadVector3(r, "positions");
  m.velocities.resize(r.SequenceLength("velocities", kVector3Size));
  for (Vector3& v : m.velocities) v = ReadVector3(r, "velocities");
  m.tensions.resize(r.SequenceLength("tensions", 8));
  for (double& t : m.tensions) t = r.F64("tensions");
  m.paid_out_length = r.F64("paid_out_length");
  m.winch_speed = r.F64("winch_speed");
  m.drum_tension = r.F64("drum_tension");
  m.node_count = r.U32("node_count");
  r.Finish();
  return m;
}

BodyEnvironment DecodeBodyEnvironment(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "towsim_msgs/msg/BodyEnvironment");
  BodyEnvironment m;
  m.header = ReadHeader(r);
  m.step = r.U64("step");
  m.wave_elevation = r.F64("wave_elevation");
  m.current = ReadVector3(r, "current");
  m.altitude = r.F64("altitude");
  m.depth = r.F64("depth");
  r.Finish();
  return m;
}

ActuatorCommand DecodeActuatorCommand(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "towsim_msgs/msg/ActuatorCommand");
  ActuatorCommand m;
  m.header = ReadHeader(r);
  m.step = r.U64("step");
  m.thrust = r.F64("thrust");
  m.rudder = r.F64("rudder");
  m.elevator = r.F64("elevator");
  r.Finish();
  return m;
}

ActuatorState DecodeActuatorState(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "towsim_msgs/msg/ActuatorState");
  ActuatorState m;
  m.header = ReadHeader(r);
  m.step = r.U64("step");
  m.thrust_command = r.F64("thrust_command");
  m.rudder_command = r.F64("rudder_command");
  m.elevator_command = r.F64("elevator_command");
  m.thrust = r.F64("thrust");
  m.rudder = r.F64("rudder");
  m.elevator = r.F64("elevator");
  m.failsafe = r.U8("failsafe") != 0;
  m.source = r.U8("source");
  r.Finish();
  return m;
}

WinchCommand DecodeWinchCommand(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "towsim_msgs/msg/WinchCommand");
  WinchCommand m;
  m.header = ReadHeader(r);
  m.step = r.U64("step");
  m.mode = r.U8("mode");
  m.value = r.F64("value");
  r.Finish();
  return m;
}

SimStatus DecodeSimStatus(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "towsim_msgs/msg/SimStatus");
  SimStatus m;
  m.header = ReadHeader(r);
  m.run_id = r.String("run_id");
  m.mode = r.String("mode");
  m.state = r.U8("state");
  m.health = r.U8("health");
  m.message = r.String("message");
  m.step = r.U64("step");
  m.sim_time = r.F64("sim_time");
  m.rate = r.F64("rate");
  m.real_time_factor = r.F64("real_time_factor");
  m.step_wall_time = r.F64("step_wall_time");
  m.lateness = r.F64("lateness");
  m.lateness_max = r.F64("lateness_max");
  m.overruns = r.U64("overruns");
  m.newton_iterations = r.I32("newton_iterations");
  m.residual = r.F64("residual");
  m.coupling_iterations = r.I32("coupling_iterations");
  m.substeps = r.I32("substeps");
  m.failsafe_count = r.U64("failsafe_count");
  m.failsafe_bodies = ReadStrings(r, "failsafe_bodies");
  m.commands_received = r.U64("commands_received");
  m.commands_rejected = r.U64("commands_rejected");
  m.commands_clamped = r.U64("commands_clamped");
  m.lockstep_timeouts = r.U64("lockstep_timeouts");
  r.Finish();
  return m;
}

SimControl DecodeSimControl(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "towsim_msgs/msg/SimControl");
  SimControl m;
  m.header = ReadHeader(r);
  m.command = r.U8("command");
  m.steps = r.U32("steps");
  m.rate = r.F64("rate");
  r.Finish();
  return m;
}

SceneInfo DecodeSceneInfo(const std::uint8_t* data, std::size_t size) {
  CdrReader r(data, size, "towsim_msgs/msg/SceneInfo");
  SceneInfo m;
  m.header = ReadHeader(r);
  m.run_id = r.String("run_id");
  m.scene = r.String("scene");
  m.mode = r.String("mode");
  m.step_size = r.F64("step_size");
  m.duration = r.F64("duration");
  m.command_timeout = r.F64("command_timeout");
  m.bodies = ReadStrings(r, "bodies");
  m.commanded_bodies = ReadStrings(r, "commanded_bodies");
  m.cable_nodes = r.U32("cable_nodes");
  m.has_winch = r.U8("has_winch") != 0;
  m.winch_min_length = r.F64("winch_min_length");
  m.winch_max_length = r.F64("winch_max_length");
  m.winch_max_speed = r.F64("winch_max_speed");
  m.winch_max_acceleration = r.F64("winch_max_acceleration");
  // the network fields, appended later: a message of an earlier towsim ends here (at most
  // its padding follows) and means one cable
  if (r.remaining() <= 3) return m;
  m.cables = ReadStrings(r, "cables");
  const std::uint32_t n = r.SequenceLength("cable_node_counts", 4);
  m.cable_node_counts.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) m.cable_node_counts.push_back(r.U32("cable_node_counts"));
  m.winches = ReadStrings(r, "winches");
  m.winch_cables = ReadStrings(r, "winch_cables");
  r.Finish();
  return m;
}

}  // namespace towsim::io::cdr
