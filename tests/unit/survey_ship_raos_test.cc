// The example RAO table config/vessels/survey_ship_raos.csv (docs/vessels.md "Example RAOs"):
// it reads, covers the seas the examples use, and tends to the long-wave limits whose signs
// follow from the conventions alone (the ship rides the surface: heave = eta, pitch = the
// slope along x, roll = minus the slope along y).
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/rao_table.h"
#include "core/wave_field.h"
#include "scene/rao_coverage.h"
#include "scene/rao_file.h"

namespace towsim::scene {
namespace {

constexpr double kPi = core::kPi;
constexpr double kDeg = kPi / 180.0;
constexpr double kG = 9.81;
const std::string kFile = std::string(TOWSIM_SOURCE_DIR) + "/config/vessels/survey_ship_raos.csv";

core::RaoTable Table() { return ReadRaoFile(kFile, "bodies.ship.raos"); }

// phase lag [deg] of H = |H| e^{-i phi}
double LagDeg(std::complex<double> h) { return -std::arg(h) / kDeg; }

TEST(SurveyShipRaos, ReadsAsAFullCircleOfHeaveRollAndPitch) {
  const core::RaoTable t = Table();
  EXPECT_TRUE(t.periodic_directions);
  EXPECT_EQ(t.directions.size(), 24u);  // 0 .. 345 every 15 (360 dropped)
  EXPECT_EQ(t.periods.front(), 1.0);
  EXPECT_EQ(t.periods.back(), 30.0);
  for (core::VesselDof d :
       {core::VesselDof::kHeave, core::VesselDof::kRoll, core::VesselDof::kPitch}) {
    EXPECT_EQ(t.amplitude[static_cast<int>(d)].size(), t.periods.size() * 24);
  }
  for (core::VesselDof d :
       {core::VesselDof::kSurge, core::VesselDof::kSway, core::VesselDof::kYaw}) {
    EXPECT_TRUE(t.amplitude[static_cast<int>(d)].empty());
  }
}

TEST(SurveyShipRaos, HeaveTendsToTheWaveElevationInLongWaves) {
  const core::RaoTable t = Table();
  // at 30 s (wave length 1400 m, 23 ship lengths) the ship rides the wave: |H| within 3 % of
  // 1 (the oscillator's 1 / (1 - (5.67/30)^2) = 1.037 and the depth factor e^{-kT} = 0.98 are
  // what is left) and the lag within 6 deg of 0; and closer to it at 30 s than at 20 s
  constexpr double kAmplitudeTol = 0.03;
  constexpr double kLagTolDeg = 6.0;
  for (int d = 0; d < 360; d += 15) {
    const std::complex<double> h30 = core::RaoAt(t, core::VesselDof::kHeave, 30.0, d * kDeg);
    const std::complex<double> h20 = core::RaoAt(t, core::VesselDof::kHeave, 20.0, d * kDeg);
    EXPECT_NEAR(std::abs(h30), 1.0, kAmplitudeTol) << d;
    EXPECT_NEAR(LagDeg(h30), 0.0, kLagTolDeg) << d;
    EXPECT_LT(std::abs(h30 - 1.0), std::abs(h20 - 1.0)) << d;
  }
}

TEST(SurveyShipRaos, PitchAndRollFollowTheWaveSlopeWithTheConventionsSigns) {
  const core::RaoTable t = Table();
  const double k = std::pow(2.0 * kPi / 30.0, 2) / kG;  // deep water, 30 s
  // eta = Re[a e^{i(w t - kx x - ky y)}]: slope along x = -i kx eta, along y = -i ky eta.
  // pitch (bow up) = d eta/dx -> H = -i k cos(beta): lag +90 deg in following seas (beta = 0),
  // -90 in head seas (the bow rises before the crest reaches midships).
  // roll (starboard down) = -d eta/dy -> H = +i k sin(beta): lag -90 deg for waves travelling
  // toward starboard (beta = 90: the port side rises first), +90 toward port.
  // amplitudes: pitch within 5 % of k (oscillator 1.027, e^{-kT} 0.98); roll within 15 % (its
  // 10 s resonance: 1 / (1 - (10/30)^2) = 1.125)
  const auto pitch = [&](double beta) {
    return core::RaoAt(t, core::VesselDof::kPitch, 30.0, beta * kDeg);
  };
  const auto roll = [&](double beta) {
    return core::RaoAt(t, core::VesselDof::kRoll, 30.0, beta * kDeg);
  };
  constexpr double kLagTolDeg = 6.0;
  EXPECT_NEAR(std::abs(pitch(0.0)) / k, 1.0, 0.05);
  EXPECT_NEAR(LagDeg(pitch(0.0)), 90.0, kLagTolDeg);
  EXPECT_NEAR(std::abs(pitch(180.0)) / k, 1.0, 0.05);
  EXPECT_NEAR(LagDeg(pitch(180.0)), -90.0, kLagTolDeg);
  EXPECT_NEAR(std::abs(roll(90.0)) / k, 1.125, 0.05);
  EXPECT_NEAR(LagDeg(roll(90.0)), -90.0, kLagTolDeg);
  EXPECT_NEAR(LagDeg(roll(270.0)), 90.0, kLagTolDeg);
  // no roll in head or following seas, no pitch in beam seas (the box is symmetric)
  EXPECT_LT(std::abs(roll(0.0)), 1e-12);
  EXPECT_LT(std::abs(roll(180.0)), 1e-12);
  EXPECT_LT(std::abs(pitch(90.0)), 1e-12);
}

TEST(SurveyShipRaos, CoversAJonswapSeaOfPeakPeriod8sFromAnyHeading) {
  // the irregular sea's band keeps all but 1e-3 of m0 at each end (core/wave_field.h): for
  // Tp 8 s it reaches down to 1.5 s, so the table starts at 1 s
  const core::RaoTable t = Table();
  double shortest = std::numeric_limits<double>::infinity();
  for (double gamma : {1.0, 3.3, 7.0}) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      core::WaveSpectrum s;
      s.hs = 2.5;
      s.tp = 8.0;
      s.gamma = gamma;
      s.direction = 0.7 * seed;
      s.components = 200;
      s.seed = seed;
      const core::WaveField sea =
          core::WaveField::Irregular(s, std::numeric_limits<double>::infinity(), kG, 1025.0);
      EXPECT_EQ(RaoCoverageProblem(t, sea.components(), /*heading_changes=*/true, 0.0), "")
          << "gamma " << gamma << " seed " << seed;
      for (const core::WaveComponent& c : sea.components()) {
        shortest = std::min(shortest, 2.0 * kPi / c.omega);
      }
    }
  }
  // the check is not vacuous: the sea holds components below 3 s
  EXPECT_LT(shortest, 2.0);
}

}  // namespace
}  // namespace towsim::scene
