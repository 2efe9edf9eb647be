#pragma once
// Elastic catenary between two pinned supports (Irvine 1981, "Cable Structures", §2.2),
// the reference for a cable hanging under its own weight.
//
// Local frame: support A at (0, 0), support B at (span, height) with the vertical axis
// pointing UP. Unstretched arc length s runs from A (s = 0) to B (s = L). The cable obeys
// Hooke's law on the engineering strain, T = EA (ds_stretched / ds - 1), with T the true
// tension; w is the weight per unit unstretched length. With H the horizontal tension and V
// the upward force that support A exerts on the cable, the piece [0, s] is in equilibrium
// when the rest pulls it with (H, w s - V), so dx/ds = (1 + T/EA) H / T and
// dy/ds = (1 + T/EA) (w s - V) / T, T = sqrt(H^2 + (V - w s)^2); integrated (Irvine §2.2):
//
//   x(s) = H s / EA + (H / w) [asinh(V / H) - asinh((V - w s) / H)]
//   y(s) = (w s^2 / 2 - V s) / EA + (H / w) [sqrt(1 + ((V - w s)/H)^2) - sqrt(1 + (V/H)^2)]
//
// and x(L) = span, y(L) = height are the two equations for (H, V), solved here with Newton
// from the inextensible catenary. EA = +inf gives the inextensible catenary.

namespace towsim::reference {

struct CatenaryProblem {
  double length = 0.0;  // unstretched length L [m]
  double span = 0.0;    // horizontal distance A -> B, > 0 [m]
  double height = 0.0;  // height of B above A (up positive) [m]
  double weight = 0.0;  // w, weight per unit unstretched length, > 0 [N/m]
  double ea = 0.0;      // axial stiffness EA [N]; +inf for an inextensible cable
};

struct CatenarySolution {
  double horizontal_tension = 0.0;  // H [N]
  double vertical_force_a = 0.0;    // V_A, upward force of support A on the cable [N]
  double vertical_force_b = 0.0;    // V_B = w L - V_A, upward force of support B [N]
  double tension_a = 0.0;           // sqrt(H^2 + V_A^2) [N]
  double tension_b = 0.0;           // sqrt(H^2 + V_B^2) [N]
  double sag_mid_span = 0.0;        // chord minus cable height at x = span / 2, > 0 [m]
  int iterations = 0;               // Newton iterations used
};

struct CatenaryPoint {
  double x = 0.0;        // [m], from A
  double y = 0.0;        // [m], up, from A
  double tension = 0.0;  // true tension T(s) [N]
};

// solves Irvine's equations; throws std::runtime_error if the cable cannot reach B
// (L <= chord with EA = inf) or Newton fails
CatenarySolution SolveElasticCatenary(const CatenaryProblem& p);

// the shape at unstretched arc length s in [0, L] for a solved (H, V_A)
CatenaryPoint CatenaryShape(const CatenaryProblem& p, double horizontal_tension,
                            double vertical_force_a, double s);

// inextensible catenary parameter a = H / w for the same supports:
// sqrt(L^2 - height^2) = 2 a sinh(span / (2 a))
double InextensibleCatenaryParameter(double length, double span, double height);

}  // namespace towsim::reference
