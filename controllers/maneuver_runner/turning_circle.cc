#include "maneuver_runner/turning_circle.h"

#include <cmath>

#include "common/laws.h"

namespace towsim::controllers {

ManeuverCommand TurningCircleStep(const TurningCircleParams& p, TurningCircleState& s, double t,
                                  double yaw) {
  ManeuverCommand c;
  c.thrust = p.thrust;
  if (t < p.start - 1e-9) return c;
  if (!s.started) {
    s.started = true;
    s.last_yaw = yaw;
  }
  s.change += WrapPi(yaw - s.last_yaw);
  s.last_yaw = yaw;
  if (!s.ended && p.until_turn > 0.0 && std::abs(s.change) >= p.until_turn) s.ended = true;
  c.rudder = s.ended ? 0.0 : p.rudder;
  return c;
}

bool FitCircle(const std::vector<double>& x, const std::vector<double>& y, double* cx, double* cy,
               double* radius) {
  const size_t n = x.size();
  if (n < 3 || y.size() != n) return false;
  // centred coordinates for conditioning; normal equations of [x y 1] [D E F]^T = -(x^2+y^2)
  double mx = 0, my = 0;
  for (size_t i = 0; i < n; ++i) mx += x[i], my += y[i];
  mx /= n;
  my /= n;
  double a[3][4] = {};
  for (size_t i = 0; i < n; ++i) {
    const double u = x[i] - mx, v = y[i] - my, rhs = -(u * u + v * v);
    const double row[3] = {u, v, 1.0};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) a[r][c] += row[r] * row[c];
      a[r][3] += row[r] * rhs;
    }
  }
  // Gaussian elimination with partial pivoting on the 3 x 3 system
  for (int k = 0; k < 3; ++k) {
    int piv = k;
    for (int r = k + 1; r < 3; ++r) {
      if (std::abs(a[r][k]) > std::abs(a[piv][k])) piv = r;
    }
    if (std::abs(a[piv][k]) < 1e-12) return false;
    for (int c = 0; c < 4; ++c) std::swap(a[k][c], a[piv][c]);
    for (int r = 0; r < 3; ++r) {
      if (r == k) continue;
      const double f = a[r][k] / a[k][k];
      for (int c = k; c < 4; ++c) a[r][c] -= f * a[k][c];
    }
  }
  const double d = a[0][3] / a[0][0], e = a[1][3] / a[1][1], f = a[2][3] / a[2][2];
  // centre (-D/2, -E/2), radius^2 = (D^2 + E^2)/4 - F
  const double r2 = 0.25 * (d * d + e * e) - f;
  if (!(r2 > 0.0)) return false;
  *cx = mx - 0.5 * d;
  *cy = my - 0.5 * e;
  *radius = std::sqrt(r2);
  return true;
}

namespace {

// the sample values interpolated where |change| crosses `angle`; false if never
bool Crossing(const std::vector<TrackSample>& track, const std::vector<double>& change,
              double angle, TrackSample* at) {
  for (size_t i = 1; i < track.size(); ++i) {
    const double a = std::abs(change[i - 1]), b = std::abs(change[i]);
    if (a < angle && b >= angle) {
      const double w = (angle - a) / (b - a);
      const TrackSample& p = track[i - 1];
      const TrackSample& q = track[i];
      at->t = p.t + w * (q.t - p.t);
      at->x = p.x + w * (q.x - p.x);
      at->y = p.y + w * (q.y - p.y);
      return true;
    }
  }
  return false;
}

}  // namespace

TurningCircleResults TurningCircleSheet(const std::vector<TrackSample>& track, double steady_from) {
  TurningCircleResults r;
  if (track.empty()) return r;
  const TrackSample& e = track.front();
  r.t_execute = e.t;
  std::vector<double> change(track.size(), 0.0);
  for (size_t i = 1; i < track.size(); ++i) {
    change[i] = change[i - 1] + WrapPi(track[i].yaw - track[i - 1].yaw);
  }
  r.total_turn = std::abs(change.back());
  const double cx = std::cos(e.yaw), sy = std::sin(e.yaw);
  // advance along the approach course, transfer to its starboard side
  auto advance = [&](const TrackSample& s) { return (s.x - e.x) * cx + (s.y - e.y) * sy; };
  auto transfer = [&](const TrackSample& s) { return -(s.x - e.x) * sy + (s.y - e.y) * cx; };
  TrackSample s;
  if (Crossing(track, change, 0.5 * kPi, &s)) {
    r.has_90 = true;
    r.advance = advance(s);
    r.transfer = transfer(s);
    r.time_90 = s.t - e.t;
  }
  if (Crossing(track, change, kPi, &s)) {
    r.has_180 = true;
    r.tactical_diameter = transfer(s);
    r.time_180 = s.t - e.t;
  }
  // the steady circle: from steady_from on, if it covers at least another 180 deg
  if (r.total_turn >= steady_from + kPi) {
    std::vector<double> xs, ys;
    double speed = 0, rate = 0;
    for (size_t i = 0; i < track.size(); ++i) {
      if (std::abs(change[i]) < steady_from) continue;
      xs.push_back(track[i].x);
      ys.push_back(track[i].y);
      speed += track[i].speed;
      rate += track[i].yaw_rate;
    }
    double radius = 0;
    if (FitCircle(xs, ys, &r.steady_center_x, &r.steady_center_y, &radius)) {
      r.has_steady = true;
      r.steady_diameter = 2.0 * radius;
      r.steady_speed = speed / xs.size();
      r.steady_yaw_rate = rate / xs.size();
      if (r.steady_yaw_rate != 0.0) {
        r.kinematic_diameter = 2.0 * r.steady_speed / std::abs(r.steady_yaw_rate);
      }
    }
  }
  return r;
}

}  // namespace towsim::controllers
