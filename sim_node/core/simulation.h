#pragma once
// The public face of the core: a Model in, a stepped State out. No I/O, no clocks.
//
//   Simulation sim(model);          // builds the initial state (solves statics if asked)
//   while (sim.time() < T) {
//     StepStatus s = sim.Step();    // one fixed step model.time.step
//     if (!s.ok()) { ... s.message ... }
//   }

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/fold_check.h"
#include "core/model.h"
#include "core/vehicle_model.h"
#include "core/vessel_motion.h"
#include "core/winch.h"

namespace towsim::core {

// Thrown when the initial state cannot be built (e.g. the static solve fails).
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Thrown when the caller's stop request ended the building of the initial state (the static
// solve asks it before every iteration).
class StopRequestedError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct StepStatus {
  enum Code { kOk, kNotConverged, kNonFinite };
  Code code = kOk;
  // Newton iterations summed over substeps, retries and vehicle-coupling passes: each is one
  // residual evaluation (System::Evaluate, with the Newton matrix when it is refreshed)
  int iterations = 0;
  int substeps = 1;       // 1 when the full step converged
  double residual = 0.0;  // final force residual, inf-norm [N]
  std::string message;    // diagnosis when !ok(): where and when
  bool ok() const { return code == kOk; }
};

class System;  // core/system.h
struct State;  // core/state.h

class Simulation {
 public:
  // throws SolverError, or StopRequestedError once `stop_requested` (if set) returns true
  explicit Simulation(const Model& model, const std::function<bool()>& stop_requested = {});
  ~Simulation();
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;

  // advance one fixed step h = model().time.step
  StepStatus Step();
  // advance one step of an arbitrary size (tests, convergence studies)
  StepStatus StepBy(double h);

  const Model& model() const;
  const System& system() const;
  const State& state() const;
  // the complete state (state.h): everything the next step depends on
  State GetState() const;
  // restores a state taken with GetState (of a Simulation of the same Model): stepping on
  // continues bit for bit as if the run had never stopped. Throws std::invalid_argument
  // naming the field if the state's shape does not fit this model (vector sizes, vehicles)
  void SetState(const State& state);
  // starts the run over from t, q, v and the vehicles of `state` (tests: perturbations): the
  // accelerations, multipliers and every history (coupling predictor, kept Newton matrix)
  // are recomputed or cleared so that the next step starts consistent; shape errors as
  // SetState
  void StartFrom(const State& state);
  int cable_dof(int node, int c = 0) const;  // offset of cable c's node's e = [r, r'] in q
  int sphere_dof(int sphere) const;  // offset of sphere's p_WB in q
  double time() const;
  long step_count() const;

  // --- outputs (world NED, SI) ---
  // the cables (Model::cables order; one: the scene's `cable`) and their names
  int num_cables() const;
  const std::string& cable_name(int c) const;
  // nodes of cable c in use now (elements in use + 1; with a winch it changes as the drum pays
  // out and reels in); node 0 is at the cable's start (the drum)
  int num_nodes(int c = 0) const;
  Vec3 node_position(int i, int c = 0) const;  // r at node i [m]
  Vec3 node_velocity(int i, int c = 0) const;  // dr/dt at node i [m/s]
  // axial force at node i [N]: the elements' average; |joint force| at a held end
  double NodeTension(int i, int c = 0) const;
  // bodies: the spheres (Model::spheres) first, then the vehicles (Model::vehicles), then the
  // vessels (Model::vessels)
  int num_bodies() const;
  int num_spheres() const;
  int num_vehicles() const;
  int num_vessels() const;
  const std::string& body_name(int b) const;
  bool body_is_sphere(int b) const;
  bool body_is_vehicle(int b) const;
  bool body_is_vessel(int b) const;
  Vec3 body_position(int b) const;                // p_WB (vehicles: the body origin) [m]
  Vec3 body_velocity(int b) const;                // v_WB expressed in W [m/s]
  Eigen::Quaterniond body_attitude(int b) const;  // q_WB (identity for spheres)
  Vec6 body_twist(int b) const;                   // [u v w p q r] in the body frame
  // force the cables exert on body b (the sum of its joint multipliers, Eq. 29-30), world
  // frame [N]; zero if b is not attached
  Vec3 BodyCableForce(int b) const;
  // the same force and its moment about the body origin, body frame (Eq. 29-30) [N, N m]
  void BodyCableWrench(int b, Vec3* force_B, Vec3* moment_B) const;
  // the body (index as above) end `end` of cable c is attached to, -1 for none
  int EndBody(int end, int c = 0) const;

  // --- vehicles (index v into Model::vehicles) ---
  const VehicleState& vehicle_state(int v) const;
  const VehicleCommand& vehicle_command(int v) const;
  // the command held from now on (thrust, rudder and elevator go through the actuator
  // dynamics and limits of the vehicle model)
  void SetVehicleCommand(int v, const VehicleCommand& command);

  // --- vessels (index v into Model::vessels; vessel.h, docs/vessels.md) ---
  // the pose now (the prescribed motion at time(), or an external vessel's last pose carried
  // forward)
  const VesselPose& vessel_pose(int v) const;
  // an external vessel (Vessel::external): its pose at time t, held and carried forward by
  // its rates until the next (the node gives the pose for the end of the next step before it;
  // the step starts from the pose reported now, vessel_pose; ignored for a prescribed vessel).
  // A pose for the time now (t == time(), e.g. the initial pose at t = 0) also replaces the
  // pose reported now, from which the next step starts.
  void SetVesselPose(int v, double t, const VesselPose& pose);

  // --- the winches at their cables' starts (winch.h, docs/winch.md) ---
  // winch w sits at the start of cable w (the scene puts the winched cables first, model.h)
  bool has_winch() const;    // the scene has a winch (cable.winch or cables.<c>.winch)
  int num_winches() const;   // how many
  // winch w's name (WinchParams::name: its topic and CSV file, docs/winch_dds.md)
  const std::string& winch_name(int w) const;
  // winch w's command held from now on, clamped into its limits (WinchCommandRange); a
  // non-finite value is ignored (the command held so far stays). No such winch: ignored.
  void SetWinchCommand(const WinchCommand& command, int w = 0);
  const WinchCommand& winch_command(int w = 0) const;
  // cable c's paid-out unstretched length now [m] (no winch: cable.length)
  double cable_length(int c = 0) const;
  double winch_speed(int c = 0) const;  // cable c's dL/dt now [m/s], + pays out (no winch: 0)
  double DrumTension(int c = 0) const;  // axial tension at cable c's start (the drum) [N]

  // force cable c exerts on its support at the start (end = 0) or the end (end = 1),
  // world frame [N]; zero for a free end
  Vec3 end_force(int end, int c = 0) const;

  // the first folded element of the cables now (fold_check.h; folded = false if none); a few
  // dot products per element, for the runners' fold watch (docs/faults.md)
  FoldReport FindFold() const;

  // what initial: static did with the vehicles (vehicle_balance.h): "balanced N vehicles in K
  // iterations (S static solves); tow_vehicle's thrust 4163 N"; empty without held vehicles
  const std::string& initial_report() const;

  // joint-force iterations of the last step (kStrong; 1 for kStaggered, 0 without vehicles)
  int coupling_iterations() const;

  // energies for conservation checks [J]: kinetic (cable + bodies, with added mass),
  // potential of gravity and buoyancy, elastic strain energy
  double KineticEnergy() const;
  double PotentialEnergy() const;
  double StrainEnergy() const;

  // --- the sea at a body (docs/environment.md), at its origin and the current time ---
  // the altitude above the seabed straight below, d(x, y) - z (NaN without a seabed), and the
  // depth below the instantaneous surface, z + eta [m]; the surface elevation eta (positive
  // up) and the water's velocity (current + waves, world frame) there [m, m/s]
  double BodyAltitude(int b) const;
  // what the body's altimeter reports (docs/sensors.md): the range [m] from the body origin
  // along its beam, the body's z axis (down in the NED body frame; a sphere's frame stays
  // aligned with the world, so straight down), to the seabed, at most max_range;
  // Seabed::RayRange's conventions (REP 117): +inf no return (no seabed, the beam at or above
  // the horizon over a flat bed, the bed beyond max_range), -inf the origin below the bed
  double BodyAltimeterRange(int b, double max_range) const;
  double BodyDepth(int b) const;
  double SurfaceElevationAt(int b) const;
  Vec3 WaterVelocityAt(int b) const;

 private:
  void CheckStateShape(const State& state) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace towsim::core
