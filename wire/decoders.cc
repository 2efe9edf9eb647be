#include "wire/decoders.h"

namespace towsim::wire {
namespace {

std::vector<std::string> Strings(const dds_sequence_string& seq) {
  std::vector<std::string> out;
  out.reserve(seq._length);
  for (uint32_t k = 0; k < seq._length; ++k) out.emplace_back(seq._buffer[k]);
  return out;
}

std::string String(const char* s) { return s != nullptr ? s : ""; }

}  // namespace

double StampSeconds(const builtin_interfaces_msg_dds__Time_& stamp) {
  return stamp.sec + 1e-9 * stamp.nanosec;
}

bool SimStatus::running() const {
  return state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_RUNNING ||
         state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_WAITING;
}
bool SimStatus::paused() const {
  return state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_PAUSED;
}
bool SimStatus::finished() const {
  return state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FINISHED;
}
bool SimStatus::failed() const {
  return state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED;
}
bool SimStatus::terminal() const {
  return finished() || failed() || state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_STOPPED;
}
bool SimStatus::failsafe() const {
  return health == towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_FAILSAFE;
}

SimStatus DecodeStatus(const towsim_msgs_msg_dds__SimStatus_& m) {
  SimStatus s;
  s.run_id = String(m.run_id);
  s.mode = String(m.mode);
  s.message = String(m.message);
  s.state = m.state;
  s.health = m.health;
  s.step = m.step;
  s.t = m.sim_time;
  s.rate = m.rate;
  s.failsafe_count = m.failsafe_count;
  s.commands_received = m.commands_received;
  s.commands_rejected = m.commands_rejected;
  s.commands_clamped = m.commands_clamped;
  s.lockstep_timeouts = m.lockstep_timeouts;
  s.failsafe_bodies = Strings(m.failsafe_bodies);
  return s;
}

SceneInfo DecodeSceneInfo(const towsim_msgs_msg_dds__SceneInfo_& m) {
  SceneInfo s;
  s.run_id = String(m.run_id);
  s.scene = String(m.scene);
  s.mode = String(m.mode);
  s.step_size = m.step_size;
  s.duration = m.duration;
  s.command_timeout = m.command_timeout;
  s.bodies = Strings(m.bodies);
  s.commanded_bodies = Strings(m.commanded_bodies);
  s.cable_nodes = m.cable_nodes;
  s.has_winch = m.has_winch;
  s.winch_min_length = m.winch_min_length;
  s.winch_max_length = m.winch_max_length;
  s.winch_max_speed = m.winch_max_speed;
  s.winch_max_acceleration = m.winch_max_acceleration;
  s.cables = Strings(m.cables);
  s.cable_node_counts.assign(m.cable_node_counts._buffer,
                             m.cable_node_counts._buffer + m.cable_node_counts._length);
  s.winches = Strings(m.winches);
  s.winch_cables = Strings(m.winch_cables);
  return s;
}

uint32_t SceneInfo::NodesOf(const std::string& name) const {
  for (size_t c = 0; c < cables.size() && c < cable_node_counts.size(); ++c) {
    if (cables[c] == name) return cable_node_counts[c];
  }
  return 0;
}

Odometry DecodeOdometry(const nav_msgs_msg_dds__Odometry_& m) {
  Odometry o;
  o.t = StampSeconds(m.header.stamp);
  const auto& p = m.pose.pose;
  o.x = p.position.x;
  o.y = p.position.y;
  o.z = p.position.z;
  o.qx = p.orientation.x;
  o.qy = p.orientation.y;
  o.qz = p.orientation.z;
  o.qw = p.orientation.w;
  const auto& tw = m.twist.twist;
  o.u = tw.linear.x;
  o.v = tw.linear.y;
  o.w = tw.linear.z;
  o.p = tw.angular.x;
  o.q = tw.angular.y;
  o.r = tw.angular.z;
  return o;
}

Wrench DecodeWrench(const geometry_msgs_msg_dds__WrenchStamped_& m) {
  Wrench f;
  f.t = StampSeconds(m.header.stamp);
  f.fx = m.wrench.force.x;
  f.fy = m.wrench.force.y;
  f.fz = m.wrench.force.z;
  f.mx = m.wrench.torque.x;
  f.my = m.wrench.torque.y;
  f.mz = m.wrench.torque.z;
  return f;
}

CableState DecodeCableState(const towsim_msgs_msg_dds__CableState_& m) {
  CableState c;
  c.step = m.step;
  c.t = StampSeconds(m.header.stamp);
  const uint32_t n = m.positions._length;
  c.x.resize(n);
  c.y.resize(n);
  c.z.resize(n);
  for (uint32_t k = 0; k < n; ++k) {
    c.x[k] = m.positions._buffer[k].x;
    c.y[k] = m.positions._buffer[k].y;
    c.z[k] = m.positions._buffer[k].z;
  }
  c.tension.assign(m.tensions._buffer, m.tensions._buffer + m.tensions._length);
  c.paid_out_length = m.paid_out_length;
  c.winch_speed = m.winch_speed;
  c.drum_tension = m.drum_tension;
  c.node_count = m.node_count;
  return c;
}

}  // namespace towsim::wire
