#pragma once
// Looking up a displacement RAO (core/vessel.h RaoTable, docs/vessels.md "RAO files") at a
// wave period T and a direction beta relative to the heading.
//
// The table holds, per degree of freedom j, the complex RAO
//   H_j = |H_j| e^{-i phi_j}        (phi_j the lag behind the crest)
// so that a component of crest phase theta(t) (increasing in time, eta = a cos theta at the
// reference point) gives xi_j = Re[a H_j e^{i theta}] = a |H_j| cos(theta - phi_j).
// H is interpolated bilinearly in (T, beta) on its real and imaginary parts: between 350 and
// 10 deg of phase the mean lies at 0 deg, not at 180 as a mean of the phase numbers would. Near a
// phase jump the interpolated amplitude dips below both neighbours (the chord of the circle);
// that is the behaviour of a linear transfer function sampled on a grid.
//
// Directions. Let d0 and d1 be the table's first and last direction (d1 - d0 < 2 pi) and
// beta' = d0 + (beta - d0 mod 2 pi), in [d0, d0 + 2 pi).
//   - periodic table (its file spanned the full circle; the duplicate end column is not
//     stored): beta' <= d1 interpolates between the neighbouring columns, beta' > d1 between
//     the last column and the first one taken at d0 + 2 pi;
//   - non-periodic table: beta' <= d1 interpolates; beta' in the gap (d1, d0 + 2 pi) takes the
//     column at the nearer end of the gap (the nearer direction on the circle), with no
//     interpolation: constant extrapolation.
// Periods. T below the first period or above the last takes that row (constant
// extrapolation). The scene reader refuses a sea outside a table that does not extrapolate
// (scene/rao_coverage.h), so there the clamp is never reached; with extrapolate: true it is
// the documented behaviour.
// A table of one period (or one direction) does not interpolate along that axis.
//
// Cost: two binary searches and four complex products per call; no allocation.

#include <array>
#include <complex>

#include "core/vessel.h"

namespace towsim::core {

// H_j(T, beta) = |H| e^{-i phi} of degree of freedom `dof` for a wave of period `period` [s]
// travelling toward `direction` [rad] relative to the heading (0 following seas, pi/2 toward
// starboard); [m/m] or [rad/m]. A degree of freedom the table does not hold (empty amplitude)
// answers 0.
std::complex<double> RaoAt(const RaoTable& table, VesselDof dof, double period, double direction);

// All six degrees of freedom at once (one search for the six): element j is
// RaoAt(table, VesselDof(j), period, direction).
std::array<std::complex<double>, kVesselDofs> RaosAt(const RaoTable& table, double period,
                                                     double direction);

}  // namespace towsim::core
