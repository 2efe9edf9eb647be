// core/rao_table.h: the complex bilinear lookup of displacement RAOs. Oracles: the table's own
// entries at grid points, and complex means computed by hand in the comments.
#include "core/rao_table.h"

#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "core/constants.h"

namespace towsim::core {
namespace {

constexpr double kDeg = kPi / 180.0;
// the interpolation is a handful of products and sums: round-off only
constexpr double kTol = 1e-14;

using C = std::complex<double>;

// a table with `periods` x `directions_deg` and, for every dof given, amplitude and phase [deg]
// per entry from `amplitude(i, j)` / `phase_deg(i, j)`
template <typename A, typename P>
RaoTable MakeTable(std::vector<double> periods, std::vector<double> directions_deg,
                   std::initializer_list<VesselDof> dofs, A amplitude, P phase_deg,
                   bool periodic = false) {
  RaoTable t;
  t.periods = std::move(periods);
  for (double d : directions_deg) t.directions.push_back(d * kDeg);
  t.periodic_directions = periodic;
  const size_t np = t.periods.size(), nd = t.directions.size();
  for (VesselDof dof : dofs) {
    const int j = static_cast<int>(dof);
    t.amplitude[j].resize(np * nd);
    t.phase[j].resize(np * nd);
    for (size_t i = 0; i < np; ++i) {
      for (size_t k = 0; k < nd; ++k) {
        t.amplitude[j][i * nd + k] = amplitude(i, k) * (j + 1);  // each dof its own values
        t.phase[j][i * nd + k] = phase_deg(i, k) * kDeg;
      }
    }
  }
  return t;
}

void ExpectNear(C got, C want, double tol, const std::string& what) {
  EXPECT_NEAR(got.real(), want.real(), tol) << what;
  EXPECT_NEAR(got.imag(), want.imag(), tol) << what;
}

TEST(RaoAt, ReturnsTheEntriesAtTheGridPoints) {
  // |H| = 0.1 + 0.3 i + 0.05 k, phi = 40 i - 25 k deg: H = |H| e^{-i phi}
  const RaoTable t = MakeTable(
      {4.0, 7.5, 12.0}, {-90.0, -30.0, 45.0, 90.0}, {VesselDof::kHeave, VesselDof::kRoll},
      [](size_t i, size_t k) { return 0.1 + 0.3 * i + 0.05 * k; },
      [](size_t i, size_t k) { return 40.0 * i - 25.0 * k; });
  for (size_t i = 0; i < t.periods.size(); ++i) {
    for (size_t k = 0; k < t.directions.size(); ++k) {
      for (VesselDof dof : {VesselDof::kHeave, VesselDof::kRoll}) {
        const int j = static_cast<int>(dof);
        const double a = (0.1 + 0.3 * i + 0.05 * k) * (j + 1);
        const double phi = (40.0 * i - 25.0 * k) * kDeg;
        const C want(a * std::cos(phi), -a * std::sin(phi));
        ExpectNear(RaoAt(t, dof, t.periods[i], t.directions[k]), want, kTol,
                   "i " + std::to_string(i) + " k " + std::to_string(k));
      }
    }
  }
  // a lag is a negative imaginary part: heave (factor 3) at i = 1, k = 0 has |H| = 1.2 and
  // phi = 40 deg, H = 1.2 (cos 40 deg - i sin 40 deg)
  EXPECT_NEAR(RaoAt(t, VesselDof::kHeave, 7.5, -90.0 * kDeg).imag(), -1.2 * std::sin(40 * kDeg),
              kTol);
}

TEST(RaoAt, InterpolatesTheComplexValueBilinearly) {
  // corners (period 5 | 9) x (direction 0 | 60 deg):
  //   H00 = 1 (1, 0 deg), H01 = -2i (2, 90 deg), H10 = -0.5 (0.5, 180 deg), H11 = i (1, -90 deg)
  static constexpr double amp[2][2] = {{1.0, 2.0}, {0.5, 1.0}};
  static constexpr double ph[2][2] = {{0.0, 90.0}, {180.0, -90.0}};
  const RaoTable t = MakeTable(
      {5.0, 9.0}, {0.0, 60.0}, {VesselDof::kSurge}, [](size_t i, size_t k) { return amp[i][k]; },
      [](size_t i, size_t k) { return ph[i][k]; });
  // midway: (1 - 2i - 0.5 + i) / 4 = 0.125 - 0.25i
  ExpectNear(RaoAt(t, VesselDof::kSurge, 7.0, 30.0 * kDeg), C(0.125, -0.25), kTol, "midway");
  // w_period = 0.25, w_direction = 0.75:
  //   period 5 row: 0.25 (1) + 0.75 (-2i) = 0.25 - 1.5i; period 9 row: 0.25 (-0.5) + 0.75 i
  //   H = 0.75 (0.25 - 1.5i) + 0.25 (-0.125 + 0.75i) = 0.15625 - 0.9375i
  ExpectNear(RaoAt(t, VesselDof::kSurge, 6.0, 45.0 * kDeg), C(0.15625, -0.9375), kTol,
             "off-centre");
}

TEST(RaoAt, InterpolatesAcrossAPhaseWrap) {
  // phases 350 and 10 deg at amplitude 1: (e^{-i 350 deg} + e^{-i 10 deg}) / 2 = cos(10 deg),
  // i.e. amplitude cos(10 deg) = 0.98481 at phase 0 (a mean of the phase numbers would give
  // 180 deg, the opposite motion)
  const RaoTable t = MakeTable(
      {8.0}, {0.0, 20.0}, {VesselDof::kSurge}, [](size_t, size_t) { return 1.0; },
      [](size_t, size_t k) { return k == 0 ? 350.0 : 10.0; });
  const C h = RaoAt(t, VesselDof::kSurge, 8.0, 10.0 * kDeg);
  ExpectNear(h, C(std::cos(10.0 * kDeg), 0.0), kTol, "midway");
  EXPECT_NEAR(std::abs(h), 0.984807753012208, 1e-15);
  EXPECT_NEAR(std::arg(h), 0.0, kTol);
}

TEST(RaoAt, PeriodicTableWrapsBetweenTheLastAndTheFirstDirection) {
  // directions 0, 30, ..., 330 (360 dropped); amplitude 1 + k/10, phase 0 except 330: -90
  std::vector<double> dirs;
  for (int k = 0; k < 12; ++k) dirs.push_back(30.0 * k);
  const RaoTable t = MakeTable(
      {6.0, 10.0}, dirs, {VesselDof::kRoll}, [](size_t, size_t k) { return 1.0 + 0.1 * k; },
      [](size_t, size_t k) { return k == 11 ? -90.0 : 0.0; }, /*periodic=*/true);
  // between 330 (H = 2.1 i x 4) and 360 = 0 (H = 1 x 4): at 345 deg the mean, 4 (0.5 + 1.05i)
  const C want(4.0 * 0.5, 4.0 * 1.05);
  for (double d : {345.0, -15.0, 705.0, -375.0}) {
    ExpectNear(RaoAt(t, VesselDof::kRoll, 6.0, d * kDeg), want, kTol, "at " + std::to_string(d));
  }
  // a third of the way from 330 to 360: (2/3) 8.4i + (1/3) 4
  ExpectNear(RaoAt(t, VesselDof::kRoll, 8.0, 340.0 * kDeg), C(4.0 / 3.0, 2.0 / 3.0 * 8.4), kTol,
             "340");
  // 360 is 0 exactly
  ExpectNear(RaoAt(t, VesselDof::kRoll, 8.0, 2.0 * kPi), C(4.0, 0.0), kTol, "360");
}

TEST(RaoAt, NonPeriodicTableTakesTheNearerEndOutsideItsDirections) {
  // directions -90 .. 90; the gap is (90, 270): held at 90 up to 180, at -90 (= 270) beyond
  const RaoTable t = MakeTable(
      {5.0}, {-90.0, 0.0, 90.0}, {VesselDof::kHeave}, [](size_t, size_t k) { return 1.0 + k; },
      [](size_t, size_t) { return 0.0; });
  const double heave = 3.0;  // the dof's factor (kHeave = 2, so j + 1 = 3)
  EXPECT_NEAR(RaoAt(t, VesselDof::kHeave, 5.0, 120.0 * kDeg).real(), 3.0 * heave, kTol);
  EXPECT_NEAR(RaoAt(t, VesselDof::kHeave, 5.0, 179.0 * kDeg).real(), 3.0 * heave, kTol);
  EXPECT_NEAR(RaoAt(t, VesselDof::kHeave, 5.0, 181.0 * kDeg).real(), 1.0 * heave, kTol);
  EXPECT_NEAR(RaoAt(t, VesselDof::kHeave, 5.0, -100.0 * kDeg).real(), 1.0 * heave, kTol);
  // inside, also when given mod 2 pi: 45 deg = 405 deg, midway between 2 and 3
  EXPECT_NEAR(RaoAt(t, VesselDof::kHeave, 5.0, 405.0 * kDeg).real(), 2.5 * heave, kTol);
}

TEST(RaoAt, HoldsTheEndRowsOutsideThePeriods) {
  const RaoTable t = MakeTable(
      {4.0, 8.0, 16.0}, {0.0, 90.0}, {VesselDof::kPitch}, [](size_t i, size_t) { return i + 1.0; },
      [](size_t i, size_t) { return 30.0 * i; });
  const int j = static_cast<int>(VesselDof::kPitch);
  const C first = std::polar(1.0 * (j + 1), 0.0);
  const C last = std::polar(3.0 * (j + 1), -60.0 * kDeg);
  ExpectNear(RaoAt(t, VesselDof::kPitch, 1.0, 0.0), first, kTol, "below");
  ExpectNear(RaoAt(t, VesselDof::kPitch, 100.0, 0.0), last, kTol, "above");
  // in between, linear in the period (not in frequency): 12 s is midway between 8 and 16
  const C mid = 0.5 * (std::polar(2.0 * (j + 1), -30.0 * kDeg) + last);
  ExpectNear(RaoAt(t, VesselDof::kPitch, 12.0, 0.0), mid, kTol, "12 s");
}

TEST(RaoAt, OnePeriodAndOneDirectionDoNotInterpolate) {
  const RaoTable t = MakeTable(
      {8.0}, {45.0}, {VesselDof::kSway}, [](size_t, size_t) { return 0.7; },
      [](size_t, size_t) { return 20.0; });
  const int j = static_cast<int>(VesselDof::kSway);
  const C want = std::polar(0.7 * (j + 1), -20.0 * kDeg);
  for (double period : {2.0, 8.0, 30.0}) {
    for (double d : {-170.0, 0.0, 45.0, 200.0}) {
      ExpectNear(RaoAt(t, VesselDof::kSway, period, d * kDeg), want, kTol, "one entry");
    }
  }
}

TEST(RaoAt, AbsentDofIsZeroAndRaosAtMatchesRaoAt) {
  const RaoTable t = MakeTable(
      {5.0, 9.0, 14.0}, {0.0, 45.0, 135.0, 180.0}, {VesselDof::kHeave, VesselDof::kPitch},
      [](size_t i, size_t k) { return 0.2 + 0.1 * i * k; },
      [](size_t i, size_t k) { return 15.0 * i + 50.0 * k; });
  EXPECT_EQ(RaoAt(t, VesselDof::kYaw, 7.0, 0.3), C(0.0, 0.0));
  const auto all = RaosAt(t, 11.3, 100.0 * kDeg);
  for (int j = 0; j < kVesselDofs; ++j) {
    EXPECT_EQ(all[j], RaoAt(t, VesselDof(j), 11.3, 100.0 * kDeg)) << j;
  }
  EXPECT_NE(all[static_cast<int>(VesselDof::kPitch)], C(0.0, 0.0));
}

}  // namespace
}  // namespace towsim::core
