#include "app/node/strain_watch.h"

#include <cstdio>

#include "core/state.h"

namespace towsim::app {

bool StrainWatch::Observe(const core::Simulation& sim) {
  const bool was = extreme();
  const core::State& s = sim.state();
  for (int i = 0; i < sim.num_nodes(); ++i) {
    // r' follows r in the node's coordinates e = [r, r']
    const double strain = s.q.segment<3>(sim.cable_dof(i) + 3).norm() - 1.0;
    if (strain > max_) {
      max_ = strain;
      node_ = i;
      t_ = sim.time();
    }
  }
  return !was && extreme();
}

std::string StrainWatch::Warning() const {
  char text[200];
  std::snprintf(text, sizeof text,
                "warning: cable strain %.3g (%.0f %%) at node %d, t = %.6g s: beyond %.0f %% (no "
                "cable material stretches that far; check cable.youngs_modulus or axial_stiffness)",
                max_, 100.0 * max_, node_, t_, 100.0 * kExtremeStrain);
  return text;
}

std::string StrainWatch::SummaryPart() const {
  if (!extreme()) return {};
  char text[120];
  std::snprintf(text, sizeof text,
                ", max cable strain %.3g at node %d (t = %.6g s): extreme (> %g)", max_, node_, t_,
                kExtremeStrain);
  return text;
}

}  // namespace towsim::app
