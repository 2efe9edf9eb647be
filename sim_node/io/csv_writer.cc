#include "io/csv_writer.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "core/model.h"
#include "io/output_error.h"

namespace towsim::io {
namespace {

// a cable end held by the ground or a kinematic driver carries a support reaction of its own
bool IsHeldSupport(const core::CableEnd& end) {
  return end.kind == core::EndKind::kFixed || end.kind == core::EndKind::kDriven;
}

}  // namespace

bool HasSea(const core::Environment& env) {
  return !env.waves.empty() || !env.current.IsZero() || env.seabed.present();
}

std::string CsvField(const std::string& name) {
  if (name.find_first_of(",\"\r\n") == std::string::npos) return name;
  std::string quoted = "\"";
  for (char c : name) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

CsvWriter::CsvWriter(const std::string& dir, bool sea, bool winch) : dir_(dir), winch_(winch) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) {
    throw std::runtime_error("cannot create CSV directory '" + dir_ + "': " + ec.message());
  }
  try {
    Open(bodies_, "bodies.csv", kCsvBodiesHeader);
    Open(cable_, "cable.csv", kCsvCableHeader);
    Open(forces_, "forces.csv", kCsvForcesHeader);
    Open(status_, "status.csv", winch_ ? kCsvStatusWinchHeader : kCsvStatusHeader);
    if (sea) Open(environment_, "environment.csv", kCsvEnvironmentHeader);
    if (winch) Open(winch_file_, "winch.csv", kCsvWinchHeader);
  } catch (...) {
    for (File* file : {&bodies_, &cable_, &forces_, &status_, &environment_, &winch_file_}) {
      if (file->f != nullptr) std::fclose(file->f);
      file->f = nullptr;
    }
    throw;
  }
}

CsvWriter::~CsvWriter() {
  for (File* file : {&bodies_, &cable_, &forces_, &status_, &environment_, &winch_file_}) {
    if (file->f != nullptr) std::fclose(file->f);
  }
}

void CsvWriter::Open(File& file, const char* name, const char* header) {
  file.path = (std::filesystem::path(dir_) / name).string();
  file.f = std::fopen(file.path.c_str(), "w");
  if (file.f == nullptr) {
    throw std::runtime_error("cannot open '" + file.path +
                             "' for writing: " + std::strerror(errno));
  }
  std::fprintf(file.f, "%s\n", header);
  Check(file);
}

void CsvWriter::Check(const File& file) const {
  if (std::fflush(file.f) != 0 || std::ferror(file.f)) {
    throw OutputError("writing '" + file.path + "' failed: " + std::strerror(errno));
  }
}

void CsvWriter::Write(const core::Simulation& sim, const core::StepStatus& status, long wall_us) {
  if (bodies_.f == nullptr) throw std::runtime_error("CsvWriter::Write after Close");
  const core::Model& model = sim.model();
  const double t = sim.time();

  // bodies (spheres, then vehicles): origin in W, ZYX Euler angles of q_WB, body-frame twist
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const core::Vec3 p_WB = sim.body_position(b);
    const core::Vec3 rpy = core::EulerZYX(sim.body_attitude(b));
    const core::Vec6 nu = sim.body_twist(b);
    std::fprintf(bodies_.f, "%.9g,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                 t, CsvField(sim.body_name(b)).c_str(), p_WB.x(), p_WB.y(), p_WB.z(), rpy.x(),
                 rpy.y(), rpy.z(), nu(0), nu(1), nu(2), nu(3), nu(4), nu(5));
  }

  for (int i = 0; i < sim.num_nodes(); ++i) {
    const core::Vec3 r = sim.node_position(i);
    std::fprintf(cable_.f, "%.9g,%d,%.9g,%.9g,%.9g,%.9g\n", t, i, r.x(), r.y(), r.z(),
                 sim.node_tension(i));
  }

  // forces: the cable's force and moment on each body (body frame), then held supports (world)
  for (int b = 0; b < sim.num_bodies(); ++b) {
    core::Vec3 f, m;
    sim.body_cable_wrench(b, &f, &m);
    std::fprintf(forces_.f, "%.9g,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", t,
                 CsvField(sim.body_name(b)).c_str(), f.x(), f.y(), f.z(), m.x(), m.y(), m.z());
  }
  const core::CableEnd* ends[2] = {&model.cable.start, &model.cable.end};
  const char* end_names[2] = {"cable.start", "cable.end"};
  for (int e = 0; e < 2; ++e) {
    if (!IsHeldSupport(*ends[e])) continue;
    const core::Vec3 f = sim.end_force(e);
    std::fprintf(forces_.f, "%.9g,%s,%.9g,%.9g,%.9g,0,0,0\n", t, end_names[e], f.x(), f.y(), f.z());
  }

  std::fprintf(status_.f, "%.9g,%ld,%d,%.9g,%ld", t, sim.step_count(), status.iterations,
               status.residual, wall_us);
  if (winch_) std::fprintf(status_.f, ",%.9g", sim.cable_length());
  std::fprintf(status_.f, "\n");

  for (const File* file : {&bodies_, &cable_, &forces_, &status_}) Check(*file);
  if (environment_.f != nullptr) WriteEnvironment(sim);
  if (winch_file_.f != nullptr) {
    std::fprintf(winch_file_.f, "%.9g,%.9g,%.9g,%.9g,%d\n", t, sim.cable_length(), sim.winch_speed(),
                 sim.drum_tension(), sim.num_nodes());
    Check(winch_file_);
  }
}

void CsvWriter::WriteEnvironment(const core::Simulation& sim) {
  const double t = sim.time();
  for (int b = 0; b < sim.num_bodies(); ++b) {
    // no seabed: the altitude is NaN, written as an empty field (the files never hold NaN)
    const double altitude = sim.body_altitude(b);
    char altitude_field[32] = "";
    if (!std::isnan(altitude))
      std::snprintf(altitude_field, sizeof altitude_field, "%.9g", altitude);
    const core::Vec3 u = sim.water_velocity_at(b);
    std::fprintf(environment_.f, "%.9g,%s,%.9g,%s,%.9g,%.9g,%.9g,%.9g\n", t,
                 CsvField(sim.body_name(b)).c_str(), sim.surface_elevation_at(b), altitude_field,
                 sim.body_depth(b), u.x(), u.y(), u.z());
  }
  Check(environment_);
}

void CsvWriter::Close() {
  std::string error;
  for (File* file : {&bodies_, &cable_, &forces_, &status_, &environment_, &winch_file_}) {
    if (file->f == nullptr) continue;
    if (std::fclose(file->f) != 0 && error.empty()) {
      error = "closing '" + file->path + "' failed: " + std::strerror(errno);
    }
    file->f = nullptr;
  }
  if (!error.empty()) throw OutputError(error);
}

}  // namespace towsim::io
