#pragma once
// The classical fourth-order Runge-Kutta step (Hairer, Norsett & Wanner 1993, Table 1.2) on a
// state packed as one fixed-size Eigen vector (MuJoCo's mj_RungeKutta integrates arrays the
// same way):
//   k1 = f(x0, 0),  k2 = f(x0 + h/2 k1, 1/2),  k3 = f(x0 + h/2 k2, 1/2),  k4 = f(x0 + h k3, 1),
//   x1 = x0 + h/6 (k1 + 2 k2 + 2 k3 + k4),
// where f(x, c) is dx/dt at the stage time t0 + c h. Local error O(h^5), global O(h^4).
// Every component sees the same floating-point operations in the same order, so a state laid
// out field by field integrates bit for bit like the fields one by one. A fixed-size Vector
// allocates nothing.

namespace towsim::core {

template <typename Vector, typename Derivative>
Vector RungeKutta4(const Vector& x0, double h, const Derivative& f) {
  const double half = 0.5 * h;
  const Vector k1 = f(x0, 0.0);
  const Vector k2 = f(Vector(x0 + half * k1), 0.5);
  const Vector k3 = f(Vector(x0 + half * k2), 0.5);
  const Vector k4 = f(Vector(x0 + h * k3), 1.0);
  // x1 = x0 + h/6 (k1 + 2 k2 + 2 k3 + k4)
  return x0 + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

}  // namespace towsim::core
