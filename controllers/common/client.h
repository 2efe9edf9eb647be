#pragma once
// The controllers' DDS client: one participant on the node's domain that
//   - reads rt/<ns>/scene_info (which bodies exist and take commands),
//   - subscribes to rt/<ns>/<body>/odom and rt/<ns>/status (and, with `altitude`, to
//     rt/<ns>/<body>/altitude),
//   - publishes towsim_msgs ActuatorCommand on rt/<ns>/<body>/command, stamped with the step
//     (and sim time) of the state it answers, and with `winch` a towsim_msgs WinchCommand on
//     rt/<ns>/winch/command stamped alike (docs/winch_dds.md),
//   - optionally reads rt/<ns>/<cable>/state (`cable`, of the cable named `cable_name`:
//     paid-out length, winch speed, drum tension, nodes) and the odometry of one more body
//     (`observe`), for what the law reports,
//   - runs the lockstep loop: wait for a status of a new step, take the body's odometry of that
//     step, call the control law, publish; it ends when the node reports the end of its run
//     (finished, failed, stopped), on SIGINT/SIGTERM, or after `timeout` s without a new step;
//     after a RESET (a new run id) it drops the old run's odometry still queued.
// The topic names, QoS, decoders and the ROS 2 graph entry are the wire library's (wire/).
// It is a ROS 2 node `<ns>/<name>` (name: ClientOptions::name; wire/ros_graph.h), so
// `ros2 node list` shows it next to /towsim/sim_node.
// It needs CYCLONEDDS_URI (config/cyclonedds.xml: loopback only); without it the constructor
// throws with a clear message. With `security` (--security DIR/NAME) the participant runs DDS
// Security with that identity (docs/security.md; the setup is wire/security.h, shared with
// sim_node and the recording tools); an identity the plugins refuse throws SecurityError. Works in
// every DDS mode (realtime and fast answer each status they see; lockstep waits for the answer).

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "wire/decoders.h"
#include "wire/security.h"

namespace towsim::controllers {

// --security DIR/NAME refused (a missing file, a bad certificate or document): exit 2
using SecurityError = towsim::wire::SecurityError;

// the flag every controller takes for its DDS Security identity
inline constexpr const char* kSecurityFlag = "security";

struct ClientOptions {
  uint32_t domain = 0;
  std::string ns = "/towsim";
  std::string body;                 // the commanded body
  double timeout = 30.0;            // [s] of wall time without a new step (or scene_info) -> error
  std::string name = "controller";  // for messages, and the ROS 2 node name
  // when set (by another thread), the constructor's waits and Run end as on a stop signal
  const std::atomic<bool>* stop = nullptr;
  std::string security;  // --security DIR/NAME: DDS Security identity; "": none
  // also subscribe to rt/<ns>/<body>/altitude (sensor_msgs/Range, docs/sensors.md) and pass
  // the newest range of the step answered in BodyState::altitude
  bool altitude = false;
  // also publish the winch's command (Actuation::winch) with each answer; the node's scene
  // must have a winch (SceneInfo.has_winch), else the constructor throws
  bool winch = false;
  // also subscribe to rt/<ns>/<cable_name>/state and pass the newest sample stamped at most
  // the step's time in BodyState::cable
  bool cable = false;
  // the cable `cable` reads (SceneInfo.cables; the one cable of a scene is "cable"); a name the
  // node's scene does not have makes the constructor throw, naming the scene's cables
  std::string cable_name = "cable";
  // another body whose odometry of the step answered is passed in BodyState::observed ("":
  // none)
  std::string observe;
};

// the winch of the node's scene (SceneInfo), zeros without one
struct WinchInfo {
  bool present = false;
  double min_length = 0.0, max_length = 0.0;  // [m]
  double max_speed = 0.0;                     // [m/s]
  double max_acceleration = 0.0;              // [m/s^2]
};

// the newest cable state (ClientOptions::cable: t, paid_out_length, winch_speed,
// drum_tension, node_count, the nodes); t < 0: none yet
using CableSample = wire::CableState;

// another body's pose at the step answered (ClientOptions::observe); valid = false: none came
struct ObservedBody {
  bool valid = false;
  double x = 0, y = 0, z = 0;           // world NED [m]
  double roll = 0, pitch = 0, yaw = 0;  // ZYX [rad]
};

// the state of the body at one step, from its odometry
struct BodyState {
  uint64_t step = 0;
  double t = 0.0;                          // sim time [s]
  double x = 0, y = 0, z = 0;              // world NED [m]
  double roll = 0, pitch = 0, yaw = 0;     // ZYX [rad]
  double u = 0, v = 0, w = 0;              // body frame [m/s]
  double p = 0, q = 0, r = 0;              // body frame [rad/s]
  double x_dot = 0, y_dot = 0, z_dot = 0;  // world NED velocity [m/s]
  double dt = 0.0;  // sim time since the previous step answered (the scene's step first) [s]
  // with ClientOptions::altitude: the altimeter's range of this step [m] (+inf: no seabed in
  // range, REP 117); NaN when none came for this step (or not subscribed)
  double altitude = std::numeric_limits<double>::quiet_NaN();
  CableSample cable;      // with ClientOptions::cable
  ObservedBody observed;  // with ClientOptions::observe
};

// what the law wants of the winch (sent with ClientOptions::winch)
struct WinchDemand {
  enum class Mode { kSpeed, kLength };
  Mode mode = Mode::kSpeed;
  double value = 0.0;  // kSpeed: dL/dt [m/s], + pays out; kLength: the length to drive to [m]
};

struct Actuation {
  Actuation() = default;
  Actuation(double thrust_n, double rudder_rad, double elevator_rad)
      : thrust(thrust_n), rudder(rudder_rad), elevator(elevator_rad) {}
  double thrust = 0.0;    // [N]
  double rudder = 0.0;    // [rad]
  double elevator = 0.0;  // [rad]
  WinchDemand winch;      // published only with ClientOptions::winch
};

// CYCLONEDDS_URI, or throws std::runtime_error saying how to set it
std::string RequireDdsUri();

// " t_c top end": what a controller's --log line ends with when it reads a cable (--cable
// NAME, ClientOptions::cable; docs/controllers.md "Cables"): the newest cable sample's stamp
// t_c [s] (-1: none yet) and its axial tension at node 0 and at the last node [N] (nan without
// nodes), each "%.6f"
std::string CableLogColumns(const CableSample& cable);

// SIGINT / SIGTERM set a flag the loop polls (every 100 ms at most)
void InstallStopHandlers();
bool StopRequested();

class LockstepClient {
 public:
  using Law = std::function<Actuation(const BodyState&)>;

  explicit LockstepClient(const ClientOptions& options);  // throws std::runtime_error
  ~LockstepClient();
  LockstepClient(const LockstepClient&) = delete;
  LockstepClient& operator=(const LockstepClient&) = delete;

  // runs until the end of the node's run or a stop signal (returns 0), or a timeout / DDS
  // error (returns 1, message on stderr)
  int Run(const Law& law);

  uint64_t steps_answered() const { return answered_; }
  // the node's winch, from its scene_info
  const WinchInfo& winch() const;

 private:
  struct Impl;
  Impl* impl_;
  uint64_t answered_ = 0;
};

}  // namespace towsim::controllers
