#pragma once
// The cable hanging between two pins of catenary_core_test.cc, built once for the test and for
// bench/tolerance_accuracy_core.cc (docs/benchmarks.md, "The reference tests' cases").
//
// 200 m of the paper's cable (d 0.041 m, rho_c 1300, E 7e8) in water, pins at equal depth
// 150 m apart; loads: gravity, buoyancy and (if `bending`) bending. Static solve.

#include "core/model.h"

namespace towsim::reference {

constexpr double kHangingCableSpan = 150.0;  // [m]

core::Model HangingCable(int elements, bool bending);

}  // namespace towsim::reference
