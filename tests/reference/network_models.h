#pragma once
// The networks of network_core_test.cc, built once for the test and for
// bench/tolerance_accuracy_core.cc (docs/benchmarks.md, "The reference tests' cases"): YAML
// scenes in the `cables:` form (docs/scene_format.md, "Networks"), read by NetworkModel;
// `factor` multiplies every cable's elements (factor 1: the test's).

#include <string>

#include "core/model.h"
#include "core/simulation.h"

namespace towsim::reference {

// the scene `yaml` (no file references) read by the scene loader
core::Model NetworkModel(const std::string& yaml);

// The paper's cable without bending (a massless junction is a pin: the one-cable solution
// bends through it, which a cable without bending stiffness does not resist either), 120 m
// from (0, 0, 0) to (100, 0, 20), statically: one cable of 20 elements, or (split) two of 60 m
// and 10 elements meeting at a massless junction.
std::string SplitCatenaryYaml(bool split, int factor);

// The two-part tow: tow point at `speed` [m/s] -> main cable (300 m, 20 elements) -> depressor
// -> tether (60 m, 20 elements) -> towfish, statically.
std::string TwoPartTowYaml(double speed, int factor);

// A bridle: a 2000 kg sphere (0.2 m^3) held by two neutrally buoyant lines (25 m, 10 elements,
// no weight in water, drag off) from fixed points 40 m apart.
std::string BridleYaml(int factor);

// The split catenary without drag and added mass, a 50 kg clump at the junction, on the
// trapezoidal rule at Newton tolerance 1e-10 (NetworkWithoutDragConservesEnergy)
core::Model KickedNetwork(int factor);

// the clump kicked sideways at 2 m/s through StartFrom
void KickTheClump(core::Simulation* sim);

}  // namespace towsim::reference
