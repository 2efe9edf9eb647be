// A vessel heaving a vertical cable with a mass at its bottom (docs/vessels.md "Verified"),
// held to the closed-form steady response of an axially vibrating rod with an end mass.
//
// The rod: x from the top (0) down to the mass (L), axial displacement u(x, t) = Re(U(x) e^{iwt})
// with Kelvin-Voigt damping (the core's N = EA (eps + c deps/dt)): EA* = EA (1 + i w c),
//   EA* U'' + m w^2 U = 0,  U = A cos(kx) + B sin(kx),  k^2 = m w^2 / EA*  (complex),
// top driven, U(0) = U_0; the mass M_e (its mass and added mass) moved by the tension alone,
//   -M_e w^2 U(L) = -EA* U'(L)   (the tension pulls it up, toward the top)
// so  A = U_0,  B = U_0 (M_e w^2 cos kL + EA* k sin kL) / (EA* k cos kL - M_e w^2 sin kL).
// The weight and the buoyancy are steady; they set the static tension (0.1 % strain here, so
// the Green strain's change of the tangent stiffness is 0.1 %) but not the linear response.
// The cable's drag and the sphere's drag are off (the closed form has none); the cable's
// tangential added mass is 0 (the core's default), its normal added mass does not act on an
// axial motion.
//
// Three periods: well below, below and near the first resonance (T_1 = 0.65 s for these
// numbers). Tolerance: 2 % of the bottom amplitude (20 ANCF elements resolve the first axial
// mode's shape to far better; the 2 % covers the discretisation of the distributed mass and
// the integrator's phase error over the 100-odd steps a period).
//
// Then the same motion from a time history that samples it (every 0.02 s): the bottom
// amplitude within 1 % of the harmonic run's.

#include <cmath>
#include <complex>
#include <vector>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"
#include "core/simulation.h"

namespace towsim::reference {
namespace {

using core::kPi;
using cd = std::complex<double>;

constexpr double kLength = 100.0;      // L [m]
constexpr double kEA = 1.0e7;          // [N]
constexpr double kMassPerLength = 2.0; // m [kg/m]
constexpr double kDamping = 0.005;     // c [s]
constexpr double kMass = 1000.0;       // M [kg]
constexpr double kVolume = 0.1;        // V [m^3]
constexpr double kAddedMassCoeff = 0.5;
constexpr double kRho = 1025.0;
constexpr double kAmplitude = 0.01;    // heave amplitude U_0 [m]
constexpr double kStep = 0.004;        // [s]
// the closed form against the core
constexpr double kRodTol = 0.02;
// the time history against the harmonic run
constexpr double kHistoryTol = 0.01;

double ClosedFormBottomAmplitude(double period) {
  const double w = 2.0 * kPi / period;
  const double me = kMass + kAddedMassCoeff * kRho * kVolume;
  const cd ea = kEA * cd(1.0, w * kDamping);
  const cd k = std::sqrt(kMassPerLength * w * w / ea);
  const cd c = std::cos(k * kLength), s = std::sin(k * kLength);
  const cd b = kAmplitude * (me * w * w * c + ea * k * s) / (ea * k * c - me * w * w * s);
  return std::abs(kAmplitude * c + b * s);
}

core::Model HeaveModel(double period) {
  core::Model m;
  m.time.step = kStep;
  m.environment.water_density = kRho;
  core::CableParams& c = m.cables[0];
  c.length = kLength;
  c.elements = 20;
  c.diameter = 0.03;
  c.mass_per_length = kMassPerLength;
  c.axial_stiffness = kEA;
  c.bending_stiffness = 10.0;
  c.axial_damping = kDamping;
  c.loads.drag = false;
  c.initial = core::InitialShape::kStatic;
  core::Vessel ship;
  ship.name = "ship";
  ship.harmonics.push_back({core::VesselDof::kHeave, kAmplitude, period, 0.0});
  m.vessels.push_back(ship);
  core::SphereBody weight;
  weight.name = "weight";
  weight.mass = kMass;
  weight.volume = kVolume;
  weight.drag_coefficient = 0.0;
  weight.added_mass_coefficient = kAddedMassCoeff;
  weight.position = core::Vec3(0.0, 0.0, kLength);
  m.spheres.push_back(weight);
  c.start.kind = core::EndKind::kVessel;
  c.start.body = 0;
  c.end.kind = core::EndKind::kSphere;
  c.end.body = 0;
  return m;
}

// the amplitude of the component of frequency 2 pi / period of z over the last `periods`
// whole periods of the run (projection on cos and sin)
double RunBottomAmplitude(const core::Model& model, double period, double settle, int periods) {
  core::Simulation sim(model);
  const double w = 2.0 * kPi / period;
  const long settle_steps = std::lround(settle / kStep);
  const long record_steps = std::lround(periods * period / kStep);
  std::vector<double> t, z;
  for (long i = 0; i < settle_steps + record_steps; ++i) {
    const core::StepStatus s = sim.Step();
    if (!s.ok()) {
      ADD_FAILURE() << s.message;
      return 0.0;
    }
    if (i < settle_steps) continue;
    t.push_back(sim.time());
    z.push_back(sim.body_position(0).z());
  }
  // the mean off first: the record is whole periods only to within a step, and the static
  // depth (100 m) would leak into the projection
  double mean = 0.0;
  for (double v : z) mean += v / static_cast<double>(z.size());
  cd sum = 0.0;
  for (size_t i = 0; i < z.size(); ++i) sum += (z[i] - mean) * std::polar(1.0, -w * t[i]);
  return 2.0 * std::abs(sum) / static_cast<double>(z.size());
}

class VesselHeaveRod : public ::testing::TestWithParam<double> {};

TEST_P(VesselHeaveRod, BottomAmplitudeMatchesTheRodWithAnEndMass) {
  const double period = GetParam();
  const double expected = ClosedFormBottomAmplitude(period);
  // the record: whole periods near 4 s, after the transient (its decay: zeta w_1 ~ 0.24 / s)
  const int periods = std::max(2, static_cast<int>(std::lround(4.0 / period)));
  const double measured = RunBottomAmplitude(HeaveModel(period), period, 30.0, periods);
  std::printf("heave T = %.2f s: bottom amplitude %.5f m, closed form %.5f m (%+.2f %%)\n", period,
              measured, expected, 100.0 * (measured / expected - 1.0));
  EXPECT_NEAR(measured / expected, 1.0, kRodTol);
}

// well below (T = 3 T_1), below (1.5 T_1) and near (1.15 T_1) the first resonance
INSTANTIATE_TEST_SUITE_P(Periods, VesselHeaveRod, ::testing::Values(2.0, 1.0, 0.75));

TEST(VesselTimeHistory, SamplesOfTheHarmonicMotionGiveTheSameRun) {
  const double period = 1.0;
  const core::Model harmonic = HeaveModel(period);
  core::Model history = harmonic;
  core::TimeHistory th;
  const double w = 2.0 * kPi / period;
  for (double t = -0.1; t < 40.0; t += 0.02) {
    Eigen::Matrix<double, 6, 1> p = Eigen::Matrix<double, 6, 1>::Zero();
    p(2) = -kAmplitude * std::cos(w * t);  // heave up is -z
    th.t.push_back(t);
    th.pose.push_back(p);
  }
  history.vessels[0].harmonics.clear();
  history.vessels[0].time_history = th;
  const double a = RunBottomAmplitude(harmonic, period, 30.0, 4);
  const double b = RunBottomAmplitude(history, period, 30.0, 4);
  std::printf("harmonic %.6f m, time history %.6f m (%+.3f %%)\n", a, b, 100.0 * (b / a - 1.0));
  EXPECT_NEAR(b / a, 1.0, kHistoryTol);
}

}  // namespace
}  // namespace towsim::reference
