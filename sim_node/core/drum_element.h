#pragma once
// Splitting and merging the winch's drum element (docs/winch.md). Element 0 at the drum has the
// variable rest length l_0 (system.h); the other elements keep l_e = cable.length /
// cable.elements. With the nodes in use at the end of the preallocated arrays (the drum node at
// array node f = System::first_node(c) of the winch's cable c):
//
// Split (l_0 -> l_0 - l_e and a new element of l_e): a node is added at x = l_0 - l_e from the
// drum, xi = x / l_0, with r, r' (and their velocities, accelerations and the
// generalized-alpha pseudo accelerations) read off element 0's cubic (paper Eq. 4):
//   e_new = [S(xi) e_0, S'(xi) e_0]   for e_0 in q, v, a, a_alpha of element 0;
// the drum node moves to array node f - 1, the new node takes array node f. A cubic restricted
// to a sub-interval is the Hermite cubic of its end values and slopes, so the shape, velocity
// field, mass and momentum are unchanged, and the strain energy too (5-point Gauss is exact for
// the degree-8 axial density of a cubic).
//
// Merge (l_0 -> l_0 + l_e): node 1 is removed and the drum node moves to its array node f + 1;
// the merged element is the Hermite cubic of the drum node and the old node 2, whose values,
// slopes and rates are kept. It conserves the mass (the rest length) and the state of every
// remaining node exactly, so everything outside the merged element is unchanged; inside it the
// piecewise cubic of two elements is replaced by the one cubic with the same end data, which
// changes the momentum and the energies by the interpolation error of the shape over 1.4 l_e
// (tests/unit/drum_element_test.cc measures it).
//
// Both invalidate the kept Newton matrix (its block structure changed).

#include "core/state.h"
#include "core/system.h"

namespace towsim::core {

// adds a node in element 0 of cable c (above); false if the arrays are full or l_0 <= l_e
bool SplitDrumElement(System* system, State* state, int c = 0);
// merges element 0 of cable c with its element 1 (above); false with fewer than 3 nodes
bool MergeDrumElement(System* system, State* state, int c = 0);

}  // namespace towsim::core
