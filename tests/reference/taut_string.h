#pragma once
// First natural frequency of a taut string pinned at both ends, pre-tensioned by
// stretching an unstretched length L over a span ell > L (transverse wave speed
// c = sqrt(T / mu), f1 = c / (2 ell)).
//
// The tension follows the core's constitutive law (Green strain, true tension):
//   lambda = ell / L = |r'|,  eps = (lambda^2 - 1) / 2,  T = EA eps lambda
// and mu = rho A L / ell is the mass per unit *stretched* length.

namespace towsim::reference {

struct TautString {
  double length = 10.0;  // unstretched L [m]
  double span = 10.1;    // distance between the pins ell [m]
  double ea = 1.0;       // axial stiffness EA [N]
  double rho_a = 1.0;    // mass per unit unstretched length rho A [kg/m]
};

double TautStringTension(const TautString& s);         // T [N]
double TautStringMassPerLength(const TautString& s);   // mu [kg/m]
double TautStringFirstFrequency(const TautString& s);  // f1 [Hz]

}  // namespace towsim::reference
