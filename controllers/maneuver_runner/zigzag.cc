#include "maneuver_runner/zigzag.h"

#include "common/laws.h"

namespace towsim::controllers {

ManeuverCommand ZigZagStep(const ZigZagParams& p, ZigZagState& s, double t, double yaw) {
  ManeuverCommand c;
  c.thrust = p.thrust;
  if (t < p.start - 1e-9) return c;
  if (!s.started) {
    s.started = true;
    s.t_execute = t;
    s.psi0 = yaw;
    s.last_yaw = yaw;
    s.change = 0.0;
    s.direction = p.port_first ? -1 : 1;
  }
  // unwrapped heading change: each increment folded into (-pi, pi]
  s.change += WrapPi(yaw - s.last_yaw);
  s.last_yaw = yaw;
  if (s.finished) return c;
  // the overshoot of the latest reversal: d (psi - psi_0) - psi, d the direction before it
  if (!s.reversals.empty()) {
    ZigZagOvershoot& o = s.reversals.back();
    const double past = -s.direction * s.change - p.switch_angle;
    if (past > o.overshoot) {
      o.overshoot = past;
      o.t_peak = t;
    }
  }
  // switch when the heading change reaches the switch angle in the current direction
  if (s.direction * s.change >= p.switch_angle) {
    if (static_cast<int>(s.reversals.size()) >= p.reversals) {
      s.finished = true;
      s.t_finished = t;
      return c;  // rudder 0
    }
    s.direction = -s.direction;
    ZigZagOvershoot o;
    o.t_reversal = t;
    o.t_peak = t;
    o.overshoot = -s.direction * s.change - p.switch_angle;  // already past it by this much
    s.reversals.push_back(o);
  }
  c.rudder = s.direction * p.rudder;
  return c;
}

ZigZagResults ZigZagSheet(const ZigZagState& s) {
  ZigZagResults r;
  r.t_execute = s.t_execute;
  r.finished = s.finished;
  const int n = static_cast<int>(s.reversals.size());
  if (n > 0) r.initial_turning_time = s.reversals[0].t_reversal - s.t_execute;
  // reversal k's overshoot is complete once the next reversal (or the end) happened
  const int complete = s.finished ? n : n - 1;
  for (int k = 0; k < complete; ++k) {
    r.overshoots.push_back(s.reversals[k].overshoot);
    r.times_to_check_yaw.push_back(s.reversals[k].t_peak - s.reversals[k].t_reversal);
  }
  for (int k = 0; k + 2 < n; ++k) {
    r.periods.push_back(s.reversals[k + 2].t_reversal - s.reversals[k].t_reversal);
  }
  return r;
}

}  // namespace towsim::controllers
