#pragma once
// The cable dragged along the seabed of seabed_core_test.cc (DraggedAlongTheBed...), built once
// for the test and for bench/tolerance_accuracy_core.cc (docs/benchmarks.md, "The reference
// tests' cases").
//
// 100 m of the catenary scene's cable, 20 elements (times `factor`), gravity and buoyancy only,
// its start driven at 0.1 m/s along +x on a flat bed 60 m deep (friction 0.5), its end free. A
// free end starts hanging vertically (into the bed), so LayOnTheBed sets the start instead: the
// cable straight along -x on the bed, every node sliding at the tow speed.

#include "core/model.h"
#include "core/simulation.h"

namespace towsim::reference {

constexpr double kDragSpeed = 0.1;     // [m/s], 10 x the friction's slip speed: tanh(10) = 1
constexpr double kDragFriction = 0.5;  // Coulomb coefficient of the bed

core::Model DraggedOnTheBed(int factor);

// StartFrom with the cable laid straight along -x on the bed, sliding at kDragSpeed
void LayOnTheBed(core::Simulation* sim);

}  // namespace towsim::reference
