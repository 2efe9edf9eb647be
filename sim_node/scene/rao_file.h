#pragma once
// A vessel's displacement RAO table (docs/vessels.md "RAO files"): a CSV file
//   period,direction_deg,dof,amplitude,phase_deg
//   8.0,180,heave,0.83,12.5
//   ...
// period [s] of the wave, > 0; direction_deg the direction the wave travels toward, relative
// to the heading, from the bow toward starboard (0 following seas, 90 waves travelling toward
// starboard, 180 head seas), within [-180, 360]; dof one of surge, sway, heave, roll, pitch,
// yaw (signs: core/vessel.h); amplitude >= 0 per metre of wave amplitude, in m/m (surge, sway,
// heave) or deg/m (roll, pitch, yaw); phase_deg the lag of the response's maximum behind the
// wave crest at the vessel's reference point [deg]. Text after '#' is a comment; blank lines
// and blanks around fields are ignored (scene/csv_data_file.h). Rows may come in any order.
//
// The table's grid is the union of the periods and the union of the directions of all rows;
// each dof the file gives must give every (period, direction) of the grid exactly once. A dof
// the file does not give is zero (its vectors in the RaoTable are left empty). When the largest
// direction minus the smallest is 360 (within 1e-9 deg) the table covers the full circle
// (periodic_directions): its two end columns are the same direction, so they must agree
// (amplitudes within 1e-9, phases within 1e-9 deg modulo 360, the phase not compared where both
// amplitudes are within 1e-9 of 0) and the last one is dropped. A span above 360 is refused
// (the same direction would be given twice).
//
// Stored in SI: periods [s], directions [rad] (strictly increasing), amplitudes [m/m] or
// [rad/m], phases [rad]. `extrapolate` is left false: it is the scene's key, the caller's.

#include <string>

#include "core/vessel.h"

namespace towsim::scene {

// Reads and checks the RAO file at `path`; `key` is the scene key that named it (e.g.
// bodies.ship.raos), used in the messages. Throws ConfigError(key, value, "<file>:<line>",
// rule), e.g.
//   bodies.ship.raos = nan (ship_raos.csv:14): amplitude must be a finite number >= 0 ...
core::RaoTable ReadRaoFile(const std::string& path, const std::string& key);

}  // namespace towsim::scene
