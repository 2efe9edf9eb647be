#include "cable_drag.h"

#include <algorithm>
#include <cmath>

namespace towsim::reference {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

double NormalDragCoefficient(double reynolds) {
  const double re = std::min(reynolds, 1.0e5);
  if (re <= 1.0) {
    // Stokes-Oseen regime
    const double s = -0.07721 + std::log(8.0 / re);
    return 8.0 * kPi / (re * s) * (1.0 - 0.87 / (s * s));
  }
  if (re < 30.0) return 1.45 + 8.55 * std::pow(re, -0.9);
  return 1.1 + 4.0 / std::sqrt(re);
}

double TangentialNusselt(double reynolds) {
  return 0.55 * std::sqrt(reynolds) + 0.084 * std::pow(reynolds, 2.0 / 3.0);
}

Eigen::Vector3d CableDragPerStretchedLength(const Fluid& fluid, double diameter,
                                            const Eigen::Vector3d& t_hat,
                                            const Eigen::Vector3d& V) {
  // V_t = (V . a) a, V_n = V - V_t (paper Eq. 20)
  const Eigen::Vector3d v_t = V.dot(t_hat) * t_hat;
  const Eigen::Vector3d v_n = V - v_t;
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  const double vn = v_n.norm();
  if (vn > 0.0) {
    const double re_n = fluid.density * vn * diameter / fluid.dynamic_viscosity;
    f -= 0.5 * fluid.density * diameter * NormalDragCoefficient(re_n) * vn * v_n;
  }
  const double vt = v_t.norm();
  if (vt > 0.0) {
    const double re_t = fluid.density * vt * diameter / fluid.dynamic_viscosity;
    f -= kPi * fluid.dynamic_viscosity * TangentialNusselt(re_t) * v_t;
  }
  return f;
}

Eigen::Vector3d CableDragPerStretchedLength(const Fluid& fluid, double diameter,
                                            const ConstantDragCoefficients& c,
                                            const Eigen::Vector3d& t_hat,
                                            const Eigen::Vector3d& V) {
  const Eigen::Vector3d v_t = V.dot(t_hat) * t_hat;
  const Eigen::Vector3d v_n = V - v_t;
  // 1/2 rho C |V| V on the area per length: d normal, pi d tangential
  return -0.5 * fluid.density *
         (c.normal * diameter * v_n.norm() * v_n +
          c.tangential * kPi * diameter * v_t.norm() * v_t);
}

}  // namespace towsim::reference
