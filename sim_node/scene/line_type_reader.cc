#include "scene/line_type_reader.h"

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "scene/config_error.h"

namespace towsim::scene::internal {
namespace {

namespace fs = std::filesystem;

// the largest physical values (docs/scene_format.md "Line types": the limits)
constexpr double kMaxDiameter = 10.0;         // [m]
constexpr double kMaxDensity = 1.0e5;         // [kg/m^3]
constexpr double kMaxYoungsModulus = 1.0e13;  // [Pa]

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// a library file: a map of line type properties, its keys under line_types.<name>
MapReader LoadLineTypeFile(const Field& name, const fs::path& path, const std::string& type) {
  std::string text, why;
  if (!ReadTextFile(path.string(), &text, &why)) {
    name.Fail("cannot read the line type file " + path.string() + " (" + why + ")");
  }
  auto source = std::make_shared<Source>();
  source->name = path.filename().string();
  const YAML::Node root = LoadOneDocument(text, source->name, name.path(), name.text());
  if (!root.IsMap()) {
    throw ConfigError(name.path(), name.text(), source->name,
                      "a line type file must be a map of line type properties (diameter, "
                      "mass_per_length, ...)");
  }
  return MapReader(Field(root, root.Mark(), "line_types." + type, source), MapKind::kLineType);
}

// the line type `name` names: the scene's first, then the library's (line_type_reader.h)
MapReader FindLineType(const Field& name, const Field& line_types, const std::string& base_dir) {
  const std::string type = name.String();
  const MapReader scene_types(line_types, MapKind::kLineTypes);
  if (scene_types.Has(type)) {
    const Field f = scene_types.Get(type);
    if (!f.node().IsMap()) f.Fail("must be a map of line type properties (diameter, ...)");
    return MapReader(f, MapKind::kLineType);
  }
  std::vector<fs::path> candidates;
  const bool is_path = type.find('/') != std::string::npos || EndsWith(type, ".yaml");
  if (is_path) {
    fs::path path(type);
    if (path.is_relative()) path = fs::path(base_dir) / path;
    candidates.push_back(path.lexically_normal());
  } else {
    if (!IsValidName(type)) name.Fail(std::string("line type names ") + kNameRule);
    for (const fs::path& dir : {fs::path(base_dir), fs::path(base_dir) / ".."}) {
      candidates.push_back((dir / "line_types" / (type + ".yaml")).lexically_normal());
    }
  }
  std::error_code ec;
  for (const fs::path& path : candidates) {
    if (fs::is_regular_file(path, ec)) {
      return LoadLineTypeFile(name, path, is_path ? path.stem().string() : type);
    }
  }
  std::string names, tried;
  for (const auto& entry : scene_types.entries())
    names += (names.empty() ? "" : ", ") + entry.first;
  for (const fs::path& path : candidates) tried += (tried.empty() ? "" : ", ") + path.string();
  name.Fail("no such line type: not in the scene's line_types (" +
            (names.empty() ? std::string("none") : names) + ") and no file " + tried);
}

// The keys of the cable over those of its line type: a group of keys comes whole from the
// cable when it gives any of them, else from the type.
class Layers {
 public:
  Layers(const MapReader& cable, const std::optional<MapReader>& type, std::string type_name)
      : cable_(cable), type_(type), type_name_(std::move(type_name)) {}

  const MapReader* For(std::initializer_list<const char*> keys) const {
    const MapReader* type = type_ ? &*type_ : nullptr;
    for (const MapReader* m : {&cable_, type}) {
      if (!m) continue;
      for (const char* key : keys)
        if (m->Has(key)) return m;
    }
    return nullptr;
  }
  // "is required" where the cable would give it
  [[noreturn]] void Missing(const std::string& key, const std::string& rule) const {
    cable_.Get(key).Fail(
        rule + (type_ ? " (in cable or in its line type " + type_name_ + ")" : std::string()));
  }
  // exactly one of a pair: its field (from the cable, else the type)
  Field OneOf(const std::string& a, const std::string& b, const std::string& what) const {
    const MapReader* m = For({a.c_str(), b.c_str()});
    if (!m) Missing(a, "is required: give " + a + " or " + b + " (" + what + ")");
    if (m->Has(a) && m->Has(b)) m->Get(b).Fail("give one of " + a + " and " + b + ", not both");
    return m->Has(a) ? m->Get(a) : m->Get(b);
  }

 private:
  const MapReader& cable_;
  const std::optional<MapReader>& type_;
  std::string type_name_;
};

// x > 0 and x <= max, with the reason for the maximum
double Physical(const Field& f, double max, const std::string& why) {
  const double x = f.Number(Range::Above(0.0));
  if (x > max) f.Fail("must be <= " + FormatNumber(max) + " " + why);
  return x;
}

// drag: choo_casarella, or {normal: C_n, tangential: C_t}; the cable's `drag` over the type's,
// a law name as a whole and a map per coefficient (`--set cable.drag.normal=1.2` keeps the
// type's C_t)
core::CableDragLaw ReadDrag(const MapReader* cable, const MapReader* type) {
  core::CableDragLaw law;
  std::optional<MapReader> maps[2];  // the cable's, the type's
  for (int k = 0; k < 2; ++k) {
    const MapReader* layer = k == 0 ? cable : type;
    if (!layer || !layer->Has("drag")) continue;
    const Field field = layer->Get("drag");
    if (field.node().IsScalar()) {
      field.Choice({"choo_casarella"});
      if (k == 0 || !maps[0]) return law;  // a law: as a whole
      break;
    }
    if (!field.node().IsMap())
      field.Fail("must be choo_casarella or {normal: C_n, tangential: C_t}");
    maps[k].emplace(field, MapKind::kLineDrag);
  }
  if (!maps[0] && !maps[1]) return law;
  law.kind = core::CableDragLaw::kConstant;
  const MapReader& own = maps[0] ? *maps[0] : *maps[1];
  for (const auto& [key, value] :
       {std::pair{"normal", &law.normal}, std::pair{"tangential", &law.tangential}}) {
    const MapReader& from = own.Has(key) || !maps[1] ? own : *maps[1];
    *value = from.Number(key, Range::AtLeast(0.0));
  }
  return law;
}

}  // namespace

LineTypeFields ReadLineType(const MapReader& cable, const Field& line_types,
                            const std::string& base_dir, core::CableParams* c) {
  std::optional<MapReader> type;
  std::string type_name;
  if (cable.Has("line_type")) {
    const Field name = cable.Get("line_type");
    type.emplace(FindLineType(name, line_types, base_dir));
    type_name = name.String();
  }
  const Layers keys(cable, type, type_name);
  // source: where the numbers come from (free text)
  if (type && type->Has("source")) type->Get("source").String();

  // the hydrodynamic diameter d
  const MapReader* m = keys.For({"diameter"});
  if (!m) keys.Missing("diameter", "is required");
  c->diameter = Physical(m->Get("diameter"), kMaxDiameter, "m (a cable, not a structure)");
  const double area = c->area();
  const std::string section = "over the section of diameter " + FormatNumber(c->diameter) + " m";

  // mass: m = rho_c A, or m
  const Field mass = keys.OneOf("mass_per_length", "density", "the line's mass");
  if (EndsWith(mass.path(), "density")) {
    c->mass_per_length =
        Physical(mass, kMaxDensity, "kg/m^3 (the densest material, osmium, is 2.26e4)") * area;
  } else {
    c->mass_per_length = Physical(
        mass, kMaxDensity * area,
        "kg/m (a density of 1e5 kg/m^3 " + section + "; the densest material, osmium, is 2.26e4)");
  }

  // axial stiffness: EA = E A, or EA; the solid section's E for the default EI
  LineTypeFields fields{keys.OneOf("axial_stiffness", "youngs_modulus", "the line's stiffness")};
  double youngs_modulus;
  if (EndsWith(fields.stiffness.path(), "youngs_modulus")) {
    youngs_modulus = Physical(fields.stiffness, kMaxYoungsModulus,
                              "Pa (the stiffest material, diamond, is 1.2e12)");
    c->axial_stiffness = youngs_modulus * area;
  } else {
    c->axial_stiffness = Physical(fields.stiffness, kMaxYoungsModulus * area,
                                  "N (a Young's modulus of 1e13 Pa " + section +
                                      "; the stiffest material, diamond, is 1.2e12)");
    youngs_modulus = c->axial_stiffness / area;
  }
  // bending stiffness: given (0: none), else the solid section's E I
  if ((m = keys.For({"bending_stiffness"}))) {
    const Field ei = m->Get("bending_stiffness");
    c->bending_stiffness = ei.Number(Range::AtLeast(0.0));
    const double max = kMaxYoungsModulus * c->second_moment();
    if (c->bending_stiffness > max) {
      ei.Fail("must be <= " + FormatNumber(max) + " N m^2 (a Young's modulus of 1e13 Pa " +
              section + ")");
    }
  } else {
    c->bending_stiffness = youngs_modulus * c->second_moment();
  }

  if ((m = keys.For({"axial_damping"})))
    c->axial_damping = m->Get("axial_damping").Number(Range::AtLeast(0.0));
  c->drag = ReadDrag(&cable, type ? &*type : nullptr);

  // added mass, per coefficient: normal from cable.added_mass, cable.added_mass_coefficient
  // (the key before line types) or the type; tangential from cable.added_mass or the type
  if (cable.Has("added_mass") && cable.Has("added_mass_coefficient")) {
    cable.Get("added_mass_coefficient")
        .Fail("give one of added_mass and added_mass_coefficient, not both");
  }
  const MapReader* type_map = type ? &*type : nullptr;
  for (const MapReader* layer : {type_map, &cable}) {
    if (!layer) continue;
    if (layer->Has("added_mass")) {
      const Field field = layer->Get("added_mass");
      if (!field.node().IsMap()) field.Fail("must be a map {normal: C_an, tangential: C_at}");
      const MapReader a(field, MapKind::kLineAddMass);
      c->added_mass.normal = a.Number("normal", Range::AtLeast(0.0), c->added_mass.normal);
      c->added_mass.tangential =
          a.Number("tangential", Range::AtLeast(0.0), c->added_mass.tangential);
    }
  }
  c->added_mass.normal =
      cable.Number("added_mass_coefficient", Range::AtLeast(0.0), c->added_mass.normal);
  return fields;
}

double MinimumTension(const core::CableParams& c, const core::Model& model) {
  const core::Environment& env = model.environment;
  double tension = 0.0;
  // the cable's weight in water, half on each of two held ends (on a seabed: none surely)
  if (!env.seabed.present()) {
    double w = 0.0;
    if (c.loads.gravity) w += c.mass_per_length * env.gravity;
    if (c.loads.buoyancy) w -= env.water_density * c.area() * env.gravity;
    tension += 0.5 * std::abs(w) * c.length;
  }
  for (const core::CableEnd* end : {&c.start, &c.end}) {
    if (end->kind != core::EndKind::kSphere) continue;
    const core::SphereBody& b = model.spheres[end->body];
    tension += std::abs(b.mass - env.water_density * b.volume) * env.gravity;
  }
  return tension;
}

void CheckStaticStrain(const core::CableParams& c, const core::Model& model,
                       const LineTypeFields& fields) {
  const double tension = MinimumTension(c, model);
  const double strain = tension / c.axial_stiffness;
  if (strain <= kMaxStaticStrain) return;
  fields.stiffness.Fail(
      "gives EA = " + FormatNumber(c.axial_stiffness) + " N, which the weights alone (" +
      FormatNumber(tension) +
      " N: half the cable's weight in water and the spheres hanging on it) would stretch by " +
      FormatNumber(100.0 * strain) + " % (at most " + FormatNumber(100.0 * kMaxStaticStrain) +
      " %: no cable material stretches that far)");
}

}  // namespace towsim::scene::internal
