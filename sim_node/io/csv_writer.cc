#include "io/csv_writer.h"

#include <cerrno>
#include <charconv>
#include <chrono>
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

// one row of a CSV file, appended to `rows` (a row built alone, or a file's pending rows):
// fields with their separating commas, numbers as "%.9g" formatted in place (io/csv_number.h)
class Row {
 public:
  explicit Row(TextBuffer* rows) : rows_(rows), start_(rows->size()) {}
  Row& Number(double x) {
    char* p = rows_->Reserve(kCsvNumberMaxChars + 1);
    if (rows_->size() > start_) *p++ = ',';
    rows_->Commit(FormatCsvNumber(x, p));
    return *this;
  }
  template <class Int>  // long, unsigned long long: in decimal
  Row& Integer(Int n) {
    constexpr int kMaxChars = 24;
    char* p = rows_->Reserve(kMaxChars + 1);
    if (rows_->size() > start_) *p++ = ',';
    rows_->Commit(std::to_chars(p, p + kMaxChars, n).ptr);
    return *this;
  }
  Row& Text(const std::string& text) {
    if (rows_->size() > start_) rows_->Push(',');
    rows_->Append(text.data(), text.size());
    return *this;
  }
  // ends the row with its line break
  void End() { rows_->Push('\n'); }
  // ends the row and writes the rows on `f` (errors: the caller's check)
  void WriteTo(std::FILE* f) {
    End();
    std::fwrite(rows_->data(), 1, rows_->size(), f);
  }

 private:
  TextBuffer* rows_;
  size_t start_;  // where this row begins in *rows_
};

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

namespace {

// the rows of WriteEnvironmentRow and WriteActuatorRow, appended to `rows`
void AppendEnvironmentRow(TextBuffer* rows, double t, const std::string& body,
                          double wave_elevation, double altitude, double depth, double u,
                          double v, double w) {
  Row row(rows);
  row.Number(t).Text(CsvField(body)).Number(wave_elevation);
  // no seabed: the altitude is NaN, written as an empty field (the files never hold NaN)
  if (std::isnan(altitude)) {
    row.Text("");
  } else {
    row.Number(altitude);
  }
  row.Number(depth).Number(u).Number(v).Number(w).End();
}

void AppendActuatorRow(TextBuffer* rows, double t, const std::string& body,
                       const core::VehicleCommand& command, const core::VehicleState& state,
                       bool failsafe) {
  Row(rows)
      .Number(t)
      .Text(CsvField(body))
      .Number(command.thrust)
      .Number(command.rudder)
      .Number(command.elevator)
      .Number(state.actuator[core::kThrust])
      .Number(state.actuator[core::kRudder])
      .Number(state.actuator[core::kElevator])
      .Integer(failsafe ? 1 : 0)
      .End();
}

}  // namespace

void WriteEnvironmentRow(std::FILE* f, double t, const std::string& body, double wave_elevation,
                         double altitude, double depth, double u, double v, double w) {
  TextBuffer line;
  AppendEnvironmentRow(&line, t, body, wave_elevation, altitude, depth, u, v, w);
  std::fwrite(line.data(), 1, line.size(), f);
}

void WriteActuatorRow(std::FILE* f, double t, const std::string& body,
                      const core::VehicleCommand& command, const core::VehicleState& state,
                      bool failsafe) {
  TextBuffer line;
  AppendActuatorRow(&line, t, body, command, state, failsafe);
  std::fwrite(line.data(), 1, line.size(), f);
}

void WriteCommandRow(std::FILE* f, double t, const std::string& body, unsigned long long step,
                     double thrust, double rudder, double elevator) {
  TextBuffer line;
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
                     const std::vector<std::string>& winches, double flush_period)
    : dir_(dir), winch_(winch), flush_period_(flush_period) {
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
    for (File* file : Files()) {
      if (file->f != nullptr) std::fclose(file->f);
      file->f = nullptr;
    }
    throw;
  }
}

CsvWriter::~CsvWriter() {
  // the rows not yet written, then close, ignoring errors (Close reports them)
  for (File* file : Files()) {
    if (file->f == nullptr) continue;
    if (!file->pending.empty())
      std::fwrite(file->pending.data(), 1, file->pending.size(), file->f);
    std::fclose(file->f);
  }
}

std::vector<CsvWriter::File*> CsvWriter::Files() {
  std::vector<File*> files = {&bodies_, &cable_, &forces_, &status_, &environment_, &actuators_};
  for (File& file : more_cables_) files.push_back(&file);
  for (File& file : winch_files_) files.push_back(&file);
  return files;
}

void CsvWriter::Open(File& file, const char* name, const char* header) {
  file.path = (std::filesystem::path(dir_) / name).string();
  file.f = std::fopen(file.path.c_str(), "w");
  if (file.f == nullptr) {
    throw std::runtime_error("cannot open '" + file.path +
                             "' for writing: " + std::strerror(errno));
  }
  std::fprintf(file.f, "%s\n", header);
  Flush(file);
}

void CsvWriter::Flush(File& file) {
  if (file.f == nullptr) return;
  const size_t size = file.pending.size();
  const bool ok = (size == 0 || std::fwrite(file.pending.data(), 1, size, file.f) == size) &&
                  std::fflush(file.f) == 0 && !std::ferror(file.f);
  file.pending.clear();  // written, or lost with the error that ends the run
  if (!ok) throw OutputError("writing '" + file.path + "' failed: " + std::strerror(errno));
}

void CsvWriter::FlushAll() {
  for (File* file : Files()) Flush(*file);
  last_flush_ = std::chrono::steady_clock::now();
  flushed_ = true;
}

void CsvWriter::Write(const core::Simulation& sim, const core::StepStatus& status, long wall_us,
                      const std::vector<bool>& failsafe,
                      const std::vector<bool>& winch_failsafe) {
  if (bodies_.f == nullptr) throw std::runtime_error("CsvWriter::Write after Close");
  const core::Model& model = sim.model();
  const double t = sim.time();
  if (body_fields_.size() != static_cast<size_t>(sim.num_bodies()) ||
      support_fields_.size() != 2 * model.cables.size()) {
    body_fields_.clear();
    for (int b = 0; b < sim.num_bodies(); ++b) body_fields_.push_back(CsvField(sim.body_name(b)));
    support_fields_.clear();
    for (const core::CableParams& cable : model.cables)
      for (const char* end : {".start", ".end"}) support_fields_.push_back(CsvField(cable.name + end));
  }

  // bodies (spheres, then vehicles): origin in W, ZYX Euler angles of q_WB, body-frame twist
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const core::Vec3 p_WB = sim.body_position(b);
    const core::Vec3 rpy = core::EulerZYX(sim.body_attitude(b));
    const core::Vec6 nu = sim.body_twist(b);
    Row row(&bodies_.pending);
    row.Number(t).Text(body_fields_[b]);
    for (int k = 0; k < 3; ++k) row.Number(p_WB(k));
    for (int k = 0; k < 3; ++k) row.Number(rpy(k));
    for (int k = 0; k < 6; ++k) row.Number(nu(k));
    row.End();
  }

  for (int c = 0; c < sim.num_cables(); ++c) {
    TextBuffer* rows = c == 0 ? &cable_.pending : &more_cables_[c - 1].pending;
    for (int i = 0; i < sim.num_nodes(c); ++i) {
      const core::Vec3 r = sim.node_position(i, c);
      Row(rows)
          .Number(t)
          .Integer(i)
          .Number(r.x())
          .Number(r.y())
          .Number(r.z())
          .Number(sim.NodeTension(i, c))
          .End();
    }
  }

  // forces: the cable's force and moment on each body (body frame), then held supports (world)
  for (int b = 0; b < sim.num_bodies(); ++b) {
    core::Vec3 f, m;
    sim.BodyCableWrench(b, &f, &m);
    Row row(&forces_.pending);
    row.Number(t).Text(body_fields_[b]);
    for (int k = 0; k < 3; ++k) row.Number(f(k));
    for (int k = 0; k < 3; ++k) row.Number(m(k));
    row.End();
    WriteAttachments(sim, b);
  }
  for (int c = 0; c < sim.num_cables(); ++c) {
    const core::CableParams& cable = model.cables[c];
    const core::CableEnd* ends[2] = {&cable.start, &cable.end};
    for (int e = 0; e < 2; ++e) {
      if (!IsHeldSupport(*ends[e])) continue;
      const core::Vec3 f = sim.end_force(e, c);
      Row(&forces_.pending)
          .Number(t)
          .Text(support_fields_[2 * c + e])
          .Number(f.x())
          .Number(f.y())
          .Number(f.z())
          .Text("0,0,0")
          .End();
    }
  }

  Row row(&status_.pending);
  row.Number(t)
      .Integer(sim.step_count())
      .Integer(status.iterations)
      .Number(status.residual)
      .Integer(wall_us);
  row.Number(sim.cable_length());
  row.End();

  if (environment_.f != nullptr) WriteEnvironment(sim);
  for (size_t w = 0; w < winch_files_.size(); ++w) {
    // winch w on cable w (core/model.h); its command appended (the header's order)
    const int c = static_cast<int>(w);
    const core::WinchCommand& command = sim.winch_command(c);
    const bool in_failsafe = w < winch_failsafe.size() && winch_failsafe[w];
    Row(&winch_files_[w].pending)
        .Number(t)
        .Number(sim.cable_length(c))
        .Number(sim.winch_speed(c))
        .Number(sim.DrumTension(c))
        .Integer(sim.num_nodes(c))
        .Integer(command.mode == core::WinchCommand::Mode::kLength ? 1 : 0)
        .Number(command.value)
        .Integer(in_failsafe ? 1 : 0)
        .End();
  }
  if (actuators_.f != nullptr) WriteActuators(sim, failsafe);

  // to the operating system in whole row sets: the first at once, then when flush_period of
  // wall time has passed or kMaxPendingBytes are waiting (csv_writer.h)
  if (!flushed_ || PendingBytes() >= kMaxPendingBytes ||
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_flush_).count() >=
          flush_period_) {
    FlushAll();
  }
}

size_t CsvWriter::PendingBytes() const {
  // the files that grow with the cable: the nodes' and the forces' (a row per end)
  size_t bytes = cable_.pending.size() + forces_.pending.size();
  for (const File& file : more_cables_) bytes += file.pending.size();
  return bytes;
}

void CsvWriter::WriteAttachments(const core::Simulation& sim, int b) {
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
      Row row(&forces_.pending);
      row.Number(sim.time()).Text(
          CsvField(sim.body_name(b) + "." + sim.cable_name(c) + "." + kEndNames[e]));
      for (int k = 0; k < 3; ++k) row.Number(f(k));
      for (int k = 0; k < 3; ++k) row.Number(m(k));
      row.End();
    }
}

void CsvWriter::WriteActuators(const core::Simulation& sim, const std::vector<bool>& failsafe) {
  const double t = sim.time();
  for (int v = 0; v < sim.num_vehicles(); ++v) {
    const bool in_failsafe = v < static_cast<int>(failsafe.size()) && failsafe[v];
    AppendActuatorRow(&actuators_.pending, t, sim.body_name(sim.num_spheres() + v),
                      sim.vehicle_command(v), sim.vehicle_state(v), in_failsafe);
  }
}

void CsvWriter::WriteEnvironment(const core::Simulation& sim) {
  const double t = sim.time();
  for (int b = 0; b < sim.num_bodies(); ++b) {
    const core::Vec3 u = sim.WaterVelocityAt(b);
    AppendEnvironmentRow(&environment_.pending, t, sim.body_name(b), sim.SurfaceElevationAt(b),
                         sim.BodyAltitude(b), sim.BodyDepth(b), u.x(), u.y(), u.z());
  }
}

void CsvWriter::Close() {
  std::string error;
  try {
    FlushAll();
  } catch (const OutputError& e) {
    error = e.what();
  }
  for (File* file : Files()) {
    if (file->f == nullptr) continue;
    if (std::fclose(file->f) != 0 && error.empty()) {
      error = "closing '" + file->path + "' failed: " + std::strerror(errno);
    }
    file->f = nullptr;
  }
  if (!error.empty()) throw OutputError(error);
}

}  // namespace towsim::io
