#include "core/current_field.h"

#include <cmath>
#include <utility>

namespace towsim::core {
namespace {

// index i of the table interval [x_i, x_{i+1}) that holds x, for x_0 <= x < x_{n-1}, n >= 2
// (binary search: no allocation, O(log n))
template <typename Row, typename Key>
size_t Interval(const std::vector<Row>& rows, double x, Key key) {
  size_t lo = 0, hi = rows.size() - 1;  // key(rows[lo]) <= x < key(rows[hi])
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    if (key(rows[mid]) <= x) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return lo;
}

}  // namespace

CurrentField CurrentField::Uniform(const Vec3& velocity) {
  CurrentField c;
  c.kind_ = Kind::kUniform;
  c.surface_ = velocity;
  c.UpdateFlags();
  return c;
}

CurrentField CurrentField::Profile(std::vector<ProfileRow> rows) {
  CurrentField c;
  c.kind_ = Kind::kProfile;
  c.rows_ = std::move(rows);
  if (!c.rows_.empty()) c.surface_ = c.rows_.front().velocity;
  c.UpdateFlags();
  return c;
}

CurrentField CurrentField::PowerLaw(const Vec3& surface, double depth, double exponent) {
  CurrentField c;
  c.kind_ = Kind::kPowerLaw;
  c.surface_ = surface;
  c.depth_ = depth;
  c.exponent_ = exponent;
  c.UpdateFlags();
  return c;
}

void CurrentField::SetTimeScale(std::vector<ScaleRow> rows) {
  scale_ = std::move(rows);
  UpdateFlags();
}

void CurrentField::UpdateFlags() {
  switch (kind_) {
    case Kind::kUniform:
      uniform_ = true;
      zero_ = surface_.isZero(0.0);
      break;
    case Kind::kProfile: {
      uniform_ = true;
      zero_ = true;
      for (const ProfileRow& r : rows_) {
        if (r.velocity != rows_.front().velocity) uniform_ = false;
        if (!r.velocity.isZero(0.0)) zero_ = false;
      }
      break;
    }
    case Kind::kPowerLaw:
      zero_ = surface_.isZero(0.0);
      uniform_ = zero_;
      break;
  }
  // a scale table that is zero throughout makes the current zero as well
  if (!zero_ && !scale_.empty()) {
    bool all_zero = true;
    for (const ScaleRow& r : scale_) all_zero = all_zero && r.scale == 0.0;
    zero_ = all_zero;
  }
}

CurrentField::Vec3 CurrentField::SteadyVelocity(double z) const {
  switch (kind_) {
    case Kind::kUniform:
      return surface_;
    case Kind::kProfile: {
      // constant beyond the ends, U_i + (z - z_i)/(z_{i+1} - z_i) (U_{i+1} - U_i) between
      if (rows_.empty()) return Vec3::Zero();
      if (z <= rows_.front().depth) return rows_.front().velocity;
      if (z >= rows_.back().depth) return rows_.back().velocity;
      const size_t i = Interval(rows_, z, [](const ProfileRow& r) { return r.depth; });
      const ProfileRow& a = rows_[i];
      const ProfileRow& b = rows_[i + 1];
      const double f = (z - a.depth) / (b.depth - a.depth);
      return a.velocity + f * (b.velocity - a.velocity);
    }
    case Kind::kPowerLaw: {
      // U_s (1 - z/D)^(1/p) on [0, D]; U_s above, 0 below
      if (z <= 0.0) return surface_;
      if (z >= depth_) return Vec3::Zero();
      return std::pow(1.0 - z / depth_, 1.0 / exponent_) * surface_;
    }
  }
  return Vec3::Zero();
}

CurrentField::Vec3 CurrentField::SteadyShear(double z) const {
  switch (kind_) {
    case Kind::kUniform:
      return Vec3::Zero();
    case Kind::kProfile: {
      // (U_{i+1} - U_i)/(z_{i+1} - z_i) in the interval below z; zero beyond the ends
      if (rows_.size() < 2 || z < rows_.front().depth || z >= rows_.back().depth) {
        return Vec3::Zero();
      }
      const size_t i = Interval(rows_, z, [](const ProfileRow& r) { return r.depth; });
      return (rows_[i + 1].velocity - rows_[i].velocity) / (rows_[i + 1].depth - rows_[i].depth);
    }
    case Kind::kPowerLaw: {
      // d/dz U_s (1 - z/D)^(1/p) = -U_s / (p D) (1 - z/D)^(1/p - 1); unbounded at z -> D for
      // p > 1, so the derivative is returned on [0, D) and zero outside
      if (z < 0.0 || z >= depth_) return Vec3::Zero();
      return (-std::pow(1.0 - z / depth_, 1.0 / exponent_ - 1.0) / (exponent_ * depth_)) * surface_;
    }
  }
  return Vec3::Zero();
}

double CurrentField::Scale(double t) const {
  // s(t): linear between the rows, constant beyond the ends, 1 without a table
  if (scale_.empty()) return 1.0;
  if (t <= scale_.front().time) return scale_.front().scale;
  if (t >= scale_.back().time) return scale_.back().scale;
  const size_t j = Interval(scale_, t, [](const ScaleRow& r) { return r.time; });
  const ScaleRow& a = scale_[j];
  const ScaleRow& b = scale_[j + 1];
  return a.scale + (t - a.time) / (b.time - a.time) * (b.scale - a.scale);
}

double CurrentField::ScaleRate(double t) const {
  // s'(t) of the interval after t; zero beyond the ends
  if (scale_.size() < 2 || t < scale_.front().time || t >= scale_.back().time) return 0.0;
  const size_t j = Interval(scale_, t, [](const ScaleRow& r) { return r.time; });
  return (scale_[j + 1].scale - scale_[j].scale) / (scale_[j + 1].time - scale_[j].time);
}

CurrentField::Vec3 CurrentField::Velocity(double z, double t) const {
  // U(z, t) = s(t) U(z)
  if (zero_) return Vec3::Zero();
  if (scale_.empty()) return SteadyVelocity(z);
  return Scale(t) * SteadyVelocity(z);
}

CurrentField::Vec3 CurrentField::Shear(double z, double t) const {
  // dU/dz = s(t) U'(z)
  if (zero_ || uniform_) return Vec3::Zero();
  if (scale_.empty()) return SteadyShear(z);
  return Scale(t) * SteadyShear(z);
}

CurrentField::Vec3 CurrentField::Acceleration(double z, double t) const {
  // DU/Dt = s'(t) U(z) + s(t)^2 U_z(z) U'(z)
  if (zero_) return Vec3::Zero();
  Vec3 a = Vec3::Zero();
  if (!scale_.empty()) a += ScaleRate(t) * SteadyVelocity(z);
  if (!uniform_) {
    const double s = Scale(t);
    a += (s * s * SteadyVelocity(z).z()) * SteadyShear(z);
  }
  return a;
}

}  // namespace towsim::core
