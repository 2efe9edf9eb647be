#include "dds/translators.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "core/actuator.h"
#include "core/model.h"
#include "core/system.h"
#include "dds/command_arbiter.h"
#include "towsim_msgs.h"
#include "wire/topic_table.h"

namespace towsim::dds {
namespace {

constexpr double kNanosecondsPerSecond = 1e9;

void Set(const core::Vec3& v, geometry_msgs_msg_dds__Vector3_* out) {
  out->x = v.x();
  out->y = v.y();
  out->z = v.z();
}

void Set(const core::Vec3& v, geometry_msgs_msg_dds__Point_* out) {
  out->x = v.x();
  out->y = v.y();
  out->z = v.z();
}

char* Chars(const std::string& s) { return const_cast<char*>(s.c_str()); }

// points `seq` at the strings of `from` (through `pointers`, resized as needed)
void PointAt(const std::vector<std::string>& from, std::vector<char*>* pointers,
             dds_sequence_string* seq) {
  pointers->resize(from.size());
  for (size_t i = 0; i < from.size(); ++i) (*pointers)[i] = Chars(from[i]);
  seq->_buffer = pointers->empty() ? nullptr : pointers->data();
  seq->_length = static_cast<uint32_t>(from.size());
  seq->_maximum = seq->_length;
  seq->_release = false;
}

// clamps *x into [lo, hi]; returns whether it had to
bool Clamp(double lo, double hi, double* x) {
  const double c = std::min(hi, std::max(lo, *x));
  const bool clamped = c != *x;
  *x = c;
  return clamped;
}

// the paid-out length of cable c: its winch's, or the scene's length (Simulation::cable_length)
double CableLength(const core::Simulation& sim, int c) { return sim.cable_length(c); }

}  // namespace

TimeMsg ToTimeMsg(double t) {
  // round to the nearest nanosecond, then split with floor division (t may be < 0)
  const long long ns = std::llround(t * kNanosecondsPerSecond);
  const long long per_s = static_cast<long long>(kNanosecondsPerSecond);
  long long sec = ns / per_s;
  long long rem = ns % per_s;
  if (rem < 0) {
    rem += per_s;
    --sec;
  }
  TimeMsg out;
  out.sec = static_cast<int32_t>(sec);
  out.nanosec = static_cast<uint32_t>(rem);
  return out;
}

double FromTimeMsg(const TimeMsg& time) {
  return static_cast<double>(time.sec) + static_cast<double>(time.nanosec) / kNanosecondsPerSecond;
}

OdometryMessage::OdometryMessage(std::string frame_id, std::string child_frame_id)
    : msg{}, frame_id_(std::move(frame_id)), child_frame_id_(std::move(child_frame_id)) {
  msg.header.frame_id = Chars(frame_id_);
  msg.child_frame_id = Chars(child_frame_id_);
  msg.pose.pose.orientation.w = 1.0;
}

WrenchStampedMessage::WrenchStampedMessage(std::string frame_id)
    : msg{}, frame_id_(std::move(frame_id)) {
  msg.header.frame_id = Chars(frame_id_);
}

CableStateMessage::CableStateMessage(std::string frame_id, int nodes)
    : msg{}, frame_id_(std::move(frame_id)) {
  msg.header.frame_id = Chars(frame_id_);
  Resize(nodes);
}

void CableStateMessage::Resize(int nodes) {
  const size_t n = static_cast<size_t>(std::max(0, nodes));
  if (n > positions_.size()) {
    positions_.resize(n);
    velocities_.resize(n);
    tensions_.resize(n);
  }
  const uint32_t length = static_cast<uint32_t>(n);
  const uint32_t capacity = static_cast<uint32_t>(positions_.size());
  msg.positions = {capacity, length, positions_.data(), false};
  msg.velocities = {capacity, length, velocities_.data(), false};
  msg.tensions = {capacity, length, tensions_.data(), false};
  msg.node_count = length;
}

int MaxCableNodes(const core::Simulation& sim, int c) {
  const int now = sim.num_nodes(c);
  const std::optional<core::WinchParams>& winch = sim.model().cables[c].winch;
  const double length = CableLength(sim, c);
  if (!winch || !(length > 0.0)) return now;
  const double elements = static_cast<double>(now - 1) * winch->max_length / length;
  return std::max(now, static_cast<int>(std::ceil(elements)) + 3);
}

void ToOdometry(const core::Simulation& sim, int body, OdometryMsg* msg) {
  msg->header.stamp = ToTimeMsg(sim.time());
  // pose of B in W (NED)
  Set(sim.body_position(body), &msg->pose.pose.position);
  const Eigen::Quaterniond q_WB = sim.body_attitude(body);
  msg->pose.pose.orientation.x = q_WB.x();
  msg->pose.pose.orientation.y = q_WB.y();
  msg->pose.pose.orientation.z = q_WB.z();
  msg->pose.pose.orientation.w = q_WB.w();
  // [u v w p q r] in B
  const core::Vec6 nu = sim.body_twist(body);
  Set(core::Vec3(nu.head<3>()), &msg->twist.twist.linear);
  Set(core::Vec3(nu.tail<3>()), &msg->twist.twist.angular);
}

void ToCableForce(const core::Simulation& sim, int body, WrenchStampedMsg* msg) {
  msg->header.stamp = ToTimeMsg(sim.time());
  core::Vec3 force_B, moment_B;
  sim.BodyCableWrench(body, &force_B, &moment_B);
  Set(force_B, &msg->wrench.force);
  Set(moment_B, &msg->wrench.torque);
}

bool HasEndForce(const core::Simulation& sim, int end, int c) {
  const core::CableParams& cable = sim.model().cables[static_cast<size_t>(c)];
  const core::EndKind kind = (end == 0 ? cable.start : cable.end).kind;
  if (kind == core::EndKind::kFixed || kind == core::EndKind::kDriven) return true;
  const int body = sim.EndBody(end, c);
  if (body < 0) return false;  // a free end
  int held = 0;  // the cable ends on that body
  for (int k = 0; k < sim.num_cables(); ++k) {
    for (int e = 0; e < 2; ++e) held += sim.EndBody(e, k) == body;
  }
  return held >= 2;
}

void ToCableEndForce(const core::Simulation& sim, int end, int c, WrenchStampedMsg* msg) {
  msg->header.stamp = ToTimeMsg(sim.time());
  const int body = sim.EndBody(end, c);
  if (body < 0) {  // a support: the force on it, in W
    Set(sim.end_force(end, c), &msg->wrench.force);
    Set(core::Vec3::Zero(), &msg->wrench.torque);
    return;
  }
  // one attachment of a body: f_B = R_WB^T f_W, m_B = at_B x f_B
  const core::Vec3 f = sim.body_attitude(body).conjugate() * sim.end_force(end, c);
  const core::Vec3 m = !sim.body_is_sphere(body)
                           ? core::Vec3(sim.system().End(end, c).at_B.cross(f))
                           : core::Vec3::Zero();
  Set(f, &msg->wrench.force);
  Set(m, &msg->wrench.torque);
}

void ToClock(double t, ClockMsg* msg) { msg->clock = ToTimeMsg(t); }

void ToCableState(const core::Simulation& sim, uint64_t step, CableStateMessage* out, int c) {
  CableStateMsg& m = out->msg;
  m.header.stamp = ToTimeMsg(sim.time());
  m.step = step;
  out->Resize(sim.num_nodes(c));
  const uint32_t n = m.node_count;
  for (uint32_t i = 0; i < n; ++i) {
    Set(sim.node_position(static_cast<int>(i), c), &m.positions._buffer[i]);
    Set(sim.node_velocity(static_cast<int>(i), c), &m.velocities._buffer[i]);
    m.tensions._buffer[i] = sim.NodeTension(static_cast<int>(i), c);
  }
  // a winch drives its cable's start (docs/winch.md); a cable without one keeps its length,
  // speed 0, and the tension at its start
  m.paid_out_length = CableLength(sim, c);
  m.winch_speed = sim.winch_speed(c);
  m.drum_tension = sim.DrumTension(c);
}

SimStatusMessage::SimStatusMessage() : msg{} { ToSimStatus(StatusSample{}, this); }

void ToSimStatus(const StatusSample& sample, SimStatusMessage* out) {
  StatusSample& s = out->storage_;
  s = sample;
  SimStatusMsg& m = out->msg;
  m.header.stamp = ToTimeMsg(s.sim_time);
  m.header.frame_id = const_cast<char*>("");  // not frame-bound
  m.run_id = Chars(s.run_id);
  m.mode = Chars(s.mode);
  m.state = s.state;
  m.health = s.health;
  m.message = Chars(s.message);
  m.step = s.step;
  m.sim_time = s.sim_time;
  m.rate = s.rate;
  m.real_time_factor = s.real_time_factor;
  m.step_wall_time = s.step_wall_time;
  m.lateness = s.lateness;
  m.lateness_max = s.lateness_max;
  m.overruns = s.overruns;
  m.newton_iterations = s.newton_iterations;
  m.residual = s.residual;
  m.coupling_iterations = s.coupling_iterations;
  m.substeps = s.substeps;
  m.failsafe_count = s.failsafe_count;
  PointAt(s.failsafe_bodies, &out->failsafe_bodies_, &m.failsafe_bodies);
  m.commands_received = s.commands_received;
  m.commands_rejected = s.commands_rejected;
  m.commands_clamped = s.commands_clamped;
  m.lockstep_timeouts = s.lockstep_timeouts;
}

SceneInfoMessage::SceneInfoMessage() : msg{} { ToSceneInfo(SceneInfoSample{}, this); }

void ToSceneInfo(const SceneInfoSample& sample, SceneInfoMessage* out) {
  SceneInfoSample& s = out->storage_;
  s = sample;
  SceneInfoMsg& m = out->msg;
  m.header.stamp = ToTimeMsg(s.time);
  m.header.frame_id = const_cast<char*>("");  // not frame-bound
  m.run_id = Chars(s.run_id);
  m.scene = Chars(s.scene);
  m.mode = Chars(s.mode);
  m.step_size = s.step_size;
  m.duration = s.duration;
  m.command_timeout = s.command_timeout;
  PointAt(s.bodies, &out->bodies_, &m.bodies);
  PointAt(s.commanded_bodies, &out->commanded_bodies_, &m.commanded_bodies);
  m.cable_nodes = static_cast<uint32_t>(std::max(0, s.cable_nodes));
  m.has_winch = s.has_winch;
  m.winch_min_length = s.winch_min_length;
  m.winch_max_length = s.winch_max_length;
  m.winch_max_speed = s.winch_max_speed;
  m.winch_max_acceleration = s.winch_max_acceleration;
  PointAt(s.cables, &out->cables_, &m.cables);
  m.cable_node_counts._buffer = s.cable_node_counts.empty() ? nullptr : s.cable_node_counts.data();
  m.cable_node_counts._length = static_cast<uint32_t>(s.cable_node_counts.size());
  m.cable_node_counts._maximum = m.cable_node_counts._length;
  m.cable_node_counts._release = false;
  PointAt(s.winches, &out->winches_, &m.winches);
  PointAt(s.winch_cables, &out->winch_cables_, &m.winch_cables);
}

void SceneOf(const core::Simulation& sim, SceneInfoSample* out) {
  out->bodies.clear();
  for (int b = 0; b < sim.num_bodies(); ++b) out->bodies.push_back(sim.body_name(b));
  out->cable_nodes = sim.num_nodes(0);
  out->cables.clear();
  out->cable_node_counts.clear();
  out->winches.clear();
  out->winch_cables.clear();
  for (int c = 0; c < sim.num_cables(); ++c) {
    out->cables.push_back(sim.cable_name(c));
    out->cable_node_counts.push_back(static_cast<uint32_t>(sim.num_nodes(c)));
  }
  // every winch by name (the one winch: "winch", wire/topic_table.h) with its cable, winch w
  // on cable w; the limits fields are the first winch's (docs/winch_dds.md)
  const std::optional<core::WinchParams>& winch = sim.model().cables[0].winch;
  out->has_winch = winch.has_value();
  if (winch) {
    out->winch_min_length = winch->min_length;
    out->winch_max_length = winch->max_length;
    out->winch_max_speed = winch->max_speed;
    out->winch_max_acceleration = winch->max_acceleration;
  }
  for (int w = 0; w < sim.num_winches(); ++w) {
    out->winches.push_back(sim.winch_name(w));
    out->winch_cables.push_back(sim.cable_name(w));
  }
}

CommandLimits LimitsOf(const core::VehicleParams& params) {
  // the actuators' ranges (core/actuator.h): the same the vehicle model clamps to
  CommandLimits limits;
  const core::Actuator thrust = core::ThrustActuator(params);
  limits.thrust_min = thrust.min;
  limits.thrust_max = thrust.max;
  for (const core::LiftingSurface& s : params.surfaces) {
    if (s.channel == core::Channel::kRudder)
      limits.rudder_max = core::FinActuator(params.rudder).max;
    if (s.channel == core::Channel::kElevator)
      limits.elevator_max = core::FinActuator(params.elevator).max;
  }
  return limits;
}

bool IsCommandable(const core::VehicleParams& params) {
  if (params.has_propeller) return true;
  for (const core::LiftingSurface& s : params.surfaces) {
    if (s.channel != core::Channel::kNone) return true;
  }
  return false;
}

CheckedCommand FromActuatorCommand(const ActuatorCommandMsg& msg, const CommandLimits& limits) {
  CheckedCommand out;
  out.step = msg.step;
  const struct {
    const char* name;
    double value;
  } fields[] = {{"thrust", msg.thrust}, {"rudder", msg.rudder}, {"elevator", msg.elevator}};
  for (const auto& f : fields) {
    if (!std::isfinite(f.value)) {
      out.verdict = CheckedCommand::kRejected;
      out.reason = std::string(f.name) + " is " + (std::isnan(f.value) ? "NaN" : "infinite");
      return out;
    }
  }
  out.command.thrust = msg.thrust;
  out.command.rudder = msg.rudder;
  out.command.elevator = msg.elevator;
  std::string clamped;
  auto note = [&clamped](const char* name, bool did) {
    if (!did) return;
    clamped += clamped.empty() ? name : std::string(", ") + name;
  };
  note("thrust", Clamp(limits.thrust_min, limits.thrust_max, &out.command.thrust));
  note("rudder", Clamp(-limits.rudder_max, limits.rudder_max, &out.command.rudder));
  note("elevator", Clamp(-limits.elevator_max, limits.elevator_max, &out.command.elevator));
  if (!clamped.empty()) {
    out.verdict = CheckedCommand::kClamped;
    out.reason = clamped + " clamped to the vehicle's limits";
  }
  return out;
}

ControlRequest FromSimControl(const SimControlMsg& msg) {
  ControlRequest r;
  switch (msg.command) {
    case towsim_msgs_msg_dds__SimControl_Constants_PAUSE:
      r.kind = ControlRequest::kPause;
      break;
    case towsim_msgs_msg_dds__SimControl_Constants_RESUME:
      r.kind = ControlRequest::kResume;
      break;
    case towsim_msgs_msg_dds__SimControl_Constants_STEP:
      if (msg.steps < 1) {
        r.error = "STEP needs steps >= 1";
        break;
      }
      r.kind = ControlRequest::kStep;
      r.steps = static_cast<long>(msg.steps);
      break;
    case towsim_msgs_msg_dds__SimControl_Constants_RESET:
      r.kind = ControlRequest::kReset;
      break;
    case towsim_msgs_msg_dds__SimControl_Constants_SET_RATE:
      if (const std::string e = CheckRate(msg.rate); !e.empty()) {
        char text[48];
        std::snprintf(text, sizeof text, "%g", msg.rate);
        r.error = std::string("SET_RATE ") + text + ": " + e;
        break;
      }
      r.kind = ControlRequest::kSetRate;
      r.rate = msg.rate;
      break;
    default:
      r.error = "unknown command " + std::to_string(msg.command);
  }
  return r;
}

void ToStatusCommands(const CommandArbiter& arbiter, const StatusNotes& notes, StatusSample* s) {
  s->failsafe_count = arbiter.failsafe_count();
  s->failsafe_bodies.clear();
  for (int i = 0; i < arbiter.size(); ++i) {
    if (arbiter.failsafe(i)) s->failsafe_bodies.push_back(arbiter.vehicle(i).name);
  }
  s->commands_received = arbiter.received() + notes.unknown_commands;
  s->commands_rejected = arbiter.rejected() + notes.unknown_commands;
  s->commands_clamped = arbiter.clamped();
  s->lockstep_timeouts = arbiter.lockstep_timeouts();
  if (s->state == towsim_msgs_msg_dds__SimStatus_Constants_STATE_FAILED) {
    s->health = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_ERROR;
    s->message.assign(notes.failure);
  } else if (!s->failsafe_bodies.empty()) {
    s->health = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_FAILSAFE;
    s->message = arbiter.last_event();
  } else {
    s->health = towsim_msgs_msg_dds__SimStatus_Constants_HEALTH_OK;
    if (!notes.peer.empty()) {
      s->message.assign(notes.peer);
    } else if (!notes.strain.empty()) {
      s->message.assign(notes.strain);
    } else if (!notes.control.empty()) {
      s->message.assign(notes.control);
    } else if (!notes.unknown_event.empty() && arbiter.last_event().empty()) {
      s->message.assign(notes.unknown_event);
    } else if (s->message != arbiter.last_event()) {
      s->message = arbiter.last_event();
    }
  }
}

}  // namespace towsim::dds
