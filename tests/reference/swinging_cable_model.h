#pragma once
// The cable swinging in vacuum of swinging_cable_core_test.cc, built once for the test and for
// bench/tolerance_accuracy_core.cc (docs/benchmarks.md, "The reference tests' cases").
//
// L = 10 m, d = 0.01 m, rho = 2000 kg/m^3, E = 1e8 Pa, 10 elements (times `factor`). Pinned
// (not clamped) at the origin, free end; loads: gravity and bending only. Released from rest,
// straight and horizontal along +x: the core builds a free-ended cable hanging vertically
// whatever the requested shape, so the horizontal start is set with StartFrom.

#include "core/model.h"
#include "core/simulation.h"

namespace towsim::reference {

constexpr double kSwingLength = 10.0;  // [m]

// the test's cable (factor 1: its 10 elements), on `scheme` with `rho_inf`, step `step`
core::Model SwingingCable(core::Scheme scheme, double rho_inf, double step, int factor);

// released from rest straight along +x: r_i = (X_i, 0, 0), r'_i = (1, 0, 0), v = 0, t = 0
void ReleaseStraight(core::Simulation* sim);

}  // namespace towsim::reference
