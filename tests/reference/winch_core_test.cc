// The winch (docs/winch.md) held to independent references while it pays out and reels in.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "core/state.h"

namespace towsim::reference {
namespace {

using core::Vec3;

core::Model VerticalCableWithWeight() {
  core::Model m;
  m.time.step = 0.05;
  m.cable.length = 100;
  m.cable.elements = 10;
  m.cable.start.kind = core::EndKind::kFixed;
  m.cable.end.kind = core::EndKind::kBody;
  m.cable.end.body = 0;
  core::SphereBody b;
  b.name = "weight";
  b.mass = 416;
  b.volume = 0.2;
  b.position = Vec3(0, 0, 100);
  m.bodies.push_back(b);
  core::WinchParams w;
  w.min_length = 50;
  w.max_length = 150;
  w.max_speed = 0.1;
  w.max_acceleration = 0.005;
  m.cable.winch = w;
  m.cable.initial = core::InitialShape::kStatic;
  return m;
}

TEST(WinchCore, VerticalCableDrumTensionIsTheHangingWeight) {
  const core::Model m = VerticalCableWithWeight();
  core::Simulation sim(m);
  const core::CableParams& c = m.cable;
  const double g = m.environment.gravity, rho = m.environment.water_density;
  const double w_cable = (c.density - rho) * c.area() * g;
  const double w_body = (m.bodies[0].mass - rho * m.bodies[0].volume) * g;
  sim.SetWinchCommand({core::WinchCommand::Mode::kLength, 120.0});
  double worst = 0;
  for (int i = 0; i < 8000; ++i) {
    ASSERT_TRUE(sim.Step().ok()) << i;
    if (i == 5000) sim.SetWinchCommand({core::WinchCommand::Mode::kLength, 100.0});
    const double ref = w_cable * sim.cable_length() + w_body;
    const double err = sim.drum_tension() / ref - 1;
    worst = std::max(worst, std::abs(err));
    if (sim.time() > 69.8 && sim.time() < 70.4) {
      const core::State& st = sim.state();
      for (int n = 0; n < 3; ++n) {
        const int o = sim.cable_dof(n);
        std::printf("   node %d z %.6f dz %.6f vz %.6f az %.6f aa %.6f\n", n, st.q(o + 2), st.q(o + 5),
                    st.v(o + 2), st.a(o + 2), st.a_alpha(o + 2));
      }
      std::printf("   T1 %.3f\n", sim.node_tension(1));
    }
    if (i % 200 == 0 || std::abs(err) > 2e-3)
      std::printf("t %g L %.4f V %.4f nodes %d T %.3f ref %.3f err %.2e\n", sim.time(),
                  sim.cable_length(), sim.winch_speed(), sim.num_nodes(), sim.drum_tension(), ref,
                  err);
  }
  std::printf("worst %.3e\n", worst);
}

}  // namespace
}  // namespace towsim::reference
