#include "scene/environment_reader.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "scene/bathymetry_file.h"

namespace towsim::scene::internal {
namespace {

using core::kPi;

// exactly one of `keys` present in `map`; returns its index
size_t OneOf(const MapReader& map, const std::vector<std::string>& keys) {
  int found = -1;
  for (size_t i = 0; i < keys.size(); ++i) {
    if (!map.Has(keys[i])) continue;
    if (found >= 0) {
      map.Get(keys[i]).Fail("give one of " + keys[found] + " and " + keys[i] + ", not both");
    }
    found = static_cast<int>(i);
  }
  if (found < 0) {
    std::string list;
    for (size_t i = 0; i < keys.size(); ++i) list += (i ? ", " : "") + keys[i];
    map.field().Fail("must hold one of " + list);
  }
  return static_cast<size_t>(found);
}

// a list of [number, second] pairs whose first entries increase strictly
template <typename Second>
void ReadTable(const Field& field, const char* first_name, const Range& first_range,
               Second read_second, std::vector<std::pair<double, Field>>* rows) {
  const std::vector<Field> items = field.Items();
  if (items.empty()) field.Fail("must be a list of at least one row");
  for (const Field& item : items) {
    if (!item.node().IsSequence() || item.node().size() != 2) {
      item.Fail(std::string("must be a row [") + first_name + ", value]");
    }
    const std::vector<Field> pair = item.Items();
    const double x = pair[0].Number(first_range);
    if (!rows->empty() && x <= rows->back().first) {
      pair[0].Fail(std::string(first_name) +
                   "s must increase strictly down the table (the row "
                   "before has " +
                   FormatNumber(rows->back().first) + ")");
    }
    read_second(pair[1]);
    rows->emplace_back(x, pair[1]);
  }
}

core::CurrentField ReadCurrent(const Field& field) {
  if (!field.present() || field.node().IsNull()) return core::CurrentField();
  // [u, v, w]: uniform
  if (field.node().IsSequence()) return core::CurrentField::Uniform(field.Vector());
  if (!field.node().IsMap()) {
    field.Fail(
        "must be [u, v, w], {profile: [[depth, [u, v, w]], ...]} or "
        "{power_law: {surface: [u, v, w], depth: D, exponent: 7}}");
  }
  const MapReader current(field, MapKind::kCurrent);
  core::CurrentField c;
  if (OneOf(current, {"profile", "power_law"}) == 0) {
    // profile: [[depth >= 0, [u, v, w]], ...], depths increasing
    std::vector<std::pair<double, Field>> rows;
    ReadTable(
        current.Get("profile"), "depth", Range::AtLeast(0.0), [](const Field& v) { v.Vector(); },
        &rows);
    std::vector<core::CurrentField::ProfileRow> profile;
    for (const auto& [depth, value] : rows) profile.push_back({depth, value.Vector()});
    c = core::CurrentField::Profile(std::move(profile));
  } else {
    // power_law: U_s (1 - z/D)^(1/p), D > 0, p > 0 (default 7)
    const MapReader law(current.Get("power_law"), MapKind::kPowerLaw);
    const core::Vec3 surface = law.Vector("surface");
    const double depth = law.Number("depth", Range::Above(0.0));
    const double exponent = law.Number("exponent", Range::Above(0.0), 7.0);
    c = core::CurrentField::PowerLaw(surface, depth, exponent);
  }
  if (current.Has("time_scale")) {
    // time_scale: [[t, s], ...], times increasing, s finite
    std::vector<std::pair<double, Field>> rows;
    ReadTable(
        current.Get("time_scale"), "time", Range::Any(), [](const Field& v) { v.Number(); }, &rows);
    std::vector<core::CurrentField::ScaleRow> scale;
    for (const auto& [t, value] : rows) scale.push_back({t, value.Number()});
    c.SetTimeScale(std::move(scale));
  }
  return c;
}

core::Seabed ReadSeabed(const Field& field, const std::string& base_dir) {
  if (!field.present() || field.node().IsNull()) return core::Seabed();
  const MapReader seabed(field, MapKind::kSeabed);
  core::Seabed s;
  if (seabed.Has("grid")) {
    // grid: a bathymetry file (bathymetry_file.h), relative to the scene's folder
    for (const char* key : {"depth", "slope_deg", "slope_direction_deg"}) {
      if (seabed.Has(key)) {
        seabed.Get(key).Fail(
            "the grid file gives the depths; leave out depth, slope_deg and "
            "slope_direction_deg");
      }
    }
    const Field grid = seabed.Get("grid");
    const std::string written = grid.String();
    std::filesystem::path path(written);
    if (path.is_relative()) path = std::filesystem::path(base_dir) / path;
    std::string text, why;
    if (!ReadTextFile(path.string(), &text, &why)) {
      grid.Fail("cannot read the bathymetry file " + path.string() + ": " + why);
    }
    BathymetryGrid g;
    if (!ParseBathymetry(text, path.filename().string(), &g, &why)) grid.Fail(why);
    s = core::Seabed::Grid(std::move(g.x), std::move(g.y), std::move(g.depth));
  } else {
    // depth > 0; slope_deg in [0, 90), 0 (flat) by default; slope_direction_deg any
    const double depth = seabed.Number("depth", Range::Above(0.0));
    const double slope = seabed.Number("slope_deg", Range{0.0, 90.0, false, true}, 0.0);
    const double direction = seabed.Number("slope_direction_deg", Range::Any(), 0.0);
    s = slope == 0.0 ? core::Seabed::Flat(depth)
                     : core::Seabed::Plane(depth, kDegToRad * slope, kDegToRad * direction);
  }
  // contact parameters: >= 0, finite
  core::SeabedContact contact;
  contact.stiffness = seabed.Number("stiffness", Range::AtLeast(0.0), contact.stiffness);
  contact.damping = seabed.Number("damping", Range::AtLeast(0.0), contact.damping);
  contact.friction = seabed.Number("friction", Range::AtLeast(0.0), contact.friction);
  // across the cable (seabed_contact.h); the axial coefficient when not given
  contact.friction_lateral =
      seabed.Number("friction_lateral", Range::AtLeast(0.0), contact.friction);
  s.set_contact(contact);
  return s;
}

// a period must span kStepsPerWavePeriod steps
std::string PeriodRule(const core::TimeSettings& time) {
  return "must be >= " + std::to_string(kStepsPerWavePeriod) + " time steps (" +
         FormatNumber(kStepsPerWavePeriod * time.step) + " s) for the integrator to resolve it";
}

core::WaveField ReadWaves(const Field& field, const core::Environment& env,
                          const core::TimeSettings& time) {
  if (!field.present() || field.node().IsNull()) return core::WaveField();
  const MapReader waves(field, MapKind::kWaves);
  if (env.gravity <= 0.0) field.Fail("waves need gravity > 0 (environment.gravity)");
  const double depth = env.seabed.WaveDepth();
  if (!(depth > 0.0)) field.Fail("waves need water: the seabed's depth at x = y = 0 is <= 0");
  const double min_period = kStepsPerWavePeriod * time.step;
  core::WaveField w;
  const size_t kind = OneOf(waves, {"regular", "jonswap", "pierson_moskowitz"});
  if (kind == 0) {
    // regular: height > 0, period >= 20 steps, direction and phase in degrees
    const MapReader regular(waves.Get("regular"), MapKind::kRegularWave);
    const double height = regular.Number("height", Range::Above(0.0));
    const double period = regular.Number("period", Range::Above(0.0));
    if (period < min_period) regular.Get("period").Fail(PeriodRule(time));
    const double direction = regular.Number("direction_deg", Range::Any(), 0.0);
    const double phase = regular.Number("phase_deg", Range::Any(), 0.0);
    w = core::WaveField::Regular(height, period, kDegToRad * direction, kDegToRad * phase, depth,
                                 env.gravity, env.water_density);
    // Miche's limit: a wave breaks above H = 0.142 L tanh(k h), L = 2 pi / k
    const double k = w.components().front().k;
    const double limit =
        0.142 * (2.0 * kPi / k) * (std::isfinite(depth) ? std::tanh(k * depth) : 1.0);
    if (height > limit) {
      regular.Get("height").Fail(
          "must be <= the breaking height 0.142 L tanh(k h) = " + FormatNumber(limit) +
          " m (wavelength L = " + FormatNumber(2.0 * kPi / k) +
          " m): linear theory needs an "
          "unbroken wave");
    }
  } else {
    // jonswap / pierson_moskowitz: hs > 0, tp > 0, gamma >= 1, components in [1, 10000]
    const bool jonswap = kind == 1;
    const MapReader sea(waves.Get(jonswap ? "jonswap" : "pierson_moskowitz"),
                        jonswap ? MapKind::kJonswap : MapKind::kPmSpectrum);
    core::WaveSpectrum s;
    s.kind = jonswap ? core::WaveSpectrumKind::kJonswap : core::WaveSpectrumKind::kPiersonMoskowitz;
    s.hs = sea.Number("hs", Range::Above(0.0));
    s.tp = sea.Number("tp", Range::Above(0.0));
    s.gamma = jonswap ? sea.Number("gamma", Range::Closed(1.0, 20.0), 3.3) : 1.0;
    s.direction = kDegToRad * sea.Number("direction_deg", Range::Any(), 0.0);
    s.components = sea.Integer("components", Range::Closed(1, 10000), 100);
    s.seed = static_cast<std::uint64_t>(
        sea.Integer("seed", Range::Closed(0, std::numeric_limits<int>::max()), 1));
    w = core::WaveField::Irregular(s, depth, env.gravity, env.water_density);
    // the spectrum's shortest component must be resolved as well
    double shortest = std::numeric_limits<double>::infinity();
    for (const core::WaveComponent& c : w.components()) {
      shortest = std::min(shortest, 2.0 * kPi / c.omega);
    }
    if (shortest < min_period) {
      sea.Get("tp").Fail("gives components as short as " + FormatNumber(shortest) + " s; each " +
                         PeriodRule(time) + " (raise tp or lower time.step)");
    }
  }
  // ramp >= 0 [s]: cosine ramp of the amplitudes from t = 0
  w.set_ramp(waves.Number("ramp", Range::AtLeast(0.0), 0.0));
  return w;
}

}  // namespace

core::Environment ReadEnvironment(const Field& field, const core::TimeSettings& time,
                                  const std::string& base_dir) {
  const MapReader env(field, MapKind::kEnvironment);
  core::Environment e;
  e.water_density = env.Number("water_density", Range::Above(0.0), e.water_density);
  e.dynamic_viscosity = env.Number("dynamic_viscosity", Range::Above(0.0), e.dynamic_viscosity);
  e.gravity = env.Number("gravity", Range::AtLeast(0.0), e.gravity);
  e.current = ReadCurrent(env.Get("current"));
  // the seabed first: its depth is the waves' water depth
  e.seabed = ReadSeabed(env.Get("seabed"), base_dir);
  e.waves = ReadWaves(env.Get("waves"), e, time);
  return e;
}

void CheckBodiesAboveSeabed(const Field& bodies, const core::Model& model) {
  const core::Seabed& seabed = model.environment.seabed;
  if (!seabed.present()) return;
  const MapReader map(bodies, MapKind::kBodies);
  const auto check = [&](const std::string& name, const core::Vec3& p) {
    const double d = seabed.Depth(p.x(), p.y());
    if (p.z() > d) {
      MapReader(map.Get(name), MapKind::kBody)
          .Get("position")
          .Fail("is below the seabed (depth " + FormatNumber(d) +
                " m at x = " + FormatNumber(p.x()) + ", y = " + FormatNumber(p.y()) + ")");
    }
  };
  for (const core::SphereBody& b : model.spheres) check(b.name, b.position);
  for (const core::Vehicle& v : model.vehicles) check(v.name, v.position);
}

}  // namespace towsim::scene::internal
