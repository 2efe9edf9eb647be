#include "io/csv_writer.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "core/model.h"
#include "core/system.h"
#include "io/output_error.h"

namespace towsim::io {
namespace {

// a cable end held by the ground or a kinematic driver carries a support reaction of its own
bool IsHeldSupport(const core::CableEnd& end) {
  return end.kind == core::EndKind::kFixed || end.kind == core::EndKind::kDriven;
}

// one row of a CSV file, built in memory and written in one call: fields appended with their
// separating commas, numbers as "%.9g"
class Row {
 public:
  explicit Row(std::string* line) : line_(line) { line_->clear(); }
  Row& Number(double x) {
    Comma();
    AppendCsvNumber(x, line_);
    return *this;
  }
  template <class Int>  // long, unsigned long long: in decimal
  Row& Integer(Int n) {
    Comma();
    char text[24];
    const std::to_chars_result r = std::to_chars(text, text + sizeof text, n);
    line_->append(text, r.ptr);
    return *this;
  }
  Row& Text(const std::string& text) {
    Comma();
    line_->append(text);
    return *this;
  }
  // the row and its line break, on `f` (errors: CsvWriter::Check)
  void WriteTo(std::FILE* f) {
    line_->push_back('\n');
    std::fwrite(line_->data(), 1, line_->size(), f);
  }

 private:
  void Comma() {
    if (!line_->empty()) line_->push_back(',');
  }
  std::string* line_;
};

}  // namespace

void AppendCsvNumber(double x, std::string* line) {
  // 9 significant digits need at most 16 characters ("-1.23456789e-308"); nan and inf fit too
  char text[32];
  const std::to_chars_result r =
      std::to_chars(text, text + sizeof text, x, std::chars_format::general, 9);
  line->append(text, r.ptr);
}

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

void WriteEnvironmentRow(std::FILE* f, double t, const std::string& body, double wave_elevation,
                         double altitude, double depth, double u, double v, double w) {
  std::string line;
  Row row(&line);
  row.Number(t).Text(CsvField(body)).Number(wave_elevation);
  // no seabed: the altitude is NaN, written as an empty field (the files never hold NaN)
  if (std::isnan(altitude)) {
    row.Text("");
  } else {
    row.Number(altitude);
  }
  row.Number(depth).Number(u).Number(v).Number(w).WriteTo(f);
}

void WriteActuatorRow(std::FILE* f, double t, const std::string& body,
                      const core::VehicleCommand& command, const core::VehicleState& state,
                      bool failsafe) {
  std::string line;
  Row(&line)
      .Number(t)
      .Text(CsvField(body))
      .Number(command.thrust)
      .Number(command.rudder)
      .Number(command.elevator)
      .Number(state.actuator[core::kThrust])
      .Number(state.actuator[core::kRudder])
      .Number(state.actuator[core::kElevator])
      .Integer(failsafe ? 1 : 0)
      .WriteTo(f);
}

void WriteCommandRow(std::FILE* f, double t, const std::string& body, unsigned long long step,
                     double thrust, double rudder, double elevator) {
  std::string line;
  Row(&line)
      .Number(t)
      .Text(CsvField(body))
      .Integer(step)
      .Number(thrust)
      .Number(rudder)
      .Number(elevator)
      .WriteTo(f);
}

CsvWriter::CsvWriter(const std::string& dir, bool sea, bool winch, bool vehicles,
                     const std::vector<std::string>& cables,
                     const std::vector<std::string>& winches)
    : dir_(dir), winch_(winch) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) {
    throw std::runtime_error("cannot create CSV directory '" + dir_ + "': " + ec.message());
  }
  try {
    Open(bodies_, "bodies.csv", kCsvBodiesHeader);
    Open(cable_, (cables.at(0) + ".csv").c_str(), kCsvCableHeader);
    more_cables_.resize(cables.size() - 1);
    for (size_t c = 1; c < cables.size(); ++c)
      Open(more_cables_[c - 1], (cables[c] + ".csv").c_str(), kCsvCableHeader);
    Open(forces_, "forces.csv", kCsvForcesHeader);
    Open(status_, "status.csv", kCsvStatusHeader);
    if (sea) Open(environment_, "environment.csv", kCsvEnvironmentHeader);
    if (winch) {
      const std::vector<std::string> names = winches.empty() ? std::vector<std::string>{"winch"}
                                                             : winches;
      winch_files_.resize(names.size());
      for (size_t w = 0; w < names.size(); ++w)
        Open(winch_files_[w], (names[w] + ".csv").c_str(), kCsvWinchCommandHeader);
    }
    if (vehicles) Open(actuators_, "actuators.csv", kCsvActuatorsHeader);
  } catch (...) {
    for (File* file :
         {&bodies_, &cable_, &forces_, &status_, &environment_, &actuators_}) {
      if (file->f != nullptr) std::fclose(file->f);
      file->f = nullptr;
    }
    for (File& file : winch_files_) {
      if (file.f != nullptr) std::fclose(file.f);
      file.f = nullptr;
    }
    for (File& file : more_cables_) {
      if (file.f != nullptr) std::fclose(file.f);
      file.f = nullptr;
    }
    throw;
  }
}

CsvWriter::~CsvWriter() {
  for (File* file :
       {&bodies_, &cable_, &forces_, &status_, &environment_, &actuators_}) {
    if (file->f != nullptr) std::fclose(file->f);
  }
  for (File& file : more_cables_)
    if (file.f != nullptr) std::fclose(file.f);
  for (File& file : winch_files_)
    if (file.f != nullptr) std::fclose(file.f);
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

void CsvWriter::Write(const core::Simulation& sim, const core::StepStatus& status, long wall_us,
                      const std::vector<bool>& failsafe,
                      const std::vector<bool>& winch_failsafe) {
  if (bodies_.f == nullptr) throw std::runtime_error("CsvWriter::Write after Close");
  const core::Model& model = sim.model();
  const double t = sim.time();

  std::string line;  // one row, reused
  // bodies (spheres, then vehicles): origin in W, ZYX Euler angles of q_WB, body-frame twist
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const core::Vec3 p_WB = sim.body_position(b);
    const core::Vec3 rpy = core::EulerZYX(sim.body_attitude(b));
    const core::Vec6 nu = sim.body_twist(b);
    Row row(&line);
    row.Number(t).Text(CsvField(sim.body_name(b)));
    for (int k = 0; k < 3; ++k) row.Number(p_WB(k));
    for (int k = 0; k < 3; ++k) row.Number(rpy(k));
    for (int k = 0; k < 6; ++k) row.Number(nu(k));
    row.WriteTo(bodies_.f);
  }

  for (int c = 0; c < sim.num_cables(); ++c) {
    std::FILE* f = c == 0 ? cable_.f : more_cables_[c - 1].f;
    for (int i = 0; i < sim.num_nodes(c); ++i) {
      const core::Vec3 r = sim.node_position(i, c);
      Row(&line)
          .Number(t)
          .Integer(i)
          .Number(r.x())
          .Number(r.y())
          .Number(r.z())
          .Number(sim.NodeTension(i, c))
          .WriteTo(f);
    }
  }

  // forces: the cable's force and moment on each body (body frame), then held supports (world)
  for (int b = 0; b < sim.num_bodies(); ++b) {
    core::Vec3 f, m;
    sim.BodyCableWrench(b, &f, &m);
    Row row(&line);
    row.Number(t).Text(CsvField(sim.body_name(b)));
    for (int k = 0; k < 3; ++k) row.Number(f(k));
    for (int k = 0; k < 3; ++k) row.Number(m(k));
    row.WriteTo(forces_.f);
    WriteAttachments(sim, b, &line);
  }
  static const char* const kEndNames[2] = {"start", "end"};
  for (int c = 0; c < sim.num_cables(); ++c) {
    const core::CableParams& cable = model.cables[c];
    const core::CableEnd* ends[2] = {&cable.start, &cable.end};
    for (int e = 0; e < 2; ++e) {
      if (!IsHeldSupport(*ends[e])) continue;
      const core::Vec3 f = sim.end_force(e, c);
      Row(&line)
          .Number(t)
          .Text(CsvField(cable.name + "." + kEndNames[e]))
          .Number(f.x())
          .Number(f.y())
          .Number(f.z())
          .Text("0,0,0")
          .WriteTo(forces_.f);
    }
  }

  Row row(&line);
  row.Number(t)
      .Integer(sim.step_count())
      .Integer(status.iterations)
      .Number(status.residual)
      .Integer(wall_us);
  row.Number(sim.cable_length());
  row.WriteTo(status_.f);

  for (const File* file : {&bodies_, &cable_, &forces_, &status_}) Check(*file);
  for (const File& file : more_cables_) Check(file);
  if (environment_.f != nullptr) WriteEnvironment(sim);
  for (size_t w = 0; w < winch_files_.size(); ++w) {
    // winch w on cable w (core/model.h); its command appended (the header's order)
    const int c = static_cast<int>(w);
    const core::WinchCommand& command = sim.winch_command(c);
    const bool in_failsafe = w < winch_failsafe.size() && winch_failsafe[w];
    Row(&line)
        .Number(t)
        .Number(sim.cable_length(c))
        .Number(sim.winch_speed(c))
        .Number(sim.DrumTension(c))
        .Integer(sim.num_nodes(c))
        .Integer(command.mode == core::WinchCommand::Mode::kLength ? 1 : 0)
        .Number(command.value)
        .Integer(in_failsafe ? 1 : 0)
        .WriteTo(winch_files_[w].f);
    Check(winch_files_[w]);
  }
  if (actuators_.f != nullptr) WriteActuators(sim, failsafe);
}

void CsvWriter::WriteAttachments(const core::Simulation& sim, int b, std::string* line) {
  // a body held by two or more cable ends: each end's own force and moment (body frame)
  static const char* const kEndNames[2] = {"start", "end"};
  int held = 0;
  for (int c = 0; c < sim.num_cables(); ++c)
    for (int e = 0; e < 2; ++e) held += sim.EndBody(e, c) == b;
  if (held < 2) return;
  const Eigen::Quaterniond q = sim.body_attitude(b);
  for (int c = 0; c < sim.num_cables(); ++c)
    for (int e = 0; e < 2; ++e) {
      if (sim.EndBody(e, c) != b) continue;
      const core::Vec3 f = q.conjugate() * sim.end_force(e, c);
      const core::Vec3 m = !sim.body_is_sphere(b)
                               ? core::Vec3(sim.system().End(e, c).at_B.cross(f))
                               : core::Vec3::Zero();
      Row row(line);
      row.Number(sim.time()).Text(
          CsvField(sim.body_name(b) + "." + sim.cable_name(c) + "." + kEndNames[e]));
      for (int k = 0; k < 3; ++k) row.Number(f(k));
      for (int k = 0; k < 3; ++k) row.Number(m(k));
      row.WriteTo(forces_.f);
    }
}

void CsvWriter::WriteActuators(const core::Simulation& sim, const std::vector<bool>& failsafe) {
  const double t = sim.time();
  for (int v = 0; v < sim.num_vehicles(); ++v) {
    const bool in_failsafe = v < static_cast<int>(failsafe.size()) && failsafe[v];
    WriteActuatorRow(actuators_.f, t, sim.body_name(sim.num_spheres() + v), sim.vehicle_command(v),
                     sim.vehicle_state(v), in_failsafe);
  }
  Check(actuators_);
}

void CsvWriter::WriteEnvironment(const core::Simulation& sim) {
  const double t = sim.time();
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const core::Vec3 u = sim.WaterVelocityAt(b);
    WriteEnvironmentRow(environment_.f, t, sim.body_name(b), sim.SurfaceElevationAt(b),
                        sim.BodyAltitude(b), sim.BodyDepth(b), u.x(), u.y(), u.z());
  }
  Check(environment_);
}

void CsvWriter::Close() {
  std::string error;
  std::vector<File*> files = {&bodies_,     &cable_, &forces_, &status_,
                              &environment_, &actuators_};
  for (File& file : more_cables_) files.push_back(&file);
  for (File& file : winch_files_) files.push_back(&file);
  for (File* file : files) {
    if (file->f == nullptr) continue;
    if (std::fclose(file->f) != 0 && error.empty()) {
      error = "closing '" + file->path + "' failed: " + std::strerror(errno);
    }
    file->f = nullptr;
  }
  if (!error.empty()) throw OutputError(error);
}

}  // namespace towsim::io
