#pragma once
// The tip-loaded cantilever of cantilever_core_test.cc, built once for the test and for
// bench/tolerance_accuracy_core.cc (docs/benchmarks.md, "The reference tests' cases").
//
// Root clamped at the origin along +x; cable loads: bending only (no weight, buoyancy, drag,
// added mass). The tip load is the weight of a point-mass sphere of volume 0 (no buoyancy, no
// drag area, no added mass) attached at the free end: P = m g along +z. Static solve.
// Steel-like rod: L = 2 m, d = 0.02 m, E = 2e11 Pa, so EI = 1570.8 N m^2.

#include "core/model.h"

namespace towsim::reference {

constexpr double kCantileverLength = 2.0;  // [m]

// `elements` elements, tip load alpha = P L^2 / EI
core::Model Cantilever(int elements, double alpha);

}  // namespace towsim::reference
