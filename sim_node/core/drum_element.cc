#include "core/drum_element.h"

namespace towsim::core {

bool SplitDrumElement(System* system, State* state, int c) {
  WinchState& winch = state->winches[c];
  const int first = system->first_node(c);
  const double l0 = system->drum_length(c), le = system->element_length(c);
  if (first == 0 || l0 <= le) return false;
  // r, r' of the new node from element 0's cubic, for each of q, v, a, a_alpha
  const double xi = (l0 - le) / l0;
  const ShapeAtPoint shape = EvaluateShape(xi, l0);
  const int drum = system->ArrayDof(first, c), added = system->ArrayDof(first - 1, c);
  const Vec12 e = state->q.segment<12>(drum), e_dot = state->v.segment<12>(drum);
  const Vec3 r0 = e.segment<3>(0), d0 = e.segment<3>(3), r1 = e.segment<3>(6), d1 = e.segment<3>(9);
  // the material velocity there (drum_element.h): the rate at fixed xi plus the material's
  // motion along the cable, (1 - xi) dl_0/dt r'
  const double rate = winch.speed;
  const Vec3 dr = Interpolate(shape.dn, e), ddr = Interpolate(shape.ddn, e);
  const Vec3 v_xi =
      Interpolate(shape.n, e_dot) + (rate / l0) * (shape.n[1] * d0 + shape.n[3] * d1);
  const Vec3 dv_xi =
      Interpolate(shape.dn, e_dot) - (rate / l0) * (shape.dn[0] * r0 + shape.dn[2] * r1);
  const Vec3 v_new = v_xi + ((1.0 - xi) * rate) * dr;
  const Vec3 dv_new = dv_xi + ((1.0 - xi) * rate) * ddr;
  Eigen::VectorXd* vectors[4] = {&state->q, &state->v, &state->a, &state->a_alpha};
  for (Eigen::VectorXd* x : vectors) {
    const Vec12 ex = x->segment<12>(drum);
    Vec3 value = Interpolate(shape.n, ex), slope = Interpolate(shape.dn, ex);
    if (x == &state->v) {
      value = v_new;
      slope = dv_new;
    }
    x->segment<6>(added) = x->segment<6>(drum);  // the drum node moves to array node f - 1
    x->segment<3>(drum) = value;
    x->segment<3>(drum + 3) = slope;
  }
  ++winch.nodes;
  system->SetLayout(winch.nodes, winch.length, c);
  state->newton.valid = false;
  return true;
}

bool MergeDrumElement(System* system, State* state, int c) {
  WinchState& winch = state->winches[c];
  if (winch.nodes < 3) return false;
  const int first = system->first_node(c);
  const int drum = system->ArrayDof(first, c), next = system->ArrayDof(first + 1, c);
  Eigen::VectorXd* vectors[4] = {&state->q, &state->v, &state->a, &state->a_alpha};
  for (Eigen::VectorXd* x : vectors) {
    x->segment<6>(next) = x->segment<6>(drum);  // the drum node replaces node 1
    if (x != &state->q) x->segment<6>(drum).setZero();  // parked at rest
  }
  --winch.nodes;
  system->SetLayout(winch.nodes, winch.length, c);
  state->newton.valid = false;
  return true;
}

}  // namespace towsim::core
