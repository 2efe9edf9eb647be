#pragma once
// The scenes of line_types_core_test.cc, built once for the test and for
// bench/tolerance_accuracy_core.cc (docs/benchmarks.md, "The reference tests' cases"), each
// read through the scene loader (docs/scene_format.md, "Line types"); `factor` multiplies the
// test's elements (factor 1: the test's). The jumper is jumper_model.h.

#include "core/model.h"

namespace towsim::reference {

// The steady tow (config/scenes/steady_tow.yaml) at `speed` [m/s] with a bare armoured tow
// cable's constant coefficients, C_n = 1.5 on d and C_t = 0.01 on pi d, solved statically in
// the frame moving with the tow point; 20 elements: the shipped discretization.
core::Model ConstantDragTow(double speed, int factor);

// A line type without bending stiffness (EI = 0) and with EA 2e5 N and m 2.5 kg/m of its own,
// 200 m pinned at both ends 150 m apart, 10 m deep; 20 elements.
core::Model RopeCatenary(int factor);

// A line type's own EI, below its solid section's: a 10 m line of 1 kg/m clamped horizontally
// at one end, free at the other, under its own weight in air (g = 9.81), with the EI that
// makes the Euler-Bernoulli tip deflection w L^4 / (8 EI) 1e-3 L; 10 elements.
constexpr double kOwnWeightLength = 10.0, kOwnWeightMass = 1.0, kOwnWeightGravity = 9.81;
double OwnBendingStiffness();  // EI [N m^2], 1.226e6
core::Model OwnBendingCantilever(int factor);

}  // namespace towsim::reference
