#pragma once
// Test helper: every number of core::VehicleParams with its SI unit kg^a m^b s^c, written out
// here from the units vehicle_model.h states for each field (angles dimensionless), one row per
// scalar (vectors and matrices entry by entry, each lifting surface's fields). The tests of
// vehicle_scaling use it as the independent statement of the units: Froude similarity must
// scale a row by lambda^(3a + b + c/2) (mass ~ rho l^3, time ~ sqrt(l / g)).

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/vehicle_model.h"

namespace towsim::test {

struct VehicleField {
  std::string name;
  std::function<double&(core::VehicleParams&)> get;
  int kg = 0, m = 0, s = 0;  // the unit kg^kg m^m s^s
  // the Froude exponent of the unit: lambda^(3 kg + m + s / 2)
  double exponent() const { return 3.0 * kg + m + 0.5 * s; }
};

// the rows for `p` (its surfaces' count decides the surface rows)
inline std::vector<VehicleField> VehicleFields(const core::VehicleParams& p) {
  using P = core::VehicleParams;
  using S = core::LiftingSurface;
  using Get = std::function<double&(P&)>;
  using Get3 = std::function<core::Vec3&(P&)>;
  std::vector<VehicleField> f;
  const auto add = [&f](const std::string& name, int kg, int m, int s, Get get) {
    f.push_back({name, std::move(get), kg, m, s});
  };
  const auto add3 = [&add](const std::string& name, int kg, int m, int s, Get3 get) {
    for (int i = 0; i < 3; ++i) {
      add(name + "[" + std::to_string(i) + "]", kg, m, s,
          [get, i](P& q) -> double& { return get(q)(i); });
    }
  };
  struct Scalar {
    const char* name;
    int kg, m, s;
    double P::*member;
  };
  struct Vector {
    const char* name;
    int kg, m, s;
    core::Vec3 P::*member;
  };
  // the rigid body, the waterplane and the propeller
  const Scalar kScalars[] = {
      {"length", 0, 1, 0, &P::length},
      {"diameter", 0, 1, 0, &P::diameter},
      {"mass", 1, 0, 0, &P::mass},
      {"volume", 0, 3, 0, &P::volume},
      {"waterplane_area", 0, 2, 0, &P::waterplane_area},
      {"design_depth", 0, 1, 0, &P::design_depth},
      {"waterplane_inertia_long", 0, 4, 0, &P::waterplane_inertia_long},
      {"waterplane_inertia_trans", 0, 4, 0, &P::waterplane_inertia_trans},
      {"max_thrust", 1, 1, -2, &P::max_thrust},
      {"thrust_time_constant", 0, 0, 1, &P::thrust_time_constant},
  };
  // damping, in the units vehicle_model.h states
  const Scalar kDamping[] = {
      {"x_uu", 1, -1, 0, &P::x_uu}, {"y_vv", 1, -1, 0, &P::y_vv}, {"z_ww", 1, -1, 0, &P::z_ww},
      {"y_rr", 1, 1, 0, &P::y_rr},  {"z_qq", 1, 1, 0, &P::z_qq},  {"m_ww", 1, 0, 0, &P::m_ww},
      {"n_vv", 1, 0, 0, &P::n_vv},  {"m_qq", 1, 2, 0, &P::m_qq},  {"n_rr", 1, 2, 0, &P::n_rr},
      {"k_pp", 1, 2, 0, &P::k_pp},  {"y_uv", 1, -1, 0, &P::y_uv}, {"z_uw", 1, -1, 0, &P::z_uw},
      {"m_uw", 1, 0, 0, &P::m_uw},  {"n_uv", 1, 0, 0, &P::n_uv},  {"y_ur", 1, 0, 0, &P::y_ur},
      {"z_uq", 1, 0, 0, &P::z_uq},  {"m_uq", 1, 1, 0, &P::m_uq},  {"n_ur", 1, 1, 0, &P::n_ur},
      {"k_p", 1, 2, -1, &P::k_p},  // N m s
  };
  const auto add_scalars = [&add](const auto& table) {
    for (const Scalar& d : table) {
      add(d.name, d.kg, d.m, d.s, [m = d.member](P& q) -> double& { return q.*m; });
    }
  };
  add_scalars(kScalars);
  add_scalars(kDamping);
  const Vector kVectors[] = {
      {"inertia", 1, 2, 0, &P::inertia},
      {"r_g", 0, 1, 0, &P::r_g},
      {"r_b", 0, 1, 0, &P::r_b},
      {"waterplane_point_B", 0, 1, 0, &P::waterplane_point_B},
  };
  for (const Vector& d : kVectors) {
    add3(d.name, d.kg, d.m, d.s, [m = d.member](P& q) -> core::Vec3& { return q.*m; });
  }
  // M_A: force per linear acceleration [kg], force per angular acceleration and moment per
  // linear acceleration [kg m], moment per angular acceleration [kg m^2]
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      add("added_mass(" + std::to_string(i) + "," + std::to_string(j) + ")", 1, (i >= 3) + (j >= 3),
          0, [i, j](P& q) -> double& { return q.added_mass(i, j); });
    }
  }
  // each lifting surface: a position, an area, the rest dimensionless
  for (size_t k = 0; k < p.surfaces.size(); ++k) {
    const std::string n = "surfaces[" + std::to_string(k) + "].";
    add3(n + "position_B", 0, 1, 0, [k](P& q) -> core::Vec3& { return q.surfaces[k].position_B; });
    add3(n + "normal_B", 0, 0, 0, [k](P& q) -> core::Vec3& { return q.surfaces[k].normal_B; });
    add(n + "area", 0, 2, 0, [k](P& q) -> double& { return q.surfaces[k].area; });
    const std::pair<const char*, double S::*> kDimensionless[] = {
        {"aspect_ratio", &S::aspect_ratio},
        {"lift_slope", &S::lift_slope},
        {"oswald", &S::oswald},
        {"cd0", &S::cd0},
        {"stall_angle", &S::stall_angle},
        {"incidence", &S::incidence},
        {"deflection_sign", &S::deflection_sign}};
    for (const auto& [name, member] : kDimensionless) {
      add(n + name, 0, 0, 0, [k, m = member](P& q) -> double& { return q.surfaces[k].*m; });
    }
  }
  // the fin channels' limits: an angle, an angular rate
  const std::pair<const char*, core::ActuatorLimits P::*> kChannels[] = {
      {"rudder", &P::rudder}, {"elevator", &P::elevator}};
  for (const auto& [name, member] : kChannels) {
    add(std::string(name) + ".max_deflection", 0, 0, 0,
        [m = member](P& q) -> double& { return (q.*m).max_deflection; });
    add(std::string(name) + ".max_rate", 0, 0, -1,
        [m = member](P& q) -> double& { return (q.*m).max_rate; });
  }
  return f;
}

// the fields that are not numbers, equal or not (source, flags, surface names and channels)
inline bool SameNonNumericFields(const core::VehicleParams& a, const core::VehicleParams& b) {
  if (a.source != b.source || a.munk_moment != b.munk_moment ||
      a.has_propeller != b.has_propeller || a.surfaces.size() != b.surfaces.size()) {
    return false;
  }
  for (size_t k = 0; k < a.surfaces.size(); ++k) {
    if (a.surfaces[k].name != b.surfaces[k].name ||
        a.surfaces[k].channel != b.surfaces[k].channel) {
      return false;
    }
  }
  return true;
}

}  // namespace towsim::test
