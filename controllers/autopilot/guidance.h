#pragma once
// Waypoint guidance for the autopilot (pure, no DDS): lookahead-based line-of-sight (LOS)
// steering along straight legs, waypoint switching, and the legs of a lawn-mower survey.
// Frames: world NED, x north, y east; a heading psi points along (cos psi, sin psi).
//
// LOS (Fossen 2011, §10.3.2): for the leg from A to B with path angle
// alpha = atan2(B_y - A_y, B_x - A_x), the along-track distance s = (p - A) . t and the
// cross-track error e = (p - A) . n, t = (cos alpha, sin alpha), n = (-sin alpha, cos alpha)
// (e > 0: starboard of the leg); the desired heading psi_d = alpha + atan(-e / Delta) points
// at the spot `Delta` (lookahead) ahead on the leg, so e decays like exp(-U t / Delta) for
// small e.
// Switching: the target B is reached when |p - B| <= acceptance radius, or when the vehicle
// has passed B's normal plane (s >= |B - A|) without entering the circle (so a vehicle whose
// turning circle is wider than the acceptance circle never orbits a waypoint).

#include <string>
#include <vector>

namespace towsim::controllers {

struct Waypoint {
  double x = 0.0, y = 0.0;  // [m] world NED
};

struct LosResult {
  double heading = 0.0;     // psi_d [rad], in (-pi, pi]
  double path_angle = 0.0;  // alpha [rad]
  double along = 0.0;       // s [m]
  double cross = 0.0;       // e [m], > 0 starboard of the leg
  double leg_length = 0.0;  // |B - A| [m]
};

// LOS on the leg a -> b at the position (x, y), lookahead > 0 [m]
LosResult LineOfSight(const Waypoint& a, const Waypoint& b, double x, double y, double lookahead);

// A lawn-mower survey: `legs` parallel legs of `leg_length` along `heading`, `spacing` apart,
// the first from `origin`; turn = +1: the pattern steps to starboard of the first leg, -1 to
// port. Waypoints: start and end of each leg in order (2 * legs points), alternating direction.
struct LawnMowerParams {
  Waypoint origin;
  double heading = 0.0;       // of the first leg [rad]
  double leg_length = 200.0;  // [m] > 0
  double spacing = 100.0;     // [m] > 0
  int legs = 3;               // >= 1
  int turn = 1;               // +1 starboard, -1 port
};
std::vector<Waypoint> LawnMower(const LawnMowerParams& p);

// follows a list of waypoints: the first leg runs from the position at the first call
struct WaypointTracker {
  std::vector<Waypoint> waypoints;
  double acceptance_radius = 30.0;  // [m]
  double lookahead = 60.0;          // [m]
  // state
  bool started = false;
  size_t target = 0;               // index of the waypoint being steered to; == size(): done
  Waypoint from;                   // start of the current leg
  std::vector<double> reached_at;  // time each waypoint was reached [s]
  std::vector<double> miss;        // distance to it when it was taken as reached [m]

  bool done() const { return target >= waypoints.size(); }
};

// the desired heading at time t [s], position (x, y) [m], heading yaw [rad]; switches
// waypoints; once all are reached, holds the last leg's path angle
double TrackWaypoints(WaypointTracker& tracker, double t, double x, double y, double yaw);

}  // namespace towsim::controllers
