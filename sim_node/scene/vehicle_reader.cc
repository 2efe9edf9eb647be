#include "scene/vehicle_reader.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "core/actuator.h"

namespace towsim::scene::internal {
namespace {

// a vector whose components are each > 0 (inertia): the component is named in the message
core::Vec3 PositiveVector(const Field& field) {
  field.Vector();  // shape and finiteness first
  const std::vector<Field> items = field.Items();
  return {items[0].Number(Range::Above(0.0)), items[1].Number(Range::Above(0.0)),
          items[2].Number(Range::Above(0.0))};
}

// a non-zero direction, normalized
core::Vec3 Direction(const Field& field) {
  const core::Vec3 v = field.Vector();
  if (v.norm() == 0.0) field.Fail("must be a non-zero direction");
  return v.normalized();
}

// M_A from the Prestero-signed coefficients (X_udot, ...): diagonal entries are -X_udot, ...
core::Mat6 ReadAddedMass(const BodyKeys::Map& map) {
  struct Entry {
    const char* key;
    int row, col;
  };
  // diagonal entries first (Prestero sign: <= 0), then the couplings (any sign)
  static const Entry kEntries[] = {
      {"x_udot", 0, 0}, {"y_vdot", 1, 1}, {"z_wdot", 2, 2}, {"k_pdot", 3, 3}, {"m_qdot", 4, 4},
      {"n_rdot", 5, 5}, {"y_rdot", 1, 5}, {"n_vdot", 5, 1}, {"z_qdot", 2, 4}, {"m_wdot", 4, 2}};
  core::Mat6 m = core::Mat6::Zero();
  for (const Entry& e : kEntries) {
    const Range range = e.row == e.col ? Range::AtMost(0.0) : Range::Any();
    m(e.row, e.col) = -map.Number(e.key, range, 0.0);
  }
  // the added kinetic energy 1/2 nu^T M_A nu is never negative: M_A + M_A^T >= 0
  const Eigen::SelfAdjointEigenSolver<core::Mat6> eigen(0.5 * (m + m.transpose()),
                                                        Eigen::EigenvaluesOnly);
  const double lowest = eigen.eigenvalues().minCoeff();
  const double scale = std::max(1.0, m.diagonal().cwiseAbs().maxCoeff());
  if (lowest < -1e-12 * scale) {
    map.field().Fail(
        "the added-mass matrix M_A must be positive semi-definite, but its symmetric part has "
        "the eigenvalue " +
        FormatNumber(lowest) +
        "; the couplings (y_rdot, n_vdot, z_qdot, m_wdot) are too large for the diagonal terms");
  }
  return m;
}

void ReadDamping(const BodyKeys::Map& map, core::VehicleParams* p) {
  // all optional, any sign (the sign is that of the force, X = x_uu u|u|)
  const struct {
    const char* key;
    double* value;
  } kTerms[] = {{"x_uu", &p->x_uu}, {"y_vv", &p->y_vv}, {"z_ww", &p->z_ww}, {"y_rr", &p->y_rr},
                {"z_qq", &p->z_qq}, {"m_ww", &p->m_ww}, {"n_vv", &p->n_vv}, {"m_qq", &p->m_qq},
                {"n_rr", &p->n_rr}, {"k_pp", &p->k_pp}, {"y_uv", &p->y_uv}, {"z_uw", &p->z_uw},
                {"m_uw", &p->m_uw}, {"n_uv", &p->n_uv}, {"y_ur", &p->y_ur}, {"z_uq", &p->z_uq},
                {"m_uq", &p->m_uq}, {"n_ur", &p->n_ur}, {"k_p", &p->k_p}};
  for (const auto& term : kTerms) *term.value = map.Number(term.key, Range::Any(), 0.0);
}

core::LiftingSurface ReadSurface(const Field& field) {
  const MapReader map(field, MapKind::kSurface);
  core::LiftingSurface s;
  const Field name = map.Require("name");
  s.name = name.String();
  if (s.name.empty()) name.Fail("must not be empty");
  static const core::Channel kChannels[] = {core::Channel::kRudder, core::Channel::kElevator,
                                            core::Channel::kNone};
  s.channel = kChannels[map.Require("channel").Choice({"rudder", "elevator", "none"})];
  s.position_B = map.Vector("position");
  s.normal_B = Direction(map.Require("normal"));
  s.area = map.Number("area", Range::Above(0.0));
  s.aspect_ratio = map.Number("aspect_ratio", Range::Above(0.0));
  s.lift_slope = map.Number("lift_slope", Range::AtLeast(0.0), 0.0);  // 0: Helmbold
  s.oswald = map.Number("oswald", Range::LeftOpen(0.0, 1.0));
  s.cd0 = map.Number("cd0", Range::AtLeast(0.0));
  s.stall_angle = kDegToRad * map.Number("stall_angle_deg", Range::Open(0.0, 90.0));
  s.incidence = kDegToRad * map.Number("incidence_deg", Range::Open(-90.0, 90.0), 0.0);
  // the sign maps a command to the angle of attack: needed where a command drives the surface
  const Field sign = map.Get("deflection_sign");
  if (sign.present() || s.channel != core::Channel::kNone) {
    s.deflection_sign = sign.Number();
    if (s.deflection_sign != 1.0 && s.deflection_sign != -1.0) sign.Fail("must be 1 or -1");
  }
  return s;
}

core::ActuatorLimits ReadActuator(const BodyKeys::Map& map) {
  core::ActuatorLimits limits;
  limits.max_deflection = kDegToRad * map.Number("max_deflection_deg", Range::LeftOpen(0.0, 90.0),
                                                 kRadToDeg * limits.max_deflection);
  limits.max_rate =
      kDegToRad * map.Number("max_rate_deg", Range::Above(0.0), kRadToDeg * limits.max_rate);
  return limits;
}

const char* ChannelName(core::Channel channel) {
  return channel == core::Channel::kRudder ? "rudder" : "elevator";
}

// a deflection given as <channel> [rad] or <channel>_deg [deg], not both; false if neither
bool ReadDeflection(const MapReader& map, const core::Vehicle& vehicle, core::Channel channel,
                    double* value) {
  const std::string key = ChannelName(channel);
  const std::string deg_key = key + "_deg";
  if (map.Has(key) && map.Has(deg_key)) {
    map.Get(deg_key).Fail("give " + key + " [rad] or " + deg_key + " [deg], not both");
  }
  if (!map.Has(key) && !map.Has(deg_key)) return false;
  const Field given = map.Get(map.Has(key) ? key : deg_key);
  *value = given.Number() * (map.Has(key) ? 1.0 : kDegToRad);
  CheckDeflection(given, *value, vehicle, channel);
  return true;
}

}  // namespace

core::VehicleParams ReadVehicleParams(const BodyKeys& keys) {
  core::VehicleParams p;
  // where the numbers come from
  const Field source = keys.Require("source");
  p.source = source.String();
  if (p.source.empty()) source.Fail("must not be empty (say where the numbers come from)");

  // rigid body: dimensions, mass, inertia about the CG, CG and CB in the body frame
  p.length = keys.Require("length").Number(Range::Above(0.0));
  // hull diameter (drawn by the markers only; default: the cylinder of the displaced volume)
  if (keys.Has("diameter")) p.diameter = keys.Get("diameter").Number(Range::Above(0.0));
  p.mass = keys.Require("mass").Number(Range::Above(0.0));
  p.inertia = PositiveVector(keys.Require("inertia"));
  p.r_g = keys.Require("r_g").Vector();
  if (keys.Has("r_b")) p.r_b = keys.Get("r_b").Vector();
  p.volume = keys.Require("volume").Number(Range::AtLeast(0.0));

  // hydrodynamics
  p.added_mass = ReadAddedMass(keys.GetMap("added_mass", MapKind::kAddedMass));
  if (keys.Has("munk_moment")) p.munk_moment = keys.Get("munk_moment").Boolean();
  ReadDamping(keys.GetMap("damping", MapKind::kDamping), &p);

  // fins and wings: a list, names unique
  for (const Field& item : keys.Get("surfaces").Items()) {
    core::LiftingSurface surface = ReadSurface(item);
    for (const core::LiftingSurface& other : p.surfaces) {
      if (other.name == surface.name) {
        MapReader(item, MapKind::kSurface)
            .Get("name")
            .Fail("duplicate surface name (names must be unique within the vehicle)");
      }
    }
    p.surfaces.push_back(std::move(surface));
  }

  // actuators
  p.rudder = ReadActuator(keys.GetMap("rudder", MapKind::kActuator));
  p.elevator = ReadActuator(keys.GetMap("elevator", MapKind::kActuator));
  const BodyKeys::Map propeller = keys.GetMap("propeller", MapKind::kPropeller);
  if (propeller.present()) {
    p.has_propeller = true;
    p.max_thrust = propeller.Get("max_thrust").Number(Range::Above(0.0));
    p.thrust_time_constant = propeller.Get("time_constant").Number(Range::Above(0.0));
  }
  // semi-submersible: the mast's waterplane (core::VehicleParams::waterplane_area)
  const BodyKeys::Map waterplane = keys.GetMap("waterplane", MapKind::kWaterplane);
  if (waterplane.present()) {
    p.waterplane_area = waterplane.Get("area").Number(Range::Above(0.0));
    p.waterplane_point_B = waterplane.Get("position").Vector();
    p.design_depth = waterplane.Get("design_depth").Number(Range::AtLeast(0.0));
    p.waterplane_inertia_long = waterplane.Number("inertia_longitudinal", Range::AtLeast(0.0), 0.0);
    p.waterplane_inertia_trans = waterplane.Number("inertia_transverse", Range::AtLeast(0.0), 0.0);
  }
  return p;
}

CommandFields ReadCommand(const MapReader& map, const core::Vehicle& vehicle,
                          core::VehicleCommand* command) {
  CommandFields given;
  if (map.Has("thrust")) {
    const Field thrust = map.Get("thrust");
    given.thrust = true;
    command->thrust = thrust.Number();
    CheckThrust(thrust, command->thrust, vehicle);
  }
  given.rudder = ReadDeflection(map, vehicle, core::Channel::kRudder, &command->rudder);
  given.elevator = ReadDeflection(map, vehicle, core::Channel::kElevator, &command->elevator);
  return given;
}

void CheckThrust(const Field& field, double thrust, const core::Vehicle& vehicle) {
  const core::VehicleParams& p = vehicle.params;
  if (!p.has_propeller) {
    if (thrust != 0.0) {
      field.Fail(vehicle.name + " has no propeller (no propeller: in its model), so its thrust " +
                 "must be 0");
    }
    return;
  }
  const core::Actuator propeller = core::ThrustActuator(p);  // its range (actuator.h)
  if (thrust < propeller.min || thrust > propeller.max) {
    field.Fail("must be in [-max_thrust/4, max_thrust] = [" + FormatNumber(propeller.min) + ", " +
               FormatNumber(propeller.max) + "] N for " + vehicle.name);
  }
}

void CheckDeflection(const Field& field, double deflection, const core::Vehicle& vehicle,
                     core::Channel channel) {
  const core::VehicleParams& p = vehicle.params;
  const char* name = ChannelName(channel);
  const bool has_surface =
      std::any_of(p.surfaces.begin(), p.surfaces.end(),
                  [&](const core::LiftingSurface& s) { return s.channel == channel; });
  if (!has_surface) {
    if (deflection != 0.0) {
      field.Fail(vehicle.name + " has no surface on channel " + name + ", so its " + name +
                 " must be 0");
    }
    return;
  }
  const double max =
      channel == core::Channel::kRudder ? p.rudder.max_deflection : p.elevator.max_deflection;
  if (std::abs(deflection) > max * (1.0 + 1e-12)) {
    field.Fail("must be within +-" + FormatNumber(kRadToDeg * max) + " deg (" + FormatNumber(max) +
               " rad), the " + name + ".max_deflection_deg of " + vehicle.name);
  }
}

}  // namespace towsim::scene::internal
