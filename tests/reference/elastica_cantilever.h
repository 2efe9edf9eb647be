#pragma once
// Large-deflection cantilever under a dead tip load (Euler elastica), the reference for
// bending. Inextensible, unshearable beam of length L and stiffness EI, clamped at s = 0
// along +x, tip load P perpendicular to the undeformed axis. theta(s) is the angle of the
// tangent from the x axis towards the load; the moment balance EI theta' = P (x_tip - x)
// differentiated gives, with sigma = s / L and alpha = P L^2 / EI,
//
//   theta'' = -alpha cos(theta),  theta(0) = 0 (clamped),  theta'(1) = 0 (free tip)
//
// solved by shooting on theta'(0) with RK4. Published values (Mattiasson 1981, Table 1):
// alpha = 5 gives v/L = 0.71379, u/L = 0.38763.

namespace towsim::reference {

struct ElasticaTip {
  double deflection = 0.0;      // v / L, tip displacement along the load
  double shortening = 0.0;      // u / L = 1 - x_tip / L
  double tip_angle = 0.0;       // theta(1) [rad]
  double root_curvature = 0.0;  // theta'(0) = alpha x_tip / L (dimensionless)
};

// alpha = P L^2 / EI >= 0; steps = RK4 steps over [0, 1]
ElasticaTip SolveCantileverElastica(double alpha, int steps = 2000);

// linear (Euler-Bernoulli) tip deflection v / L = alpha / 3
inline double LinearCantileverDeflection(double alpha) { return alpha / 3.0; }

}  // namespace towsim::reference
