#include "scene/vessel_reader.h"

#include <filesystem>

#include "scene/config_error.h"
#include "scene/rao_file.h"
#include "scene/time_history_file.h"

namespace towsim::scene::internal {
namespace {

// the path a file key names, relative to the folder of the file it is written in
std::string FilePath(const BodyKeys& keys, const std::string& key, const std::string& scene_dir,
                     const std::string& model_dir) {
  std::filesystem::path path(keys.Get(key).String());
  if (path.is_relative())
    path = std::filesystem::path(keys.scene().Has(key) || model_dir.empty() ? scene_dir
                                                                             : model_dir) /
           path;
  return path.lexically_normal().string();
}

// a harmonic motion {dof, amplitude, period, phase_deg}: amplitude in m, or deg for rotations
core::HarmonicMotion ReadHarmonic(const Field& item) {
  const MapReader map(item, MapKind::kHarmonic);
  core::HarmonicMotion h;
  const size_t dof =
      map.Require("dof").Choice({"surge", "sway", "heave", "roll", "pitch", "yaw"});
  h.dof = static_cast<core::VesselDof>(dof);
  const double amplitude = map.Require("amplitude").Number(Range::AtLeast(0.0));
  h.amplitude = dof >= 3 ? kDegToRad * amplitude : amplitude;
  h.period = map.Require("period").Number(Range::Above(0.0));
  h.phase = kDegToRad * map.Number("phase_deg", Range::Any(), 0.0);
  return h;
}

}  // namespace

core::Vessel ReadVessel(const std::string& name, const BodyKeys& keys,
                        const std::string& scene_dir, const std::string& model_dir) {
  core::Vessel v;
  v.name = name;
  const MapReader& scene = keys.scene();
  v.external = keys.Has("external") && keys.Get("external").Boolean();
  if (keys.Has("time_history")) {
    // the history is the whole motion: nothing else may move the vessel
    for (const char* key : {"speed", "harmonic", "raos", "rao_extrapolation", "external",
                            "position", "euler_deg", "max_acceleration",
                            "max_yaw_acceleration_deg"}) {
      if (keys.Has(key)) {
        keys.Get(key).Fail(
            std::string("a vessel with a time_history takes its whole motion from it; remove ") +
            key + " (or the time_history)");
      }
    }
    v.time_history = ReadTimeHistoryFile(FilePath(keys, "time_history", scene_dir, model_dir),
                                         keys.Get("time_history").path());
    const core::TimeHistory& th = *v.time_history;
    v.position = th.pose.front().head<3>();
    v.euler = th.pose.front().tail<3>();
    return v;
  }
  if (v.external) {
    for (const char* key : {"harmonic", "raos", "rao_extrapolation"}) {
      if (keys.Has(key)) {
        keys.Get(key).Fail(std::string("an external vessel's motion comes from another program; "
                                       "remove ") + key + " (or external: true)");
      }
    }
  }
  // the initial pose belongs to the scene
  v.position = scene.Vector("position");
  v.euler = ReadEulerDeg(scene);
  if (keys.Has("speed")) v.speed = keys.Get("speed").Number();
  if (keys.Has("max_acceleration"))
    v.max_acceleration = keys.Get("max_acceleration").Number(Range::Above(0.0));
  v.max_yaw_acceleration =
      kDegToRad * (keys.Has("max_yaw_acceleration_deg")
                       ? keys.Get("max_yaw_acceleration_deg").Number(Range::Above(0.0))
                       : 0.5);
  if (keys.Has("harmonic"))
    for (const Field& item : keys.Get("harmonic").Items()) v.harmonics.push_back(ReadHarmonic(item));
  if (keys.Has("raos")) {
    v.raos = ReadRaoFile(FilePath(keys, "raos", scene_dir, model_dir), keys.Get("raos").path());
    if (keys.Has("rao_extrapolation"))
      v.raos->extrapolate = keys.Get("rao_extrapolation").Choice({"none", "hold"}) == 1;
  } else if (keys.Has("rao_extrapolation")) {
    keys.Get("rao_extrapolation").Fail("applies only with raos");
  }
  return v;
}

}  // namespace towsim::scene::internal
