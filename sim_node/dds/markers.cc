#include "dds/markers.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/constants.h"
#include "dds/frames.h"
#include "dds/translators.h"

namespace towsim::dds {
namespace {

using core::kPi;

void SetPoint(const core::Vec3& p, geometry_msgs_msg_dds__Point_* out) {
  out->x = p.x();
  out->y = p.y();
  out->z = p.z();
}

void SetPose(const core::Vec3& p, const Eigen::Quaterniond& q, geometry_msgs_msg_dds__Pose_* out) {
  SetPoint(p, &out->position);
  out->orientation.x = q.x();
  out->orientation.y = q.y();
  out->orientation.z = q.z();
  out->orientation.w = q.w();
}

ColorMsg Rgba(float r, float g, float b, float a) {
  ColorMsg c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

// an FRD vector of the body frame in FLU: (x, -y, -z)
core::Vec3 FrdToFlu(const core::Vec3& v) { return core::Vec3(v.x(), -v.y(), -v.z()); }

// the number of markers of sim's scene (so that the vector never reallocates)
size_t CountMarkers(const core::Simulation& sim) {
  // cables, bodies, two arrows per cable, the sea and the seabed
  size_t n = 3 * static_cast<size_t>(sim.num_cables()) + static_cast<size_t>(sim.num_bodies()) + 2;
  for (const core::Vehicle& v : sim.model().vehicles) n += v.params.surfaces.size();
  return n;
}

// the body the sea patches follow: the first vehicle with a propeller, else the first vessel,
// else the first vehicle; -1: none (the cable's start node)
int TowVehicle(const core::Simulation& sim) {
  const std::vector<core::Vehicle>& vehicles = sim.model().vehicles;
  for (size_t v = 0; v < vehicles.size(); ++v) {
    if (vehicles[v].params.has_propeller) return sim.num_spheres() + static_cast<int>(v);
  }
  if (sim.num_vessels() > 0) return sim.num_spheres() + sim.num_vehicles();
  return vehicles.empty() ? -1 : sim.num_spheres();
}

// vertex k of the patch's triangle list: cell (i, j) has the triangles (i, j) (i + 1, j)
// (i + 1, j + 1) and (i, j) (i + 1, j + 1) (i, j + 1), corners counted from the patch's
// lower-left (x0, y0)
constexpr int kCorner[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
constexpr size_t kPatchVertices = 6 * kSeaPatchCells * kSeaPatchCells;
constexpr size_t kPatchCorners = (kSeaPatchCells + 1) * (kSeaPatchCells + 1);

bool Held(const core::CableEnd& end) { return end.kind != core::EndKind::kFree; }

}  // namespace

ColorMsg TensionColor(double tension) {
  const double s = std::clamp(tension / kTensionLegendMax, 0.0, 1.0);
  // blue -> green over [0, 0.5], green -> red over [0.5, 1]
  const double r = std::max(0.0, 2.0 * s - 1.0);
  const double b = std::max(0.0, 1.0 - 2.0 * s);
  const double g = 1.0 - r - b;
  return Rgba(static_cast<float>(r), static_cast<float>(g), static_cast<float>(b), 1.0f);
}

ColorMsg SeaColor(double eta, double eta_max) {
  const double s = eta_max > 0.0 ? std::clamp(0.5 + eta / (2.0 * eta_max), 0.0, 1.0) : 0.5;
  return Rgba(static_cast<float>(0.6 * s), static_cast<float>(0.15 + 0.7 * s),
              static_cast<float>(0.45 + 0.55 * s), kSeaAlpha);
}

MarkerMsg& SceneMarkers::Add(const std::string& ns, int id, int type, const std::string& frame) {
  // strings_ was reserved: the pointers stay valid
  strings_.push_back(ns);
  const char* ns_chars = strings_.back().c_str();
  strings_.push_back(frame);
  const char* frame_chars = strings_.back().c_str();
  markers_.push_back(MarkerMsg{});
  MarkerMsg& m = markers_.back();
  m.header.frame_id = const_cast<char*>(frame_chars);
  m.ns = const_cast<char*>(ns_chars);
  m.id = id;
  m.type = type;
  m.action = visualization_msgs_msg_dds__Marker_Constants_ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color = Rgba(1.0f, 1.0f, 1.0f, 1.0f);
  static char kEmpty[] = "";
  m.texture_resource = kEmpty;
  m.texture.header.frame_id = kEmpty;
  m.texture.format = kEmpty;
  m.text = kEmpty;
  m.mesh_resource = kEmpty;
  m.mesh_file.filename = kEmpty;
  return m;
}

SceneMarkers::SceneMarkers(const core::Simulation& sim) : msg{} {
  const size_t count = CountMarkers(sim);
  markers_.reserve(count);
  strings_.reserve(2 * count);
  const core::Model& model = sim.model();

  // the cables
  // storage for the most nodes of the run (a winch changes the count: Update sets it)
  const int cables = sim.num_cables();
  cable_points_.resize(static_cast<size_t>(cables));
  cable_colors_.resize(static_cast<size_t>(cables));
  for (int c = 0; c < cables; ++c) {
    std::vector<geometry_msgs_msg_dds__Point_>& points = cable_points_[static_cast<size_t>(c)];
    std::vector<ColorMsg>& colors = cable_colors_[static_cast<size_t>(c)];
    points.resize(static_cast<size_t>(MaxCableNodes(sim, c)));
    colors.resize(points.size());
    MarkerMsg& m =
        Add("cable", c, visualization_msgs_msg_dds__Marker_Constants_LINE_STRIP, kEnuWorldFrame);
    m.scale.x = kCableLineWidth;
    const uint32_t n = static_cast<uint32_t>(points.size());
    m.points = {n, n, points.data(), false};
    m.colors = {n, n, colors.data(), false};
  }

  // hulls and fins
  const Eigen::Quaterniond z_to_x(Eigen::AngleAxisd(0.5 * kPi, core::Vec3::UnitY()));
  int fin_id = 0;
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const std::string& name = sim.body_name(b);
    if (sim.body_is_vessel(b)) {
      // the scene gives a vessel no geometry: a box of kVesselMarkerSize, its keel at the origin
      MarkerMsg& m = Add("hull", b, visualization_msgs_msg_dds__Marker_Constants_CUBE, name);
      SetPose(core::Vec3(0.0, 0.0, 0.5 * kVesselMarkerSize.z() - kVesselMarkerDraught),
              Eigen::Quaterniond::Identity(), &m.pose);
      m.scale.x = kVesselMarkerSize.x();
      m.scale.y = kVesselMarkerSize.y();
      m.scale.z = kVesselMarkerSize.z();
      m.color = Rgba(0.6f, 0.6f, 0.65f, 1.0f);
      m.frame_locked = true;
      continue;
    }
    if (!sim.body_is_vehicle(b)) {
      const core::SphereBody& s = model.spheres[static_cast<size_t>(b)];
      const double d = 2.0 * std::cbrt(3.0 * s.volume / (4.0 * kPi));
      MarkerMsg& m = Add("hull", b, visualization_msgs_msg_dds__Marker_Constants_SPHERE, name);
      m.scale.x = m.scale.y = m.scale.z = d;
      m.color = Rgba(0.9f, 0.5f, 0.1f, 1.0f);
      m.frame_locked = true;
      continue;
    }
    const core::VehicleParams& p =
        model.vehicles[static_cast<size_t>(b - sim.num_spheres())].params;
    const double d = p.diameter > 0.0 ? p.diameter : std::sqrt(4.0 * p.volume / (kPi * p.length));
    MarkerMsg& hull = Add("hull", b, visualization_msgs_msg_dds__Marker_Constants_CYLINDER, name);
    // the cylinder's axis is its z: turned onto x
    SetPose(core::Vec3::Zero(), z_to_x, &hull.pose);
    hull.scale.x = hull.scale.y = d;
    hull.scale.z = p.length;
    hull.color = p.has_propeller ? Rgba(1.0f, 0.85f, 0.1f, 1.0f) : Rgba(0.9f, 0.5f, 0.1f, 1.0f);
    hull.frame_locked = true;
    for (const core::LiftingSurface& s : p.surfaces) {
      const double span = std::sqrt(s.area * s.aspect_ratio);
      const double chord = span > 0.0 ? s.area / span : 0.0;
      // plate axes in FLU: x chordwise (body x without its normal part), z the normal
      const core::Vec3 n = FrdToFlu(s.normal_B).normalized();
      core::Vec3 x = core::Vec3::UnitX() - n.x() * n;
      if (x.norm() < 1e-9) x = core::Vec3::UnitY() - n.y() * n;
      x.normalize();
      Eigen::Matrix3d R;
      R.col(0) = x;
      R.col(1) = n.cross(x);
      R.col(2) = n;
      MarkerMsg& fin =
          Add("fins", fin_id++, visualization_msgs_msg_dds__Marker_Constants_CUBE, name);
      SetPose(FrdToFlu(s.position_B), Eigen::Quaterniond(R), &fin.pose);
      fin.scale.x = chord;
      fin.scale.y = span;
      fin.scale.z = kFinThickness;
      fin.color = Rgba(0.3f, 0.3f, 0.35f, 1.0f);
      fin.frame_locked = true;
    }
  }

  // force arrows at the held ends
  arrow_points_.resize(4 * static_cast<size_t>(cables));
  for (int c = 0; c < cables; ++c) {
    const core::CableEnd* ends[2] = {&model.cables[c].start, &model.cables[c].end};
    for (int e = 0; e < 2; ++e) {
      if (!Held(*ends[e])) continue;
      const int k = 2 * c + e;
      MarkerMsg& m =
          Add("cable_force", k, visualization_msgs_msg_dds__Marker_Constants_ARROW, kEnuWorldFrame);
      m.scale.x = 0.15;  // shaft diameter [m]
      m.scale.y = 0.4;   // head diameter [m]
      m.scale.z = 0.6;   // head length [m]
      m.color = Rgba(0.9f, 0.1f, 0.9f, 1.0f);
      m.points = {2, 2, &arrow_points_[static_cast<size_t>(2 * k)], false};
      arrows_.push_back({markers_.size() - 1, c, e});
    }
  }

  // the sea patches
  const core::Environment& env = model.environment;
  patch_body_ = TowVehicle(sim);
  if (!env.waves.empty()) {
    for (const core::WaveComponent& c : env.waves.components()) eta_max_ += std::abs(c.amplitude);
    sea_points_.resize(kPatchVertices);
    sea_colors_.resize(kPatchVertices);
    corner_eta_.resize(kPatchCorners);
    wave_work_.resize(4 * (kSeaPatchCells + 1));
    MarkerMsg& m = Add("sea_surface", 0, visualization_msgs_msg_dds__Marker_Constants_TRIANGLE_LIST,
                       kWorldFrame);
    const uint32_t k = static_cast<uint32_t>(kPatchVertices);
    m.points = {k, k, sea_points_.data(), false};
    m.colors = {k, k, sea_colors_.data(), false};
    sea_marker_ = static_cast<long>(markers_.size() - 1);
  }
  if (env.seabed.present()) {
    seabed_points_.resize(kPatchVertices);
    corner_depth_.resize(kPatchCorners);
    MarkerMsg& m =
        Add("seabed", 0, visualization_msgs_msg_dds__Marker_Constants_TRIANGLE_LIST, kWorldFrame);
    m.color = Rgba(0.55f, 0.47f, 0.33f, 1.0f);
    const uint32_t k = static_cast<uint32_t>(kPatchVertices);
    m.points = {k, k, seabed_points_.data(), false};
    seabed_marker_ = static_cast<long>(markers_.size() - 1);
  }

  const uint32_t n = static_cast<uint32_t>(markers_.size());
  msg.markers = {n, n, markers_.data(), false};
  Update(sim);
}

void SceneMarkers::UpdatePatches(const core::Simulation& sim) {
  if (sea_marker_ < 0 && seabed_marker_ < 0) return;
  const core::Environment& env = sim.model().environment;
  // the patch's centre: the grid corner nearest the tow vehicle
  const core::Vec3 c = patch_body_ >= 0 ? sim.body_position(patch_body_) : sim.node_position(0);
  const double h = 0.5 * kSeaPatchCells * kSeaPatchCellSize;
  const double x0 = kSeaPatchCellSize * std::round(c.x() / kSeaPatchCellSize) - h;
  const double y0 = kSeaPatchCellSize * std::round(c.y() / kSeaPatchCellSize) - h;
  // the surface and the bottom at the (n + 1)^2 corners, once each
  constexpr int kCorners = kSeaPatchCells + 1;
  if (sea_marker_ >= 0) {
    env.waves.ElevationGrid(x0, kSeaPatchCellSize, kCorners, y0, kSeaPatchCellSize, kCorners,
                            sim.time(), &wave_work_, corner_eta_.data());
  }
  if (seabed_marker_ >= 0) {
    for (int i = 0; i < kCorners; ++i) {
      for (int j = 0; j < kCorners; ++j) {
        corner_depth_[static_cast<size_t>(i * kCorners + j)] =
            env.seabed.Depth(x0 + i * kSeaPatchCellSize, y0 + j * kSeaPatchCellSize);
      }
    }
  }
  size_t k = 0;
  for (int i = 0; i < kSeaPatchCells; ++i) {
    for (int j = 0; j < kSeaPatchCells; ++j) {
      for (const auto& corner : kCorner) {
        const int ci = i + corner[0], cj = j + corner[1];
        const size_t n = static_cast<size_t>(ci * kCorners + cj);
        const double x = x0 + ci * kSeaPatchCellSize;
        const double y = y0 + cj * kSeaPatchCellSize;
        if (sea_marker_ >= 0) {
          SetPoint(core::Vec3(x, y, -corner_eta_[n]), &sea_points_[k]);
          sea_colors_[k] = SeaColor(corner_eta_[n], eta_max_);
        }
        if (seabed_marker_ >= 0) SetPoint(core::Vec3(x, y, corner_depth_[n]), &seabed_points_[k]);
        ++k;
      }
    }
  }
}

void SceneMarkers::Update(const core::Simulation& sim) {
  const TimeMsg stamp = ToTimeMsg(sim.time());
  for (MarkerMsg& m : markers_) m.header.stamp = stamp;
  for (int c = 0; c < static_cast<int>(cable_points_.size()); ++c) {
    std::vector<geometry_msgs_msg_dds__Point_>& points = cable_points_[static_cast<size_t>(c)];
    std::vector<ColorMsg>& colors = cable_colors_[static_cast<size_t>(c)];
    const size_t n = static_cast<size_t>(sim.num_nodes(c));
    if (n > points.size()) {  // past the bound of the start: grown once
      points.resize(n);
      colors.resize(n);
    }
    MarkerMsg& cable = markers_[static_cast<size_t>(cable_marker(c))];
    const uint32_t capacity = static_cast<uint32_t>(points.size());
    cable.points = {capacity, static_cast<uint32_t>(n), points.data(), false};
    cable.colors = {capacity, static_cast<uint32_t>(n), colors.data(), false};
    for (size_t i = 0; i < n; ++i) {
      SetPoint(NedToEnu(sim.node_position(static_cast<int>(i), c)), &points[i]);
      colors[i] = TensionColor(sim.NodeTension(static_cast<int>(i), c));
    }
  }
  for (const Arrow& a : arrows_) {
    const core::Vec3 p = sim.node_position(a.end == 0 ? 0 : sim.num_nodes(a.cable) - 1, a.cable);
    const core::Vec3 f = sim.end_force(a.end, a.cable);
    const size_t k = static_cast<size_t>(2 * a.cable + a.end);
    SetPoint(NedToEnu(p), &arrow_points_[2 * k]);
    SetPoint(NedToEnu(p + kForceArrowScale * f), &arrow_points_[2 * k + 1]);
  }
  UpdatePatches(sim);
}

}  // namespace towsim::dds
