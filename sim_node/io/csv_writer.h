#pragma once
// CSV output of a run (docs/contract.md §5): four files in one directory, one row set per Write(), and
// a fifth, environment.csv, when the scene has a sea (HasSea below).
//
//   bodies.csv  t,body,x,y,z,roll,pitch,yaw,u,v,w,p,q,r
//               one row per body, spheres then vehicles (Simulation's body order): position
//               p_WB of the body origin in world NED [m], Euler angles (ZYX) of q_WB [rad],
//               velocity v_WB_B and angular rate w_WB_B in the body frame [m/s, rad/s]
//   cable.csv   t,node,x,y,z,tension
//               node position r in world NED [m], axial force at the node [N]; a network
//               (cables:) writes one such file per cable, <cable>.csv
//   forces.csv  t,body,fx,fy,fz,mx,my,mz
//               force and moment (about the body origin) the cable exerts on each body, body
//               frame [N, N m] (Simulation::BodyCableWrench); plus
//               rows "cable.start" / "cable.end" (<cable>.start / <cable>.end in a network)
//               for a cable end held by a fixed or driven support (not a body): the force
//               the cable exerts on the support, world frame; and a body held by two or more
//               cable ends has, after its total, one row per attachment,
//               "<body>.<cable>.<start|end>", the force and moment of that end alone (body
//               frame, about the body origin)
//   status.csv  t,step,newton_iterations,residual,wall_us,cable_length
//               Newton iterations and final residual [N] of the step that led here, its
//               wall time [us] as measured by the caller, and the paid-out unstretched cable
//               length [m] (Simulation::cable_length: cable.length in a scene without a winch;
//               docs/winch.md)
//   environment.csv  t,body,wave_elevation,altitude,depth,current_u,current_v,current_w
//               one row per body, only when HasSea(model.environment) (a calm scene writes
//               exactly the four files above): the surface elevation eta at the body origin
//               (positive up) [m], the altitude above the seabed straight below [m] (an EMPTY
//               field without a seabed; the files never hold NaN), the depth below the
//               instantaneous surface z + eta [m], and the water's velocity there (current +
//               wave orbital velocity, world NED) [m/s] (Simulation::BodyAltitude, BodyDepth,
//               SurfaceElevationAt, WaterVelocityAt; docs/environment.md)
//
//   winch.csv   t,paid_out_length,winch_speed,drum_tension,node_count,
//               command_mode,command_value,failsafe
//               one file per winch, <winch name>.csv (winch.csv for a scene's one winch; a
//               scene without one writes none), one row per Write: the paid-out unstretched
//               length [m], dL/dt (+ pays out) [m/s], the axial tension at the cable's start
//               (the drum) [N] and the nodes in use (the rows of its cable's CSV at that time)
//               (Simulation::cable_length, winch_speed, DrumTension, num_nodes;
//               docs/winch_dds.md); then, appended, the command in force during the step that
//               ended at t (Simulation::winch_command: the script's offline, the arbiter's
//               choice over DDS): its mode, 0 speed or 1 length (WinchCommand.SPEED / LENGTH),
//               its value [m/s or m], and 1 if the winch was in failsafe during that step, else
//               0 (offline: always 0)
//
//   actuators.csv  t,body,thrust_command,rudder_command,elevator_command,
//                  thrust,rudder,elevator,failsafe
//               one row per vehicle (Model::vehicles order), only when the scene has vehicles:
//               the command in force during the step that ended at t (Simulation::
//               vehicle_command: the script's offline, the arbiter's choice over DDS; at t = 0
//               the initial command), then the actuator states VehicleState::actuator
//               [kThrust, kRudder, kElevator] after their rate limits and lags [N, rad, rad],
//               and 1 if the vehicle was in failsafe (dds/command_arbiter.h) during that step,
//               else 0 (offline: always 0) (docs/command_line.md, "Output files")
//
// And one file that only towsim_export writes (app/export/export_csv.h), from a recording:
//   commands.csv  t,body,step,thrust,rudder,elevator
//               one row per ActuatorCommand recorded on rt/<ns>/<body>/command, in recorded
//               order, only when the recording holds any: the command's header stamp [s], the
//               step it answers, thrust [N], rudder and elevator [rad] as sent (before the
//               node's checks: a rejected NaN is written as nan, a clamped value as sent)
//
// Spheres: their frame stays aligned with the world, so roll = pitch = yaw = 0, p = q = r = 0,
// (u, v, w) is the world velocity and the moment is 0.
//
// Numbers are written with 9 significant digits, exactly as printf's "%.9g" writes them
// (io/csv_number.h). Rows are kept in memory and written to the operating system in whole
// row sets: the first Write's at once, then whenever flush_period of wall time (kFlushPeriod,
// 0.25 s) has passed since the last write or kMaxPendingBytes wait, and at Close (a signal
// stops sim_node at a step boundary and closes the files). So the files hold only complete
// rows at every moment, and a process killed outright (SIGKILL) loses at most the rows of its
// last flush_period; a short offline run is written in a few system calls instead of one per
// file and row set (docs/command_line.md, "Output files"; docs/benchmarks.md, "Against
// MoorDyn").

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "core/simulation.h"
#include "io/csv_number.h"
#include "io/text_buffer.h"

namespace towsim::io {

// the header lines of the four files (above)
inline constexpr char kCsvBodiesHeader[] = "t,body,x,y,z,roll,pitch,yaw,u,v,w,p,q,r";
inline constexpr char kCsvCableHeader[] = "t,node,x,y,z,tension";
inline constexpr char kCsvForcesHeader[] = "t,body,fx,fy,fz,mx,my,mz";
inline constexpr char kCsvStatusHeader[] = "t,step,newton_iterations,residual,wall_us,cable_length";
inline constexpr char kCsvEnvironmentHeader[] =
    "t,body,wave_elevation,altitude,depth,current_u,current_v,current_w";
// the winch's state columns (towsim_export writes these alone, from CableState), and the
// node's file: those and its command's, appended (above)
inline constexpr char kCsvWinchHeader[] = "t,paid_out_length,winch_speed,drum_tension,node_count";
inline constexpr char kCsvWinchCommandHeader[] =
    "t,paid_out_length,winch_speed,drum_tension,node_count,command_mode,command_value,failsafe";
inline constexpr char kCsvActuatorsHeader[] =
    "t,body,thrust_command,rudder_command,elevator_command,thrust,rudder,elevator,failsafe";
inline constexpr char kCsvCommandsHeader[] = "t,body,step,thrust,rudder,elevator";

// whether a run in `env` writes environment.csv: it has waves, a (non-zero) current or a seabed
bool HasSea(const core::Environment& env);

// a name as a CSV field: quoted (RFC 4180) only if it holds a comma, quote or line break
std::string CsvField(const std::string& name);

// one environment.csv row (header kCsvEnvironmentHeader) at time t [s] for `body`: the altitude
// NaN (no seabed) as an empty field; for CsvWriter and towsim_export, so that both print alike
void WriteEnvironmentRow(std::FILE* f, double t, const std::string& body, double wave_elevation,
                         double altitude, double depth, double u, double v, double w);

// one actuators.csv row (header kCsvActuatorsHeader) at time t [s] for the vehicle `body`: the
// command in force, the actuator states of `state` and the failsafe flag as 0 / 1
void WriteActuatorRow(std::FILE* f, double t, const std::string& body,
                      const core::VehicleCommand& command, const core::VehicleState& state,
                      bool failsafe);

// one commands.csv row (header kCsvCommandsHeader): a recorded command stamped t [s] for `body`
void WriteCommandRow(std::FILE* f, double t, const std::string& body, unsigned long long step,
                     double thrust, double rudder, double elevator);

class CsvWriter {
 public:
  // wall time [s] after which a Write passes its rows to the operating system (above)
  static constexpr double kFlushPeriod = 0.25;
  // rows of the node and force files waiting [bytes] that are written whatever the time:
  // small enough that the buffers, reused after each write, stay in the cache and do not
  // grow with the run (a buffer of the whole run's rows cost a page fault per 4 kB)
  static constexpr size_t kMaxPendingBytes = size_t{64} << 10;

  // creates `dir` (and its parents) if needed, truncates the four files (and environment.csv
  // when `sea`, i.e. HasSea of the scene; winch.csv when `winch`, the scene has a winch;
  // actuators.csv when `vehicles`, the scene has vehicles) and writes their headers; throws
  // std::runtime_error naming the path if a file cannot be opened
  // `cables`: the cables' names (Model::cables order), one <name>.csv each; `winches`: the
  // winches' names (winch w on cable w), one <name>.csv each (empty with `winch`: {"winch"});
  // `flush_period`: see kFlushPeriod (0: every Write is written at once)
  explicit CsvWriter(const std::string& dir, bool sea = false, bool winch = false,
                     bool vehicles = false,
                     const std::vector<std::string>& cables = {"cable"},
                     const std::vector<std::string>& winches = {},
                     double flush_period = kFlushPeriod);
  ~CsvWriter();  // writes the rows still held and closes, ignoring errors
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  // appends one row set for the current state of `sim`: one row per body, one per cable node,
  // one per body and held cable end in forces.csv, one status row (and one per body in
  // environment.csv when it is written, one per vehicle in actuators.csv). `status` is the
  // status of the step that produced the state (a default StepStatus at t = 0), `wall_us` its
  // wall time; `failsafe[v]` whether vehicle v was in failsafe during that step (a vehicle
  // beyond its size: not; offline: empty), `winch_failsafe[w]` the same for winch w. The rows
  // reach the files when the writer flushes (above). Throws std::runtime_error if writing
  // fails (e.g. disk full), at the flush that fails.
  void Write(const core::Simulation& sim, const core::StepStatus& status, long wall_us,
             const std::vector<bool>& failsafe = {},
             const std::vector<bool>& winch_failsafe = {});

  // writes the rows still held, flushes and closes the files; further Write() calls throw.
  // Throws std::runtime_error if the final flush fails.
  void Close();

  const std::string& dir() const { return dir_; }

 private:
  struct File {
    std::string path;
    std::FILE* f = nullptr;
    TextBuffer pending;  // whole rows not yet written
  };
  void Open(File& file, const char* name, const char* header);
  std::vector<File*> Files();  // every file, open or not
  // writes and flushes the file's pending rows; throws OutputError naming it on failure
  void Flush(File& file);
  void FlushAll();
  size_t PendingBytes() const;
  // forces.csv's per-attachment rows of body b (Write)
  void WriteAttachments(const core::Simulation& sim, int b);
  void WriteEnvironment(const core::Simulation& sim);
  void WriteActuators(const core::Simulation& sim, const std::vector<bool>& failsafe);

  std::string dir_;
  bool winch_ = false;
  File bodies_;
  File cable_;                     // the first cable's
  std::vector<File> more_cables_;  // the others' (a network)
  File forces_;
  File status_;
  File environment_;  // f == nullptr: not written (a calm scene)
  std::vector<File> winch_files_;  // one per winch (none: no winch)
  File actuators_;    // f == nullptr: not written (no vehicles)
  // the bodies' names as CSV fields (CsvField), from the first Write: a writer serves one
  // simulation, whose bodies do not change
  std::vector<std::string> body_fields_;
  std::vector<std::string> support_fields_;  // "<cable>.start", "<cable>.end" per cable
  double flush_period_ = kFlushPeriod;
  bool flushed_ = false;  // a Write has been flushed
  std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace towsim::io
