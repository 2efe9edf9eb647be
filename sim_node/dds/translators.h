#pragma once
// Pure translators between the core's state and the wire messages (docs/contract.md §3): no DDS
// entities, no clocks; unit-tested without a participant (tests/unit/dds_translators_test.cc).
//
// Frames and units: the world frame W is NED ("world_ned"); a body frame B is x forward,
// y starboard, z down (a sphere's B stays aligned with W). SI units throughout.
//   Odometry:       pose = (p_WB, q_WB) in W; twist = ([u v w], [p q r]) in B (the ROS
//                   convention: the twist is expressed in child_frame_id = the body)
//   cable_force:    the force the cable exerts on the body and its moment about the body
//                   origin, in B (Eq. 29-30) [N, N m]
//   CableState:     node positions and velocities in W, axial forces [m, m/s, N]
//
// The *Message classes own a C message struct and the storage its strings and sequences point
// into; they are neither copyable nor movable (the struct points into the object itself).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/simulation.h"
#include "core/vehicle_model.h"
#include "dds/messages.h"
#include "dds/pacing_rate.h"

namespace towsim::dds {

// frame_id of world-frame data (NED; REP 103's "_ned" suffix)
inline constexpr const char* kWorldFrame = "world_ned";

// --- time ---

// t [s] -> (sec, nanosec) rounded to the nearest nanosecond; nanosec in [0, 1e9)
TimeMsg ToTimeMsg(double t);
double FromTimeMsg(const TimeMsg& time);  // [s]

// --- outgoing ---

class OdometryMessage {
 public:
  // frame_id: the world frame; child_frame_id: the body (the twist's frame)
  OdometryMessage(std::string frame_id, std::string child_frame_id);
  OdometryMessage(const OdometryMessage&) = delete;
  OdometryMessage& operator=(const OdometryMessage&) = delete;
  OdometryMsg msg;

 private:
  std::string frame_id_, child_frame_id_;
};

class WrenchStampedMessage {
 public:
  explicit WrenchStampedMessage(std::string frame_id);
  WrenchStampedMessage(const WrenchStampedMessage&) = delete;
  WrenchStampedMessage& operator=(const WrenchStampedMessage&) = delete;
  WrenchStampedMsg msg;

 private:
  std::string frame_id_;
};

class CableStateMessage {
 public:
  // frame_id: the world frame; nodes: the most nodes expected (the sequences' storage, sized
  // once; a winch scene: MaxCableNodes)
  CableStateMessage(std::string frame_id, int nodes);
  CableStateMessage(const CableStateMessage&) = delete;
  CableStateMessage& operator=(const CableStateMessage&) = delete;
  // the sequences hold `nodes` entries; the storage grows only past its size so far
  void Resize(int nodes);
  CableStateMsg msg;

 private:
  std::string frame_id_;
  std::vector<geometry_msgs_msg_dds__Point_> positions_;
  std::vector<geometry_msgs_msg_dds__Vector3_> velocities_;
  std::vector<double> tensions_;
};

// body b of sim (0 .. num_bodies - 1): stamp, pose in W, twist in B; covariances zero (exact)
void ToOdometry(const core::Simulation& sim, int body, OdometryMsg* msg);
// the cable's force and moment on body b, in B; zero when the cable is not attached to it
void ToCableForce(const core::Simulation& sim, int body, WrenchStampedMsg* msg);
// whether forces.csv has a row of end `end` (0: start, 1: end) of cable c, and so the node the
// topic <c>/start_force or <c>/end_force (docs/topics.md "Cable end forces"): the end is held
// by a fixed or driven support, or by a body that holds two or more cable ends
bool HasEndForce(const core::Simulation& sim, int end, int c);
// that end's force, as its forces.csv row (docs/command_line.md "Output files"): on a support,
// the force the cable exerts on it in W (NED) and moment 0; on a body (EndBody >= 0), the force
// f_B = R_WB^T f_W of that end alone and its moment about the body origin at_B x f_B in B
// (Eq. 29-30; a sphere: 0)
void ToCableEndForce(const core::Simulation& sim, int end, int c, WrenchStampedMsg* msg);
void ToClock(double t, ClockMsg* msg);
// cable c of sim (Model::cables order; the one cable: 0): every node in use (sim.num_nodes(c),
// which a winch changes), and the winch's paid-out length, speed, drum tension and the node
// count; a cable without a winch: its length, 0, the tension at its start, the node count
void ToCableState(const core::Simulation& sim, uint64_t step, CableStateMessage* msg, int c = 0);
// the storage a CableStateMessage of cable c needs for the whole run: num_nodes(c) now, or with
// a winch the bound of docs/winch.md on the nodes at its max_length, max_length / (length /
// elements) + 3 at the element length of the start (should a run go past it, Resize grows the
// storage once)
int MaxCableNodes(const core::Simulation& sim, int c = 0);

// what the node reports in SimStatus (field meanings: msgs/towsim_msgs/msg/SimStatus.msg)
struct StatusSample {
  std::string run_id;
  std::string mode;
  uint8_t state = 0;   // towsim_msgs_msg_dds__SimStatus_Constants_STATE_*
  uint8_t health = 0;  // ..._HEALTH_*
  std::string message;
  uint64_t step = 0;
  double sim_time = 0.0;          // [s]
  double rate = 1.0;              // [-]
  double real_time_factor = 0.0;  // [-]
  double step_wall_time = 0.0;    // [s]
  double lateness = 0.0;          // [s]
  double lateness_max = 0.0;      // [s]
  uint64_t overruns = 0;
  int newton_iterations = 0;
  double residual = 0.0;  // [N]
  int coupling_iterations = 0;
  int substeps = 0;
  uint64_t failsafe_count = 0;
  std::vector<std::string> failsafe_bodies;
  uint64_t commands_received = 0;
  uint64_t commands_rejected = 0;
  uint64_t commands_clamped = 0;
  uint64_t lockstep_timeouts = 0;
};

class SimStatusMessage {
 public:
  SimStatusMessage();
  SimStatusMessage(const SimStatusMessage&) = delete;
  SimStatusMessage& operator=(const SimStatusMessage&) = delete;
  SimStatusMsg msg;

 private:
  friend void ToSimStatus(const StatusSample& sample, SimStatusMessage* out);
  StatusSample storage_;  // the strings msg points into
  std::vector<char*> failsafe_bodies_;
};

// the sample's strings are copied into `out`
void ToSimStatus(const StatusSample& sample, SimStatusMessage* out);

class CommandArbiter;  // dds/command_arbiter.h

// what the status says beside the numbers of the run
struct StatusNotes {
  std::string_view failure;        // the run failed (state FAILED): why
  std::string_view peer;           // another node in the namespace
  std::string_view strain;         // the cable's strain warning
  std::string_view control;        // the last refused control request
  uint64_t unknown_commands = 0;   // commands on topics of no commandable body (rejected)
  std::string_view unknown_event;  // the last of them
};

// The command counts, failsafes, health and message of the node's status `s` (whose state is
// set): the arbiter's counts plus the unknown commands (received and rejected); health ERROR
// with the failure when s->state is FAILED, FAILSAFE with the arbiter's last event while a
// vehicle is in failsafe, else OK with the first of: the peer warning, the strain warning, the
// refused control request, the unknown-command event (when the arbiter has none), the
// arbiter's last event. Assigns the strings only when they change (no allocation per step).
void ToStatusCommands(const CommandArbiter& arbiter, const StatusNotes& notes, StatusSample* s);

struct SceneInfoSample {
  std::string run_id, scene, mode;
  double time = 0.0;             // stamp [s]
  double step_size = 0.0;        // [s]
  double duration = 0.0;         // [s], < 0: no end
  double command_timeout = 0.0;  // [s]
  std::vector<std::string> bodies;
  std::vector<std::string> commanded_bodies;
  int cable_nodes = 0;     // of the first cable
  bool has_winch = false;  // the winch's limits, zero without one
  double winch_min_length = 0.0, winch_max_length = 0.0;         // [m]
  double winch_max_speed = 0.0, winch_max_acceleration = 0.0;    // [m/s, m/s^2]
  // every cable (Model::cables order) and its nodes at the start; the winches and the cable
  // each drives (SceneInfo.msg)
  std::vector<std::string> cables;
  std::vector<uint32_t> cable_node_counts;
  std::vector<std::string> winches, winch_cables;
};

// the scene part of a SceneInfoSample of `sim` (cables, node counts, winch and its limits,
// bodies); the run's fields (run_id, mode, time, step, duration, commands) are the caller's
void SceneOf(const core::Simulation& sim, SceneInfoSample* out);

class SceneInfoMessage {
 public:
  SceneInfoMessage();
  SceneInfoMessage(const SceneInfoMessage&) = delete;
  SceneInfoMessage& operator=(const SceneInfoMessage&) = delete;
  SceneInfoMsg msg;

 private:
  friend void ToSceneInfo(const SceneInfoSample& sample, SceneInfoMessage* out);
  SceneInfoSample storage_;
  std::vector<char*> bodies_, commanded_bodies_, cables_, winches_, winch_cables_;
};

void ToSceneInfo(const SceneInfoSample& sample, SceneInfoMessage* out);

// --- incoming ---

// the limits a command is clamped to (a vehicle without the actuator: [0, 0])
struct CommandLimits {
  double thrust_min = 0.0, thrust_max = 0.0;  // [N]
  double rudder_max = 0.0;                    // |rudder| [rad]
  double elevator_max = 0.0;                  // |elevator| [rad]
};

// the ranges of the vehicle's actuators (core/actuator.h): thrust in
// [-max_thrust / 4, max_thrust], fins within +-max_deflection of each channel that drives a
// surface
CommandLimits LimitsOf(const core::VehicleParams& params);

// whether a vehicle takes commands at all (a propeller, or a surface on a channel)
bool IsCommandable(const core::VehicleParams& params);

struct CheckedCommand {
  enum Verdict { kAccepted, kClamped, kRejected };
  Verdict verdict = kAccepted;
  core::VehicleCommand command;  // clamped (kClamped) or as sent (kAccepted); unset if rejected
  uint64_t step = 0;             // the step the command answers
  std::string reason;            // kClamped / kRejected: which field and why
};

// NaN or infinite in any field: rejected; beyond the limits: clamped
CheckedCommand FromActuatorCommand(const ActuatorCommandMsg& msg, const CommandLimits& limits);

// the realtime pacing factor of SET_RATE: CheckRate in dds/pacing_rate.h

struct ControlRequest {
  enum Kind { kInvalid, kPause, kResume, kStep, kReset, kSetRate };
  Kind kind = kInvalid;
  long steps = 0;     // kStep: >= 1
  double rate = 0.0;  // kSetRate: finite, > 0
  std::string error;  // kInvalid: why
};

ControlRequest FromSimControl(const SimControlMsg& msg);

}  // namespace towsim::dds
