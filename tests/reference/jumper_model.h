#pragma once
// Lowe & Langley's flexible jumper (OMAE 2006) as line_types_core_test.cc and
// static_solve_core_test.cc build it, once for both and for bench/tolerance_accuracy_core.cc
// (docs/benchmarks.md, "The reference tests' cases"): 170 m of library type
// lowe_langley_jumper pinned at an anchor 55 m deep and a fairlead 5 m deep, 100 m apart, in
// water of 1000 kg/m^3, g = 9.807; loads: gravity, buoyancy and bending; static solve. Read
// through the scene loader with `overrides` (docs/scene_format.md, "Line types").

#include <string>
#include <vector>

#include "core/model.h"

namespace towsim::reference {

// line_types_core_test: 68 elements; static_solve_core_test: 5 to 200
core::Model Jumper(int elements, const std::vector<std::string>& overrides = {});

}  // namespace towsim::reference
