#pragma once
// Elastic catenary of a mooring line lying partly on a flat, frictionless seabed: the
// reference for cable-seabed contact (the quasi-static mooring line of Jonkman 2007, NREL
// TP-500-41958, §2.1, with the seabed friction coefficient C_B = 0; also Faltinsen 1990 §8).
//
// Local frame: the anchor A on the seabed at (0, 0), the fairlead F at (span, height) with the
// vertical axis UP (height above the seabed). Unstretched arc length s runs from A (s = 0) to
// F (s = L); Hooke's law T = EA (ds_stretched / ds - 1); w is the weight in water per unit
// unstretched length. H is the horizontal tension (the same all along the line: the seabed
// is frictionless, the suspended part has no horizontal load) and V_F the vertical force at
// the fairlead. The suspended length is V_F / w (its lowest point, the touchdown point, has
// no vertical tension); the grounded length L_B = L - V_F / w >= 0 lies straight on the bed
// with tension H. Then (Jonkman 2007 Eq. 2-1, 2-2 with C_B = 0):
//
//   span   = L_B + (H / w) asinh(V_F / H) + H L / EA
//   height = (H / w) [sqrt(1 + (V_F / H)^2) - 1] + V_F^2 / (2 EA w)
//
// solved for (H, V_F) by Newton. When the solution would need V_F > w L (no grounded length),
// the line hangs free from the anchor and the result is the elastic catenary of
// elastic_catenary.h between A and F; that case is flagged.

#include "elastic_catenary.h"

namespace towsim::reference {

struct GroundedCatenaryProblem {
  double length = 0.0;  // unstretched length L [m]
  double span = 0.0;    // horizontal distance anchor -> fairlead, > 0 [m]
  double height = 0.0;  // fairlead height above the seabed (water depth - fairlead depth) [m]
  double weight = 0.0;  // w, weight in water per unit unstretched length, > 0 [N/m]
  double ea = 0.0;      // EA [N]; +inf for an inextensible line
};

struct GroundedCatenarySolution {
  double horizontal_tension = 0.0;  // H [N]
  double vertical_force = 0.0;      // V_F, at the fairlead [N]
  double fairlead_tension = 0.0;    // sqrt(H^2 + V_F^2) [N]
  double anchor_tension = 0.0;      // H when grounded, else the free catenary's end tension [N]
  double grounded_length = 0.0;     // L_B, unstretched [m]; 0 when suspended
  double touchdown = 0.0;           // horizontal distance anchor -> touchdown, L_B (1 + H/EA) [m]
  bool suspended = false;           // no grounded length: an elastic catenary from the anchor
};

struct GroundedCatenaryPoint {
  double x = 0.0;        // [m] from the anchor
  double y = 0.0;        // [m] above the seabed
  double tension = 0.0;  // T(s) [N]
};

// throws std::runtime_error if the line cannot reach the fairlead or Newton fails
GroundedCatenarySolution SolveGroundedCatenary(const GroundedCatenaryProblem& p);

// the position and tension at unstretched arc length s in [0, L] of a solved line
GroundedCatenaryPoint GroundedCatenaryShape(const GroundedCatenaryProblem& p,
                                            const GroundedCatenarySolution& solution, double s);

}  // namespace towsim::reference
