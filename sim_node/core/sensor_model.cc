#include "core/sensor_model.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/constants.h"
#include "core/wave_field.h"

namespace towsim::core {

std::uint64_t DefaultSensorSeed(const std::string& body, const std::string& sensor) {
  // FNV-1a, 64 bits
  std::uint64_t h = 14695981039346656037ull;
  const std::string key = body + "/" + sensor;
  for (unsigned char c : key) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

SensorModel::SensorModel(std::vector<double> sigma, std::vector<double> bias,
                         const SensorErrors& errors, double h)
    : sigma_(std::move(sigma)),
      bias_(std::move(bias)),
      rate_(errors.rate),
      h_(h),
      dropout_(errors.dropout),
      latency_(errors.latency_steps),
      seed_(errors.seed) {
  if (sigma_.size() != bias_.size() || sigma_.empty()) {
    throw std::invalid_argument("SensorModel: sigma and bias need one entry per channel");
  }
  if (latency_ < 0 || !(dropout_ >= 0.0 && dropout_ < 1.0) || !(rate_ >= 0.0) || !(h_ > 0.0)) {
    throw std::invalid_argument("SensorModel: latency >= 0, 0 <= dropout < 1, rate >= 0, h > 0");
  }
  ring_.assign(static_cast<size_t>(latency_ + 1) * sigma_.size(), 0.0);
  Restart();
}

void SensorModel::Restart() {
  noise_rng_.seed(seed_);
  dropout_rng_.seed(SplitMix64(seed_));
  stored_ = 0;
}

double SensorModel::Normal(std::mt19937_64& rng) {
  // Box-Muller: u1 in (0, 1] (1 - UniformUnit), z = sqrt(-2 ln u1) cos(2 pi u2)
  const double u1 = 1.0 - UniformUnit(rng());
  const double u2 = UniformUnit(rng());
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

bool SensorModel::SampleInstant(std::uint64_t n, bool publish_due) const {
  if (rate_ <= 0.0) return publish_due;
  if (n == 0) return true;
  // the first step at or after each t = k / f: floor(n h f) > floor((n - 1) h f); a 1e-9
  // guard so that n h f landing on an integer in exact arithmetic counts there
  const double now = std::floor(static_cast<double>(n) * h_ * rate_ + 1e-9);
  const double before = std::floor(static_cast<double>(n - 1) * h_ * rate_ + 1e-9);
  return now > before;
}

bool SensorModel::Step(std::uint64_t n, bool publish_due, const double* truth, double* out) {
  const size_t c = sigma_.size();
  const size_t slots = static_cast<size_t>(latency_) + 1;
  // measured m_n = x_n + b + sigma z_n, into the ring at n mod (L + 1)
  double* slot = &ring_[(stored_ % slots) * c];
  for (size_t i = 0; i < c; ++i) {
    const double z = sigma_[i] > 0.0 ? Normal(noise_rng_) : 0.0;
    slot[i] = sigma_[i] > 0.0 ? truth[i] + bias_[i] + sigma_[i] * z : truth[i] + bias_[i];
  }
  ++stored_;
  if (!SampleInstant(n, publish_due)) return false;
  // one dropout draw per sample instant
  if (dropout_ > 0.0 && UniformUnit(dropout_rng_()) < dropout_) return false;
  // delayed d_n = m_{max(0, n-L)}: the slot written L steps ago; before step L the first
  // measurement (the sensor was on before t = 0, the body in its initial state; slot 0 holds
  // m_0 until step L + 1 overwrites it)
  const std::uint64_t latency = static_cast<std::uint64_t>(latency_);
  const std::uint64_t from = stored_ - 1 > latency ? stored_ - 1 - latency : 0;
  const double* old = &ring_[(from % slots) * c];
  for (size_t i = 0; i < c; ++i) out[i] = old[i];
  return true;
}

}  // namespace towsim::core
