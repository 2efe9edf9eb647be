#include "autopilot/guidance.h"

#include <cmath>

#include "common/laws.h"

namespace towsim::controllers {

LosResult LineOfSight(const Waypoint& a, const Waypoint& b, double x, double y, double lookahead) {
  LosResult r;
  const double dx = b.x - a.x, dy = b.y - a.y;
  r.leg_length = std::hypot(dx, dy);
  r.path_angle = std::atan2(dy, dx);
  const double c = std::cos(r.path_angle), s = std::sin(r.path_angle);
  r.along = (x - a.x) * c + (y - a.y) * s;
  r.cross = -(x - a.x) * s + (y - a.y) * c;
  r.heading = WrapPi(r.path_angle + std::atan(-r.cross / lookahead));
  return r;
}

std::vector<Waypoint> LawnMower(const LawnMowerParams& p) {
  std::vector<Waypoint> w;
  const double c = std::cos(p.heading), s = std::sin(p.heading);
  // along the first leg t = (c, s); the side the pattern steps to: starboard n = (-s, c)
  const double side = p.turn >= 0 ? 1.0 : -1.0;
  const double nx = -s * side, ny = c * side;
  for (int i = 0; i < p.legs; ++i) {
    const double ox = p.origin.x + i * p.spacing * nx, oy = p.origin.y + i * p.spacing * ny;
    const Waypoint near{ox, oy}, far{ox + p.leg_length * c, oy + p.leg_length * s};
    // even legs run out along t, odd legs back
    if (i % 2 == 0) {
      w.push_back(near);
      w.push_back(far);
    } else {
      w.push_back(far);
      w.push_back(near);
    }
  }
  return w;
}

double TrackWaypoints(WaypointTracker& k, double t, double x, double y, double yaw) {
  if (!k.started) {
    k.started = true;
    k.from = {x, y};
    k.target = 0;
    k.reached_at.assign(k.waypoints.size(), -1.0);
    k.miss.assign(k.waypoints.size(), -1.0);
  }
  // take every waypoint reached (within the circle, or passed)
  while (!k.done()) {
    const Waypoint& b = k.waypoints[k.target];
    const double distance = std::hypot(b.x - x, b.y - y);
    const LosResult los = LineOfSight(k.from, b, x, y, k.lookahead);
    const bool inside = distance <= k.acceptance_radius;
    const bool passed = los.leg_length > 0.0 && los.along >= los.leg_length;
    if (!inside && !passed && los.leg_length > 0.0) break;
    k.reached_at[k.target] = t;
    k.miss[k.target] = distance;
    k.from = b;
    ++k.target;
  }
  if (k.done()) {
    // hold the last leg's direction
    if (k.waypoints.size() >= 2) {
      const Waypoint& a = k.waypoints[k.waypoints.size() - 2];
      const Waypoint& b = k.waypoints.back();
      return std::atan2(b.y - a.y, b.x - a.x);
    }
    return yaw;
  }
  return LineOfSight(k.from, k.waypoints[k.target], x, y, k.lookahead).heading;
}

}  // namespace towsim::controllers
