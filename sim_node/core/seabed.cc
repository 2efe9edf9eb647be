#include "core/seabed.h"

#include <cmath>
#include <utility>

namespace towsim::core {
namespace {

// Cell of a strictly increasing axis v (n >= 2) for coordinate x: index i in [0, n-2] and the
// fraction f in [0, 1] of x in [v_i, v_{i+1}], with x held to [v_0, v_{n-1}]; `inside` is false
// when x lay outside (then the slope across that axis is zero).
void Locate(const std::vector<double>& v, double x, size_t* i, double* f, bool* inside) {
  const size_t n = v.size();
  *inside = x >= v.front() && x <= v.back();
  if (x <= v.front()) {
    *i = 0;
    *f = 0.0;
    return;
  }
  if (x >= v.back()) {
    *i = n - 2;
    *f = 1.0;
    return;
  }
  // largest i with v_i <= x (binary search), at most n - 2
  size_t lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    if (v[mid] <= x) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  *i = lo;
  *f = (x - v[lo]) / (v[lo + 1] - v[lo]);
}

}  // namespace

Seabed Seabed::Flat(double depth) {
  Seabed s;
  s.kind_ = Kind::kFlat;
  s.depth_ = depth;
  return s;
}

Seabed Seabed::Plane(double depth, double slope, double slope_direction) {
  Seabed s;
  s.kind_ = Kind::kPlane;
  s.depth_ = depth;
  s.slope_ = slope;
  s.slope_direction_ = slope_direction;
  // grad d = tan(slope) (cos c, sin c)
  s.gx_ = std::tan(slope) * std::cos(slope_direction);
  s.gy_ = std::tan(slope) * std::sin(slope_direction);
  return s;
}

Seabed Seabed::Grid(std::vector<double> x, std::vector<double> y, std::vector<double> depth) {
  Seabed s;
  s.kind_ = Kind::kGrid;
  s.x_ = std::move(x);
  s.y_ = std::move(y);
  s.d_ = std::move(depth);
  s.depth_ = s.Depth(0.0, 0.0);
  return s;
}

void Seabed::Evaluate(double x, double y, double* d, double* d_x, double* d_y) const {
  switch (kind_) {
    case Kind::kNone:
      *d = std::numeric_limits<double>::infinity();
      *d_x = *d_y = 0.0;
      return;
    case Kind::kFlat:
      *d = depth_;
      *d_x = *d_y = 0.0;
      return;
    case Kind::kPlane:
      // d = d_0 + g . (x, y)
      *d = depth_ + gx_ * x + gy_ * y;
      *d_x = gx_;
      *d_y = gy_;
      return;
    case Kind::kGrid: {
      size_t i, j;
      double fx, fy;
      bool in_x, in_y;
      Locate(x_, x, &i, &fx, &in_x);
      Locate(y_, y, &j, &fy, &in_y);
      const size_t nx = x_.size();
      const double d00 = d_[j * nx + i], d10 = d_[j * nx + i + 1];
      const double d01 = d_[(j + 1) * nx + i], d11 = d_[(j + 1) * nx + i + 1];
      // d = (1-fx)(1-fy) d00 + fx (1-fy) d10 + (1-fx) fy d01 + fx fy d11
      *d = (1.0 - fy) * ((1.0 - fx) * d00 + fx * d10) + fy * ((1.0 - fx) * d01 + fx * d11);
      // d_x = ((1-fy)(d10 - d00) + fy (d11 - d01)) / (x_{i+1} - x_i), d_y likewise
      *d_x = in_x ? ((1.0 - fy) * (d10 - d00) + fy * (d11 - d01)) / (x_[i + 1] - x_[i]) : 0.0;
      *d_y = in_y ? ((1.0 - fx) * (d01 - d00) + fx * (d11 - d10)) / (y_[j + 1] - y_[j]) : 0.0;
      return;
    }
  }
}

double Seabed::Depth(double x, double y) const {
  switch (kind_) {
    case Kind::kNone:
      return std::numeric_limits<double>::infinity();
    case Kind::kFlat:
      return depth_;
    default: {
      double d = 0.0, d_x = 0.0, d_y = 0.0;
      Evaluate(x, y, &d, &d_x, &d_y);
      return d;
    }
  }
}

Seabed::Vec3 Seabed::Normal(double x, double y) const {
  if (kind_ == Kind::kNone || kind_ == Kind::kFlat) return -Vec3::UnitZ();
  // n = (d_x, d_y, -1) / sqrt(1 + d_x^2 + d_y^2)
  double d = 0.0, d_x = 0.0, d_y = 0.0;
  Evaluate(x, y, &d, &d_x, &d_y);
  return Vec3(d_x, d_y, -1.0) / std::sqrt(1.0 + d_x * d_x + d_y * d_y);
}

double Seabed::WaveDepth() const {
  return kind_ == Kind::kNone ? std::numeric_limits<double>::infinity() : Depth(0.0, 0.0);
}

}  // namespace towsim::core
