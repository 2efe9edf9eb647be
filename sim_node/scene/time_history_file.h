#pragma once
// A vessel's time history of poses (docs/vessels.md "Time history files"): a CSV file
//   t,x,y,z,roll,pitch,yaw
//   0.0,0.0,0.0,0.0,0.0,0.0,0.0
//   ...
// t [s] strictly increasing; x, y, z the reference point in the world frame NED [m]; roll,
// pitch, yaw the ZYX Euler angles of the vessel's body frame [rad], roll within (-pi, pi],
// pitch within (-pi/2, pi/2), yaw any finite number. Text after '#' is a comment; blank lines
// and blanks around fields are ignored (scene/csv_data_file.h). At least two samples.
//
// Yaw is unwrapped on reading: a logger that writes yaw within (-pi, pi] jumps by 2 pi where the
// heading crosses south; a step of more than pi between consecutive samples is taken as such a
// wrap and 2 pi n added (n the integer that brings the step within [-pi, pi]), so the spline
// (core/pose_spline.h) sees a continuous heading. A vessel therefore cannot be logged turning
// by more than pi between two samples (at 1 Hz: 180 deg/s), which no ship does.

#include <string>

#include "core/vessel.h"

namespace towsim::scene {

// Reads and checks the time-history file at `path`; `key` is the scene key that named it
// (e.g. bodies.ship.time_history), used in the messages. Throws ConfigError(key, value,
// "<file>:<line>", rule), e.g.
//   bodies.ship.time_history = 4.5 (ship_log.csv:12): t must increase strictly: 4.5 after 4.5
//   at line 11
core::TimeHistory ReadTimeHistoryFile(const std::string& path, const std::string& key);

// Empty when the history covers the run, t from 0 to `duration` [s] (it starts at t <= 0 and
// ends at t >= duration); else a sentence naming its span and the duration, for the caller's
// ConfigError.
std::string TimeHistoryCoverageProblem(const core::TimeHistory& history, double duration);

}  // namespace towsim::scene
