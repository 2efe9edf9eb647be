// CsvWriter writes the four files of docs/contract.md §5 with exactly the documented headers and one row
// set per Write(): a row per body, per cable node, per body and held end, and a status row; and
// environment.csv (a row per body: the sea at the body) only for a scene with a sea.

#include "io/csv_writer.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/model.h"
#include "core/simulation.h"
#include "temp_dir.h"

namespace towsim::io {
namespace {

namespace fs = std::filesystem;

constexpr char kBodiesHeader[] = "t,body,x,y,z,roll,pitch,yaw,u,v,w,p,q,r";
constexpr char kCableHeader[] = "t,node,x,y,z,tension";
constexpr char kForcesHeader[] = "t,body,fx,fy,fz,mx,my,mz";
constexpr char kStatusHeader[] = "t,step,newton_iterations,residual,wall_us,cable_length";

// "%.9g" keeps 9 significant digits: values read back agree to ~1e-8 relative
constexpr double kPrintRelTol = 1e-8;
constexpr double kPrintAbsTol = 1e-9;

using test::TempDir;

using Rows = std::vector<std::vector<std::string>>;

// the whole file
std::string FileText(const fs::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// header line and the rows split at commas (the names used here hold none)
Rows ReadCsv(const fs::path& path, std::string* header) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::getline(in, *header);
  Rows rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.push_back("");
    rows.push_back(fields);
  }
  return rows;
}

// a 10 m, 2-element cable hanging from a fixed point with a sphere at its lower end
core::Model TinyModel() {
  core::Model model;
  model.name = "tiny";
  model.time.step = 0.01;
  model.time.duration = 0.1;
  model.cables[0].length = 10.0;
  model.cables[0].elements = 2;
  model.cables[0].initial = core::InitialShape::kVertical;
  model.cables[0].start.kind = core::EndKind::kFixed;
  model.cables[0].start.position = core::Vec3(0.0, 0.0, 0.0);
  model.cables[0].end.kind = core::EndKind::kSphere;
  model.cables[0].end.body = 0;
  model.cables[0].end.at_B = core::Vec3::Zero();
  core::SphereBody sphere;
  sphere.name = "ball";
  sphere.mass = 50.0;
  sphere.volume = 0.01;
  sphere.position = core::Vec3(0.0, 0.0, 10.0);
  model.spheres.push_back(sphere);
  return model;
}

void ExpectNear(const std::string& field, double expected, const std::string& what) {
  const double value = std::stod(field);
  EXPECT_NEAR(value, expected, kPrintAbsTol + kPrintRelTol * std::abs(expected)) << what;
}

TEST(CsvWriterTest, HeadersColumnsAndRowsFollowDesign) {
  TempDir tmp;
  const fs::path dir = tmp.path() / "nested" / "out";  // created by the writer
  const core::Model model = TinyModel();
  core::Simulation sim(model);

  CsvWriter csv(dir.string());
  csv.Write(sim, core::StepStatus{}, 0);
  const core::StepStatus status = sim.Step();
  ASSERT_TRUE(status.ok()) << status.message;
  csv.Write(sim, status, 1234);
  csv.Close();

  const int writes = 2;
  const int nodes = model.cables[0].elements + 1;
  std::string header;

  const Rows bodies = ReadCsv(dir / "bodies.csv", &header);
  EXPECT_EQ(header, kBodiesHeader);
  ASSERT_EQ(bodies.size(), static_cast<size_t>(writes));
  for (const auto& row : bodies) {
    ASSERT_EQ(row.size(), 14u);
    EXPECT_EQ(row[1], "ball");
    for (int c : {5, 6, 7, 11, 12, 13}) EXPECT_EQ(std::stod(row[c]), 0.0) << "column " << c;
  }
  EXPECT_EQ(std::stod(bodies[0][0]), 0.0);
  ExpectNear(bodies[1][0], sim.time(), "t");
  for (int k = 0; k < 3; ++k) {
    ExpectNear(bodies[1][2 + k], sim.body_position(0)[k], "body position");
    ExpectNear(bodies[1][8 + k], sim.body_velocity(0)[k], "body velocity");
  }

  const Rows cable = ReadCsv(dir / "cable.csv", &header);
  EXPECT_EQ(header, kCableHeader);
  ASSERT_EQ(cable.size(), static_cast<size_t>(writes * nodes));
  for (int w = 0; w < writes; ++w) {
    for (int i = 0; i < nodes; ++i) {
      const auto& row = cable[w * nodes + i];
      ASSERT_EQ(row.size(), 6u);
      EXPECT_EQ(row[1], std::to_string(i));
    }
  }
  for (int i = 0; i < nodes; ++i) {
    const auto& row = cable[nodes + i];
    for (int k = 0; k < 3; ++k) ExpectNear(row[2 + k], sim.node_position(i)[k], "node position");
    ExpectNear(row[5], sim.NodeTension(i), "tension");
  }

  // the sphere (attached at the end) and the fixed start support
  const Rows forces = ReadCsv(dir / "forces.csv", &header);
  EXPECT_EQ(header, kForcesHeader);
  ASSERT_EQ(forces.size(), static_cast<size_t>(writes * 2));
  for (int w = 0; w < writes; ++w) {
    EXPECT_EQ(forces[2 * w][1], "ball");
    EXPECT_EQ(forces[2 * w + 1][1], "cable.start");
  }
  for (const auto& row : forces) {
    ASSERT_EQ(row.size(), 8u);
    for (int c : {5, 6, 7}) EXPECT_EQ(std::stod(row[c]), 0.0) << "sphere moment column " << c;
  }
  for (int k = 0; k < 3; ++k) {
    ExpectNear(forces[2][2 + k], sim.BodyCableForce(0)[k], "force on the body");
    ExpectNear(forces[3][2 + k], sim.end_force(0)[k], "force on the start support");
  }

  const Rows status_rows = ReadCsv(dir / "status.csv", &header);
  EXPECT_EQ(header, kStatusHeader);
  ASSERT_EQ(status_rows.size(), static_cast<size_t>(writes));
  for (const auto& row : status_rows) ASSERT_EQ(row.size(), 6u);
  EXPECT_EQ(status_rows[0][1], "0");
  EXPECT_EQ(status_rows[0][4], "0");
  EXPECT_EQ(status_rows[1][1], "1");
  EXPECT_EQ(status_rows[1][2], std::to_string(status.iterations));
  EXPECT_EQ(status_rows[1][4], "1234");
  // no winch: the paid-out length is the scene's cable.length at every row (docs/winch.md)
  for (const auto& row : status_rows) EXPECT_EQ(std::stod(row[5]), model.cables[0].length);
}

// a 6-DOF vehicle (turned and pitched) holds the cable's start; the sphere hangs at its end
core::Model VehicleModel() {
  core::Model model = TinyModel();
  core::Vehicle boat;
  boat.name = "boat";
  core::VehicleParams& p = boat.params;
  p.source = "test";
  p.length = 2.0;
  p.mass = 100.0;
  p.inertia = core::Vec3(1.0, 10.0, 10.0);
  p.volume = 100.0 / 1025.0;
  p.added_mass.diagonal() << 5, 80, 80, 1, 9, 9;
  boat.position = core::Vec3(1.0, 2.0, 3.0);
  boat.euler = core::Vec3(0.0, 0.1, 0.5);  // pitch, yaw [rad]
  boat.nu << 1.0, 0.0, 0.0, 0.0, 0.0, 0.02;
  model.vehicles.push_back(boat);
  model.cables[0].start.kind = core::EndKind::kVehicle;
  model.cables[0].start.body = 0;
  model.cables[0].start.at_B = core::Vec3(-1.0, 0.0, 0.2);  // astern: the cable makes a moment
  const core::Vec3 top =
      boat.position + core::QuaternionFromEulerZYX(boat.euler) * model.cables[0].start.at_B;
  model.spheres[0].position = top + core::Vec3(0.0, 0.0, model.cables[0].length);
  return model;
}

// one actuators.csv row: t, the body, the command (thrust, rudder, elevator), the actuator states
// in VehicleActuator order, failsafe as 0 / 1; "%.9g" numbers, the name quoted if it must be
TEST(CsvWriterTest, WriteActuatorRowWritesCommandStatesAndFailsafe) {
  TempDir tmp;
  const fs::path path = tmp.path() / "actuators.csv";
  core::VehicleCommand command;
  command.thrust = 4165.0;
  command.rudder = 0.349065850398866;  // 20 deg
  command.elevator = -0.1;
  core::VehicleState state;
  state.actuator[core::kThrust] = 1234.5;
  state.actuator[core::kRudder] = 0.0349065850398866;  // 2 deg, rate-limited on its way
  state.actuator[core::kElevator] = -0.0125;
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  WriteActuatorRow(f, 0.6, "tow_vehicle", command, state, false);
  WriteActuatorRow(f, 12.25, "fish, towed", core::VehicleCommand{}, core::VehicleState{}, true);
  std::fclose(f);
  EXPECT_EQ(FileText(path),
            "0.6,tow_vehicle,4165,0.34906585,-0.1,1234.5,0.034906585,-0.0125,0\n"
            "12.25,\"fish, towed\",0,0,0,0,0,0,1\n");
}

// one commands.csv row (towsim_export): t, the body, the step as an unsigned 64-bit integer,
// then thrust, rudder, elevator as sent (a NaN as nan)
TEST(CsvWriterTest, WriteCommandRowWritesTheRecordedCommand) {
  TempDir tmp;
  const fs::path path = tmp.path() / "commands.csv";
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  WriteCommandRow(f, 1.05, "tow_vehicle", 21, 4165.0, 0.1, -0.2);
  WriteCommandRow(f, 0.0, "towfish", 18446744073709551615ULL, 0.0,
                  std::numeric_limits<double>::quiet_NaN(), 1e-12);
  std::fclose(f);
  EXPECT_EQ(FileText(path),
            "1.05,tow_vehicle,21,4165,0.1,-0.2\n"
            "0,towfish,18446744073709551615,0,nan,1e-12\n");
}

// actuators.csv of a run: one row per vehicle per Write, the accessors' command and actuator
// states, the failsafe flag given per vehicle (none given: 0); only when asked for (vehicles)
TEST(CsvWriterTest, ActuatorRowsAreTheVehiclesCommandsAndStates) {
  TempDir tmp;
  const core::Model model = VehicleModel();
  core::Simulation sim(model);
  CsvWriter csv(tmp.path().string(), false, false, /*vehicles=*/true);
  csv.Write(sim, core::StepStatus{}, 0);
  core::VehicleCommand command;
  command.rudder = 0.2;
  command.elevator = -0.1;
  sim.SetVehicleCommand(0, command);
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(sim.Step().ok());
  csv.Write(sim, core::StepStatus{}, 0, {true});
  csv.Close();
  std::string header;
  const Rows rows = ReadCsv(tmp.path() / "actuators.csv", &header);
  EXPECT_EQ(header,
            "t,body,thrust_command,rudder_command,elevator_command,thrust,rudder,elevator,failsafe");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"0", "boat", "0", "0", "0", "0", "0", "0", "0"}));
  ASSERT_EQ(rows[1].size(), 9u);
  EXPECT_EQ(rows[1][1], "boat");
  ExpectNear(rows[1][0], sim.time(), "t");
  ExpectNear(rows[1][3], 0.2, "rudder_command");
  ExpectNear(rows[1][4], -0.1, "elevator_command");
  const core::VehicleState& s = sim.vehicle_state(0);
  ExpectNear(rows[1][6], s.actuator[core::kRudder], "rudder");
  ExpectNear(rows[1][7], s.actuator[core::kElevator], "elevator");
  // 0.05 s at the default fin rate limit (0.5236 rad/s): under way, not there
  EXPECT_GT(s.actuator[core::kRudder], 0.0);
  EXPECT_LE(s.actuator[core::kRudder], 0.5236 * 0.05 + 1e-12);
  EXPECT_EQ(rows[1][8], "1");

  // a scene without vehicles (not asked for): no actuators.csv
  TempDir plain;
  core::Simulation fixed(TinyModel());
  CsvWriter csv_plain(plain.path().string());
  csv_plain.Write(fixed, core::StepStatus{}, 0);
  csv_plain.Close();
  EXPECT_FALSE(fs::exists(plain.path() / "actuators.csv"));
}

// a scene with a winch: status.csv ends in the paid-out length (docs/winch.md)
TEST(CsvWriterTest, WinchSceneWritesTheCableLength) {
  TempDir tmp;
  core::Model model = TinyModel();
  // min_length, max_length [m], max_speed [m/s], max_acceleration [m/s^2]
  core::WinchParams w{5.0, 20.0, 1.0, 10.0};
  model.cables[0].winch = w;
  core::Simulation sim(model);
  sim.SetWinchCommand({core::WinchCommand::Mode::kSpeed, 1.0});
  CsvWriter csv(tmp.path().string(), false, true);
  csv.Write(sim, core::StepStatus{}, 0);
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(sim.Step().ok());
  csv.Write(sim, core::StepStatus{}, 0);
  csv.Close();
  std::string header;
  const Rows rows = ReadCsv(tmp.path() / "status.csv", &header);
  EXPECT_EQ(header, "t,step,newton_iterations,residual,wall_us,cable_length");
  ASSERT_EQ(rows.size(), 2u);
  ASSERT_EQ(rows[1].size(), 6u);
  EXPECT_EQ(std::stod(rows[0][5]), 10.0);
  ExpectNear(rows[1][5], sim.cable_length(), "cable_length");
  EXPECT_GT(sim.cable_length(), 10.0);  // it paid out
}

TEST(CsvWriterTest, VehicleRowsFollowTheSpheres) {
  TempDir tmp;
  const core::Model model = VehicleModel();
  core::Simulation sim(model);
  const core::StepStatus status = sim.Step();
  ASSERT_TRUE(status.ok()) << status.message;
  CsvWriter csv(tmp.path().string());
  csv.Write(sim, status, 0);
  csv.Close();

  // bodies: the sphere, then the vehicle with its attitude and body-frame twist
  std::string header;
  const Rows bodies = ReadCsv(tmp.path() / "bodies.csv", &header);
  ASSERT_EQ(bodies.size(), 2u);
  EXPECT_EQ(bodies[0][1], "ball");
  EXPECT_EQ(bodies[1][1], "boat");
  const int b = 1;  // the vehicle in the unified body order
  ASSERT_TRUE(sim.body_is_vehicle(b));
  const core::Vec3 p_WB = sim.body_position(b);
  const core::Vec3 rpy = core::EulerZYX(sim.body_attitude(b));
  const core::Vec6 nu = sim.body_twist(b);
  ASSERT_EQ(bodies[1].size(), 14u);
  for (int k = 0; k < 3; ++k) {
    ExpectNear(bodies[1][2 + k], p_WB[k], "vehicle position");
    ExpectNear(bodies[1][5 + k], rpy[k], "vehicle Euler angles");
  }
  for (int k = 0; k < 6; ++k) ExpectNear(bodies[1][8 + k], nu[k], "vehicle twist");
  // the attitude is the vehicle's own: close to the initial pitch and yaw after one step
  EXPECT_NEAR(std::stod(bodies[1][6]), 0.1, 0.01);
  EXPECT_NEAR(std::stod(bodies[1][7]), 0.5, 0.01);

  // forces: sphere and vehicle in body frames; no support row (both ends are on bodies)
  const Rows forces = ReadCsv(tmp.path() / "forces.csv", &header);
  ASSERT_EQ(forces.size(), 2u);
  EXPECT_EQ(forces[0][1], "ball");
  EXPECT_EQ(forces[1][1], "boat");
  core::Vec3 f_B, m_B;
  sim.BodyCableWrench(b, &f_B, &m_B);
  for (int k = 0; k < 3; ++k) {
    ExpectNear(forces[1][2 + k], f_B[k], "force on the vehicle");
    ExpectNear(forces[1][5 + k], m_B[k], "moment on the vehicle");
  }
  // the cable hangs off the stern: its moment about the origin is not zero
  EXPECT_GT(m_B.norm(), 1.0);
  for (int c : {5, 6, 7}) EXPECT_EQ(std::stod(forces[0][c]), 0.0) << "sphere moment column " << c;
}

TEST(CsvWriterTest, FreeEndHasNoSupportRow) {
  TempDir tmp;
  core::Model model = TinyModel();
  model.cables[0].end = core::CableEnd{};  // free; the sphere is not attached
  core::Simulation sim(model);
  CsvWriter csv(tmp.path().string());
  csv.Write(sim, core::StepStatus{}, 0);
  csv.Close();

  std::string header;
  const Rows forces = ReadCsv(tmp.path() / "forces.csv", &header);
  ASSERT_EQ(forces.size(), 2u);  // the (unattached) body, then the start support
  EXPECT_EQ(forces[0][1], "ball");
  EXPECT_EQ(forces[1][1], "cable.start");
  for (int c : {2, 3, 4}) EXPECT_EQ(std::stod(forces[0][c]), 0.0) << "unattached body";
}

TEST(CsvWriterTest, RowsAreOnDiskBeforeClose) {
  TempDir tmp;
  const core::Model model = TinyModel();
  core::Simulation sim(model);
  CsvWriter csv(tmp.path().string());
  csv.Write(sim, core::StepStatus{}, 0);
  // not closed: a killed process must still leave its rows behind
  std::string header;
  EXPECT_EQ(ReadCsv(tmp.path() / "status.csv", &header).size(), 1u);
  EXPECT_EQ(ReadCsv(tmp.path() / "cable.csv", &header).size(), 3u);
  csv.Close();
  EXPECT_THROW(csv.Write(sim, core::StepStatus{}, 0), std::runtime_error);
}

// Rows are written in whole row sets (csv_writer.h): the first Write's at once, the next ones
// when the flush period has passed, or at Close; never part of a row. A period of 0 writes
// every Write at once.
TEST(CsvWriterTest, RowsReachTheFilesInWholeRowSets) {
  TempDir tmp;
  const core::Model model = TinyModel();
  core::Simulation sim(model);
  std::string header;
  {
    CsvWriter held(tmp.path().string(), false, false, false, {"cable"}, {}, 1e9);  // no period
    held.Write(sim, core::StepStatus{}, 0);
    EXPECT_EQ(ReadCsv(tmp.path() / "status.csv", &header).size(), 1u);
    held.Write(sim, core::StepStatus{}, 0);
    // held: the files still end with the first row set's line break
    EXPECT_EQ(ReadCsv(tmp.path() / "status.csv", &header).size(), 1u);
    EXPECT_EQ(ReadCsv(tmp.path() / "cable.csv", &header).size(), 3u);
    EXPECT_EQ(FileText(tmp.path() / "cable.csv").back(), '\n');
    held.Close();
    EXPECT_EQ(ReadCsv(tmp.path() / "status.csv", &header).size(), 2u);
    EXPECT_EQ(ReadCsv(tmp.path() / "cable.csv", &header).size(), 6u);
  }
  {
    CsvWriter each(tmp.path().string(), false, false, false, {"cable"}, {}, 0.0);
    for (size_t k = 1; k <= 3; ++k) {
      each.Write(sim, core::StepStatus{}, 0);
      EXPECT_EQ(ReadCsv(tmp.path() / "status.csv", &header).size(), k);
    }
  }
  {
    // without a period the rows waiting are written once they pass kMaxPendingBytes
    CsvWriter held(tmp.path().string(), false, false, false, {"cable"}, {}, 1e9);
    held.Write(sim, core::StepStatus{}, 0);
    const size_t row_set = fs::file_size(tmp.path() / "cable.csv") +
                           fs::file_size(tmp.path() / "forces.csv") -
                           std::strlen(kCableHeader) - std::strlen(kForcesHeader) - 2;
    const size_t writes = CsvWriter::kMaxPendingBytes / row_set + 2;
    for (size_t k = 1; k < writes; ++k) held.Write(sim, core::StepStatus{}, 0);
    EXPECT_GT(ReadCsv(tmp.path() / "status.csv", &header).size(), 1u);
    EXPECT_EQ(FileText(tmp.path() / "status.csv").back(), '\n');
    held.Close();
    EXPECT_EQ(ReadCsv(tmp.path() / "status.csv", &header).size(), writes);
  }
  {
    // the destructor writes what it holds, as Close does
    CsvWriter held(tmp.path().string(), false, false, false, {"cable"}, {}, 1e9);
    held.Write(sim, core::StepStatus{}, 0);
    held.Write(sim, core::StepStatus{}, 0);
  }
  EXPECT_EQ(ReadCsv(tmp.path() / "status.csv", &header).size(), 2u);
}

TEST(CsvWriterTest, UncreatableDirectoryThrowsNamingIt) {
  TempDir tmp;
  const fs::path file = tmp.path() / "a_file";
  std::ofstream(file) << "x";
  const std::string dir = (file / "sub").string();  // below a regular file
  try {
    CsvWriter csv(dir);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(dir), std::string::npos) << e.what();
  }
}

// the sphere of TinyModel in a regular sea over a flat bed, in a uniform current
core::Model SeaModel() {
  core::Model model = TinyModel();
  core::Environment& env = model.environment;
  constexpr double kBedDepth = 30.0;
  env.seabed = core::Seabed::Flat(kBedDepth);
  env.current = core::CurrentField::Uniform(core::Vec3(0.5, -0.2, 0.0));
  // H 2 m, T 6 s (wavelength 56 m: the 10 m deep sphere sees orbital velocity e^{-kz} ~ 0.33)
  env.waves =
      core::WaveField::Regular(2.0, 6.0, 0.3, 0.4, kBedDepth, env.gravity, env.water_density);
  return model;
}

TEST(CsvWriterTest, EnvironmentRowsAreTheCoreAccessorsAtTheWrittenTimes) {
  TempDir tmp;
  const core::Model model = SeaModel();
  ASSERT_TRUE(HasSea(model.environment));
  core::Simulation sim(model);
  CsvWriter csv(tmp.path().string(), HasSea(model.environment));
  // what the accessors say at each written time: eta, altitude, depth, water velocity
  std::vector<std::vector<double>> expected;
  auto write = [&](const core::StepStatus& status) {
    csv.Write(sim, status, 0);
    const core::Vec3 u = sim.WaterVelocityAt(0);
    expected.push_back({sim.time(), sim.SurfaceElevationAt(0), sim.BodyAltitude(0),
                        sim.BodyDepth(0), u.x(), u.y(), u.z()});
  };
  write(core::StepStatus{});
  for (int k = 0; k < 10; ++k) {
    const core::StepStatus status = sim.Step();
    ASSERT_TRUE(status.ok()) << status.message;
    if (k % 3 == 2) write(status);
  }
  csv.Close();

  std::string header;
  const Rows rows = ReadCsv(tmp.path() / "environment.csv", &header);
  EXPECT_EQ(header, "t,body,wave_elevation,altitude,depth,current_u,current_v,current_w");
  ASSERT_EQ(rows.size(), expected.size());
  double max_eta = 0.0, max_orbital = 0.0;
  for (size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 8u) << "row " << i;
    EXPECT_EQ(rows[i][1], "ball");
    const std::vector<double>& e = expected[i];
    ExpectNear(rows[i][0], e[0], "t");
    for (int c = 1; c < 7; ++c) ExpectNear(rows[i][c + 1], e[c], "column " + std::to_string(c + 1));
    // independent of the accessors: the altitude is the bed depth minus z, the depth z + eta
    EXPECT_NEAR(e[2] + e[3] - e[1], 30.0, 1e-9) << "altitude + z = bed depth, row " << i;
    max_eta = std::max(max_eta, std::abs(e[1]));
    max_orbital =
        std::max(max_orbital, (core::Vec3(e[4], e[5], e[6]) - core::Vec3(0.5, -0.2, 0.0)).norm());
  }
  // the columns carry the sea, not zeros: a wave and its orbital velocity were there
  EXPECT_GT(max_eta, 0.1);
  EXPECT_GT(max_orbital, 0.01);
}

TEST(CsvWriterTest, NoSeabedLeavesTheAltitudeEmpty) {
  TempDir tmp;
  core::Model model = TinyModel();
  model.environment.current = core::CurrentField::Uniform(core::Vec3(1.0, 0.0, 0.0));
  ASSERT_TRUE(HasSea(model.environment));
  core::Simulation sim(model);
  CsvWriter csv(tmp.path().string(), HasSea(model.environment));
  csv.Write(sim, core::StepStatus{}, 0);
  csv.Close();
  std::string header;
  const Rows rows = ReadCsv(tmp.path() / "environment.csv", &header);
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0].size(), 8u);
  EXPECT_EQ(rows[0][3], "") << "no seabed: an empty altitude, never nan";
  ExpectNear(rows[0][2], 0.0, "calm surface");
  ExpectNear(rows[0][4], 10.0, "depth of the sphere");
  ExpectNear(rows[0][5], 1.0, "current_u");
}

TEST(CsvWriterTest, CalmSceneWritesNoEnvironmentFile) {
  TempDir tmp;
  const core::Model model = TinyModel();
  EXPECT_FALSE(HasSea(model.environment));
  core::Simulation sim(model);
  CsvWriter csv(tmp.path().string(), HasSea(model.environment));
  csv.Write(sim, core::StepStatus{}, 0);
  csv.Close();
  EXPECT_FALSE(fs::exists(tmp.path() / "environment.csv"));
  EXPECT_TRUE(fs::exists(tmp.path() / "status.csv"));
}

// AppendCsvNumber writes the bytes printf's "%.9g" writes (the reference: snprintf), for the
// edge cases and for 200 000 seeded random doubles: every bit pattern (subnormals, huge, NaN,
// infinities) and magnitudes a simulation writes (1e-12 to 1e12, both signs). Exact equality:
// the files must not change by a byte.
TEST(AppendCsvNumber, SameBytesAsPrintf) {
  auto printf_9g = [](double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", x);
    return std::string(text);
  };
  auto check = [&](double x) {
    std::string line = "prefix,";
    AppendCsvNumber(x, &line);
    ASSERT_EQ(line, "prefix," + printf_9g(x)) << "bits 0x" << std::hex << [&] {
      uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      return bits;
    }();
  };
  const double kInf = std::numeric_limits<double>::infinity();
  const double kNaN = std::numeric_limits<double>::quiet_NaN();
  // clang-format off
  const double kEdges[] = {0.0, -0.0, 1.0, -1.0, 0.1, 0.05, 100.0, 123456789.0, 1234567890.0,
                           1e9, 1e-5, 1e-4, 9.99999999e-5, 999999999.5, 0.000123456789, 5e-324,
                           2.2250738585072014e-308, 1.7976931348623157e308, kInf, -kInf, kNaN};
  // clang-format on
  for (double x : kEdges) check(x);
  std::mt19937_64 random(20261201);  // seeded: the same numbers every run
  std::uniform_real_distribution<double> exponent(-12.0, 12.0);
  for (int i = 0; i < 100000; ++i) {
    uint64_t bits = random();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    check(x);
    const double y = std::pow(10.0, exponent(random)) * ((random() & 1) ? 1.0 : -1.0);
    check(y);
  }
}

// The fast path of FormatCsvNumber (1e-14 <= |x| < 1e30) where it could go wrong, against
// snprintf's "%.9g": 10-digit ties (m + 1/2) 10^j and their neighbours (the exact value on
// the tie, just below and just above it), 9-digit values and their neighbours, the decades
// 10^j and the carries 999999999.5 10^j with their neighbours, and the output's own kind of
// values (multiples of the step and output interval, integers).
TEST(AppendCsvNumber, SameBytesAsPrintfAtTiesAndDecades) {
  auto same = [](double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", x);
    std::string line;
    AppendCsvNumber(x, &line);
    return line == text;
  };
  auto check = [&](double x) {
    for (double y : {x, std::nextafter(x, 0.0), std::nextafter(x, 1e300), -x}) {
      ASSERT_TRUE(same(y)) << std::hexfloat << y;
    }
  };
  std::mt19937_64 random(20261203);  // seeded: the same numbers every run
  for (int i = 0; i < 100000; ++i) {
    const int64_t m = 100000000 + static_cast<int64_t>(random() % 900000000);
    const int j = static_cast<int>(random() % 46) - 15;  // 10^-15 ... 10^30
    check((static_cast<double>(m) + 0.5) * std::pow(10.0, j - 9));
    check(static_cast<double>(m) * std::pow(10.0, j - 8));
  }
  for (int j = -16; j <= 32; ++j) {
    check(std::pow(10.0, j));
    check(999999999.5 * std::pow(10.0, j - 9));
    check(99999999.95 * std::pow(10.0, j - 8));
  }
  for (int i = 0; i < 100000; ++i) {
    check(i * 0.2);
    check(i * 0.05);
    check(i * 0.0125);
    check(static_cast<double>(i));
  }
}

}  // namespace
}  // namespace towsim::io

namespace towsim::io {
namespace {

TEST(CsvWriterTest, WinchRowsAreTheCoreAccessorsOnlyWithAWinch) {
  TempDir tmp;
  core::Model model = TinyModel();
  core::WinchParams w;
  w.min_length = 5.0;
  w.max_length = 20.0;
  w.max_speed = 1.0;
  w.max_acceleration = 0.5;
  model.cables[0].winch = w;
  core::Simulation sim(model);
  ASSERT_TRUE(sim.has_winch());
  sim.SetWinchCommand({core::WinchCommand::Mode::kSpeed, 0.5});
  CsvWriter csv(tmp.path().string(), false, /*winch=*/true);
  std::vector<std::vector<double>> expected;
  auto write = [&](const core::StepStatus& status) {
    csv.Write(sim, status, 0);
    expected.push_back({sim.time(), sim.cable_length(), sim.winch_speed(), sim.DrumTension(),
                        static_cast<double>(sim.num_nodes()), 0.0, 0.5, 0.0});
  };
  write(core::StepStatus{});
  for (int k = 0; k < 4; ++k) {
    const core::StepStatus status = sim.Step();
    ASSERT_TRUE(status.ok()) << status.message;
    write(status);
  }
  csv.Close();
  std::string header;
  const Rows rows = ReadCsv(tmp.path() / "winch.csv", &header);
  // the state's columns, then the command's appended (mode 0 speed, its value, no failsafe)
  EXPECT_EQ(header,
            "t,paid_out_length,winch_speed,drum_tension,node_count,command_mode,command_value,"
            "failsafe");
  ASSERT_EQ(rows.size(), expected.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 8u) << "row " << i;
    for (int c = 0; c < 4; ++c) ExpectNear(rows[i][c], expected[i][c], "column " + std::to_string(c));
    EXPECT_EQ(std::stoi(rows[i][4]), static_cast<int>(expected[i][4])) << "node_count, row " << i;
    EXPECT_EQ(rows[i][5], "0") << "command_mode, row " << i;
    EXPECT_EQ(rows[i][6], "0.5") << "command_value, row " << i;
    EXPECT_EQ(rows[i][7], "0") << "failsafe, row " << i;
  }
  // the drum's tension is the tension at node 0 (the accessors agree), the cable's weight
  // below it in this hanging cable: > 0
  EXPECT_GT(expected.back()[3], 0.0);

  // without a winch: no winch.csv
  TempDir plain;
  core::Simulation fixed(TinyModel());
  CsvWriter csv_plain(plain.path().string());
  csv_plain.Write(fixed, core::StepStatus{}, 0);
  csv_plain.Close();
  EXPECT_FALSE(std::filesystem::exists(plain.path() / "winch.csv"));
}

// two winches (docs/recording_formats.md): one <winch name>.csv each, its cable's drum and its
// own command, and the failsafe flag the caller gives per winch
TEST(CsvWriterTest, OneFilePerWinchWithItsOwnCommand) {
  TempDir tmp;
  core::Model model = TinyModel();
  core::WinchParams w;
  w.min_length = 5.0;
  w.max_length = 20.0;
  w.max_speed = 1.0;
  w.max_acceleration = 0.5;
  w.name = "port_winch";
  model.cables[0].winch = w;
  model.cables[0].name = "port";
  core::CableParams second = model.cables[0];
  second.name = "starboard";
  second.winch->name = "starboard_winch";
  second.start.position = core::Vec3(0.0, 5.0, 0.0);
  second.end.kind = core::EndKind::kFixed;
  second.end.position = core::Vec3(0.0, 5.0, 10.0);
  model.cables.push_back(second);
  core::Simulation sim(model);
  ASSERT_EQ(sim.num_winches(), 2);
  sim.SetWinchCommand({core::WinchCommand::Mode::kSpeed, 0.5}, 0);
  sim.SetWinchCommand({core::WinchCommand::Mode::kLength, 7.5}, 1);
  CsvWriter csv(tmp.path().string(), false, /*winch=*/true, false, {"port", "starboard"},
                {"port_winch", "starboard_winch"});
  csv.Write(sim, core::StepStatus{}, 0, {}, {false, true});
  for (int k = 0; k < 4; ++k) {
    ASSERT_TRUE(sim.Step().ok());
    csv.Write(sim, core::StepStatus{}, 0, {}, {false, true});
  }
  csv.Close();
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "winch.csv"));
  std::string header;
  const Rows port = ReadCsv(tmp.path() / "port_winch.csv", &header);
  EXPECT_EQ(header, kCsvWinchCommandHeader);
  const Rows star = ReadCsv(tmp.path() / "starboard_winch.csv", &header);
  EXPECT_EQ(header, kCsvWinchCommandHeader);
  ASSERT_EQ(port.size(), 5u);
  ASSERT_EQ(star.size(), 5u);
  // port pays out at 0.5 m/s^2 toward 0.5 m/s; starboard reels in toward 7.5 m
  ExpectNear(port.back()[1], sim.cable_length(0), "port length");
  ExpectNear(star.back()[1], sim.cable_length(1), "starboard length");
  EXPECT_GT(sim.cable_length(0), 10.0);
  EXPECT_LT(sim.cable_length(1), 10.0);
  EXPECT_EQ(port.back()[4], std::to_string(sim.num_nodes(0)));
  EXPECT_EQ(port.back()[5] + "," + port.back()[6] + "," + port.back()[7], "0,0.5,0");
  EXPECT_EQ(star.back()[5] + "," + star.back()[6] + "," + star.back()[7], "1,7.5,1");
}

}  // namespace
}  // namespace towsim::io
