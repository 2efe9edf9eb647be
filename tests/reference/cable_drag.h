#pragma once
// Hydrodynamic drag laws of a circular cable (paper Eq. 17-19, Choo & Casarella 1971),
// written independently of the core for the reference solvers. SI units.
//
//   normal:     F_n = -1/2 rho_w d C_Dn(Re_n) |V_n| V_n,   Re_n = rho_w |V_n| d / mu
//   tangential: F_t = -(s_c / d) mu Nu(Re_t) V_t = -pi mu Nu(Re_t) V_t,
//               Re_t = rho_w |V_t| d / mu
// both per unit *stretched* length; V = cable velocity minus current. Or, with constant
// coefficients (a line type's `drag: {normal, tangential}`, MoorDyn's Cd and CdAx):
//   normal:     F_n = -1/2 rho_w C_n d |V_n| V_n        (on the projected area d per length)
//   tangential: F_t = -1/2 rho_w C_t pi d |V_t| V_t     (on the wetted area pi d per length)

#include <Eigen/Core>

namespace towsim::reference {

// normal drag coefficient C_Dn(Re) of paper Eq. 18 (Choo & Casarella):
//   Re <= 1:        8 pi / (Re S) (1 - 0.87 S^-2),  S = -0.07721 + ln(8 / Re)
//   1 < Re < 30:    1.45 + 8.55 Re^-0.9
//   30 <= Re <= 1e5: 1.1 + 4 Re^-0.5
//   Re > 1e5:       the value at 1e5
// Re must be > 0 (the force vanishes at Re = 0 whatever C is).
double NormalDragCoefficient(double reynolds);

// average Nusselt number of paper Eq. 19: Nu = 0.55 Re^0.5 + 0.084 Re^(2/3)
double TangentialNusselt(double reynolds);

struct Fluid {
  double density = 1025.0;          // rho_w [kg/m^3]
  double dynamic_viscosity = 1e-3;  // mu [Pa s]
};

// drag per unit stretched length [N/m] on a cable of diameter d [m] whose unit tangent is
// t_hat, moving with velocity V [m/s] relative to the water (cable velocity minus current)
Eigen::Vector3d CableDragPerStretchedLength(const Fluid& fluid, double diameter,
                                            const Eigen::Vector3d& t_hat, const Eigen::Vector3d& V);

struct ConstantDragCoefficients {
  double normal = 0.0;      // C_n on d
  double tangential = 0.0;  // C_t on pi d
};
// the same with constant coefficients
Eigen::Vector3d CableDragPerStretchedLength(const Fluid& fluid, double diameter,
                                            const ConstantDragCoefficients& c,
                                            const Eigen::Vector3d& t_hat, const Eigen::Vector3d& V);

}  // namespace towsim::reference
