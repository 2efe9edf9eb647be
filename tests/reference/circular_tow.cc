#include "circular_tow.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

namespace towsim::reference {

namespace {

constexpr double kPi = 3.14159265358979323846;

// state: F (3) then r - r_s (3): positions relative to the sphere keep their round-off at the
// cable's scale even on a circle of 1e6 m
using Y = Eigen::Matrix<double, 6, 1>;

// v = Omega e_z x r, a = Omega e_z x (Omega e_z x r)
Eigen::Vector3d Velocity(double omega, const Eigen::Vector3d& r) {
  return Eigen::Vector3d(-omega * r.y(), omega * r.x(), 0.0);
}
Eigen::Vector3d Acceleration(double omega, const Eigen::Vector3d& r) {
  return Eigen::Vector3d(-omega * omega * r.x(), -omega * omega * r.y(), 0.0);
}

struct Rhs {
  const CircularTowProblem& p;
  Eigen::Vector3d r_s;  // the sphere (turning frame)
  double w;             // net weight per unstretched length [N/m]
  double m;             // mass per unstretched length [kg/m]
  double m_water;       // rho_w A [kg/m]

  Y operator()(const Y& y) const {
    const Eigen::Vector3d f_cable = y.head<3>();
    const double tension = f_cable.norm();
    const Eigen::Vector3d t_hat = f_cable / tension;
    const double lambda = CableStretch(p.line, tension);
    const Eigen::Vector3d r = r_s + y.tail<3>();
    Eigen::Vector3d load = Eigen::Vector3d::Zero();
    // f = w e_z + lambda D(t_hat, v) - m a - rho_w A (C_an a_n + C_at a_t)
    if (p.line.cable_weight) load.z() += w;
    if (p.line.cable_drag) {
      const Eigen::Vector3d v = Velocity(p.turn_rate, r);
      load += lambda * (p.line.drag_coefficients
                            ? CableDragPerStretchedLength(p.line.fluid, p.line.diameter,
                                                          *p.line.drag_coefficients, t_hat, v)
                            : CableDragPerStretchedLength(p.line.fluid, p.line.diameter, t_hat, v));
    }
    if (p.inertia) {
      const Eigen::Vector3d a = Acceleration(p.turn_rate, r);
      const Eigen::Vector3d a_t = a.dot(t_hat) * t_hat;
      load -= m * a + m_water * (p.added_mass_normal * (a - a_t) + p.added_mass_tangential * a_t);
    }
    Y dy;
    dy.head<3>() = -load;
    dy.tail<3>() = lambda * t_hat;
    return dy;
  }
};

// W_s e_z + D_s(v_s) - (M + C_a rho_w V) a_s: the straight tow's sphere force at the sphere's
// own velocity, and its d'Alembert force
Eigen::Vector3d SphereLoad(const CircularTowProblem& p, const Eigen::Vector3d& r_s) {
  TowedCableProblem at_sphere = p.line;
  at_sphere.tow_velocity = Velocity(p.turn_rate, r_s);
  at_sphere.current.setZero();
  Eigen::Vector3d f = SphereExternalForce(at_sphere);
  if (p.inertia) {
    const double m_eff = p.line.sphere_mass + p.sphere_added_mass_coefficient *
                                                  p.line.fluid.density * p.line.sphere_volume;
    f -= m_eff * Acceleration(p.turn_rate, r_s);
  }
  return f;
}

struct Integration {
  Y top;  // F(L), r(L) - r_s
  Eigen::Vector3d sphere_load = Eigen::Vector3d::Zero();
  std::vector<CircularTowPoint> shape;
};

// one RK4 integration from the sphere at r_s to the top; `samples` > 0 stores the shape
Integration Integrate(const CircularTowProblem& p, const Eigen::Vector3d& r_s, int steps,
                      int samples) {
  const double area = 0.25 * kPi * p.line.diameter * p.line.diameter;
  const Rhs rhs{p, r_s, (p.line.density - p.line.fluid.density) * area * p.line.gravity,
                p.line.density * area, p.line.fluid.density * area};
  Integration out;
  out.sphere_load = SphereLoad(p, r_s);
  // the sphere is in equilibrium: the cable pulls it with F(0) = -(its other loads)
  Y y;
  y.head<3>() = -out.sphere_load;
  y.tail<3>().setZero();
  if (!(y.head<3>().norm() > 0.0)) throw std::runtime_error("circular tow: slack at the sphere");
  if (samples > 0) out.shape.push_back({0.0, r_s, y.head<3>(), y.head<3>().norm()});
  const double h = p.line.length / steps;
  for (int i = 0; i < steps; ++i) {
    const Y k1 = rhs(y);
    const Y k2 = rhs(y + 0.5 * h * k1);
    const Y k3 = rhs(y + 0.5 * h * k2);
    const Y k4 = rhs(y + h * k3);
    y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (!y.allFinite()) throw std::runtime_error("circular tow: non-finite state in the cable");
    if (samples > 0 && (i + 1) % (steps / samples) == 0) {
      out.shape.push_back({(i + 1) * h, r_s + y.tail<3>(), y.head<3>(), y.head<3>().norm()});
    }
  }
  out.top = y;
  return out;
}

void Require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("circular tow: " + what);
}

}  // namespace

CircularTowSolution SolveCircularTow(const CircularTowProblem& p, int steps, int samples) {
  Require(steps >= 1 && samples >= 1 && steps % samples == 0,
          "steps = " + std::to_string(steps) + ", samples = " + std::to_string(samples) +
              ": steps must be a positive multiple of samples");
  Require(p.radius > 0.0 && std::isfinite(p.radius),
          "radius = " + std::to_string(p.radius) + ": must be > 0");
  Require(p.turn_rate != 0.0 && std::isfinite(p.turn_rate),
          "turn_rate = " + std::to_string(p.turn_rate) + ": must be finite and != 0");
  Require(p.line.current.isZero() && !p.line.current_profile && p.line.sphere_extra_force.isZero(),
          "line.current, line.current_profile, line.sphere_extra_force: must be unset (the "
          "water is at rest)");

  const Eigen::Vector3d target(p.radius, 0.0, p.tow_depth);
  const double sign = p.turn_rate > 0.0 ? 1.0 : -1.0;
  // g(r_s) = r(L) - (R, 0, z_top)
  auto residual = [&](const Eigen::Vector3d& r_s, int n) {
    return Eigen::Vector3d((r_s - target) + Integrate(p, r_s, n, 0).top.tail<3>());
  };

  // initial guess: the straight tow at U = |Omega| R, its layback l laid along the circle as a
  // chord behind the tow point (angle 2 asin(l / 2R)), its depth below it
  TowedCableProblem straight = p.line;
  straight.tow_velocity = Eigen::Vector3d(std::abs(p.turn_rate) * p.radius, 0.0, 0.0);
  const TowedCableSolution s0 = SolveTowedCableSteady(straight, 2000, 1);
  const double lag = 2.0 * std::asin(std::min(1.0, s0.layback / (2.0 * p.radius)));
  Eigen::Vector3d x(p.radius * std::cos(lag), -sign * p.radius * std::sin(lag),
                    p.tow_depth + s0.depth);

  // Newton: J dx = -g, J by forward differences on a coarser integration (it only steers the
  // iteration), the step halved until |g| falls
  const double tolerance = 1e-11 * p.line.length + 1e-15 * p.radius;
  const int coarse = std::max(200, steps / 10);
  const double fd = 1e-6 * p.line.length;
  Eigen::Vector3d g = residual(x, steps);
  int it = 0;
  for (; it < 50 && g.norm() > tolerance; ++it) {
    const Eigen::Vector3d g_c = residual(x, coarse);
    Eigen::Matrix3d jac;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d e = Eigen::Vector3d::Zero();
      e(j) = fd;
      jac.col(j) = (residual(x + e, coarse) - g_c) / fd;
    }
    const Eigen::Vector3d dx = -jac.partialPivLu().solve(g);
    double step = 1.0;
    bool accepted = false;
    for (int k = 0; k < 30 && !accepted; ++k, step *= 0.5) {
      const Eigen::Vector3d x_new = x + step * dx;
      Eigen::Vector3d g_new;
      try {
        g_new = residual(x_new, steps);
      } catch (const std::runtime_error&) {
        continue;  // a slack or diverging trial: shorten the step
      }
      if (g_new.norm() < g.norm()) {
        x = x_new;
        g = g_new;
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  if (!(g.norm() <= tolerance)) {
    throw std::runtime_error(
        "circular tow: the shooting did not converge (|g| = " + std::to_string(g.norm()) +
        " m after " + std::to_string(it) + " Newton iterations)");
  }

  const Integration fin = Integrate(p, x, steps, samples);
  CircularTowSolution sol;
  sol.sphere_position = x;
  sol.sphere_radius = std::hypot(x.x(), x.y());
  sol.lag_angle = std::atan2(-sign * x.y(), x.x());
  sol.layback = -sign * x.y();  // (r_top - r_s) . sign e_y, r_top = (R, 0, z_top)
  sol.depth = x.z() - p.tow_depth;
  sol.top_tension = fin.top.head<3>().norm();
  sol.bottom_tension = fin.sphere_load.norm();
  sol.top_force = -fin.top.head<3>();  // the cable pulls the tow point back along -t_hat
  sol.sphere_load = fin.sphere_load;
  sol.shape = fin.shape;
  sol.residual = g.norm();
  sol.newton_iterations = it;
  return sol;
}

}  // namespace towsim::reference
