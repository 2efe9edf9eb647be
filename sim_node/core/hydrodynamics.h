#pragma once
// Hydrodynamic laws of the cable: drag, either Choo & Casarella's (1971) smooth-cylinder laws
// (paper Eq. 17-20) or constant coefficients as a line type gives them (docs/physics.md
// "Drag"), and the added mass (Eq. 22-23), as force densities per unit length with their
// Jacobians.

#include <Eigen/Core>

namespace towsim::core {

// Normal drag coefficient C_Dn(Re) of paper Eq. 18; beyond Re = 1e5 the value at 1e5.
double NormalDragCoefficient(double re);
// Nusselt number of paper Eq. 19, Nu = 0.55 Re^1/2 + 0.084 Re^2/3.
double NusseltNumber(double re);

// G(Re) = Re C_Dn(Re), so that the normal drag of Eq. 17 reads F_n = -1/2 mu G(Re_n) V_n, which
// stays finite as Re -> 0 (Stokes-Oseen regime, G ~ 8 pi / S). Also returns Re G'(Re).
struct DragLaw {
  double g;      // G(Re)
  double re_dg;  // Re dG/dRe
};
DragLaw NormalDragLaw(double re);
// Nu(Re) and Re dNu/dRe
DragLaw TangentialDragLaw(double re);

struct FluidProperties {
  double density = 1025.0;    // rho_w [kg/m^3]
  double viscosity = 1.0e-3;  // mu [Pa s]
};

// The drag law of a cable (a line type's `drag`, docs/scene_format.md):
//   kChooCasarella: C_Dn(Re) and Nu(Re) of paper Eq. 17-20 (smooth cylinder);
//   kConstant:      constant C_n on the diameter d and C_t on the wetted perimeter pi d,
//                   quadratic in the relative velocity (MoorDyn's Cd and CdAx, docs/inputs.rst
//                   of MoorDyn v2: "with respect to frontal area, d*l" and "surface area,
//                   pi*d*l").
struct CableDragLaw {
  enum Kind { kChooCasarella, kConstant };
  Kind kind = kChooCasarella;
  double normal = 0.0;      // C_n (kConstant)
  double tangential = 0.0;  // C_t (kConstant)
};

// Drag per unit *stretched* length at a cable point (Eq. 17, 20), on the velocity relative to
// the water V = r_dot - U. With a = r' (so the stretch is |a| and the unit tangent t = a/|a|),
// the force per unit unstretched length is f = |a| (h_n + h_t),
//   V_t = (V.t) t, V_n = V - V_t, Re_n = rho |V_n| d / mu, Re_t = rho |V_t| d / mu,
// Choo & Casarella (s_c / d = pi for a circular section):
//   h_n = -1/2 mu G(Re_n) V_n,                h_t = -pi mu Nu(Re_t) V_t,
// constant coefficients:
//   h_n = -1/2 rho C_n d |V_n| V_n,           h_t = -1/2 rho C_t pi d |V_t| V_t.
// The constant law is the first form with G = C_n Re and Nu = C_t Re / 2 (one code for both).
// Jacobians df/dV and df/da (3 x 3) when asked.
// Why per stretched length: drag acts on the wetted surface, and a stretched cable of constant
// diameter d presents d |a| dx of it per unstretched dx. MoorDyn 2.7.1 (Line.cpp) takes it per
// unstretched segment length instead; the two differ by the strain (0.01-0.2 % here).
struct DragResult {
  Eigen::Vector3d f;
  Eigen::Matrix3d df_dv;
  Eigen::Matrix3d df_da;
};
DragResult CableDrag(const FluidProperties& fluid, const CableDragLaw& law, double diameter,
                     const Eigen::Vector3d& a, const Eigen::Vector3d& v_rel, bool jacobians);

// Normal added-mass force per unit unstretched length (Eq. 22-23):
//   f = -m_a (I - t t^T) r_ddot,  m_a = C_a rho_w A,
// and df/da at fixed acceleration (the projector turns with the tangent). The tangential part
// of a line type's C_at, f = -m_at t t^T r_ddot, has df/da = -AddedMassTangentDerivative(m_at).
Eigen::Matrix3d NormalProjector(const Eigen::Vector3d& a);
Eigen::Matrix3d AddedMassTangentDerivative(double m_a, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& acc);

}  // namespace towsim::core
