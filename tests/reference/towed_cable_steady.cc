#include "towed_cable_steady.h"

#include <cmath>
#include <stdexcept>

namespace towsim::reference {

namespace {

constexpr double kPi = 3.14159265358979323846;

// state: F (3) then r (3)
using Y = Eigen::Matrix<double, 6, 1>;

struct Rhs {
  const TowedCableProblem& p;
  double w;                   // weight in water per unstretched length [N/m]
  Eigen::Vector3d v_uniform;  // uniform current: U_tow - U
  double sphere_z = 0.0;      // with a profile: z of the sphere (NED)

  Y operator()(const Y& y) const {
    // V = U_tow - U(z_sphere + r_z) with a profile
    const Eigen::Vector3d v_rel =
        p.current_profile ? Eigen::Vector3d(p.tow_velocity - p.current_profile(sphere_z + y(5)))
                          : v_uniform;
    const Eigen::Vector3d f_cable = y.head<3>();
    const double tension = f_cable.norm();
    const Eigen::Vector3d t_hat = f_cable / tension;
    const double lambda = CableStretch(p, tension);
    Eigen::Vector3d load = Eigen::Vector3d::Zero();
    if (p.cable_weight) load.z() += w;
    if (p.cable_drag) {
      load += lambda * (p.drag_coefficients
                            ? CableDragPerStretchedLength(p.fluid, p.diameter, *p.drag_coefficients,
                                                          t_hat, v_rel)
                            : CableDragPerStretchedLength(p.fluid, p.diameter, t_hat, v_rel));
    }
    Y dy;
    dy.head<3>() = -load;
    dy.tail<3>() = lambda * t_hat;
    return dy;
  }
};

}  // namespace

Eigen::Vector3d SphereExternalForce(const TowedCableProblem& p) {
  return SphereExternalForce(p, p.current);
}

Eigen::Vector3d SphereExternalForce(const TowedCableProblem& p, const Eigen::Vector3d& current) {
  const Eigen::Vector3d v_rel = p.tow_velocity - current;
  const double radius = std::cbrt(3.0 * p.sphere_volume / (4.0 * kPi));
  const double area = kPi * radius * radius;
  Eigen::Vector3d f(0.0, 0.0, (p.sphere_mass - p.fluid.density * p.sphere_volume) * p.gravity);
  f -= 0.5 * p.fluid.density * p.sphere_cd * area * v_rel.norm() * v_rel;
  return f;
}

double CableStretch(const TowedCableProblem& p, double tension) {
  const double ea = p.youngs_modulus * 0.25 * kPi * p.diameter * p.diameter;
  if (p.stretch_law == StretchLaw::kHooke) return 1.0 + tension / ea;
  // solve g(lambda) = EA (lambda^3 - lambda) / 2 - T = 0 by Newton from the Hooke value
  double lambda = 1.0 + tension / ea;
  for (int it = 0; it < 50; ++it) {
    const double g = 0.5 * ea * (lambda * lambda * lambda - lambda) - tension;
    const double dg = 0.5 * ea * (3.0 * lambda * lambda - 1.0);
    const double d = -g / dg;
    lambda += d;
    if (std::abs(d) < 1e-16) break;
  }
  return lambda;
}

namespace {

// one RK4 integration from the sphere (at depth sphere_z with a profile) to the tow point
TowedCableSolution Integrate(const TowedCableProblem& p, double sphere_z, int steps, int samples) {
  const double area = 0.25 * kPi * p.diameter * p.diameter;
  const Rhs rhs{p, (p.density - p.fluid.density) * area * p.gravity, p.tow_velocity - p.current,
                sphere_z};

  // the sphere is in equilibrium: the cable pulls it with F(0) = -(its external force)
  Y y;
  y.head<3>() = p.current_profile ? -SphereExternalForce(p, p.current_profile(sphere_z))
                                  : -SphereExternalForce(p);
  // and whatever else pulls on the sphere (the cable below it in a chain)
  y.head<3>() -= p.sphere_extra_force;
  y.tail<3>().setZero();
  if (!(y.head<3>().norm() > 0.0)) throw std::runtime_error("towed cable: slack at the sphere");

  TowedCableSolution sol;
  sol.bottom_tension = y.head<3>().norm();
  sol.shape.push_back({0.0, Eigen::Vector3d::Zero(), sol.bottom_tension});
  const double h = p.length / steps;
  for (int i = 0; i < steps; ++i) {
    // classical RK4 in s
    const Y k1 = rhs(y);
    const Y k2 = rhs(y + 0.5 * h * k1);
    const Y k3 = rhs(y + 0.5 * h * k2);
    const Y k4 = rhs(y + h * k3);
    y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if ((i + 1) % (steps / samples) == 0) {
      sol.shape.push_back({(i + 1) * h, y.tail<3>(), y.head<3>().norm()});
    }
  }
  sol.top_minus_sphere = y.tail<3>();
  sol.layback = y(3);  // x_top - x_sphere
  sol.depth = -y(5);   // z_sphere - z_top
  sol.top_tension = y.head<3>().norm();
  sol.top_force = -y.head<3>();  // the cable pulls the tow point back along -t_hat
  sol.sphere_z = sphere_z;
  return sol;
}

}  // namespace

TowedCableSolution SolveTowedCableSteady(const TowedCableProblem& p, int steps, int samples) {
  if (steps < 1 || samples < 1 || steps % samples != 0) {
    throw std::runtime_error("towed cable: steps must be a positive multiple of samples");
  }
  if (!p.current_profile) return Integrate(p, 0.0, steps, samples);
  // shooting on z_sphere: g(z) = z - depth(z) - tow_depth = 0, secant from the solution in
  // the uniform current of the tow point's depth
  TowedCableProblem uniform = p;
  uniform.current_profile = nullptr;
  uniform.current = p.current_profile(p.tow_depth);
  double z0 = p.tow_depth + Integrate(uniform, 0.0, steps, samples).depth;
  TowedCableSolution s0 = Integrate(p, z0, steps, samples);
  double g0 = z0 - s0.depth - p.tow_depth;
  double z1 = z0 - g0;  // g' ~ 1: the sphere's depth barely changes the shape
  for (int it = 1; it <= 50; ++it) {
    TowedCableSolution s1 = Integrate(p, z1, steps, samples);
    const double g1 = z1 - s1.depth - p.tow_depth;
    if (std::abs(g1) <= 1e-12 * p.length) {
      s1.shooting_iterations = it;
      return s1;
    }
    const double z2 = g1 == g0 ? z1 - g1 : z1 - g1 * (z1 - z0) / (g1 - g0);
    z0 = z1;
    g0 = g1;
    z1 = z2;
  }
  throw std::runtime_error("towed cable: shooting on the sphere's depth did not converge");
}

}  // namespace towsim::reference
