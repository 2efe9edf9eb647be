#include "dds/frames.h"

#include <algorithm>
#include <cmath>

#include "dds/translators.h"

namespace towsim::dds {
namespace {

char* Chars(const std::string& s) { return const_cast<char*>(s.c_str()); }

// the attachment frame of a cable end on /tf_static and its pose in the parent frame; false if
// the end has none there (free, or driven: its frame moves, on /tf)
bool EndFrame(const core::Simulation& sim, const core::CableEnd& end, std::string* parent,
              core::Vec3* offset) {
  switch (end.kind) {
    case core::EndKind::kFixed:
      *parent = kWorldFrame;
      *offset = end.position;
      return true;
    case core::EndKind::kSphere:
      *parent = FrdFrame(sim.body_name(end.body));
      *offset = end.at_B;
      return true;
    case core::EndKind::kVehicle:
      *parent = FrdFrame(sim.body_name(sim.num_spheres() + end.body));
      *offset = end.at_B;
      return true;
    case core::EndKind::kVessel:
      *parent = FrdFrame(sim.body_name(sim.num_spheres() + sim.num_vehicles() + end.body));
      *offset = end.at_B;
      return true;
    case core::EndKind::kFree:
    case core::EndKind::kDriven:
      return false;
  }
  return false;
}

}  // namespace

std::string FrdFrame(const std::string& body) { return body + "_frd"; }

std::string CableEndFrame(const std::string& cable, int end) {
  return cable + (end == 0 ? "_start" : "_end");
}

Eigen::Quaterniond EnuFromNed() {
  const double s = std::sqrt(0.5);
  return Eigen::Quaterniond(/*w=*/0.0, /*x=*/s, /*y=*/s, /*z=*/0.0);
}

Eigen::Quaterniond FrdFromFlu() { return Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0); }

core::Vec3 NedToEnu(const core::Vec3& p_W) { return core::Vec3(p_W.y(), p_W.x(), -p_W.z()); }

TransformsMessage::TransformsMessage(const std::vector<std::pair<std::string, std::string>>& edges)
    : msg{}, transforms_(edges.size()) {
  names_.reserve(2 * edges.size());
  for (const auto& [parent, child] : edges) {
    names_.push_back(parent);
    names_.push_back(child);
  }
  for (size_t i = 0; i < edges.size(); ++i) {
    TransformStampedMsg& t = transforms_[i];
    t = TransformStampedMsg{};
    t.header.frame_id = Chars(names_[2 * i]);
    t.child_frame_id = Chars(names_[2 * i + 1]);
    t.transform.rotation.w = 1.0;
  }
  const uint32_t n = static_cast<uint32_t>(transforms_.size());
  msg.transforms = {n, n, transforms_.empty() ? nullptr : transforms_.data(), false};
}

void SetTransform(const core::Vec3& translation, const Eigen::Quaterniond& rotation,
                  TransformStampedMsg* out) {
  out->transform.translation.x = translation.x();
  out->transform.translation.y = translation.y();
  out->transform.translation.z = translation.z();
  out->transform.rotation.x = rotation.x();
  out->transform.rotation.y = rotation.y();
  out->transform.rotation.z = rotation.z();
  out->transform.rotation.w = rotation.w();
}

std::unique_ptr<TransformsMessage> StaticTransforms(const core::Simulation& sim) {
  std::vector<std::pair<std::string, std::string>> edges = {{kEnuWorldFrame, kWorldFrame}};
  std::vector<std::pair<core::Vec3, Eigen::Quaterniond>> poses = {
      {core::Vec3::Zero(), EnuFromNed()}};
  for (int b = 0; b < sim.num_bodies(); ++b) {
    edges.emplace_back(FrdFrame(sim.body_name(b)), sim.body_name(b));
    poses.emplace_back(core::Vec3::Zero(), FrdFromFlu());
  }
  for (const core::CableParams& cable : sim.model().cables) {
    const core::CableEnd* ends[2] = {&cable.start, &cable.end};
    for (int e = 0; e < 2; ++e) {
      std::string parent;
      core::Vec3 offset;
      if (!EndFrame(sim, *ends[e], &parent, &offset)) continue;
      edges.emplace_back(parent, CableEndFrame(cable.name, e));
      poses.emplace_back(offset, Eigen::Quaterniond::Identity());
    }
  }
  auto out = std::make_unique<TransformsMessage>(edges);
  const TimeMsg stamp = ToTimeMsg(sim.time());
  for (int i = 0; i < out->size(); ++i) {
    out->transform(i).header.stamp = stamp;
    SetTransform(poses[static_cast<size_t>(i)].first, poses[static_cast<size_t>(i)].second,
                 &out->transform(i));
  }
  return out;
}

std::unique_ptr<TransformsMessage> BodyTransforms(const core::Simulation& sim) {
  std::vector<std::pair<std::string, std::string>> edges;
  for (int b = 0; b < sim.num_bodies(); ++b) {
    edges.emplace_back(kWorldFrame, FrdFrame(sim.body_name(b)));
  }
  for (const core::CableParams& cable : sim.model().cables) {
    const core::CableEnd* ends[2] = {&cable.start, &cable.end};
    for (int e = 0; e < 2; ++e) {
      if (ends[e]->kind == core::EndKind::kDriven) {
        edges.emplace_back(kWorldFrame, CableEndFrame(cable.name, e));
      }
    }
  }
  return std::make_unique<TransformsMessage>(edges);
}

void ToBodyTransforms(const core::Simulation& sim, TransformsMessage* out) {
  const TimeMsg stamp = ToTimeMsg(sim.time());
  const int n = std::min(out->size(), sim.num_bodies());
  for (int b = 0; b < n; ++b) {
    TransformStampedMsg& t = out->transform(b);
    t.header.stamp = stamp;
    // the pose of the odometry (ToOdometry): p_WB, q_WB
    SetTransform(sim.body_position(b), sim.body_attitude(b), &t);
  }
  // the driven ends, in BodyTransforms' order: the driven point r(t) = position + velocity t
  int i = n;
  for (const core::CableParams& cable : sim.model().cables) {
    const core::CableEnd* ends[2] = {&cable.start, &cable.end};
    for (int e = 0; e < 2 && i < out->size(); ++e) {
      if (ends[e]->kind != core::EndKind::kDriven) continue;
      TransformStampedMsg& t = out->transform(i++);
      t.header.stamp = stamp;
      SetTransform(ends[e]->position + ends[e]->velocity * sim.time(),
                   Eigen::Quaterniond::Identity(), &t);
    }
  }
}

}  // namespace towsim::dds
