#pragma once
// Distributed external loads of one cable element, as generalized forces (paper Eq. 14):
// gravity and buoyancy (Eq. 15-16), drag (Eq. 17-21, or a line type's constant coefficients:
// hydrodynamics.h) on the velocity relative to the local water, normal added mass (Eq. 22-23)
// and a line type's tangential added mass, and, in accelerating water (waves, an unsteady
// current), the fluid-inertia (Froude-Krylov + added mass) force of Morison's equation in the
// normal direction (docs/environment.md), on the water's material acceleration a_fluid = Du/Dt
// (environment_field.h; docs/physics.md, "Fluid inertia in waves"):
//   f_fluid = (rho_w A + m_a) (I - t t^T) a_fluid,  m_a = C_a rho_w A,
// so that with the added mass -m_a (I - t t^T) r_ddot the normal inertia load is
// (1 + C_a) rho_w A a_n,fluid - C_a rho_w A a_n,cable (the rho_w A part goes with buoyancy,
// the C_a part with added mass: a load left out of the scene drops its part). A tangential
// added mass m_at = C_at rho_w A (line types; 0 by default) adds
//   f_at = m_at t t^T (a_fluid - r_ddot)
// (MoorDyn's CaAx; the tangential Froude-Krylov part rho_w A t t^T a_fluid stays out, as
// without it: docs/physics.md "Added mass"). They enter the
// residual as
//   R_load(e, e_dot, e_ddot) = M_a(e) e_ddot - Q_drag(e, e_dot) - Q_fluid(e) - Q_weight
// where M_a = int m_a S^T (I - t t^T) S dx depends on the tangent t; the implicit solve needs
// M_a and the Jacobians dR_load/de (at fixed e_ddot) and dR_load/de_dot.
//
// The water is read from the EnvironmentField at each Gauss point's position r(x) = S(x) e and
// the time t: the current exactly there (with its shear dU/dz in dR/de), the waves from their
// samples at the two nodes interpolated with the element's cubic Hermite shape functions
// (ElementWaves; environment_field.h says why). Loads are per unit unstretched length x; the
// element length comes from the element (it may differ between elements).

#include <cmath>

#include <Eigen/Core>

#include "core/ancf_element.h"
#include "core/environment_field.h"
#include "core/hydrodynamics.h"

namespace towsim::core {

struct CableLoadContext {
  FluidProperties fluid;
  double diameter = 0.0;                  // d [m]
  CableDragLaw drag_law;                  // Choo & Casarella or constant coefficients
  double added_mass_per_length = 0.0;     // m_a = C_a rho_w A [kg/m] (0: off)
  double tangential_added_mass_per_length = 0.0;  // m_at = C_at rho_w A [kg/m] (0: off)
  double fluid_inertia_per_length = 0.0;  // rho_w A (buoyancy on) + m_a [kg/m]
  bool drag = false;
  Eigen::Vector3d weight_per_length = Eigen::Vector3d::Zero();  // (rho_c - rho_w) A g e_z [N/m]
};

// The waves at an element's two nodes, in the layout of its coordinates e:
// [w(0), dw/dx(0), w(l), dw/dx(l)] for the velocity and for the acceleration, so that
// Interpolate(point.n, velocity) is the waves' velocity at a Gauss point.
struct ElementWaves {
  Vec12 velocity = Vec12::Zero();
  Vec12 acceleration = Vec12::Zero();
};
// ... from the samples at its two nodes
ElementWaves NodeWaves(const WaveSample& start, const WaveSample& end);

// The waves at an element's five Gauss points, Interpolate(point.n, ...) of its ElementWaves:
// the node samples are held over a step (environment_field.h), so these are formed once per
// step (StepSampler::SampleWaves), not at every Newton evaluation
struct GaussWaves {
  Mat35 velocity = Mat35::Zero(), acceleration = Mat35::Zero();  // column g: Gauss point g
};
GaussWaves WavesAtGaussPoints(const AncfElement& element, const ElementWaves& waves);

struct ElementLoadJacobians {
  Mat12 added_mass;  // M_a (12 x 12)
  Mat12 d_de;        // dR_load/de
  Mat12 d_dedot;     // dR_load/de_dot
};

// Generalized load residual of one element at time t in the sea `sea`, with the waves at its
// Gauss points (nullptr: none), from the element's fields there (AncfElement::
// InterpolateFields with LoadFields(ctx, sea); interpolated once per element for this and the
// internal force); `scale` multiplies weight and drag (static load continuation). Jacobians
// are filled when jac != nullptr; the residual is the same to the bit with or without them
// (one load law, cable_loads.cc). `bed_in_reach` false: the caller knows that no point of the
// element reaches the shallowest seabed (ClearOfSeabed), so no contact is looked for (and r
// need not be among the fields).
Vec12 ElementLoadResidual(const AncfElement& element, const CableLoadContext& ctx,
                          const EnvironmentField& sea, double t, const GaussWaves* waves,
                          const GaussFields& fields, double scale, ElementLoadJacobians* jac,
                          bool bed_in_reach = true);
// the fields ElementLoadResidual reads at the Gauss points besides r' (GaussFields: kField*),
// for an element that may reach the seabed (bed_in_reach) or not
unsigned LoadFields(const CableLoadContext& ctx, const EnvironmentField& sea,
                    bool bed_in_reach = true);
// no point of the element (coordinates e, length l) reaches the shallowest seabed: its
// DeepestBound is above it, by a margin that covers the rounding of r at the Gauss points
// (false without a seabed: there is nothing to reach; inline, so that a scene without one
// pays a flag's test per element)
inline bool ClearOfSeabed(const EnvironmentField& sea, const Vec12& e, double l) {
  if (!sea.has_seabed()) return false;
  const double deepest = DeepestBound(e, l);
  return deepest + 1e-9 * (std::abs(deepest) + l) < sea.SeabedShallowest();
}
// the same from the element coordinates and the waves at its nodes (both interpolated here)
Vec12 ElementLoadResidual(const AncfElement& element, const CableLoadContext& ctx,
                          const EnvironmentField& sea, double t, const ElementWaves* waves,
                          const Vec12& e, const Vec12& e_dot, const Vec12& e_ddot, double scale,
                          ElementLoadJacobians* jac);

// Consistent generalized force of a uniform load f per unit unstretched length:
//   Q_k = f int S_k dx = f l [1/2, l/12, 1/2, -l/12]_k
Vec12 UniformLoad(const Eigen::Vector3d& f, double l);

}  // namespace towsim::core
