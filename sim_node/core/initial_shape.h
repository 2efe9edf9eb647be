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

}  // namespace towsim::core
