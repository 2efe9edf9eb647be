#pragma once
// towsim_export --csv: a recording of a towsim node (MCAP, CDR payloads) back into the CSV
// files of docs/contract.md §5, with the columns and number formatting of io/csv_writer ("%.9g"), so
// that scripts (plot_paper.py, summarize.py) work on recordings as on `sim_node --csv` output.
//
// Topics used, under the namespace NS (default /towsim):
//   NS/<b>/odom        nav_msgs/Odometry      -> bodies.csv  (Euler ZYX from the quaternion,
//                                                 by the core's own EulerZYX)
//   NS/<b>/cable_force geometry_msgs/WrenchStamped -> forces.csv
//   NS/<c>/state       towsim_msgs/CableState -> <c>.csv per cable (NS/cable/state ->
//                                                 cable.csv for the one cable), and winch.csv
//                                                 (paid_out_length, winch_speed, drum_tension,
//                                                 node_count) from the first cable's when the
//                                                 scene info says the scene has a winch
//   NS/status          towsim_msgs/SimStatus  -> status.csv (wall_us = step_wall_time in us;
//                                                 the end-of-run repeat of a step is dropped)
//   NS/<b>/environment towsim_msgs/BodyEnvironment -> environment.csv (written, as by the node,
//                                                 only when the recording has these topics: a
//                                                 scene with a sea; NaN altitude as an empty field)
//                                                 the end-of-run repeat of a step is dropped;
//                                                 cable_length from the newest cable state
//                                                 at or before the status)
//   NS/scene_info      towsim_msgs/SceneInfo  -> the body order of the rows (else channel order)
//                                                 and the cables (else those recorded; the
//                                                 first one's paid-out length is status.csv's
//                                                 cable_length)
//   NS/<b>/command     towsim_msgs/ActuatorCommand -> commands.csv (t,body,step,thrust,rudder,
//                                                 elevator; t = the command's stamp; one row per
//                                                 message in recorded order; written only when
//                                                 the recording holds commands: towsim_record
//                                                 captures them, sim_node --record does not)
//   NS/<b>/actuator_state towsim_msgs/ActuatorState -> actuators.csv (the node's columns:
//                                                 commands, actuator states, failsafe as
//                                                 0 / 1; written only when the recording has
//                                                 these topics: commanded vehicles; the first
//                                                 message of a body and stamp)
// A row set is written per recorded time stamp; `t` is the status's exact sim_time where a
// status message has the same stamp, else the stamp (rounded to 1 ns by the node).
//   NS/<c>/start_force geometry_msgs/WrenchStamped -> forces.csv's rows of held cable ends:
//   NS/<c>/end_force                              frame world_ned: a fixed or driven support,
//                                                 row "<c>.start" / "<c>.end" after the
//                                                 bodies; frame <b>_frd: one attachment of a
//                                                 body held by several cable ends, row
//                                                 "<b>.<c>.<start|end>" after that body's total
//                                                 (the node's order, io/csv_writer.h)
// One run per recording: after a RESET the stamps repeat and the rows of equal stamps are
// merged.

#include <cstdint>
#include <string>

#include "io/mcap_reader.h"

namespace towsim::app {

struct ExportCounts {
  std::uint64_t bodies_rows = 0, cable_rows = 0, forces_rows = 0, status_rows = 0;
  std::uint64_t environment_rows = 0;
  std::uint64_t winch_rows = 0;  // a scene with a winch
  std::uint64_t commands_rows = 0;  // a recording with the vehicles' commands
  std::uint64_t actuators_rows = 0;  // a recording with the vehicles' actuator states
};

// reads `reader_path` (McapReader::Open, or Recover if `recover`) and writes the four files
// (and environment.csv, actuators.csv, commands.csv, winch.csv, above)
// into `dir` (created if needed). Throws mcap::McapError / cdr::CdrError (bad file: the
// message names the offset and, for a payload, the topic), std::invalid_argument (no towsim
// topics under `ns`, a topic with an unexpected type) or std::runtime_error (writing failed).
ExportCounts ExportCsv(const std::string& mcap_path, const std::string& dir, const std::string& ns,
                       bool recover);
// the same from a reader opened (or recovered) by the caller
ExportCounts ExportCsv(const io::McapReader& reader, const std::string& dir, const std::string& ns);

}  // namespace towsim::app
