#pragma once
// The taut string of taut_string_core_test.cc, built once for the test and for
// bench/tolerance_accuracy_core.cc (docs/benchmarks.md, "The reference tests' cases"), and its
// reference (taut_string.h).
//
// L = 10 m unstretched between pins 10.1 m apart (straight initial shape), no weight,
// buoyancy, drag, added mass or bending; EA = 1e4 N and rho A = 0.1 kg/m; 10 elements (times
// `factor`), trapezoidal rule, h = 1e-3 s. Set moving with a small half-sine transverse
// velocity through StartFrom.

#include "core/model.h"
#include "core/simulation.h"
#include "taut_string.h"

namespace towsim::reference {

constexpr double kStringLength = 10.0;  // unstretched L [m]
constexpr double kStringSpan = 10.1;    // ell [m]
constexpr double kStringEA = 1.0e4;     // [N]
constexpr double kStringRhoA = 0.1;     // [kg/m]

// the test's string (factor 1: its 10 elements)
core::Model String(int factor);

// the reference string of the same L, ell, EA and rho A
TautString StringReference();

// r_dot = v0 sin(pi X / L) e_z and, consistently, r'_dot = d r_dot / dX
// = v0 (pi / L) cos(pi X / L) e_z at every node (X = unstretched coordinate), v0 such that the
// amplitude v0 / omega is 1 mm at the reference's first frequency `f_ref` [Hz]
void StartHalfSine(core::Simulation* sim, double f_ref);

}  // namespace towsim::reference
