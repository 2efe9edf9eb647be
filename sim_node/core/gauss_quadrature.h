#pragma once
// Gauss-Legendre points on [0, 1] (xi) with weights summing to 1.

#include <array>

namespace towsim::core {

template <int N>
struct GaussRule {
  std::array<double, N> xi;
  std::array<double, N> weight;
};

// the rule on [0, 1] from the points x and weights w of the rule on [-1, 1]
template <int N>
GaussRule<N> OnUnitInterval(const double (&x)[N], const double (&w)[N]) {
  GaussRule<N> g;
  for (int i = 0; i < N; ++i) {
    g.xi[i] = 0.5 * (x[i] + 1.0);
    g.weight[i] = 0.5 * w[i];
  }
  return g;
}

// 3 points: exact for polynomials of degree 5; the middle point is xi = 1/2.
inline GaussRule<3> Gauss3() {
  constexpr double a = 0.7745966692414834;  // sqrt(3/5)
  const double x[3] = {-a, 0.0, a};
  const double w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  return OnUnitInterval(x, w);
}

// 4 points: exact for polynomials of degree 7.
inline GaussRule<4> Gauss4() {
  constexpr double a = 0.8611363115940526;  // roots of P4 on [-1, 1]
  constexpr double b = 0.3399810435848563;
  constexpr double wa = 0.3478548451374538;
  constexpr double wb = 0.6521451548625461;
  const double x[4] = {-a, -b, b, a};
  const double w[4] = {wa, wb, wb, wa};
  return OnUnitInterval(x, w);
}

// 5 points: exact for polynomials of degree 9 (the Green-strain axial force integrand of the
// cubic ANCF element is of degree 8 in xi).
inline GaussRule<5> Gauss5() {
  constexpr double a = 0.9061798459386640;  // roots of P5 on [-1, 1]
  constexpr double b = 0.5384693101056831;
  constexpr double wa = 0.2369268850561891;
  constexpr double wb = 0.4786286704993665;
  constexpr double wc = 0.5688888888888889;
  const double x[5] = {-a, -b, 0.0, b, a};
  const double w[5] = {wa, wb, wc, wb, wa};
  return OnUnitInterval(x, w);
}

}  // namespace towsim::core
