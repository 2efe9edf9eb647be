#include "vehicle_file.h"

#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace towsim::test {
namespace {

using core::Vec3;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

class Reader {
 public:
  Reader(std::string file, YAML::Node node, std::string path, std::set<std::string> allowed)
      : file_(std::move(file)), node_(node), path_(std::move(path)) {
    if (!node_.IsMap()) Fail(path_, "must be a map");
    for (const auto& kv : node_) {
      const std::string key = kv.first.as<std::string>();
      if (!allowed.count(key)) Fail(Path(key), "unknown key");
    }
  }
  bool Has(const std::string& key) const { return static_cast<bool>(node_[key]); }
  YAML::Node Node(const std::string& key) const {
    if (!Has(key)) Fail(Path(key), "is required");
    return node_[key];
  }
  double Number(const std::string& key) const { return Node(key).as<double>(); }
  double Number(const std::string& key, double fallback) const {
    return Has(key) ? Number(key) : fallback;
  }
  Vec3 Vector(const std::string& key) const {
    const auto v = Node(key).as<std::vector<double>>();
    if (v.size() != 3) Fail(Path(key), "must have 3 entries");
    return Vec3(v[0], v[1], v[2]);
  }
  Reader Child(const std::string& key, std::set<std::string> allowed) const {
    return Reader(file_, Node(key), Path(key), std::move(allowed));
  }
  std::string Path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  [[noreturn]] void Fail(const std::string& key, const std::string& rule) const {
    throw std::runtime_error(file_ + ": " + key + " " + rule);
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  YAML::Node node_;
  std::string path_;
};

core::Channel ChannelOf(const Reader& r, const std::string& name) {
  if (name == "rudder") return core::Channel::kRudder;
  if (name == "elevator") return core::Channel::kElevator;
  if (name == "none") return core::Channel::kNone;
  r.Fail(r.Path("channel"), "must be rudder, elevator or none");
}

core::ActuatorLimits Limits(const Reader& top, const std::string& key) {
  core::ActuatorLimits lim;
  if (!top.Has(key)) return lim;
  const Reader r = top.Child(key, {"max_deflection_deg", "max_rate_deg"});
  lim.max_deflection = r.Number("max_deflection_deg") * kDeg;
  lim.max_rate = r.Number("max_rate_deg") * kDeg;
  return lim;
}

}  // namespace

core::VehicleParams ReadVehicleFile(const std::string& path) {
  const YAML::Node root = YAML::LoadFile(path);
  const Reader top(path, root, "",
                   {"type", "source", "length", "mass", "inertia", "r_g", "r_b", "volume",
                    "added_mass", "munk_moment", "damping", "surfaces", "rudder", "elevator",
                    "propeller"});
  if (top.Node("type").as<std::string>() != "vehicle") top.Fail("type", "must be vehicle");
  core::VehicleParams p;
  p.source = top.Node("source").as<std::string>();
  p.length = top.Number("length");
  p.mass = top.Number("mass");
  p.inertia = top.Vector("inertia");
  p.r_g = top.Vector("r_g");
  p.r_b = top.Vector("r_b");
  p.volume = top.Number("volume");
  p.munk_moment = top.Node("munk_moment").as<bool>();

  // M_A = -[X_udot ...] with the couplings (1,5), (5,1), (2,4), (4,2) (0-based)
  const Reader am = top.Child("added_mass", {"x_udot", "y_vdot", "z_wdot", "k_pdot", "m_qdot",
                                             "n_rdot", "y_rdot", "n_vdot", "z_qdot", "m_wdot"});
  p.added_mass.setZero();
  p.added_mass.diagonal() << -am.Number("x_udot"), -am.Number("y_vdot"), -am.Number("z_wdot"),
      -am.Number("k_pdot"), -am.Number("m_qdot"), -am.Number("n_rdot");
  p.added_mass(1, 5) = -am.Number("y_rdot", 0.0);
  p.added_mass(5, 1) = -am.Number("n_vdot", 0.0);
  p.added_mass(2, 4) = -am.Number("z_qdot", 0.0);
  p.added_mass(4, 2) = -am.Number("m_wdot", 0.0);

  const Reader d = top.Child(
      "damping", {"x_uu", "y_vv", "z_ww", "y_rr", "z_qq", "m_ww", "n_vv", "m_qq", "n_rr", "k_pp",
                  "y_uv", "z_uw", "m_uw", "n_uv", "y_ur", "z_uq", "m_uq", "n_ur", "k_p"});
  p.x_uu = d.Number("x_uu");
  p.y_vv = d.Number("y_vv");
  p.z_ww = d.Number("z_ww");
  p.y_rr = d.Number("y_rr");
  p.z_qq = d.Number("z_qq");
  p.m_ww = d.Number("m_ww");
  p.n_vv = d.Number("n_vv");
  p.m_qq = d.Number("m_qq");
  p.n_rr = d.Number("n_rr");
  p.k_pp = d.Number("k_pp");
  p.y_uv = d.Number("y_uv");
  p.z_uw = d.Number("z_uw");
  p.m_uw = d.Number("m_uw");
  p.n_uv = d.Number("n_uv");
  p.y_ur = d.Number("y_ur");
  p.z_uq = d.Number("z_uq");
  p.m_uq = d.Number("m_uq");
  p.n_ur = d.Number("n_ur");
  p.k_p = d.Number("k_p");

  const YAML::Node surfaces = top.Node("surfaces");
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    const Reader s(path, surfaces[i], "surfaces[" + std::to_string(i) + "]",
                   {"name", "channel", "position", "normal", "area", "aspect_ratio", "lift_slope",
                    "oswald", "cd0", "stall_angle_deg", "incidence_deg", "deflection_sign"});
    core::LiftingSurface ls;
    ls.name = s.Node("name").as<std::string>();
    ls.channel = ChannelOf(s, s.Node("channel").as<std::string>());
    ls.position_B = s.Vector("position");
    ls.normal_B = s.Vector("normal");
    ls.area = s.Number("area");
    ls.aspect_ratio = s.Number("aspect_ratio");
    ls.lift_slope = s.Number("lift_slope");
    ls.oswald = s.Number("oswald");
    ls.cd0 = s.Number("cd0");
    ls.stall_angle = s.Number("stall_angle_deg") * kDeg;
    ls.incidence = s.Number("incidence_deg", 0.0) * kDeg;
    ls.deflection_sign = s.Number("deflection_sign", 1.0);
    p.surfaces.push_back(ls);
  }
  p.rudder = Limits(top, "rudder");
  p.elevator = Limits(top, "elevator");
  if (top.Has("propeller")) {
    const Reader pr = top.Child("propeller", {"max_thrust", "time_constant"});
    p.has_propeller = true;
    p.max_thrust = pr.Number("max_thrust");
    p.thrust_time_constant = pr.Number("time_constant");
  }
  return p;
}

core::VehicleParams ReadProjectVehicle(const std::string& name) {
  return ReadVehicleFile(std::string(TOWSIM_SOURCE_DIR) + "/config/vehicles/" + name + ".yaml");
}

}  // namespace towsim::test
