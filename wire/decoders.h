#pragma once
// Observers' decoders (docs/topics.md): one function per message that turns a taken sample
// into a plain value that owns its strings and sequences, so that it outlives the sample's
// loan. The controllers' client, the test fixture (towsim::testing), the integration tests and
// the benchmarks decode the node's messages here and nowhere else.
//
//   const wire::SimStatus s = wire::DecodeStatus(*static_cast<const SimStatusMsg*>(sample));
//
// Times are the header stamps in seconds (sim time); frames as on the wire: positions world
// NED, attitude body FRD -> world NED, velocities and wrenches in the body frame.

#include <cstdint>
#include <string>
#include <vector>

#include "geometry_msgs.h"
#include "nav_msgs.h"
#include "towsim_msgs.h"

namespace towsim::wire {

// a header stamp in seconds
double StampSeconds(const builtin_interfaces_msg_dds__Time_& stamp);

// towsim_msgs/SimStatus: the run's state and the command counters
struct SimStatus {
  std::string run_id, mode, message;
  uint8_t state = 0, health = 0;  // towsim_msgs SimStatus STATE_*, HEALTH_*
  uint64_t step = 0;
  double t = 0.0;     // sim_time [s]
  double rate = 0.0;  // requested pacing factor [-]
  uint64_t failsafe_count = 0, commands_received = 0, commands_rejected = 0, commands_clamped = 0,
           lockstep_timeouts = 0;
  std::vector<std::string> failsafe_bodies;
  bool running() const;  // running or waiting for commands
  bool paused() const;
  bool finished() const;  // duration reached
  bool failed() const;    // a solver, output or failsafe failure (sim_node --fail-on-failsafe)
  bool terminal() const;  // finished, failed or stopped: the last status of the run
  bool failsafe() const;  // a body is in failsafe
};
SimStatus DecodeStatus(const towsim_msgs_msg_dds__SimStatus_& m);

// towsim_msgs/SceneInfo: what the node simulates
struct SceneInfo {
  std::string run_id, scene, mode;
  double step_size = 0.0, duration = 0.0, command_timeout = 0.0;  // [s]
  std::vector<std::string> bodies, commanded_bodies;
  uint32_t cable_nodes = 0;
  bool has_winch = false;
  double winch_min_length = 0.0, winch_max_length = 0.0;  // [m]
  double winch_max_speed = 0.0;                           // [m/s]
  double winch_max_acceleration = 0.0;                    // [m/s^2]
  // every cable (scene order; the one-cable form: {"cable"}) with its node count at the start,
  // and the winches with the cable whose start each drives
  std::vector<std::string> cables;
  std::vector<uint32_t> cable_node_counts;
  std::vector<std::string> winches, winch_cables;
  // the node count of cable `name` at the start; 0 for a cable the scene does not have
  uint32_t NodesOf(const std::string& name) const;
};
SceneInfo DecodeSceneInfo(const towsim_msgs_msg_dds__SceneInfo_& m);

// nav_msgs/Odometry: a body's pose and velocity
struct Odometry {
  double t = 0.0;                         // stamp [s]
  double x = 0, y = 0, z = 0;             // world NED [m]
  double qx = 0, qy = 0, qz = 0, qw = 1;  // attitude, body -> world NED
  double u = 0, v = 0, w = 0;             // body frame [m/s]
  double p = 0, q = 0, r = 0;             // body frame [rad/s]
};
Odometry DecodeOdometry(const nav_msgs_msg_dds__Odometry_& m);

// geometry_msgs/WrenchStamped: the cable's force and moment on a body, body frame
struct Wrench {
  double t = 0.0;                 // stamp [s]
  double fx = 0, fy = 0, fz = 0;  // [N]
  double mx = 0, my = 0, mz = 0;  // [N m]
};
Wrench DecodeWrench(const geometry_msgs_msg_dds__WrenchStamped_& m);

// towsim_msgs/CableState: a cable's nodes and its winch
struct CableState {
  uint64_t step = 0;
  double t = -1.0;               // stamp [s]; < 0: none (a default value)
  std::vector<double> x, y, z;   // node positions, world NED [m]
  std::vector<double> tension;   // axial force at each node [N]
  double paid_out_length = 0.0;  // [m]
  double winch_speed = 0.0;      // [m/s], + pays out
  double drum_tension = 0.0;     // [N]
  unsigned node_count = 0;
};
CableState DecodeCableState(const towsim_msgs_msg_dds__CableState_& m);

}  // namespace towsim::wire
