#pragma once
// A sensor's errors (docs/sensors.md, "Sensor models"): what turns the true value of a
// quantity at each step into what a sensor driver publishes. Pure and deterministic: no
// clocks, no threads, no allocation after construction.
//
// Per step n the true value x_n (one or more channels, e.g. a range, or an odometry's
// position and linear velocity) is turned, in this order, into
//   measured   m_n = x_n + b + sigma z_n     b the bias, z_n ~ N(0, 1) per channel, drawn every
//                                            step from the noise stream (Box-Muller)
//   delayed    d_n = m_{max(0, n-L)}         L = latency_steps; before step L the first
//                                            measurement m_0 (the sensor was on before t = 0,
//                                            the body in its initial state)
//   sampled    published at the sensor's sample instants only: with a rate f > 0 at step n
//              when floor(n h f) > floor((n - 1) h f) (step 0 always), i.e. the first step at
//              or after each t = k / f, so f T (+-1) samples in T seconds; without a rate at
//              the topic's publish steps
//   dropped    each sample is lost (not published) with probability p: one uniform draw u
//              per sample instant from the dropout stream, lost when u < p
// Between samples nothing is published (a driver publishes each new reading once; a
// subscriber holds the last one).
//
// Random numbers: std::mt19937_64 (its sequence is fixed by the C++ standard) mapped by our
// own UniformUnit (core/wave_field.h) and a Box-Muller transform, not by a std distribution
// (those differ between standard libraries): the same seed gives the same errors everywhere.
// Noise and dropout use two generators (seed, and seed mixed by SplitMix64) so that changing
// one error does not change the other's sequence.

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace towsim::core {

// One sensor's error keys (bodies.<name>.sensors.<sensor>, docs/scene_format.md)
struct SensorErrors {
  double noise = 0.0;           // sigma [the sensor's unit]: m (range, odometry position), Pa
  double bias = 0.0;            // b [the sensor's unit]
  double velocity_noise = 0.0;  // odometry only: sigma of each linear velocity component [m/s]
  double velocity_bias = 0.0;   // odometry only: b of each linear velocity component [m/s]
  double rate = 0.0;            // f [Hz]; 0: the topic's publish rate
  int latency_steps = 0;        // L >= 0 [steps]
  double dropout = 0.0;         // p in [0, 1)
  std::uint64_t seed = 0;       // the generators' seed
};

// The sensor keys of one body; a sensor without keys is perfect (its topic as before)
struct BodySensors {
  std::string body;
  std::optional<SensorErrors> altimeter, pressure, odometry;
};

// The default seed of a body's sensor: FNV-1a 64 of "<body>/<sensor>" (fixed, so two bodies and
// two sensors of one body differ and a run repeats)
std::uint64_t DefaultSensorSeed(const std::string& body, const std::string& sensor);

// SplitMix64's output function: a seed mixed into an unrelated one
std::uint64_t SplitMix64(std::uint64_t x);

class SensorModel {
 public:
  // `sigma` and `bias` per channel (their sizes: the number of channels); rate, latency,
  // dropout and seed from `errors`; h the step [s]
  SensorModel(std::vector<double> sigma, std::vector<double> bias, const SensorErrors& errors,
              double h);

  int channels() const { return static_cast<int>(sigma_.size()); }
  double sigma(int channel) const { return sigma_[static_cast<size_t>(channel)]; }

  // step n's true value `truth` (channels() values); `publish_due`: the topic's publish step
  // (used without a rate). Returns true and writes the published value to `out` when a sample
  // is published at this step. Steps must be 0, 1, 2, ... (Restart() for another run).
  bool Step(std::uint64_t n, bool publish_due, const double* truth, double* out);
  // back to before step 0: the generators reseeded, the latency buffer emptied
  void Restart();

  // one standard normal draw of a generator (Box-Muller on two UniformUnit draws); exposed for
  // the tests
  static double Normal(std::mt19937_64& rng);

 private:
  bool SampleInstant(std::uint64_t n, bool publish_due) const;

  std::vector<double> sigma_, bias_;
  double rate_, h_, dropout_;
  int latency_;
  std::uint64_t seed_;
  std::mt19937_64 noise_rng_, dropout_rng_;
  std::vector<double> ring_;  // (latency + 1) x channels measured values
  std::uint64_t stored_ = 0;  // measurements written so far
};

}  // namespace towsim::core
