// core/sensor_model: a sensor's bias, noise, latency, rate and dropout (docs/sensors.md "Sensor
// models") against their definitions: the bias exactly, the noise's sample mean and standard
// deviation over N = 20000 samples within 4.5 standard errors, the latency as an exact shift,
// the dropout fraction within 4.5 binomial standard errors, the sample count f T +- 1.

#include "core/sensor_model.h"

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

namespace towsim::core {
namespace {

constexpr int kN = 20000;
// statistical bound: 4.5 standard errors (a fixed seed makes each test deterministic; 4.5
// sigma would fail for fewer than 1 in 10^5 seeds)
constexpr double kSigmas = 4.5;

SensorErrors Errors(double noise, double bias, std::uint64_t seed = 7) {
  SensorErrors e;
  e.noise = noise;
  e.bias = bias;
  e.seed = seed;
  return e;
}

// the published values of a one-channel sensor over steps 0..n-1 for the true value
// truth(step); NaN where nothing is published
template <class Truth>
std::vector<double> RunSensor(SensorModel* m, int n, Truth truth) {
  std::vector<double> out(static_cast<size_t>(n), std::nan(""));
  for (int i = 0; i < n; ++i) {
    const double x = truth(i);
    double y = 0.0;
    if (m->Step(static_cast<std::uint64_t>(i), true, &x, &y)) out[static_cast<size_t>(i)] = y;
  }
  return out;
}

bool SameBits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i]) != std::isnan(b[i])) return false;
    if (!std::isnan(a[i]) && a[i] != b[i]) return false;
  }
  return true;
}

TEST(SensorModel, SameSeedSameSequenceOtherSeedOther) {
  SensorErrors e = Errors(0.3, 0.1, 42);
  e.dropout = 0.1;
  e.latency_steps = 3;
  const auto truth = [](int i) { return std::sin(0.01 * i); };
  SensorModel a({e.noise}, {e.bias}, e, 0.01), b({e.noise}, {e.bias}, e, 0.01);
  const std::vector<double> ya = RunSensor(&a, 2000, truth);
  EXPECT_TRUE(SameBits(ya, RunSensor(&b, 2000, truth)));
  // Restart: the same run again
  a.Restart();
  EXPECT_TRUE(SameBits(ya, RunSensor(&a, 2000, truth)));
  e.seed = 43;
  SensorModel c({e.noise}, {e.bias}, e, 0.01);
  const std::vector<double> yc = RunSensor(&c, 2000, truth);
  int differ = 0;
  for (size_t i = 0; i < ya.size(); ++i) differ += !(ya[i] == yc[i]);
  EXPECT_GT(differ, 1900);  // every published value differs (noise), and the dropouts
}

TEST(SensorModel, NoiseHasItsMeanAndStandardDeviation) {
  const double sigma = 0.5, truth = 12.0;
  SensorModel m({sigma}, {0.0}, Errors(sigma, 0.0), 0.05);
  const std::vector<double> y = RunSensor(&m, kN, [&](int) { return truth; });
  double sum = 0.0, sum2 = 0.0;
  int within_one_sigma = 0;
  for (double v : y) {
    sum += v - truth;
    sum2 += (v - truth) * (v - truth);
    within_one_sigma += std::abs(v - truth) < sigma;
  }
  const double mean = sum / kN;
  const double sd = std::sqrt((sum2 - kN * mean * mean) / (kN - 1));
  // mean: standard error sigma / sqrt(N) = 0.0035; sd: sigma / sqrt(2 N) = 0.0025
  EXPECT_NEAR(mean, 0.0, kSigmas * sigma / std::sqrt(kN));
  EXPECT_NEAR(sd, sigma, kSigmas * sigma / std::sqrt(2.0 * kN));
  // a normal's shape: P(|z| < 1) = erf(1 / sqrt 2) = 0.682689, binomial bound
  const double p = std::erf(1.0 / std::sqrt(2.0));
  EXPECT_NEAR(static_cast<double>(within_one_sigma) / kN, p, kSigmas * std::sqrt(p * (1 - p) / kN));
}

TEST(SensorModel, NormalIsStandard) {
  std::mt19937_64 rng(3);
  double sum = 0.0, sum2 = 0.0, sum4 = 0.0;
  for (int i = 0; i < kN; ++i) {
    const double z = SensorModel::Normal(rng);
    sum += z;
    sum2 += z * z;
    sum4 += z * z * z * z;
  }
  EXPECT_NEAR(sum / kN, 0.0, kSigmas / std::sqrt(kN));
  EXPECT_NEAR(sum2 / kN, 1.0, kSigmas * std::sqrt(2.0 / kN));   // var(z^2) = 2
  EXPECT_NEAR(sum4 / kN, 3.0, kSigmas * std::sqrt(96.0 / kN));  // var(z^4) = 105 - 9
}

TEST(SensorModel, BiasIsExact) {
  const double bias = 0.75;
  SensorModel m({0.0}, {bias}, Errors(0.0, bias), 0.05);
  const auto truth = [](int i) { return 20.0 + 0.37 * i; };
  const std::vector<double> y = RunSensor(&m, 500, truth);
  for (int i = 0; i < 500; ++i) EXPECT_EQ(y[static_cast<size_t>(i)], truth(i) + bias) << i;
}

TEST(SensorModel, LatencyShiftsTheSignalByExactlyItsSteps) {
  const auto truth = [](int i) { return 100.0 + std::sin(0.05 * i) + 1e-3 * i; };
  for (int k : {0, 1, 7, 64}) {
    SensorErrors e = Errors(0.0, 0.0);
    e.latency_steps = k;
    SensorModel m({0.0}, {0.0}, e, 0.01);
    const std::vector<double> y = RunSensor(&m, 1000, truth);
    for (int i = 0; i < 1000; ++i) {
      // before step k: the first measurement (the sensor was on before t = 0)
      EXPECT_EQ(y[static_cast<size_t>(i)], truth(i < k ? 0 : i - k))
          << "k = " << k << ", step " << i;
    }
    // with noise: the noisy signal of the same seed, shifted by k (the noise belongs to the
    // measurement, the latency to its delivery)
    SensorErrors noisy = Errors(0.2, 0.1, 11), late = noisy;
    late.latency_steps = k;
    SensorModel now({0.2}, {0.1}, noisy, 0.01), delayed({0.2}, {0.1}, late, 0.01);
    const std::vector<double> y0 = RunSensor(&now, 1000, truth),
                              yk = RunSensor(&delayed, 1000, truth);
    for (int i = 0; i < 1000; ++i) {
      EXPECT_EQ(yk[static_cast<size_t>(i)], y0[static_cast<size_t>(i < k ? 0 : i - k)]) << i;
    }
  }
}

TEST(SensorModel, DropoutLosesItsFraction) {
  for (double p : {0.05, 0.3}) {
    SensorErrors e = Errors(0.0, 0.0, 5);
    e.dropout = p;
    SensorModel m({0.0}, {0.0}, e, 0.05);
    const std::vector<double> y = RunSensor(&m, kN, [](int i) { return 1.0 * i; });
    int lost = 0;
    for (int i = 0; i < kN; ++i) {
      if (std::isnan(y[static_cast<size_t>(i)])) {
        ++lost;
      } else {
        EXPECT_EQ(y[static_cast<size_t>(i)], 1.0 * i);  // a sample that arrives is the true one
      }
    }
    // binomial: standard error sqrt(p (1 - p) / N)
    EXPECT_NEAR(static_cast<double>(lost) / kN, p, kSigmas * std::sqrt(p * (1 - p) / kN)) << p;
  }
}

TEST(SensorModel, RateGivesRateTimesDurationSamples) {
  struct Case {
    double h, f, T;
  };
  for (const Case& c : {Case{0.01, 3.0, 100.0}, Case{0.05, 7.3, 60.0}, Case{0.01, 10.0, 30.0},
                        Case{0.02, 50.0, 10.0}, Case{0.1, 0.37, 500.0}}) {
    SensorErrors e = Errors(0.0, 0.0);
    e.rate = c.f;
    SensorModel m({0.0}, {0.0}, e, c.h);
    const int steps = static_cast<int>(std::lround(c.T / c.h));  // steps 0..steps: T seconds
    int count = 0;
    int last = -1;
    const double period = 1.0 / (c.f * c.h);  // [steps]
    for (int i = 0; i <= steps; ++i) {
      const double x = i;
      double y = 0.0;
      // publish_due false: with a rate the topic's stride plays no part
      if (!m.Step(static_cast<std::uint64_t>(i), false, &x, &y)) continue;
      EXPECT_EQ(y, x);
      if (last >= 0) {
        // each sample the first step at or after k / f: gaps of floor or ceil of the period
        EXPECT_GE(i - last, std::floor(period) - 1e-9);
        EXPECT_LE(i - last, std::ceil(period) + 1e-9);
      }
      last = i;
      ++count;
    }
    EXPECT_NEAR(count, c.f * c.T, 1.0) << "h " << c.h << " f " << c.f;
  }
}

TEST(SensorModel, WithoutARateItSamplesAtThePublishSteps) {
  SensorModel m({0.0}, {0.0}, Errors(0.0, 0.0), 0.01);
  for (int i = 0; i < 100; ++i) {
    const double x = i;
    double y = -1.0;
    const bool due = i % 4 == 0;
    EXPECT_EQ(m.Step(static_cast<std::uint64_t>(i), due, &x, &y), due) << i;
    if (due) {
      EXPECT_EQ(y, x);
    }
  }
}

TEST(SensorModel, DefaultSeedsDifferBetweenBodiesAndSensors) {
  EXPECT_NE(DefaultSensorSeed("fish", "altimeter"), DefaultSensorSeed("fish2", "altimeter"));
  EXPECT_NE(DefaultSensorSeed("fish", "altimeter"), DefaultSensorSeed("fish", "pressure"));
  // FNV-1a 64 of "fish/altimeter" (computed independently in Python)
  EXPECT_EQ(DefaultSensorSeed("fish", "altimeter"), 0x5c44ebacb3d0f70bull);
}

}  // namespace
}  // namespace towsim::core
