#pragma once
// Newton's acceptance test on forces (docs/physics.md, "Newton convergence"). The integrator,
// the vehicle coupling and the static solve accept an iterate only when both its increment and
// its force residual are within their bounds:
//   increment:  theta / (1 - theta) |dq|_inf <= tolerance x max(1 m, L)      (integrator.h)
//   force:      |r|_F <= force_tolerance x F
// |r|_F is the residual in force units: the rows of node positions and bodies in N, the rows of
// slopes (generalized forces [N m], conjugate to the dimensionless r') divided by the cable's
// element length. F is the step's force scale: the largest joint force at the cable ends
// (|lambda| of each end's three position multipliers, Eq. 26: the tensions the cables carry
// into their supports and bodies), at least the scene's wet weight W (sum over the cables of
// |m - rho A| g L and over the bodies of |m - rho V| g; 1 N at least).
//
// Why both. The increment bound is a bound on positions. Through a cable's axial stiffness EA /
// l_e a position error e carries a force error up to about EA e / l_e, so for a stiff cable
// (EA / l_e large against F / (tolerance L)) an increment within its bound can leave a force
// error larger than the tension itself: steady_tow with E x100 at tolerance 1e-4 accepted such
// iterates step after step and ended with exit 0, its towfish 12.6 m deep against 25.25 m and
// strains of 35 %. The force bound holds the force error to a fraction of the forces the
// system carries, whatever the stiffness: the same run with it (the default bound) ends within
// 2e-7 m of the converged run (docs/benchmarks.md, "Newton tolerance against discretisation
// error", has the measurements and the choice of the defaults).
#include <Eigen/Core>

#include "core/model.h"

namespace towsim::core {

class System;

// max(1 m, L), L the longest cable: the increment bound is tolerance x this
double IncrementScale(const Model& model);

// the scene's wet weight, sum over the cables of |m - rho A| g L and over the bodies of
// |m - rho V| g [N]; W (above) is it, at least kMinForceScale
double WetWeight(const Model& model);
double WetWeightScale(const Model& model);
constexpr double kMinForceScale = 1.0;  // [N]

// F: the largest |lambda| over the ends' position multipliers of `lambda`, at least
// `weight_scale`
double JointForceScale(const System& system, const Eigen::VectorXd& lambda, double weight_scale);

// the shortest element length l_e of any cable [m] (the nominal one, which the slope rows are
// divided by); |r|_F <= |r|_inf when it is at least 1 m
double ShortestElement(const System& system);

// |r|_F (above); *worst_row, if given, receives the row that attains it
double ForceResidualNorm(const System& system, const Eigen::VectorXd& residual,
                         int* worst_row = nullptr);

}  // namespace towsim::core
