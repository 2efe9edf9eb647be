#include "scene/network_reader.h"

#include <algorithm>
#include <numeric>

#include "scene/body_reader.h"
#include "scene/cable_reader.h"
#include "scene/scene_schema.h"

namespace towsim::scene::internal {
namespace {

// union-find over the network's parts: bodies (spheres, then vehicles) and cables
struct Parts {
  std::vector<int> parent;
  explicit Parts(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int Find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void Join(int a, int b) { parent[Find(a)] = Find(b); }
};

std::string Join(const std::vector<std::string>& names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i)
    s += (i == 0 ? "" : (i + 1 == names.size() ? " and " : ", ")) + names[i];
  return s;
}

}  // namespace

bool IsReservedCableName(const std::string& name) {
  // the run's CSV files (bodies.csv, ...) and the node's own topics (rt/<ns>/status, ...)
  static const std::vector<std::string> kReserved = {
      "bodies",     "forces",  "status", "environment", "winch", "actuators", "commands",
      "scene_info", "markers", "clock",  "tf",          "tf_static", "sim_control", "results"};
  return std::find(kReserved.begin(), kReserved.end(), name) != kReserved.end();
}

std::vector<core::CableParams> ReadCables(const Field& field, const Field& line_types,
                                          const std::string& base_dir, const core::Model& model) {
  const MapReader map(field, MapKind::kCables);
  if (map.entries().empty()) field.Fail("must name at least one cable (name: {length, ...})");
  std::vector<core::CableParams> cables;
  std::vector<Field> fields;
  for (const auto& [name, entry] : map.entries()) {
    // one namespace: cables, bodies (their topics, frames and files)
    if (IsReservedCableName(name)) {
      entry.Fail("cable name " + name +
                 " is taken by a file or topic of every run (bodies, forces, status, "
                 "environment, winch, actuators, commands, scene_info, markers, clock, tf, "
                 "tf_static, sim_control, results): choose another");
    }
    if (FindBody(model, name).kind != BodyRef::kNone) {
      entry.Fail("cable name " + name +
                 " is also a body's name: cables and bodies share one namespace (topics, "
                 "frames, files)");
    }
    core::CableParams c = ReadCable(entry, line_types, base_dir, model);
    c.name = name;
    cables.push_back(std::move(c));
    fields.push_back(entry);
  }
  const int nc = static_cast<int>(cables.size());

  // the winches, each on its cable's start (its drum): named `winch` when the scene has one,
  // `<cable>_winch` when it has several, unless `name:` names it; one namespace with the
  // cables and bodies (topics <ns>/<name>/command, files <name>.csv)
  int num_winches = 0;
  for (int c = 0; c < nc; ++c) num_winches += cables[c].winch ? 1 : 0;
  std::vector<std::string> winch_names;
  for (int c = 0; c < nc; ++c) {
    if (!cables[c].winch) continue;
    core::WinchParams& w = *cables[c].winch;
    const MapReader winch(MapReader(fields[c], MapKind::kCable).Get("winch"), MapKind::kWinch);
    const bool given = !w.name.empty();
    if (!given) w.name = num_winches == 1 ? "winch" : cables[c].name + "_winch";
    const Field at = given ? winch.Get("name") : winch.field();
    const std::string what = given ? "winch name " : "winch name (cable name + _winch) ";
    if (w.name != "winch" && IsReservedCableName(w.name)) {
      at.Fail(what + w.name +
              " is taken by a file or topic of every run (bodies, forces, status, environment, "
              "actuators, commands, scene_info, markers, clock, tf, tf_static, sim_control, "
              "results): choose another");
    }
    if (w.name == "winch" && num_winches > 1) {
      at.Fail("winch name winch is the one winch's of a scene (winch.csv, rt/<ns>/winch/command); "
              "with " + std::to_string(num_winches) + " winches name them otherwise");
    }
    for (const core::CableParams& other : cables) {
      if (other.name == w.name) {
        at.Fail(what + w.name +
                " is also a cable's name: winches, cables and bodies share one namespace "
                "(topics, files)");
      }
    }
    // (a body named winch beside the one winch: sim_node's rule for its command topic)
    if (w.name != "winch" && FindBody(model, w.name).kind != BodyRef::kNone) {
      at.Fail(what + w.name +
              " is also a body's name: winches, cables and bodies share one namespace (topics, "
              "files)");
    }
    for (size_t k = 0; k < winch_names.size(); ++k) {
      if (winch_names[k] == w.name)
        at.Fail(what + w.name + " is taken by another winch: each winch has its own name");
    }
    winch_names.push_back(w.name);
  }

  // initial: static solves the whole network at once, in one frame moving with the tow
  int static_cable = -1;
  for (int c = nc - 1; c >= 0; --c)
    if (cables[c].initial == core::InitialShape::kStatic) static_cable = c;  // the first
  if (static_cable >= 0) {
    for (int c = 0; c < nc; ++c) {
      const MapReader cable(fields[c], MapKind::kCable);
      if (cables[c].initial != core::InitialShape::kStatic) {
        (cable.Has("initial") ? cable.Get("initial") : fields[c])
            .Fail("must be initial: static like cables." + cables[static_cable].name +
                  ": the static solve finds the whole network's equilibrium");
      }
      if (cables[c].initial_velocity != cables[static_cable].initial_velocity) {
        (cable.Has("initial_velocity") ? cable.Get("initial_velocity") : fields[c])
            .Fail("initial_velocity must equal cables." + cables[static_cable].name +
                  "'s: the static solve runs in one frame moving with the tow");
      }
    }
  }

  // every connected part is held: by a fixed or driven end, a vehicle (its own dynamics keep
  // it up) or a buoyant sphere (rho_w V > m); otherwise it sinks for ever
  const int ns = static_cast<int>(model.spheres.size());
  const int nv = static_cast<int>(model.vehicles.size());
  Parts parts(ns + nv + nc);
  std::vector<bool> held(ns + nv + nc, false);
  for (int v = 0; v < nv; ++v) held[ns + v] = true;
  for (int s = 0; s < ns; ++s)
    held[s] = model.environment.water_density * model.spheres[s].volume > model.spheres[s].mass;
  for (int c = 0; c < nc; ++c) {
    for (const core::CableEnd* e : {&cables[c].start, &cables[c].end}) {
      // a fixed or driven point or a vessel: its motion is given
      if (e->kind == core::EndKind::kFixed || e->kind == core::EndKind::kDriven ||
          e->kind == core::EndKind::kVessel)
        held[ns + nv + c] = true;
      if (e->kind == core::EndKind::kSphere) parts.Join(ns + nv + c, e->body);
      if (e->kind == core::EndKind::kVehicle) parts.Join(ns + nv + c, ns + e->body);
    }
  }
  std::vector<bool> root_held(ns + nv + nc, false);
  for (int i = 0; i < ns + nv + nc; ++i)
    if (held[i]) root_held[parts.Find(i)] = true;
  for (int c = 0; c < nc; ++c) {
    const int root = parts.Find(ns + nv + c);
    if (root_held[root]) continue;
    std::vector<std::string> names;
    for (int k = 0; k < nc; ++k)
      if (parts.Find(ns + nv + k) == root) names.push_back("cables." + cables[k].name);
    for (int s = 0; s < ns; ++s)
      if (parts.Find(s) == root) names.push_back("bodies." + model.spheres[s].name);
    fields[c].Fail("nothing holds " + Join(names) +
                   ": give one of their cable ends a fixed or driven support, or attach them "
                   "to a vehicle or a buoyant sphere (rho_w V > m)");
  }

  // the winched cables first, each group in the scene's order (core/model.h: winch w on cable w)
  std::stable_partition(cables.begin(), cables.end(),
                        [](const core::CableParams& c) { return c.winch.has_value(); });
  return cables;
}

}  // namespace towsim::scene::internal
