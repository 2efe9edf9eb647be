#pragma once
// The largest axial strain of the cable over a run (docs/physics.md "Cable"):
// eps = |r'| - 1 at the nodes (r' = dr/dx, x the unstretched arc length, Eq. 1), sampled at
// the output times. Beyond kExtremeStrain (20 %: nylon, the most extensible rope fibre,
// breaks at about that; steel wire at 1-2 %) the cable is no longer a cable in any material
// the scene could mean (e.g. youngs_modulus = 1 Pa stretches it sixfold), and the linear
// law N = EA eps is far outside its range. The run goes on; the status message and the
// summary line say so.

#include <string>

#include "core/simulation.h"

namespace towsim::app {

class StrainWatch {
 public:
  static constexpr double kExtremeStrain = 0.2;

  // the strain at every node of `sim`'s state; true when it first exceeds kExtremeStrain
  bool Observe(const core::Simulation& sim);
  bool extreme() const { return max_ > kExtremeStrain; }
  double max() const { return max_; }
  // "cable strain 5.02 (502 %) at node 20, t = 5 s: beyond 20 % (no cable material stretches
  // that far; check cable.youngs_modulus or axial_stiffness)"
  std::string Warning() const;
  // ", max cable strain 5.02 at node 20 (t = 5 s): extreme (> 0.2)", or empty when not extreme
  std::string SummaryPart() const;

 private:
  double max_ = 0.0;
  int node_ = 0;
  double t_ = 0.0;
};

}  // namespace towsim::app
