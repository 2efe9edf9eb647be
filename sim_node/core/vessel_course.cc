#include "core/vessel_course.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.h"
#include "core/gauss_quadrature.h"

namespace towsim::core {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMaxQuadraturePiece = 0.5;  // [s]

// x wrapped into (-pi, pi]
double WrapAngle(double x) {
  double w = std::remainder(x, 2.0 * kPi);
  if (w <= -kPi) w += 2.0 * kPi;
  return w;
}

}  // namespace

void VesselCourse::Eval(const Piece& p, double t, double* f, double* df, double* integral) {
  const double s = t - p.t0;
  if (p.T <= 0.0 || s <= 0.0) {  // a hold, or before the ramp
    *f = p.fa;
    *df = 0.0;
    *integral = p.ga + p.fa * s;
    return;
  }
  const double d = p.fb - p.fa;
  if (s >= p.T) {  // after the ramp: f_b, and the ramp's integral (f_a + f_b) T / 2
    *f = p.fb;
    *df = 0.0;
    *integral = p.ga + 0.5 * (p.fa + p.fb) * p.T + p.fb * (s - p.T);
    return;
  }
  const double w = kPi / p.T;
  *f = p.fa + 0.5 * d * (1.0 - std::cos(w * s));
  *df = 0.5 * d * w * std::sin(w * s);
  *integral = p.ga + p.fa * s + 0.5 * d * (s - std::sin(w * s) / w);
}

int VesselCourse::Find(const std::vector<Piece>& pieces, double t) {
  // the last piece with t0 <= t (the first for t before it)
  int lo = 0;
  for (int hi = static_cast<int>(pieces.size()) - 1; lo < hi;) {
    const int mid = (lo + hi + 1) / 2;
    if (pieces[mid].t0 <= t)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

void VesselCourse::CutAt(std::vector<Piece>* pieces, double at, double* f, double* integral) {
  const int k = Find(*pieces, at);
  double df = 0.0;
  Eval((*pieces)[k], at, f, &df, integral);
  pieces->resize(k + 1);
  if (k > 0 && (*pieces)[k].t0 >= at) pieces->pop_back();
  pieces->back().t1 = at;
}

void VesselCourse::Append(std::vector<Piece>* pieces, double t0, double T, double fa, double fb,
                          double ga) {
  if (!pieces->empty()) pieces->back().t1 = t0;
  Piece p;
  p.t0 = t0;
  p.t1 = kInf;
  p.T = T;
  p.fa = fa;
  p.fb = T > 0.0 ? fb : fa;
  p.ga = ga;
  pieces->push_back(p);
}

void VesselCourse::RampTo(std::vector<Piece>* pieces, double at, double fb, double limit) {
  double f = 0.0, g = 0.0;
  CutAt(pieces, at, &f, &g);
  const double T = 0.5 * kPi * std::abs(fb - f) / limit;
  if (T > 0.0) {
    Append(pieces, at, T, f, fb, g);
    Append(pieces, at + T, 0.0, fb, fb, g + 0.5 * (f + fb) * T);
  } else {
    Append(pieces, at, 0.0, f, f, g);
  }
}

void VesselCourse::Heading(double at, double target, double rate, double alpha) {
  double r0 = 0.0, psi0 = 0.0;
  CutAt(&turn_, at, &r0, &psi0);
  const double d = WrapAngle(target - psi0);
  const double sign = d >= 0.0 ? 1.0 : -1.0;
  const double dist = std::abs(d);
  const double rho0 = sign * r0;  // the present turn rate in the turn's direction
  const double k = 0.5 * kPi / alpha;  // a ramp's duration per unit change of r
  double t = at, psi = psi0;
  // a ramp of r from ra to rb (in the turn's direction), appended
  const auto ramp = [&](double ra, double rb, double T) {
    if (T <= 0.0) return;
    Append(&turn_, t, T, sign * ra, sign * rb, psi);
    psi += sign * 0.5 * (ra + rb) * T;
    t += T;
  };
  const double R = rate;
  const double up = k * std::abs(R - rho0), down = k * R;
  const double hold = (dist - 0.5 * (rho0 + R) * up - 0.5 * R * down) / R;
  if (hold >= 0.0) {
    ramp(rho0, R, up);
    if (hold > 0.0) {
      Append(&turn_, t, 0.0, sign * R, sign * R, psi);
      psi += sign * R * hold;
      t += hold;
    }
    ramp(R, 0.0, down);
  } else {
    // the peak P that ends at the target with no hold: pi (2 P^2 - rho0^2) / (4 alpha) = dist
    const double p = std::sqrt(0.5 * (dist / (0.5 * k) + rho0 * rho0));
    if (p >= rho0) {
      ramp(rho0, p, k * (p - rho0));
      ramp(p, 0.0, k * p);
    } else {  // turning too fast to stop at the target: stop at once (it overshoots)
      ramp(rho0, 0.0, k * rho0);
    }
  }
  Append(&turn_, t, 0.0, 0.0, 0.0, psi);
}

VesselCourse::VesselCourse(const Vessel& vessel) {
  z_ = vessel.position.z();
  Append(&speed_, 0.0, 0.0, vessel.speed, vessel.speed, 0.0);
  Append(&turn_, 0.0, 0.0, 0.0, 0.0, vessel.euler.z());
  std::vector<CourseChange> changes = vessel.course;
  std::stable_sort(changes.begin(), changes.end(),
                   [](const CourseChange& a, const CourseChange& b) { return a.at < b.at; });
  for (const CourseChange& c : changes) {
    const double at = std::max(c.at, 0.0);
    if (c.set_speed) RampTo(&speed_, at, c.speed, vessel.max_acceleration);
    if (c.set_heading)
      Heading(at, c.heading, std::abs(c.turn_rate), vessel.max_yaw_acceleration);
    else if (c.set_turn_rate)
      RampTo(&turn_, at, c.turn_rate, vessel.max_yaw_acceleration);
  }
  // the joints of both lists and the positions there
  for (const Piece& p : speed_) joints_.push_back(p.t0);
  for (const Piece& p : turn_) joints_.push_back(p.t0);
  std::sort(joints_.begin(), joints_.end());
  joints_.erase(std::unique(joints_.begin(), joints_.end()), joints_.end());
  joint_position_.resize(joints_.size());
  joint_position_[0] = vessel.position.head<2>();
  for (size_t j = 1; j < joints_.size(); ++j)
    joint_position_[j] = Integrate(joints_[j - 1], joint_position_[j - 1], joints_[j]);
}

Eigen::Vector2d VesselCourse::Velocity(double t) const {
  double u = 0.0, du = 0.0, x = 0.0, r = 0.0, dr = 0.0, psi = 0.0;
  Eval(speed_[Find(speed_, t)], t, &u, &du, &x);
  Eval(turn_[Find(turn_, t)], t, &r, &dr, &psi);
  return u * Eigen::Vector2d(std::cos(psi), std::sin(psi));
}

Eigen::Vector2d VesselCourse::Integrate(double t0, const Eigen::Vector2d& x0, double t) const {
  // no joint lies in (t0, t): each quantity is one piece there
  const Piece& s = speed_[Find(speed_, t0)];
  const Piece& r = turn_[Find(turn_, t0)];
  const bool speed_ramps = s.T > 0.0 && t0 < s.t0 + s.T;
  const bool turn_ramps = r.T > 0.0 && t0 < r.t0 + r.T;
  if (!speed_ramps && !turn_ramps) {
    // U and r constant: a straight line, or an arc of radius U / r
    double u = 0.0, du = 0.0, dist = 0.0, rate = 0.0, drate = 0.0, psi0 = 0.0;
    Eval(s, t0, &u, &du, &dist);
    Eval(r, t0, &rate, &drate, &psi0);
    const double dt = t - t0;
    if (std::abs(rate * dt) < 1e-9) {
      // to second order in r dt: the chord of the arc
      const double psi = psi0 + 0.5 * rate * dt;
      return x0 + u * dt * Eigen::Vector2d(std::cos(psi), std::sin(psi));
    }
    const double psi1 = psi0 + rate * dt;
    return x0 + (u / rate) * Eigen::Vector2d(std::sin(psi1) - std::sin(psi0),
                                             std::cos(psi0) - std::cos(psi1));
  }
  const GaussRule<5> g = Gauss5();
  const int n = std::max(1, static_cast<int>(std::ceil((t - t0) / kMaxQuadraturePiece)));
  const double h = (t - t0) / n;
  Eigen::Vector2d x = x0;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 5; ++k) x += h * g.weight[k] * Velocity(t0 + (i + g.xi[k]) * h);
  return x;
}

CourseSample VesselCourse::At(double t) const {
  CourseSample out;
  double u = 0.0, du = 0.0, dist = 0.0, r = 0.0, dr = 0.0, psi = 0.0;
  Eval(speed_[Find(speed_, t)], t, &u, &du, &dist);
  Eval(turn_[Find(turn_, t)], t, &r, &dr, &psi);
  const auto j = std::upper_bound(joints_.begin(), joints_.end(), t) - joints_.begin();
  const size_t k = j > 0 ? static_cast<size_t>(j - 1) : 0;
  const Eigen::Vector2d xy = t > joints_[k] ? Integrate(joints_[k], joint_position_[k], t)
                                            : joint_position_[k];
  const Eigen::Vector2d e(std::cos(psi), std::sin(psi)), n(-std::sin(psi), std::cos(psi));
  out.position << xy, z_;
  out.velocity << u * e, 0.0;
  // d/dt (U e) = dU/dt e + U r n
  out.acceleration << du * e + u * r * n, 0.0;
  out.heading = psi;
  out.turn_rate = r;
  out.yaw_acceleration = dr;
  out.speed = u;
  return out;
}

}  // namespace towsim::core
