#include "core/seabed.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

// parameter s > s_from at which the line o + s du (du != 0) next meets one of the values v_i of
// a strictly increasing axis; +infinity when it meets none after s_from
double NextCrossing(const std::vector<double>& v, double o, double du, double s_from) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (du == 0.0) return kInf;
  const double x = o + s_from * du;
  if (du > 0.0) {
    // the first v_i > x, skipping any that round-off puts at or before s_from
    for (auto it = std::upper_bound(v.begin(), v.end(), x); it != v.end(); ++it) {
      const double s = (*it - o) / du;
      if (s > s_from) return s;
    }
    return kInf;
  }
  // the last v_i < x, likewise
  for (auto it = std::lower_bound(v.begin(), v.end(), x); it != v.begin();) {
    --it;
    const double s = (*it - o) / du;
    if (s > s_from) return s;
  }
  return kInf;
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
  const auto [lo, hi] = std::minmax_element(s.d_.begin(), s.d_.end());
  s.d_min_ = *lo;
  s.d_max_ = *hi;
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

double Seabed::Shallowest() const {
  switch (kind_) {
    case Kind::kNone:
      return std::numeric_limits<double>::infinity();
    case Kind::kFlat:
      return depth_;
    case Kind::kPlane:
      // a level plane is flat; a sloping one reaches every depth
      return slope_ == 0.0 ? depth_ : -std::numeric_limits<double>::infinity();
    case Kind::kGrid:
      return d_min_;  // bilinear patches and their constant extension stay within the nodes'
  }
  return -std::numeric_limits<double>::infinity();
}

Seabed::Vec3 Seabed::Normal(double x, double y) const {
  if (kind_ == Kind::kNone || kind_ == Kind::kFlat) return -Vec3::UnitZ();
  // n = (d_x, d_y, -1) / sqrt(1 + d_x^2 + d_y^2)
  double d = 0.0, d_x = 0.0, d_y = 0.0;
  Evaluate(x, y, &d, &d_x, &d_y);
  return Vec3(d_x, d_y, -1.0) / std::sqrt(1.0 + d_x * d_x + d_y * d_y);
}

double Seabed::RayRange(const Vec3& origin, const Vec3& direction, double max_range) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (kind_ == Kind::kNone) return kInf;
  // F(0) = o_z - d(o_x, o_y): > 0 below the bed (too close), 0 on it
  const double f0 = origin.z() - Depth(origin.x(), origin.y());
  if (f0 > 0.0) return -kInf;
  if (f0 == 0.0) return 0.0;
  if (kind_ == Kind::kFlat || kind_ == Kind::kPlane) {
    // F(s) = F(0) + s dF/ds, dF/ds = u_z - g . (u_x, u_y) (g = 0 flat): s = -F(0) / (dF/ds)
    const double rate = kind_ == Kind::kFlat
                            ? direction.z()
                            : direction.z() - gx_ * direction.x() - gy_ * direction.y();
    if (!(rate > 0.0)) return kInf;  // the ray runs parallel to the bed or away from it
    const double s = -f0 / rate;
    return s <= max_range ? s : kInf;
  }
  // grid: F < 0 while the ray's depth is above min d_ij, F >= 0 once it is below max d_ij
  double s_lo = 0.0, s_hi = max_range;
  const double z0 = origin.z(), u_z = direction.z();
  if (u_z > 0.0) {
    s_lo = std::max(0.0, (d_min_ - z0) / u_z);
    s_hi = std::min(max_range, (d_max_ - z0) / u_z);
  } else if (z0 < d_min_) {
    return kInf;  // level or rising, above every node
  } else if (u_z < 0.0) {
    s_hi = std::min(max_range, (d_min_ - z0) / u_z);  // beyond, above every node
  }
  if (!(s_lo <= s_hi)) return kInf;
  return GridRayRange(origin, direction, s_lo, s_hi);
}

double Seabed::GridRayRange(const Vec3& origin, const Vec3& direction, double s_lo,
                            double s_hi) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // F(s) = z(s) - d(x(s), y(s)) along the ray
  const auto f = [&](double s) {
    return origin.z() + s * direction.z() -
           Depth(origin.x() + s * direction.x(), origin.y() + s * direction.y());
  };
  // first root in [a, b] given F(a) < 0 <= F(b) and one sign change: bisection on F
  const auto bisect = [&](double a, double b) {
    constexpr int kMaxBisections = 200;  // ends well before: the bracket halves each time
    for (int k = 0; k < kMaxBisections; ++k) {
      const double m = 0.5 * (a + b);
      if (!(m > a && m < b)) break;  // adjacent doubles
      if (f(m) >= 0.0) {
        b = m;
      } else {
        a = m;
      }
    }
    return b;
  };
  double s_a = s_lo, f_a = f(s_a);
  if (f_a >= 0.0) return s_a;
  // a straight trace crosses each grid line at most once: at most nx + ny + 1 pieces
  const size_t max_pieces = x_.size() + y_.size() + 1;
  for (size_t piece = 0; piece < max_pieces && s_a < s_hi; ++piece) {
    const double s_b =
        std::min({s_hi, NextCrossing(x_, origin.x(), direction.x(), s_a),
                  NextCrossing(y_, origin.y(), direction.y(), s_a)});
    // only a level ray with an infinite max_range gets here: past the last grid line its
    // depth and the bed's are both constant, F = F(s_a) < 0
    if (!std::isfinite(s_b)) return kInf;
    // in one cell F is quadratic in s; with t = (s - s_m) / h on [-1, 1]:
    // q(t) = f_m + c1 t + c2 t^2, c1 = (f_b - f_a) / 2, c2 = (f_a + f_b) / 2 - f_m
    const double s_m = 0.5 * (s_a + s_b), h = 0.5 * (s_b - s_a);
    const double f_m = f(s_m), f_b = f(s_b);
    const double c1 = 0.5 * (f_b - f_a), c2 = 0.5 * (f_a + f_b) - f_m;
    // the first sample at or below the bed bounds the first root (F(s_a) < 0 before it)
    double end = kInf;
    if (c2 < 0.0) {
      const double t_v = -c1 / (2.0 * c2);  // a maximum inside: a hump the ends may miss
      if (t_v > -1.0 && t_v < 1.0) {
        const double s_v = s_m + t_v * h;
        if (f(s_v) >= 0.0) end = s_v;
      }
    }
    if (f_m >= 0.0) end = std::min(end, s_m);
    if (f_b >= 0.0) end = std::min(end, s_b);
    if (end < kInf) return bisect(s_a, end);
    s_a = s_b;
    f_a = f_b;
  }
  return kInf;
}

double Seabed::WaveDepth() const {
  return kind_ == Kind::kNone ? std::numeric_limits<double>::infinity() : Depth(0.0, 0.0);
}

}  // namespace towsim::core
