// Splitting and merging the drum element (drum_element.h) against the element's own cubic: a
// split leaves the shape r(x) along the old element unchanged (the two new cubics are the old
// one on their sub-intervals), keeps the drum node, and, with the drum at rest, the velocity
// field too; merging right after a split gives back the element it came from. The reference is
// the old element's Hermite cubic (paper Eq. 4) evaluated directly; the tolerance is round-off.

#include "core/drum_element.h"

#include <vector>

#include <gtest/gtest.h>

#include "core/initial_shape.h"
#include "core/system.h"
#include "steady_tow_model.h"

namespace towsim::core {
namespace {

// round-off of a cubic evaluated on 10 m elements at coordinates of order 100 m
constexpr double kShapeTol = 1e-11;  // [m]

// the steady tow with a winch, 204 m paid out on 10 m elements: a drum element of 14 m, bent
// and moving
struct Fixture {
  Fixture() : system(test::SteadyTowWithWinch()) {
    BuildInitialState(system, &state);
    state.winches.resize(1);  // WinchDrive::Initialize's (winch_drive.h)
    state.winches[0].nodes = system.num_nodes();
    state.winches[0].length = 204.0;  // the drum element 14 m
    system.SetLayout(state.winches[0].nodes, state.winches[0].length);
    // bend element 0 and give it a velocity field (any smooth values)
    const int o = system.CableDof(0);
    state.q.segment<3>(o + 3) = Vec3(0.3, 0.1, 0.95);
    state.q.segment<3>(o + 6) = Vec3(4.0, 1.0, 13.0);
    state.q.segment<3>(o + 9) = Vec3(0.2, 0.05, 0.98);
    state.v.segment<12>(o) << 0.1, 0.0, 0.2, 0.01, 0.02, 0.0, 0.5, -0.2, 0.3, 0.0, 0.01, -0.02;
  }
  System system;
  State state;
};

// r (or v) at arc length `at` along element `element` of rest length `length`, from x = q (v)
Vec3 At(const System& sys, const Eigen::VectorXd& x, int element, double at, double length) {
  const Vec12 e = x.segment<12>(sys.CableDof(element));
  return Interpolate(EvaluateShape(at / length, length).n, e);
}

TEST(DrumElement, SplitKeepsTheCubicAndMergeUndoesIt) {
  Fixture f;
  const double l0 = f.system.drum_length(), le = f.system.element_length();
  ASSERT_DOUBLE_EQ(l0, 14.0);
  const State before = f.state;
  const int nodes = f.state.winches[0].nodes;
  std::vector<Vec3> r, v;
  for (int k = 0; k <= 14; ++k) {
    r.push_back(At(f.system, before.q, 0, k, l0));
    v.push_back(At(f.system, before.v, 0, k, l0));
  }
  ASSERT_TRUE(SplitDrumElement(&f.system, &f.state));
  EXPECT_EQ(f.state.winches[0].nodes, nodes + 1);
  EXPECT_DOUBLE_EQ(f.system.drum_length(), l0 - le);
  EXPECT_FALSE(f.state.newton.valid);
  // x in [0, 4]: the new drum element; x in [4, 14]: the new element 1 of l_e
  for (int k = 0; k <= 14; ++k) {
    const double x = k;
    const bool drum = x <= l0 - le;
    const Vec3 rk = drum ? At(f.system, f.state.q, 0, x, l0 - le)
                         : At(f.system, f.state.q, 1, x - (l0 - le), le);
    const Vec3 vk = drum ? At(f.system, f.state.v, 0, x, l0 - le)
                         : At(f.system, f.state.v, 1, x - (l0 - le), le);
    EXPECT_LE((rk - r[k]).norm(), kShapeTol) << "r at x = " << x;
    EXPECT_LE((vk - v[k]).norm(), kShapeTol) << "v at x = " << x;  // drum at rest
  }
  ASSERT_TRUE(MergeDrumElement(&f.system, &f.state));
  EXPECT_EQ(f.state.winches[0].nodes, nodes);
  EXPECT_DOUBLE_EQ(f.system.drum_length(), l0);
  const int o = f.system.CableDof(0);
  EXPECT_LE((f.state.q.segment<12>(o) - before.q.segment<12>(o)).lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_LE((f.state.v.segment<12>(o) - before.v.segment<12>(o)).lpNorm<Eigen::Infinity>(), 0.0);
  // the rest of the cable untouched
  EXPECT_EQ(f.state.q.tail(f.state.q.size() - o - 12), before.q.tail(before.q.size() - o - 12));
}

}  // namespace
}  // namespace towsim::core
