#pragma once
// The immutable description of a scene, as the core sees it. Built and validated by
// scene/ (yaml -> Model); the core trusts it. SI units, world frame NED (z down).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/constants.h"
#include "core/current_field.h"
#include "core/hydrodynamics.h"
#include "core/publish_rates.h"
#include "core/seabed.h"
#include "core/sensor_model.h"
#include "core/vehicle_model.h"
#include "core/vessel.h"
#include "core/wave_field.h"
#include "core/winch.h"

namespace towsim::core {

using Vec3 = Eigen::Vector3d;

// the most steps a run may have (time.duration / time.step, --duration / time.step): a
// step count must fit a long and a simulated time must advance (t + h > t); 1e12 steps are
// 30 years of a 1 us step
inline constexpr double kMaxSteps = 1e12;

struct TimeSettings {
  double step = 0.01;         // fixed step h [s]
  double duration = 10.0;     // default run length [s]
  double output_rate = 10.0;  // CSV / publish rate [Hz]
};

struct Environment {
  double water_density = 1025.0;      // rho_w [kg/m^3]
  double dynamic_viscosity = 1.0e-3;  // mu [Pa s]
  double gravity = 9.81;              // g [m/s^2], acts along +z (NED)
  CurrentField current;               // U_W(z, t) [m/s] (current_field.h); default: none
  WaveField waves;                    // Airy waves (wave_field.h); default: calm
  Seabed seabed;                      // the bottom (seabed.h); default: none (bottomless)
};

// Each cable load can be switched off per scene (paper Eq. 15-23, Eq. 8 bending term).
struct CableLoads {
  bool gravity = true;     // Eq. 15
  bool buoyancy = true;    // Eq. 16
  bool drag = true;        // Eq. 17-21
  bool added_mass = true;  // Eq. 22-23
  bool bending = true;     // EI kappa^2 term of Eq. 8
};

enum class EndKind {
  kFree,     // no constraint
  kFixed,    // r = position (Eq. 24 against the ground)
  kDriven,   // r = position + velocity * t
  kSphere,   // r = p_WB + at_B on a sphere (Eq. 24)
  kVehicle,  // r = p_WB + R_WB * at_B on a 6-DOF vehicle (Eq. 24)
  kVessel,   // r = p_WB(t) + R_WB(t) * at_B on a vessel, its pose prescribed (vessel.h)
};

struct CableEnd {
  EndKind kind = EndKind::kFree;
  Vec3 position = Vec3::Zero();  // fixed point, or driven position at t = 0 [m]
  Vec3 velocity = Vec3::Zero();  // driven velocity [m/s]
  // clamped ends also hold the cable direction: r' x slope = 0 (cantilever roots).
  bool clamped = false;
  Vec3 slope = Vec3::UnitX();  // unit direction, used when clamped
  // index into Model::spheres (kSphere), Model::vehicles (kVehicle) or Model::vessels (kVessel)
  int body = -1;
  Vec3 at_B = Vec3::Zero();    // attachment point in the body frame [m]
};

enum class InitialShape {
  kVertical,  // hanging straight down (+z) from the start end
  kStraight,  // straight line from the start end to the end's position
  kStatic,    // static equilibrium solved before t = 0
};

// The added-mass coefficients of a cable on its displaced mass rho_w A (docs/physics.md
// "Added mass"): normal (Eq. 23 has C_an = 1) and tangential (MoorDyn's CaAx; 0: none).
struct AddedMassCoefficients {
  double normal = 1.0;      // C_an
  double tangential = 0.0;  // C_at
};

struct CableParams {
  // the cable's name (docs/scene_format.md "Networks"): `cable` for the one-cable form, the
  // key of `cables:` otherwise; it names the cable's topic, CSV file and rows
  std::string name = "cable";
  // unstretched length L [m]; with a winch the initial paid-out length
  double length = 200.0;
  int elements = 20;  // number of ANCF elements
  // the line type (docs/scene_format.md "Line types"); the defaults: the paper's cable, a solid
  // section of d = 0.041 m, rho_c = 1300 kg/m^3, E = 7e8 Pa
  // hydrodynamic (volume-equivalent) diameter d: buoyancy rho_w A g, drag, added mass [m]
  double diameter = 0.041;
  double mass_per_length = 1300.0 * (0.25 * kPi * 0.041 * 0.041);                   // m [kg/m]
  double axial_stiffness = 7.0e8 * (0.25 * kPi * 0.041 * 0.041);                    // EA [N]
  double bending_stiffness = 7.0e8 * (kPi * 0.041 * 0.041 * 0.041 * 0.041 / 64.0);  // EI [N m^2]
  double axial_damping = 0.0;  // c in N = EA (eps + c deps/dt) [s]
  CableDragLaw drag;           // Choo & Casarella (default) or constant C_n, C_t
  AddedMassCoefficients added_mass;
  CableLoads loads;
  InitialShape initial = InitialShape::kVertical;
  // velocity of every node at t = 0; for kStatic, the static shape is solved in the frame
  // moving at this velocity (steady towing) [m/s]
  Vec3 initial_velocity = Vec3::Zero();
  CableEnd start;
  CableEnd end;
  // the winch at the start (winch.h, docs/winch.md); absent: the length is fixed
  std::optional<WinchParams> winch;

  // the circular section of diameter d: A = pi d^2 / 4, I = pi d^4 / 64
  double area() const { return 0.25 * kPi * diameter * diameter; }
  double second_moment() const { return kPi * diameter * diameter * diameter * diameter / 64.0; }
  // a solid section of density rho_c [kg/m^3] and Young's modulus E [Pa]: m = rho_c A,
  // EA = E A, EI = E I (the scene keys density and youngs_modulus)
  void SetSolidSection(double density, double youngs_modulus) {
    mass_per_length = density * area();
    axial_stiffness = youngs_modulus * area();
    bending_stiffness = youngs_modulus * second_moment();
  }
};

// A point-mass body: translational dynamics with weight, buoyancy, quadratic drag and added
// mass. Its body frame stays aligned with the world frame.
struct SphereBody {
  std::string name;
  double mass = 1.0;                    // m [kg]
  double volume = 0.0;                  // displaced volume V [m^3]
  double drag_coefficient = 0.5;        // C_D on the frontal area pi r^2, r = (3V/4pi)^(1/3)
  double added_mass_coefficient = 0.5;  // C_a, added mass = C_a rho_w V
  Vec3 position = Vec3::Zero();         // initial p_WB [m]
  Vec3 velocity = Vec3::Zero();         // initial v_WB [m/s]
};

enum class Scheme {
  kGeneralizedAlpha,  // Chung & Hulbert with rho_inf
  kTrapezoidal,       // Newmark average acceleration (= generalized-alpha, rho_inf = 1)
};

// How 6-DOF vehicles and the cable are coupled within a step (vehicle_coupling.h):
//   kStaggered: the paper's Fig. 7: vehicles advance with the previous step's joint force, then
//               the cable with the vehicles' attachment points as boundary conditions;
//   kStrong:    the same two solves iterated to convergence of the joint force within the step.
enum class Coupling { kStrong, kStaggered };

struct IntegratorSettings {
  Scheme scheme = Scheme::kGeneralizedAlpha;
  double rho_inf = 0.8;  // spectral radius at infinite frequency, [0, 1]
  Coupling coupling = Coupling::kStrong;
  // Newton (newton_convergence.h): the increment bound, relative to the longest cable, and the
  // force residual bound, relative to the largest joint force; the defaults are the measured
  // pair that keeps the solver error within 10 % of the discretisation error on every shipped
  // scene with no scene taking more Newton iterations than the increment test alone at 1e-8
  // (docs/benchmarks.md, "Newton tolerance against discretisation error")
  double tolerance = 1.0e-7;
  double force_tolerance = 3.0e-4;
  int max_iterations = 20;    // Newton iterations per (sub)step
  int max_substep_level = 6;  // halve the step at most this many times (2^6 substeps)
  int max_coupling_iterations = 30;  // kStrong: joint-force iterations per step
  // resample the waves at every Newton iteration instead of once per step (integrator.h; for
  // accuracy checks)
  bool waves_per_iteration = false;
};

// A 6-DOF vehicle of the scene (its model from config/vehicles/*.yaml).
struct Vehicle {
  std::string name;
  VehicleParams params;
  Vec3 position = Vec3::Zero();  // initial p_WB (body origin) [m]
  Vec3 euler = Vec3::Zero();     // initial roll, pitch, yaw (ZYX) [rad]
  Vec6 nu = Vec6::Zero();        // initial [u v w p q r] in the body frame
  VehicleCommand command;        // command held from t = 0 until the script or a controller
};

// Condition of a script entry: <vehicle>.<quantity> <op> <value>, e.g. tow_vehicle.yaw_deg >= 170
struct ScriptCondition {
  enum Quantity { kX, kY, kZ, kRollDeg, kPitchDeg, kYawDeg, kU, kV, kW, kP, kQ, kR, kSpeed };
  enum Op { kGreaterEqual, kLessEqual, kGreater, kLess };
  int vehicle = -1;  // index into Model::vehicles
  Quantity quantity = kYawDeg;
  Op op = kGreaterEqual;
  double value = 0.0;  // in the quantity's unit (m, deg, m/s, rad/s)
};

// Scripted command (offline; controllers replace it on DDS). Fires once: at time `at`, or, when
// has_condition, the first step at which the condition holds (and t >= at). Only the given
// fields change the vehicle's command; set_winch replaces the winch's command.
struct ScriptEntry {
  double at = 0.0;  // [s]
  bool has_condition = false;
  ScriptCondition condition;
  std::string body;
  int vehicle = -1;  // index into Model::vehicles
  bool set_thrust = false, set_rudder = false, set_elevator = false;
  double thrust = 0.0;    // [N]
  double rudder = 0.0;    // [rad]
  double elevator = 0.0;  // [rad]
  bool set_winch = false;  // winch_speed or winch_length given (vehicle = -1 without a body)
  int winch_index = 0;     // the winch it commands (cable winch_index's; the entry's `winch:`)
  WinchCommand winch;
};

// What a DDS node publishes and when (docs/contract.md §3-4); plain scene data, unused offline.
struct Publishing {
  PublishRates rates;            // per-topic rates (core/publish_rates.h)
  double command_timeout = 0.5;  // failsafe after this much sim time without a command [s]
  // security.open_outputs: with DDS Security, participants without a certificate may read the
  // outputs (never command); docs/security.md
  bool open_outputs = false;
};

struct Model {
  std::string name;
  TimeSettings time;
  Environment environment;
  // the cables (docs/scene_format.md "Networks"): one for the one-cable form `cable:`, else
  // the entries of `cables:`; the winched cables come first, in the scene's order (their
  // drums' nodes are the ones that change, system.h; winch w is cable w's). Any number of
  // cable ends may hold the same sphere or vehicle.
  std::vector<CableParams> cables = std::vector<CableParams>(1);
  std::vector<SphereBody> spheres;  // 3-DOF point bodies, coupled in the cables' Newton solve
  std::vector<Vehicle> vehicles;   // 6-DOF vehicles, coupled by the `integrator.coupling` scheme
  std::vector<Vessel> vessels;     // kinematic 6-DOF bodies of prescribed motion (vessel.h)
  IntegratorSettings integrator;
  std::vector<ScriptEntry> script;
  Publishing publishing;
  // sensor errors by body (docs/sensors.md "Sensor models"): only the bodies whose scene entry
  // has `sensors`; none: every sensor perfect
  std::vector<BodySensors> sensors;
};

}  // namespace towsim::core
