#pragma once
// The water's current: a horizontal (or any) velocity field that depends on depth and time
// only, U_W(z, t) in the world frame NED [m/s], z the NED coordinate (depth, positive down).
//
//   uniform:    U(z)   = U_0
//   profile:    U(z)   = linear interpolation of a table (z_i, U_i), z_i strictly increasing;
//                        U(z) = U_0 above the first row (z < z_0), U_{n-1} below the last
//   power law:  U(z)   = U_s (1 - z/D)^(1/p)   for 0 <= z <= D   (p: exponent, e.g. 7)
//                        U(z) = U_s above the mean surface (z < 0),
//                        U(z) = 0   below z = D (the profile ends at the bed it decays to)
//   in time:    U(z,t) = s(t) U(z),  s(t) a table (t_j, s_j) interpolated linearly, t_j strictly
//                        increasing, constant beyond the ends; no table: s = 1 (steady)
//
// The fluid acceleration a current contributes is its material derivative. Because U depends
// on z and t only, (U . grad) U = U_z dU/dz, so
//   a(z, t) = dU/dt + U_z dU/dz = s'(t) U(z) + s(t)^2 U_z(z) U'(z).
// Both derivatives are piecewise constant (profile, scale table) or smooth (power law); at the
// kinks the one-sided derivative below (larger z, later t) is returned.
//
// The queries are cheap and never allocate; IsUniform / IsSteady / IsZero let callers skip the
// work for the simple cases (a uniform steady current costs what a Vec3 costs).

#include <vector>

#include <Eigen/Core>

namespace towsim::core {

class CurrentField {
 public:
  using Vec3 = Eigen::Vector3d;

  enum class Kind { kUniform, kProfile, kPowerLaw };

  struct ProfileRow {
    double depth = 0.0;            // z [m], NED, positive down
    Vec3 velocity = Vec3::Zero();  // U_W [m/s]
  };
  struct ScaleRow {
    double time = 0.0;   // t [s]
    double scale = 1.0;  // s(t) [-]
  };

  // zero current
  CurrentField() = default;
  // U = velocity everywhere
  static CurrentField Uniform(const Vec3& velocity);
  // rows non-empty, depths finite and strictly increasing, velocities finite (the scene reader
  // validates; the core trusts it)
  static CurrentField Profile(std::vector<ProfileRow> rows);
  // surface velocity U_s, depth D > 0 at which U reaches zero, exponent p > 0
  static CurrentField PowerLaw(const Vec3& surface, double depth, double exponent);

  // s(t) from a table (times strictly increasing, non-empty); an empty table means steady
  void SetTimeScale(std::vector<ScaleRow> rows);

  // U_W(z, t) [m/s]
  Vec3 Velocity(double z, double t) const;
  // dU/dz at (z, t) [1/s]: the shear (zero for a uniform current)
  Vec3 Shear(double z, double t) const;
  // DU/Dt = dU/dt + U_z dU/dz at (z, t) [m/s^2] (zero for a steady uniform current)
  Vec3 Acceleration(double z, double t) const;

  Kind kind() const { return kind_; }
  // the velocity does not depend on depth (a uniform current, or a one-row profile)
  bool IsUniform() const { return uniform_; }
  // the velocity does not depend on time
  bool IsSteady() const { return scale_.empty(); }
  // zero everywhere at all times
  bool IsZero() const { return zero_; }

  // the data it was built from (for output and the scene echo)
  const std::vector<ProfileRow>& profile() const { return rows_; }
  const std::vector<ScaleRow>& time_scale() const { return scale_; }
  const Vec3& surface_velocity() const { return surface_; }  // U_0 / U_s
  double power_law_depth() const { return depth_; }
  double power_law_exponent() const { return exponent_; }

 private:
  // U(z) at s = 1 and its derivative dU/dz
  Vec3 SteadyVelocity(double z) const;
  Vec3 SteadyShear(double z) const;
  // s(t) and s'(t)
  double Scale(double t) const;
  double ScaleRate(double t) const;
  void UpdateFlags();

  Kind kind_ = Kind::kUniform;
  Vec3 surface_ = Vec3::Zero();  // uniform value, or U_s of the power law
  double depth_ = 0.0;           // D of the power law [m]
  double exponent_ = 7.0;        // p of the power law
  std::vector<ProfileRow> rows_;
  std::vector<ScaleRow> scale_;
  bool uniform_ = true;
  bool zero_ = true;
};

}  // namespace towsim::core
