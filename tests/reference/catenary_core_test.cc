// The core's static solve of a cable hanging between two pins, held to Irvine's elastic
// catenary (elastic_catenary.h).
//
// 200 m of the paper's cable (d 0.041 m, rho_c 1300, E 7e8) in water, pins at equal depth
// 150 m apart. Loads: gravity, buoyancy and bending. Bending is absent from the reference;
// it is negligible here: EI = E pi d^4 / 64 = 97.1 N m^2 against H = 197.5 N and the catenary
// parameter a = H / w = 55.5 m. The bending energy EI kappa^2 / 2 with kappa ~ 1 / a changes
// the global equilibrium (H, sag) by a relative O(EI / (H a^2)) = 1.6e-4; at the pins (zero
// moment) the end curvature w H / T_end^2 = 4e-3 1/m is released over the bending length
// sqrt(EI / T) ~ 0.5 m, a local shape change of ~1e-3 m (2e-5 of the 59 m sag). Both are an
// order below the 2e-3 tolerance; the test also measures the core's bending-on / -off
// difference.
//
// Constitutive law: the reference uses Hooke on the engineering strain, the core Green strain
// with true tension; at the strains here (T / EA ~ 4.5e-4) the two differ by 1.5 (T/EA)^2 ~
// 3e-7, invisible at 2e-3.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "elastic_catenary.h"
#include "hanging_cable_model.h"

namespace towsim::reference {
namespace {

using core::Vec3;

// issue requirement for 20 elements: mid-span sag, horizontal tension and end tension
constexpr double kRelTol = 2e-3;

CatenaryProblem ReferenceProblem(const core::Model& m) {
  const core::CableParams& c = m.cables[0];
  const core::Environment& env = m.environment;
  CatenaryProblem p;
  p.length = c.length;
  p.span = kHangingCableSpan;
  p.height = 0.0;
  p.weight = (c.mass_per_length - env.water_density * c.area()) * env.gravity;  // (m - rho_w A) g
  p.ea = c.axial_stiffness;
  return p;
}

struct Measured {
  double sag;          // z of the middle node (z down: the sag below the pins) [m]
  double h;            // |x| of the force on the start pin [N]
  double tension;      // |force on the start pin| [N]
  double shape_error;  // max over nodes of |r_core - r_reference| [m]
};

Measured Measure(const core::Simulation& sim, const CatenaryProblem& p,
                 const CatenarySolution& ref) {
  const int n = sim.num_nodes();
  Measured out;
  out.sag = sim.node_position((n - 1) / 2).z();
  const Vec3 f = sim.end_force(0);
  out.h = std::abs(f.x());
  out.tension = f.norm();
  out.shape_error = 0.0;
  for (int i = 0; i < n; ++i) {
    const double s = p.length * i / (n - 1);
    const CatenaryPoint pt = CatenaryShape(p, ref.horizontal_tension, ref.vertical_force_a, s);
    const Vec3 r_ref(pt.x, 0.0, -pt.y);  // reference y is up, core z is down
    out.shape_error = std::max(out.shape_error, (sim.node_position(i) - r_ref).norm());
  }
  return out;
}

void Print(const char* label, const Measured& m, const CatenarySolution& ref) {
  std::printf(
      "%s: sag %.5f m (ref %.5f, %+.2e), H %.4f N (ref %.4f, %+.2e), "
      "T_end %.4f N (ref %.4f, %+.2e), max node offset %.2e m\n",
      label, m.sag, ref.sag_mid_span, m.sag / ref.sag_mid_span - 1.0, m.h, ref.horizontal_tension,
      m.h / ref.horizontal_tension - 1.0, m.tension, ref.tension_a, m.tension / ref.tension_a - 1.0,
      m.shape_error);
}

TEST(CatenaryCore, TwentyElementsMatchIrvine) {
  const core::Model model = HangingCable(20, /*bending=*/true);
  const CatenaryProblem p = ReferenceProblem(model);
  const CatenarySolution ref = SolveElasticCatenary(p);
  const core::Simulation sim(model);
  ASSERT_EQ(sim.num_nodes(), 21);
  const Measured m = Measure(sim, p, ref);
  Print("20 elements", m, ref);
  EXPECT_NEAR(m.sag, ref.sag_mid_span, kRelTol * ref.sag_mid_span);
  EXPECT_NEAR(m.h, ref.horizontal_tension, kRelTol * ref.horizontal_tension);
  EXPECT_NEAR(m.tension, ref.tension_a, kRelTol * ref.tension_a);
  // the whole shape, node by node, to the same relative accuracy as the sag
  EXPECT_LT(m.shape_error, kRelTol * ref.sag_mid_span);
  // the pins share the weight equally: the end force points along the cable, up and inwards
  const Vec3 f = sim.end_force(0);
  EXPECT_NEAR(std::abs(f.z()), ref.vertical_force_a, kRelTol * ref.vertical_force_a);
}

// the same cable without bending: the bending contribution the reference leaves out
TEST(CatenaryCore, BendingIsNegligible) {
  const core::Model with = HangingCable(20, /*bending=*/true);
  const core::Model without = HangingCable(20, /*bending=*/false);
  const CatenaryProblem p = ReferenceProblem(with);
  const CatenarySolution ref = SolveElasticCatenary(p);
  const Measured a = Measure(core::Simulation(with), p, ref);
  const Measured b = Measure(core::Simulation(without), p, ref);
  Print("20 elements, no bending", b, ref);
  std::printf("bending on - off: sag %+.2e m (%+.2e rel), H %+.2e N (%+.2e rel)\n", a.sag - b.sag,
              a.sag / b.sag - 1.0, a.h - b.h, a.h / b.h - 1.0);
  // estimate above: EI / (H a^2) = 1.6e-4 relative; 3x that, still 4x below the 2e-3 test
  // tolerance
  constexpr double kBendingRelEffect = 5e-4;
  EXPECT_NEAR(a.sag, b.sag, kBendingRelEffect * ref.sag_mid_span);
  EXPECT_NEAR(a.h, b.h, kBendingRelEffect * ref.horizontal_tension);
}

// 10 elements: reported, not asserted (the requirement is for 20)
TEST(CatenaryCore, TenElementsReported) {
  const core::Model model = HangingCable(10, /*bending=*/true);
  const CatenaryProblem p = ReferenceProblem(model);
  const CatenarySolution ref = SolveElasticCatenary(p);
  const core::Simulation sim(model);
  Print("10 elements", Measure(sim, p, ref), ref);
}

}  // namespace
}  // namespace towsim::reference
