#pragma once
// The per-topic publishing rates of a DDS node (the scene's `publish` map, docs/topics.md;
// plain scene data, unused offline). One row per rate key: the scene loader reads every key of
// kPublishRateKeys, the node turns each rate into a stride of whole steps. A new rate is one
// row here and one enumerator.
//
//   rate [Hz] = 0   every step
//   rate [Hz] > 0   every max(1, round(1 / (rate h))) steps
//   rate < 0        (the default of cable_state and markers) at the scene's time.output_rate

#include <array>
#include <cmath>
#include <cstdint>

namespace towsim::core {

enum class PublishRate : int {
  kClock,
  kOdom,  // odometry and /tf (docs/frames.md): the same state
  kCableState,
  kCableForce,
  kStatus,
  kMarkers,  // 3D markers (docs/foxglove.md)
  kSensors,  // altitude and pressure of every body (docs/sensors.md)
};
inline constexpr int kNumPublishRates = 7;

struct PublishRateKey {
  PublishRate rate;
  const char* key;    // publish.<key> in the scene
  double default_hz;  // < 0: time.output_rate
};

// in the order of the scene's `publish` keys
inline constexpr std::array<PublishRateKey, kNumPublishRates> kPublishRateKeys = {{
    {PublishRate::kClock, "clock", 0.0},
    {PublishRate::kOdom, "odom", 0.0},
    {PublishRate::kCableState, "cable_state", -1.0},
    {PublishRate::kCableForce, "cable_force", 0.0},
    {PublishRate::kStatus, "status", 0.0},
    {PublishRate::kMarkers, "markers", -1.0},
    {PublishRate::kSensors, "sensors", 0.0},
}};

// steps per publication at rate_hz [Hz] with step size h [s]: max(1, round(1 / (rate_hz h)));
// rate_hz <= 0: every step
inline long StepsPer(double rate_hz, double h) {
  if (!(rate_hz > 0.0)) return 1;
  const long steps = std::lround(1.0 / (rate_hz * h));
  return steps < 1 ? 1 : steps;
}

// the rate of every key [Hz], defaults from kPublishRateKeys
class PublishRates {
 public:
  PublishRates() {
    for (const PublishRateKey& k : kPublishRateKeys) hz_[Index(k.rate)] = k.default_hz;
  }
  double operator[](PublishRate rate) const { return hz_[Index(rate)]; }
  double& operator[](PublishRate rate) { return hz_[Index(rate)]; }

  // steps per publication with step size h [s] and the scene's output rate [Hz], >= 1
  long Stride(PublishRate rate, double h, double output_rate) const {
    const double hz = hz_[Index(rate)];
    return StepsPer(hz < 0.0 ? output_rate : hz, h);
  }

  static constexpr int Index(PublishRate rate) { return static_cast<int>(rate); }

 private:
  std::array<double, kNumPublishRates> hz_{};
};

// the rates as strides of whole steps [steps], >= 1
class PublishStrides {
 public:
  PublishStrides() { steps_.fill(1); }
  PublishStrides(const PublishRates& rates, double h, double output_rate) {
    for (const PublishRateKey& k : kPublishRateKeys) {
      steps_[PublishRates::Index(k.rate)] = rates.Stride(k.rate, h, output_rate);
    }
  }
  long operator[](PublishRate rate) const { return steps_[PublishRates::Index(rate)]; }
  void Set(PublishRate rate, long steps) {
    steps_[PublishRates::Index(rate)] = steps < 1 ? 1 : steps;
  }
  // a topic of this rate is published after `step` steps (always when `all`)
  bool Due(PublishRate rate, uint64_t step, bool all) const {
    return all || step % static_cast<uint64_t>(steps_[PublishRates::Index(rate)]) == 0;
  }

 private:
  std::array<long, kNumPublishRates> steps_{};
};

}  // namespace towsim::core
