#pragma once
// environment: the water (density, viscosity), gravity, the current, the waves and the seabed
// (docs/environment.md gives every key, its range and the grid file format).

#include <string>

#include "core/model.h"
#include "scene/yaml_reader.h"

namespace towsim::scene::internal {

// Wave periods shorter than this many time steps are rejected: the integrator's period error,
// (w h)^2 / 12 for second-order Newmark schemes, stays below 1 % at 20 steps per period.
inline constexpr int kStepsPerWavePeriod = 20;

// Reads and checks the environment map. `time` gives the step the shortest wave period is held
// to; relative grid file paths resolve against `base_dir`.
core::Environment ReadEnvironment(const Field& field, const core::TimeSettings& time,
                                  const std::string& base_dir);

// No body starts below the seabed: each body's bodies.<name>.position against the seabed's
// depth under it.
void CheckBodiesAboveSeabed(const Field& bodies, const core::Model& model);

}  // namespace towsim::scene::internal
