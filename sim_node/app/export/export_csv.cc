#include "app/export/export_csv.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include "core/vehicle_model.h"
#include "io/cdr_messages.h"
#include "io/cdr_reader.h"
#include "io/csv_writer.h"
#include "io/mcap_reader.h"

namespace towsim::app {
namespace {

using io::cdr::ActuatorCommand;
using io::cdr::ActuatorState;
using io::cdr::BodyEnvironment;
using io::cdr::CableState;
using io::cdr::Odometry;
using io::cdr::WrenchStamped;

std::int64_t StampNs(const io::cdr::Time& t) {
  return static_cast<std::int64_t>(t.sec) * 1'000'000'000 + t.nanosec;
}

// what the node published at one time stamp
struct Frame {
  std::map<std::string, Odometry> odom;         // by body
  std::map<std::string, WrenchStamped> forces;  // by body
  std::map<std::string, BodyEnvironment> environment;  // by body
  std::map<std::string, ActuatorState> actuators;      // by body
  std::map<std::string, CableState> cables;            // by cable
  // the held ends' forces (<c>/start_force, <c>/end_force) by cable and end (0, 1)
  std::map<std::pair<std::string, int>, WrenchStamped> end_forces;
};

class CsvFile {
 public:
  CsvFile(const std::filesystem::path& path, const char* header) : path_(path.string()) {
    f_ = std::fopen(path_.c_str(), "w");
    if (f_ == nullptr) {
      throw std::runtime_error("cannot open '" + path_ + "' for writing: " + std::strerror(errno));
    }
    std::fprintf(f_, "%s\n", header);
  }
  ~CsvFile() {
    if (f_ != nullptr) std::fclose(f_);
  }
  std::FILE* get() { return f_; }
  void Close() {
    const bool failed = std::ferror(f_) != 0;
    const int rc = std::fclose(f_);
    f_ = nullptr;
    if (failed || rc != 0) {
      throw std::runtime_error("writing '" + path_ + "' failed: " + std::strerror(errno));
    }
  }

 private:
  std::string path_;
  std::FILE* f_ = nullptr;
};

}  // namespace

ExportCounts ExportCsv(const std::string& mcap_path, const std::string& dir, const std::string& ns,
                       bool recover) {
  return ExportCsv(recover ? io::McapReader::Recover(mcap_path) : io::McapReader::Open(mcap_path),
                   dir, ns);
}

ExportCounts ExportCsv(const io::McapReader& reader, const std::string& dir,
                       const std::string& ns) {
  // the channels of the node under `ns`, by what they carry
  enum class Kind {
    kOdom,
    kForce,
    kEnvironment,
    kCable,
    kEndForce,
    kStatus,
    kSceneInfo,
    kCommand,
    kActuatorState
  };
  struct Route {
    Kind kind;
    std::string body;  // kOdom, kForce, kEnvironment, kCommand, kActuatorState; the cable's
                       // name for kCable
                       // and kEndForce
    int end = 0;       // kEndForce: 0 start, 1 end
  };
  bool sea = false;  // environment topics: environment.csv is written
  bool actuators = false;  // actuator_state topics: actuators.csv is written
  std::map<std::uint16_t, Route> routes;
  std::vector<std::string> channel_bodies;  // bodies in channel order (fallback order)
  std::vector<std::string> channel_cables;  // cables in channel order (fallback order)
  std::string all_topics;
  const std::string prefix = ns == "/" ? "/" : ns + "/";
  for (const auto& [id, channel] : reader.channels()) {
    all_topics += (all_topics.empty() ? "" : ", ") + channel.topic;
    const auto schema = reader.schemas().find(channel.schema_id);
    const std::string type = schema == reader.schemas().end() ? "" : schema->second.name;
    if (channel.topic.rfind(prefix, 0) != 0) continue;
    const std::string rest = channel.topic.substr(prefix.size());
    auto expect = [&](const char* wanted) {
      if (type != wanted || channel.message_encoding != "cdr") {
        throw std::invalid_argument("topic " + channel.topic + " has type '" + type +
                                    "' and encoding '" + channel.message_encoding + "', expected " +
                                    wanted + " in cdr");
      }
    };
    const auto slash = rest.find('/');
    if (rest == "cable/state" ||
        (slash != std::string::npos && rest.substr(slash) == "/state" &&
         type == "towsim_msgs/msg/CableState")) {
      // rt/<ns>/<cable>/state: the one cable's ("cable") or a network's cables
      expect("towsim_msgs/msg/CableState");
      routes[id] = {Kind::kCable, rest.substr(0, slash)};
      channel_cables.push_back(rest.substr(0, slash));
    } else if (slash != std::string::npos &&
               (rest.substr(slash) == "/start_force" || rest.substr(slash) == "/end_force")) {
      // rt/<ns>/<cable>/start_force, end_force: a held end's force (forces.csv's dotted rows)
      expect("geometry_msgs/msg/WrenchStamped");
      routes[id] = {Kind::kEndForce, rest.substr(0, slash), rest.substr(slash) == "/end_force"};
    } else if (rest == "status") {
      expect("towsim_msgs/msg/SimStatus");
      routes[id] = {Kind::kStatus, ""};
    } else if (rest == "scene_info") {
      expect("towsim_msgs/msg/SceneInfo");
      routes[id] = {Kind::kSceneInfo, ""};
    } else if (slash != std::string::npos && rest.substr(slash) == "/odom") {
      expect("nav_msgs/msg/Odometry");
      routes[id] = {Kind::kOdom, rest.substr(0, slash)};
      channel_bodies.push_back(rest.substr(0, slash));
    } else if (slash != std::string::npos && rest.substr(slash) == "/cable_force") {
      expect("geometry_msgs/msg/WrenchStamped");
      routes[id] = {Kind::kForce, rest.substr(0, slash)};
    } else if (slash != std::string::npos && rest.substr(slash) == "/environment") {
      expect("towsim_msgs/msg/BodyEnvironment");
      routes[id] = {Kind::kEnvironment, rest.substr(0, slash)};
      sea = true;
    } else if (slash != std::string::npos && rest.substr(slash) == "/actuator_state") {
      expect("towsim_msgs/msg/ActuatorState");
      routes[id] = {Kind::kActuatorState, rest.substr(0, slash)};
      actuators = true;
    } else if (slash != std::string::npos && rest.substr(slash) == "/command" &&
               type == "towsim_msgs/msg/ActuatorCommand" && channel.message_encoding == "cdr") {
      // a vehicle's commands (the winch's, towsim_msgs/WinchCommand, are not exported)
      routes[id] = {Kind::kCommand, rest.substr(0, slash)};
    }
  }
  if (routes.empty()) {
    throw std::invalid_argument(
        "no towsim topics under the namespace '" + ns +
        "' in the recording (topics: " + (all_topics.empty() ? "none" : all_topics) + ")");
  }

  // decode every message of those channels, in log-time order
  std::map<std::int64_t, Frame> frames;              // by stamp [ns]
  std::map<std::int64_t, double> sim_time_of_stamp;  // from the status messages
  std::vector<io::cdr::SimStatus> statuses;
  std::optional<std::vector<std::string>> scene_bodies;
  std::vector<std::string> scene_cables;  // SceneInfo.cables (empty from an earlier towsim)
  bool has_winch = false;  // the scene info says so: winch.csv, as the node writes it
  std::vector<std::pair<std::string, ActuatorCommand>> commands;  // (body, command), recorded order
  std::uint64_t index = 0;
  reader.ForEachMessage([&](const io::McapMessage& m) {
    ++index;
    const auto route = routes.find(m.channel_id);
    if (route == routes.end()) return;
    const std::uint8_t* p = m.data.data();
    const std::size_t n = m.data.size();
    try {
      switch (route->second.kind) {
        case Kind::kOdom: {
          Odometry o = io::cdr::DecodeOdometry(p, n);
          frames[StampNs(o.header.stamp)].odom[route->second.body] = std::move(o);
          break;
        }
        case Kind::kForce: {
          WrenchStamped w = io::cdr::DecodeWrenchStamped(p, n);
          frames[StampNs(w.header.stamp)].forces[route->second.body] = std::move(w);
          break;
        }
        case Kind::kEnvironment: {
          BodyEnvironment e = io::cdr::DecodeBodyEnvironment(p, n);
          frames[StampNs(e.header.stamp)].environment[route->second.body] = std::move(e);
          break;
        }
        case Kind::kCable: {
          CableState c = io::cdr::DecodeCableState(p, n);
          const std::int64_t stamp = StampNs(c.header.stamp);
          frames[stamp].cables[route->second.body] = std::move(c);
          break;
        }
        case Kind::kEndForce: {
          WrenchStamped w = io::cdr::DecodeWrenchStamped(p, n);
          frames[StampNs(w.header.stamp)].end_forces[{route->second.body, route->second.end}] =
              std::move(w);
          break;
        }
        case Kind::kStatus: {
          io::cdr::SimStatus s = io::cdr::DecodeSimStatus(p, n);
          sim_time_of_stamp[StampNs(s.header.stamp)] = s.sim_time;
          // the node repeats the last step's status with the final state: one row per step
          if (!statuses.empty() && statuses.back().step == s.step &&
              statuses.back().run_id == s.run_id) {
            break;
          }
          statuses.push_back(std::move(s));
          break;
        }
        case Kind::kActuatorState: {
          ActuatorState a = io::cdr::DecodeActuatorState(p, n);
          // the first message of a stamp: the one published with the step, whose values the
          // node's actuators.csv row has (a lockstep wait republishes the step later)
          frames[StampNs(a.header.stamp)].actuators.emplace(route->second.body, std::move(a));
          break;
        }
        case Kind::kCommand:
          commands.emplace_back(route->second.body, io::cdr::DecodeActuatorCommand(p, n));
          break;
        case Kind::kSceneInfo:
          if (!scene_bodies) {
            io::cdr::SceneInfo info = io::cdr::DecodeSceneInfo(p, n);
            scene_bodies = std::move(info.bodies);
            scene_cables = std::move(info.cables);
            has_winch = info.has_winch;
          }
          break;
      }
    } catch (const io::cdr::CdrError& e) {
      throw io::cdr::CdrError("message " + std::to_string(index) + " on " +
                                  reader.channels().at(m.channel_id).topic + " (log time " +
                                  std::to_string(m.log_time) + " ns): " + e.what(),
                              e.offset());
    }
  });

  // row order of the bodies: the node's (scene info), then any other recorded body
  std::vector<std::string> bodies = scene_bodies.value_or(std::vector<std::string>{});
  for (const std::string& b : channel_bodies) {
    if (std::find(bodies.begin(), bodies.end(), b) == bodies.end()) bodies.push_back(b);
  }

  // the cables: the node's order (scene info), then any other recorded cable; the first one
  // has the winch and gives status.csv its cable_length (as io/csv_writer.h)
  std::vector<std::string> cables = scene_cables;
  for (const std::string& c : channel_cables) {
    if (std::find(cables.begin(), cables.end(), c) == cables.end()) cables.push_back(c);
  }
  if (cables.empty()) cables.push_back("cable");
  const std::string& first_cable = cables.front();

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create CSV directory '" + dir + "': " + ec.message());
  const std::filesystem::path d(dir);
  CsvFile bodies_csv(d / "bodies.csv", io::kCsvBodiesHeader);
  // <cable>.csv per cable (cable.csv for the one cable)
  std::map<std::string, std::unique_ptr<CsvFile>> cable_csv;
  for (const std::string& c : cables) {
    cable_csv[c] = std::make_unique<CsvFile>(d / (c + ".csv"), io::kCsvCableHeader);
  }
  CsvFile forces_csv(d / "forces.csv", io::kCsvForcesHeader);
  std::optional<CsvFile> environment_csv;  // as the node: only for a scene with a sea
  if (sea) environment_csv.emplace(d / "environment.csv", io::kCsvEnvironmentHeader);
  CsvFile status_csv(d / "status.csv", io::kCsvStatusHeader);
  std::optional<CsvFile> actuators_csv;  // a recording of a node with commanded vehicles
  if (actuators) actuators_csv.emplace(d / "actuators.csv", io::kCsvActuatorsHeader);
  std::optional<CsvFile> winch_csv;
  if (has_winch) winch_csv.emplace(d / "winch.csv", io::kCsvWinchHeader);
  ExportCounts counts;
  if (!commands.empty()) {
    CsvFile commands_csv(d / "commands.csv", io::kCsvCommandsHeader);
    for (const auto& [body, c] : commands) {
      io::WriteCommandRow(commands_csv.get(), 1e-9 * static_cast<double>(StampNs(c.header.stamp)),
                          body, c.step, c.thrust, c.rudder, c.elevator);
    }
    commands_csv.Close();
    counts.commands_rows = commands.size();
  }

  for (const auto& [stamp, frame] : frames) {
    const auto exact = sim_time_of_stamp.find(stamp);
    const double t = exact != sim_time_of_stamp.end() ? exact->second : 1e-9 * stamp;
    for (const std::string& b : bodies) {
      const auto o = frame.odom.find(b);
      if (o == frame.odom.end()) continue;
      const Odometry& m = o->second;
      const Eigen::Quaterniond q_WB(m.orientation.w, m.orientation.x, m.orientation.y,
                                    m.orientation.z);
      const core::Vec3 rpy = core::EulerZYX(q_WB);
      std::fprintf(
          bodies_csv.get(), "%.9g,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
          t, io::CsvField(b).c_str(), m.position.x, m.position.y, m.position.z, rpy.x(), rpy.y(),
          rpy.z(), m.linear.x, m.linear.y, m.linear.z, m.angular.x, m.angular.y, m.angular.z);
      ++counts.bodies_rows;
    }
    for (const auto& [name, c] : frame.cables) {
      std::FILE* f = cable_csv.at(name)->get();
      for (std::size_t i = 0; i < c.positions.size(); ++i) {
        const double tension = i < c.tensions.size() ? c.tensions[i] : 0.0;
        std::fprintf(f, "%.9g,%zu,%.9g,%.9g,%.9g,%.9g\n", t, i, c.positions[i].x,
                     c.positions[i].y, c.positions[i].z, tension);
        ++counts.cable_rows;
      }
      if (winch_csv && name == first_cable) {
        std::fprintf(winch_csv->get(), "%.9g,%.9g,%.9g,%.9g,%u\n", t, c.paid_out_length,
                     c.winch_speed, c.drum_tension, static_cast<unsigned>(c.node_count));
        ++counts.winch_rows;
      }
    }
    // forces.csv in the node's order (io/csv_writer.h): each body's total, then its
    // attachments (the end forces in its frame <b>_frd, cables in order, start before end),
    // then the supports (the end forces in world_ned); the frames of docs/frames.md
    auto force_row = [&](const std::string& name, const WrenchStamped& m) {
      std::fprintf(forces_csv.get(), "%.9g,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", t,
                   io::CsvField(name).c_str(), m.force.x, m.force.y, m.force.z, m.torque.x,
                   m.torque.y, m.torque.z);
      ++counts.forces_rows;
    };
    static const char* const kEndNames[2] = {"start", "end"};
    for (const std::string& b : bodies) {
      const auto w = frame.forces.find(b);
      if (w == frame.forces.end()) continue;
      force_row(b, w->second);
      for (const std::string& c : cables) {
        for (int e = 0; e < 2; ++e) {
          const auto f = frame.end_forces.find({c, e});
          if (f == frame.end_forces.end() || f->second.header.frame_id != b + "_frd") continue;
          force_row(b + "." + c + "." + kEndNames[e], f->second);
        }
      }
    }
    for (const std::string& c : cables) {
      for (int e = 0; e < 2; ++e) {
        const auto f = frame.end_forces.find({c, e});
        if (f == frame.end_forces.end() || f->second.header.frame_id != "world_ned") continue;
        force_row(c + "." + kEndNames[e], f->second);
      }
    }
    for (const std::string& b : bodies) {
      const auto e = frame.environment.find(b);
      if (e == frame.environment.end()) continue;
      const BodyEnvironment& m = e->second;
      io::WriteEnvironmentRow(environment_csv->get(), t, b, m.wave_elevation, m.altitude, m.depth,
                              m.current.x, m.current.y, m.current.z);
      ++counts.environment_rows;
    }
    for (const std::string& b : bodies) {
      const auto a = frame.actuators.find(b);
      if (a == frame.actuators.end()) continue;
      const ActuatorState& m = a->second;
      core::VehicleCommand command;
      command.thrust = m.thrust_command;
      command.rudder = m.rudder_command;
      command.elevator = m.elevator_command;
      core::VehicleState state;
      state.actuator[core::kThrust] = m.thrust;
      state.actuator[core::kRudder] = m.rudder;
      state.actuator[core::kElevator] = m.elevator;
      io::WriteActuatorRow(actuators_csv->get(), t, b, command, state, m.failsafe);
      ++counts.actuators_rows;
    }
  }
  for (const io::cdr::SimStatus& s : statuses) {
    // the node's CSV: wall_us = lround(step wall time * 1e6), the same number it publishes
    std::fprintf(status_csv.get(), "%.9g,%llu,%d,%.9g,%ld", s.sim_time,
                 static_cast<unsigned long long>(s.step), s.newton_iterations, s.residual,
                 std::lround(s.step_wall_time * 1e6));
    // cable_length: the paid-out length of the newest cable state at or before this stamp
    // (the cable state comes at its own rate)
    double length = std::numeric_limits<double>::quiet_NaN();
    for (auto f = frames.upper_bound(StampNs(s.header.stamp)); f != frames.begin();) {
      --f;
      const auto c = f->second.cables.find(first_cable);
      if (c != f->second.cables.end()) {
        length = c->second.paid_out_length;
        break;
      }
    }
    std::fprintf(status_csv.get(), ",%.9g\n", length);
    ++counts.status_rows;
  }
  bodies_csv.Close();
  for (auto& [name, file] : cable_csv) file->Close();
  forces_csv.Close();
  status_csv.Close();
  if (environment_csv) environment_csv->Close();
  if (winch_csv) winch_csv->Close();
  if (actuators_csv) actuators_csv->Close();
  return counts;
}

}  // namespace towsim::app
