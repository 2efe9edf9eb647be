#pragma once
// A folded cable element (docs/physics.md "Folded elements"): a shape the cable model can hold
// but a cable cannot. Element e between nodes a and b has the chord c = r_b - r_a and the
// slopes r'_a, r'_b (and r'_m = 3 c / (2 l) - (r'_a + r'_b) / 4 at its middle, from the cubic
// Hermite interpolation, Eq. 4). Along a smooth cable the tangent turns by the curvature times
// the arc length; an element resolves its piece of cable as long as the tangent turns by less
// than 180 deg over it, so each slope has a positive component along the chord:
//
//   r'_a . c > 0,   r'_m . c > 0,   r'_b . c > 0.
//
// A slope turned against its chord (<= 0) is an element folded back on itself or looped: the
// spurious equilibria of a stiff line solved from a compressed guess, and the loops a slack
// cable released with compressed elements settles into. A node strain |r'| - 1 below
// -kFoldCompression (no cable carries that compression: it buckles first) or above
// kFoldStretch (five times the strain watch's 20 %, beyond any cable material) is reported the
// same way. The check costs a few dot products per element.

#include <string>

#include <Eigen/Core>

namespace towsim::core {

class System;  // system.h

// compressive node strain no cable carries (it buckles at a small fraction of a percent) [-]
constexpr double kFoldCompression = 0.2;
// stretch beyond every cable material (nylon breaks at about 0.2) [-]
constexpr double kFoldStretch = 1.0;

struct FoldReport {
  bool folded = false;
  int cable = 0;        // Model::cables index
  int element = 0;      // element in use, 0 at the cable's start
  double strain = 0.0;  // the element's largest |node strain| (signed) [-]
  double cosine = 1.0;  // smallest cosine between a slope of the element and its chord [-]
  // "cable 'cable' element 29 (nodes 29-30): slope turned against its chord (cos -0.93),
  // strain 0.0512"; empty when not folded
  std::string Describe(const System& system) const;
};

// the first folded element of any cable at q (only the nodes in use); folded = false if none
FoldReport FindFold(const System& system, const Eigen::VectorXd& q);

// the angle the tangent of cable c turns through from its start to its end, summed in absolute
// value (the angles between the slopes at each element's ends and middle) [rad]. A cable in
// static equilibrium under gravity, buoyancy and the drag of a uniform flow carries each piece
// by its tension alone: T kappa = f_n, and f_n keeps one side of the tangent, so the tangent
// turns one way by less than pi in all; a loop turns it by at least 2 pi more.
double TotalTurning(const System& system, const Eigen::VectorXd& q, int c);

}  // namespace towsim::core
