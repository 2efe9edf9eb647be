#pragma once
// The seabed: its depth d(x, y) (the NED z of the bottom, positive down) and unit normal, and
// the parameters of the contact with it.
//
//   none:   no seabed (bottomless water, infinitely deep for the waves)
//   flat:   d(x, y) = d_0
//   plane:  d(x, y) = d_0 + tan(slope) (x cos c + y sin c), c the direction (from +x toward +y)
//           in which the bottom gets deeper, slope in [0, 90) deg, d_0 the depth at the origin
//   grid:   bilinear interpolation of depths d_ij at the nodes of a rectilinear grid
//           x_0 < ... < x_{nx-1}, y_0 < ... < y_{ny-1}; outside the grid, the value at the
//           nearest point of its edge (the grid is extended by constants); the file that holds
//           the grid is read by the scene layer (docs/environment.md gives its format).
//
// Normal into the water: the bottom is the surface F = z - d(x, y) = 0 with the water on the
// side F < 0, so n = -grad F / |grad F| = (d_x, d_y, -1) / sqrt(1 + d_x^2 + d_y^2) (NED, it
// points up). On the grid, d_x and d_y are those of the bilinear patch that holds the point
// (on an interior cell edge, those of the cell with the larger index; outside the grid the
// extended constants give zero slope across the edge the point lies beyond).
//
// The range along a ray (RayRange, an altimeter's beam; docs/sensors.md): the smallest s >= 0
// with F(o + s u) = 0, F = z - d(x, y) the signed depth below the bed, u a unit direction.
// Along the ray F(s) = o_z + s u_z - d(o_x + s u_x, o_y + s u_y) is
//   flat:   linear, F(s) = F(0) + s u_z, closed form s = -F(0) / u_z;
//   plane:  linear, F(s) = F(0) + s (u_z - g . (u_x, u_y)), g = grad d, closed form;
//   grid:   piecewise quadratic: between the parameters where the ray's horizontal trace
//           crosses a grid line x = x_i or y = y_j it stays in one bilinear cell (or one strip
//           of the constant extension), where d is bilinear in (x, y) and so quadratic in s.
//           The ray is marched from one crossing to the next; in each piece the quadratic
//           through F at its ends and middle brackets the first root (the piece's end, or its
//           vertex where F has a maximum >= 0 inside, so a grazing hump is not stepped over),
//           and bisection on F itself finds it. The march covers only the s where the ray's
//           depth lies within [min d_ij, max d_ij] (outside, F has one sign).
// The result is +infinity when the ray meets the bed nowhere in [0, max_range] (no seabed, a
// beam at or above the horizon over a flat bed, a bed beyond max_range), 0 when o lies on the
// bed and -infinity when o lies below it (F(0) > 0): REP 117's "no return" and "too close".
//
// The water depth the waves' dispersion relation uses (WaveDepth): the depth d(0, 0) under
// the scene origin for every kind (flat: its depth), infinity when there is no seabed.
//
// Queries never allocate.

#include <limits>
#include <vector>

#include <Eigen/Core>

namespace towsim::core {

// Contact of the cable and the bodies with the seabed (their loads define the physical meaning
// of each; all >= 0 and finite).
// Meaning and units (seabed_contact.h): pressure per metre of penetration and per m/s of
// penetration rate on a contact area of the cable's diameter per unit length (MoorDyn's kbot,
// cbot); defaults MoorDyn's kbot, and a damping that leaves the penetration critically damped
// for the shipped cable and stable in the vehicles' explicit RK4 at h = 0.05 s.
struct SeabedContact {
  double stiffness = 3.0e6;  // normal penalty stiffness k [Pa/m]
  double damping = 3.0e4;    // normal penalty damping c [Pa s/m]
  double friction = 0.0;     // Coulomb friction coefficient mu [-] (0: frictionless), axial
  double friction_lateral = -1.0;  // across the cable [-]; < 0: the same as `friction`
  double lateral_friction() const { return friction_lateral < 0.0 ? friction : friction_lateral; }
};

class Seabed {
 public:
  using Vec3 = Eigen::Vector3d;

  enum class Kind { kNone, kFlat, kPlane, kGrid };

  // no seabed
  Seabed() = default;
  // d = depth > 0
  static Seabed Flat(double depth);
  // depth at the origin, slope [rad] in [0, pi/2), slope_direction [rad]
  static Seabed Plane(double depth, double slope, double slope_direction);
  // x (nx >= 2) and y (ny >= 2) strictly increasing, depth row by row in y:
  // depth[j * nx + i] = d(x_i, y_j) (validated by the scene layer; the core trusts it)
  static Seabed Grid(std::vector<double> x, std::vector<double> y, std::vector<double> depth);

  bool present() const { return kind_ != Kind::kNone; }
  Kind kind() const { return kind_; }

  // d(x, y) [m], NED z of the bottom (positive down); +infinity without a seabed
  double Depth(double x, double y) const;
  // unit normal into the water (NED, upward); -e_z without a seabed
  Vec3 Normal(double x, double y) const;
  // range [m] from `origin` along the unit `direction` to the bed, at most max_range (see
  // above: +inf no return, -inf origin below the bed); never allocates
  double RayRange(const Vec3& origin, const Vec3& direction, double max_range) const;
  // depth for the waves' dispersion relation (see above)
  double WaveDepth() const;
  // a depth no point of the bed is shallower than [m]: flat d_0, grid min d_ij, +infinity
  // without a seabed, -infinity for a plane (it rises without bound)
  double Shallowest() const;

  const SeabedContact& contact() const { return contact_; }
  void set_contact(const SeabedContact& contact) { contact_ = contact; }

  // the data it was built from
  double depth() const { return depth_; }                      // d_0 (flat, plane)
  double slope() const { return slope_; }                      // [rad]
  double slope_direction() const { return slope_direction_; }  // [rad]
  const std::vector<double>& grid_x() const { return x_; }
  const std::vector<double>& grid_y() const { return y_; }
  const std::vector<double>& grid_depth() const { return d_; }

 private:
  // d and its gradient (d_x, d_y) at (x, y)
  void Evaluate(double x, double y, double* d, double* d_x, double* d_y) const;
  // RayRange on the grid, for F(0) < 0 and s in [s_lo, s_hi]
  double GridRayRange(const Vec3& origin, const Vec3& direction, double s_lo, double s_hi) const;

  Kind kind_ = Kind::kNone;
  double depth_ = std::numeric_limits<double>::infinity();
  double slope_ = 0.0;
  double slope_direction_ = 0.0;
  double gx_ = 0.0, gy_ = 0.0;  // plane gradient tan(slope) (cos c, sin c)
  std::vector<double> x_, y_, d_;
  double d_min_ = 0.0, d_max_ = 0.0;  // of the grid's depths
  SeabedContact contact_;
};

}  // namespace towsim::core
