#pragma once
// Test helper: every number of core::VehicleParams with its SI unit kg^a m^b s^c, written out
// here from the units vehicle_model.h states for each field (angles dimensionless), one row per
// scalar (vectors and matrices entry by entry, each lifting surface's fields). The tests of
// vehicle_scaling use it as the independent statement of the units: Froude similarity must
// scale a row by lambda^(3a + b + c/2) (mass ~ rho l^3, time ~ sqrt(l / g)).

#include <functional>
#include <string>
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
  std::vector<VehicleField> f;
  const auto add = [&f](std::string name, std::function<double&(P&)> get, int kg, int m, int s) {
    f.push_back({std::move(name), std::move(get), kg, m, s});
  };
  const auto add3 = [&](const std::string& name, std::function<core::Vec3&(P&)> get, int kg,
                        int m, int s) {
    for (int i = 0; i < 3; ++i) {
      add(name + "[" + std::to_string(i) + "]", [get, i](P& q) -> double& { return get(q)(i); },
          kg, m, s);
    }
  };
  add("length", [](P& q) -> double& { return q.length; }, 0, 1, 0);
  add("diameter", [](P& q) -> double& { return q.diameter; }, 0, 1, 0);
  add("mass", [](P& q) -> double& { return q.mass; }, 1, 0, 0);
  add3("inertia", [](P& q) -> core::Vec3& { return q.inertia; }, 1, 2, 0);
  add3("r_g", [](P& q) -> core::Vec3& { return q.r_g; }, 0, 1, 0);
  add3("r_b", [](P& q) -> core::Vec3& { return q.r_b; }, 0, 1, 0);
  add("volume", [](P& q) -> double& { return q.volume; }, 0, 3, 0);
  add("waterplane_area", [](P& q) -> double& { return q.waterplane_area; }, 0, 2, 0);
  add3("waterplane_point_B", [](P& q) -> core::Vec3& { return q.waterplane_point_B; }, 0, 1, 0);
  add("design_depth", [](P& q) -> double& { return q.design_depth; }, 0, 1, 0);
  add("waterplane_inertia_long", [](P& q) -> double& { return q.waterplane_inertia_long; }, 0,
      4, 0);
  add("waterplane_inertia_trans", [](P& q) -> double& { return q.waterplane_inertia_trans; }, 0,
      4, 0);
  // M_A: force per linear acceleration [kg], force per angular acceleration and moment per
  // linear acceleration [kg m], moment per angular acceleration [kg m^2]
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      add("added_mass(" + std::to_string(i) + "," + std::to_string(j) + ")",
          [i, j](P& q) -> double& { return q.added_mass(i, j); }, 1, (i >= 3) + (j >= 3), 0);
    }
  }
  // damping, the units of vehicle_model.h
  const struct {
    const char* name;
    double P::*member;
    int kg, m, s;
  } kDamping[] = {
      {"x_uu", &P::x_uu, 1, -1, 0}, {"y_vv", &P::y_vv, 1, -1, 0}, {"z_ww", &P::z_ww, 1, -1, 0},
      {"y_rr", &P::y_rr, 1, 1, 0},  {"z_qq", &P::z_qq, 1, 1, 0},  {"m_ww", &P::m_ww, 1, 0, 0},
      {"n_vv", &P::n_vv, 1, 0, 0},  {"m_qq", &P::m_qq, 1, 2, 0},  {"n_rr", &P::n_rr, 1, 2, 0},
      {"k_pp", &P::k_pp, 1, 2, 0},  {"y_uv", &P::y_uv, 1, -1, 0}, {"z_uw", &P::z_uw, 1, -1, 0},
      {"m_uw", &P::m_uw, 1, 0, 0},  {"n_uv", &P::n_uv, 1, 0, 0},  {"y_ur", &P::y_ur, 1, 0, 0},
      {"z_uq", &P::z_uq, 1, 0, 0},  {"m_uq", &P::m_uq, 1, 1, 0},  {"n_ur", &P::n_ur, 1, 1, 0},
      {"k_p", &P::k_p, 1, 2, -1},  // N m s
  };
  for (const auto& d : kDamping) {
    const auto member = d.member;
    add(d.name, [member](P& q) -> double& { return q.*member; }, d.kg, d.m, d.s);
  }
  for (size_t k = 0; k < p.surfaces.size(); ++k) {
    const std::string n = "surfaces[" + std::to_string(k) + "].";
    using S = core::LiftingSurface;
    const auto surface = [k](P& q) -> S& { return q.surfaces[k]; };
    add3(n + "position_B", [surface](P& q) -> core::Vec3& { return surface(q).position_B; }, 0,
         1, 0);
    add3(n + "normal_B", [surface](P& q) -> core::Vec3& { return surface(q).normal_B; }, 0, 0,
         0);
    add(n + "area", [surface](P& q) -> double& { return surface(q).area; }, 0, 2, 0);
    const struct {
      const char* name;
      double S::*member;
    } kDimensionless[] = {{"aspect_ratio", &S::aspect_ratio}, {"lift_slope", &S::lift_slope},
                          {"oswald", &S::oswald},             {"cd0", &S::cd0},
                          {"stall_angle", &S::stall_angle},   {"incidence", &S::incidence},
                          {"deflection_sign", &S::deflection_sign}};
    for (const auto& d : kDimensionless) {
      const auto member = d.member;
      add(n + d.name, [surface, member](P& q) -> double& { return surface(q).*member; }, 0, 0, 0);
    }
  }
  add("rudder.max_deflection", [](P& q) -> double& { return q.rudder.max_deflection; }, 0, 0, 0);
  add("rudder.max_rate", [](P& q) -> double& { return q.rudder.max_rate; }, 0, 0, -1);
  add("elevator.max_deflection", [](P& q) -> double& { return q.elevator.max_deflection; }, 0, 0,
      0);
  add("elevator.max_rate", [](P& q) -> double& { return q.elevator.max_rate; }, 0, 0, -1);
  add("max_thrust", [](P& q) -> double& { return q.max_thrust; }, 1, 1, -2);
  add("thrust_time_constant", [](P& q) -> double& { return q.thrust_time_constant; }, 0, 0, 1);
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
