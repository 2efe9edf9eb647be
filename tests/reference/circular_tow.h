#pragma once
// Steady state of a cable towed around a horizontal circle with a sphere hanging at its lower
// end, computed independently of the core by integrating the cable equations along the cable
// (the turning counterpart of towed_cable_steady.h, whose drag laws, stretch law and sphere
// force it calls).
//
// The tow point runs on a circle of radius R about the vertical axis through the origin at the
// turn rate Omega (NED, z down; Omega > 0 turns to starboard: the yaw increases, clockwise seen
// from above). In the frame turning with it everything is at rest; the tow point is at
// (R, 0, z_top) there (at t = 0 in the world frame), moving along +y for Omega > 0. With
// Omega_vec = Omega e_z and r the position relative to the circle's centre (in the turning
// frame, which is the world frame at t = 0), a material point of the steady shape moves with
//   v = Omega_vec x r = Omega (-r_y, r_x, 0),
//   a = Omega_vec x (Omega_vec x r) = -Omega^2 (r_x, r_y, 0)   (the centripetal acceleration).
// Unstretched arc length s runs from the sphere (s = 0) to the tow point (s = L); t_hat is the
// unit tangent towards the tow point and F(s) = T t_hat the force the upper part of the cable
// exerts across s. Equilibrium of the piece below s, loads per unit unstretched length, with
// d'Alembert's inertia forces:
//
//   dF/ds = -f,
//   f = w e_z + lambda(T) D(t_hat, v)                               (net weight, drag:
//                                                                     cable_drag.h, on the
//                                                                     velocity relative to the
//                                                                     water at rest)
//       - m a - rho_w A (C_an a_n + C_at a_t)                         (inertia: the cable's
//                                                                     mass and its normal and
//                                                                     tangential added mass)
//   a_t = (a . t_hat) t_hat,  a_n = a - a_t,
//   dr/ds = lambda(T) t_hat,  t_hat = F / |F|,
//   F(0) = -(W_s e_z + D_s(v_s) - (M + C_a rho_w V) a_s)              (the sphere in equilibrium
//                                                                     with its net weight, drag
//                                                                     and d'Alembert force)
//
// with w = (rho_c - rho_w) A g, m = rho_c A, lambda(T) from the problem's stretch law, v_s and
// a_s the sphere's velocity and acceleration at its position r_s. The loads depend on where the
// cable is, so the unknown is r_s: Newton shooting on
//   g(r_s) = r(L; r_s) - (R, 0, z_top) = 0
// with a forward-difference 3 x 3 Jacobian (from a coarser integration: it only steers the
// iteration; the residual is the fine one), started from the straight steady tow at the speed
// Omega R laid back along the circle, step halved until |g| falls. Integrated with classical
// RK4; converged to |g| <= 1e-11 L.

#include <vector>

#include <Eigen/Core>

#include "towed_cable_steady.h"

namespace towsim::reference {

struct CircularTowProblem {
  // the cable and sphere (length, diameter, density, E, drag coefficients, sphere mass, volume
  // and C_D), the fluid, gravity, the stretch law and the load switches; its motion fields
  // (tow_velocity, current, current_profile, tow_depth, sphere_extra_force) are not used and
  // must be left at rest: a current makes the turning problem unsteady
  TowedCableProblem line;
  double added_mass_normal = 1.0;              // C_an of the cable on rho_w A (the core's default)
  double added_mass_tangential = 0.0;          // C_at of the cable on rho_w A
  double sphere_added_mass_coefficient = 0.5;  // C_a of the sphere on rho_w V
  bool inertia = true;  // the d'Alembert forces (off: the circle's kinematics only in the drag)
  // the motion
  double radius = 300.0;    // R of the tow point's circle [m], > 0
  double turn_rate = 0.02;  // Omega [rad/s], != 0 (+ to starboard)
  double tow_depth = 0.0;   // z_top of the tow point (NED) [m]
};

struct CircularTowPoint {
  double s = 0.0;                                   // unstretched arc length from the sphere
  Eigen::Vector3d r = Eigen::Vector3d::Zero();      // position in the turning frame [m]
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // F(s) [N]
  double tension = 0.0;                             // |F| [N]
};

struct CircularTowSolution {
  Eigen::Vector3d sphere_position = Eigen::Vector3d::Zero();  // r_s, turning frame [m]
  double sphere_radius = 0.0;  // horizontal distance of the sphere from the centre [m]
  double lag_angle = 0.0;      // angle by which the sphere trails the tow point [rad]
  // (r_top - r_s) . (the tow point's direction of motion): the straight tow's layback when
  // R -> infinity [m]
  double layback = 0.0;
  double depth = 0.0;           // z_s - z_top [m] (> 0: the sphere below the tow point)
  double top_tension = 0.0;     // |F(L)| [N]
  double bottom_tension = 0.0;  // |F(0)| [N]
  Eigen::Vector3d top_force = Eigen::Vector3d::Zero();  // force of the cable on the tow point
  // the sphere's loads other than the cable's: W_s e_z + D_s - (M + C_a rho_w V) a_s [N]
  Eigen::Vector3d sphere_load = Eigen::Vector3d::Zero();
  std::vector<CircularTowPoint> shape;  // samples, s from 0 to L
  double residual = 0.0;                // |r(L) - (R, 0, z_top)| [m]
  int newton_iterations = 0;
};

// solve with `steps` RK4 steps per integration; `samples` + 1 shape points are stored
CircularTowSolution SolveCircularTow(const CircularTowProblem& p, int steps = 20000,
                                     int samples = 20);

}  // namespace towsim::reference
