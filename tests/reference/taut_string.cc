#include "taut_string.h"

#include <cmath>

namespace towsim::reference {

double TautStringTension(const TautString& s) {
  const double lambda = s.span / s.length;
  const double eps = 0.5 * (lambda * lambda - 1.0);  // Green strain
  return s.ea * eps * lambda;
}

double TautStringMassPerLength(const TautString& s) { return s.rho_a * s.length / s.span; }

double TautStringFirstFrequency(const TautString& s) {
  return std::sqrt(TautStringTension(s) / TautStringMassPerLength(s)) / (2.0 * s.span);
}

}  // namespace towsim::reference
