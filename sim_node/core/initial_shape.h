#pragma once
// Initial cable coordinates q(0) (cable.initial): hanging vertically from the start, straight
// from start to end, or, as the first guess of the static solve, a parabola of the right arc
// length sagging along gravity between the two supports.

#include "core/state.h"
#include "core/system.h"

namespace towsim::core {

// fills state->q (cable nodes and body positions), state->v (cable.initial_velocity on every
// node, the bodies' own velocities) and t = 0
void BuildInitialState(const System& system, State* state);

// Lays cable k out along the inextensible catenary through its two supports, in the vertical
// plane of its chord (docs/physics.md "Initial shapes"): node i at the arc length
// s_i = L i / elements, its slope the unit tangent there, so no element is compressed. Where
// that catenary would dip below a seabed, the grounded catenary instead: from the deeper end
// straight along the bed toward the other end, then the catenary with its vertex at the
// touchdown point (Jonkman 2007, §2.1). A cable not longer than its chord is laid straight,
// stretched (r' = chord / L). Returns false (q untouched) when the shape is not defined: a free
// end, or a chord with no horizontal extent.
bool LayOutCatenary(const System& system, int k, State* state);

}  // namespace towsim::core
