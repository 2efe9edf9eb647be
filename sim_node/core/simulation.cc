#include "core/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/environment_field.h"
#include "core/initial_shape.h"
#include "core/integrator.h"
#include "core/state.h"
#include "core/static_solver.h"
#include "core/system.h"
#include "core/vehicle_balance.h"
#include "core/vehicle_coupling.h"
#include "core/winch_drive.h"

namespace towsim::core {

struct Simulation::Impl {
  explicit Impl(const Model& m)
      : system(m),
        integrator(system, &inputs),
        coupling(system, &integrator, &inputs),
        winch(&system) {}
  System system;
  StepInputs inputs;  // what a step reads besides its unknowns (step_inputs.h)
  Integrator integrator;
  VehicleCoupling coupling;
  WinchDrive winch;
  State state;
  std::vector<VehicleCommand> commands;
  std::string initial_report;  // initial_report()
  // the vessels' motions, their poses at state.t and the cable ends they hold
  std::vector<VesselMotion> vessels;
  std::vector<VesselPose> vessel_now;
  struct VesselEnd {
    int end = 0;     // 2 c + k
    int vessel = 0;  // index into Model::vessels
    Vec3 at_B = Vec3::Zero();
  };
  std::vector<VesselEnd> vessel_ends;
  std::vector<VesselPose> vessel_next;  // work space: the poses at the step's end,
  double vessel_next_t = std::numeric_limits<double>::quiet_NaN();  // at this time
  int coupling_iterations = 0;
  // the vessels' poses at state.t and their ends held there (a state that starts a run)
  void HoldVessels();
  // the vessels' attachment points as supports moving over [t, t + h] (SupportMotion)
  void MoveVessels(double h);
  // the cable (and the vehicles) over h from the current state
  StepStatus StepSystem(double h);
};

Simulation::Simulation(const Model& model, const std::function<bool()>& stop_requested)
    : impl_(std::make_unique<Impl>(model)) {
  System& sys = impl_->system;
  State& s = impl_->state;
  BuildInitialState(sys, &s);
  impl_->winch.Initialize(&s);
  for (const Vehicle& v : model.vehicles) impl_->commands.push_back(v.command);
  const Model& m = sys.model();  // the System's copy: the motions keep pointers into it
  for (const Vessel& v : m.vessels) impl_->vessels.emplace_back(v, m.environment.waves);
  for (int end = 0; end < sys.num_ends(); ++end) {
    const CableEnd& e = sys.End(end % 2, end / 2);
    if (e.kind == EndKind::kVessel) impl_->vessel_ends.push_back({end, e.body, e.at_B});
  }
  impl_->vessel_next.resize(m.vessels.size());
  impl_->coupling.HoldSupports(&s);
  impl_->HoldVessels();
  // a static start solves the whole network, in the frame moving with the cables' common
  // initial velocity (the scene requires it common, docs/scene_format.md)
  const CableParams* static_cable = nullptr;
  for (const CableParams& c : model.cables)
    if (c.initial == InitialShape::kStatic && !static_cable) static_cable = &c;
  if (static_cable) {
    if (HeldVehicles(sys).empty()) {
      const StaticResult r = SolveStatic(sys, static_cable->initial_velocity, &s, stop_requested);
      if (r.stopped) {
        throw StopRequestedError("stopped during the static solve after " +
                                 std::to_string(r.iterations) + " iterations");
      }
      if (!r.ok) throw SolverError(r.message);
    } else {
      // the vehicles balanced with the cables (vehicle_balance.h); a towing vehicle's thrust
      // becomes its command
      const BalanceResult r = SolveStaticWithVehicles(sys, static_cable->initial_velocity,
                                                      &impl_->commands, &s, stop_requested);
      if (r.stopped) {
        throw StopRequestedError("stopped during the static solve after " +
                                 std::to_string(r.static_solves) + " static solves");
      }
      if (!r.ok) throw SolverError("initial: static: " + r.message);
      impl_->initial_report = r.report;
      impl_->coupling.HoldSupports(&s);
      impl_->HoldVessels();
    }
  }
  if (!impl_->integrator.InitializeAcceleration(&s))
    throw SolverError(
        "initial accelerations could not be computed: singular or non-finite "
        "system at t = 0 (check the cable ends and masses)");
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

StepStatus Simulation::Step() { return StepBy(impl_->system.model().time.step); }

void Simulation::Impl::HoldVessels() {
  vessel_now.resize(vessels.size());
  for (size_t v = 0; v < vessels.size(); ++v) vessel_now[v] = vessels[v].At(state.t);
  for (const VesselEnd& e : vessel_ends) {
    const Vec3 p = vessel_now[e.vessel].PointAt(e.at_B);
    state.supports[e.end] = {p, p, state.t, state.t};
  }
}

void Simulation::Impl::MoveVessels(double h) {
  if (vessels.empty()) return;
  const double t0 = state.t, t1 = t0 + h;
  for (size_t v = 0; v < vessels.size(); ++v) vessel_next[v] = vessels[v].At(t1);
  vessel_next_t = t1;
  for (const VesselEnd& e : vessel_ends) {
    SupportMotion& s = state.supports[e.end];
    s.p0 = vessel_now[e.vessel].PointAt(e.at_B);  // the pose at t0 as it was reported
    s.p1 = vessel_next[e.vessel].PointAt(e.at_B);
    s.t0 = t0;
    s.t1 = t1;
    s.compliance.setZero();
    s.lambda1.setZero();
  }
}

StepStatus Simulation::Impl::StepSystem(double h) {
  MoveVessels(h);
  if (system.model().vehicles.empty()) {
    coupling_iterations = 0;
    return integrator.Step(&state, h);
  }
  const StepStatus s = coupling.Step(&state, commands, h);
  coupling_iterations = coupling.last_iterations();
  return s;
}

StepStatus Simulation::StepBy(double h) {
  // the winch's drum around the cable's step (winch_drive.h)
  const StepStatus s =
      impl_->winch.Step(h, &impl_->state, [this](double dt) { return impl_->StepSystem(dt); });
  if (s.ok()) ++impl_->state.step;
  // the poses now: those the step ended on, unless the state ended elsewhere (a failed step)
  if (impl_->vessel_next_t == impl_->state.t) {
    impl_->vessel_now = impl_->vessel_next;  // same size: copies in place
  } else {
    for (size_t v = 0; v < impl_->vessels.size(); ++v)
      impl_->vessel_now[v] = impl_->vessels[v].At(impl_->state.t);
  }
  return s;
}

const Model& Simulation::model() const { return impl_->system.model(); }
const System& Simulation::system() const { return impl_->system; }
const State& Simulation::state() const { return impl_->state; }
double Simulation::time() const { return impl_->state.t; }
long Simulation::step_count() const { return impl_->state.step; }
const std::string& Simulation::initial_report() const { return impl_->initial_report; }
FoldReport Simulation::FindFold() const {
  return core::FindFold(impl_->system, impl_->state.q);
}
int Simulation::coupling_iterations() const { return impl_->coupling_iterations; }

State Simulation::GetState() const { return impl_->state; }

namespace {

// "SetState: <what> has <n> entries, this model needs <m> (<why>)" unless n == m
void CheckSize(const char* what, long n, long m, const std::string& why) {
  if (n == m) return;
  std::ostringstream msg;
  msg << "SetState: " << what << " has " << n << " entries, this model needs " << m << " (" << why
      << ")";
  throw std::invalid_argument(msg.str());
}

}  // namespace

void Simulation::CheckStateShape(const State& s) const {
  const System& sys = impl_->system;
  std::ostringstream why;
  why << "3 per sphere body and 6 per cable node: " << sys.num_spheres() << " bodies, "
      << sys.total_array_nodes() << " nodes";
  const long n = sys.num_q();
  CheckSize("q", s.q.size(), n, why.str());
  CheckSize("v", s.v.size(), n, why.str());
  CheckSize("a", s.a.size(), n, why.str());
  CheckSize("a_alpha", s.a_alpha.size(), n, why.str());
  CheckSize("lambda", s.lambda.size(), sys.num_lambda(),
            "3 per held cable end, 2 more per clamped end");
  CheckSize("winches", static_cast<long>(s.winches.size()), sys.num_cables(), "one per cable");
  // each cable's nodes in use are part of the shape (with a winch the arrays hold max_nodes)
  for (int c = 0; c < sys.num_cables(); ++c) {
    const int nodes = s.winches[c].nodes;
    if (nodes >= 2 && nodes <= sys.max_nodes(c) && (sys.has_winch(c) || nodes == sys.max_nodes(c)))
      continue;
    std::ostringstream msg;
    msg << "SetState: winches[" << c << "].nodes = " << nodes << ", this model needs ";
    if (sys.has_winch(c))
      msg << "2 to " << sys.max_nodes(c)
          << " (cable nodes in use; the winch's max_length holds at most that many)";
    else
      msg << sys.max_nodes(c) << " (cable.elements + 1; the cable has no winch)";
    throw std::invalid_argument(msg.str());
  }
  const long nv = num_vehicles();
  CheckSize("vehicles", static_cast<long>(s.vehicles.size()), nv, "one per scene vehicle");
  CheckSize("coupling.f_previous", static_cast<long>(s.coupling.f_previous.size()),
            impl_->coupling.num_attachments(), "one per cable end held by a vehicle");
  CheckSize("coupling.f_second", static_cast<long>(s.coupling.f_second.size()),
            impl_->coupling.num_attachments(), "one per cable end held by a vehicle");
  CheckSize("supports", static_cast<long>(s.supports.size()), sys.num_ends(),
            "one per cable end");
  CheckSize("coupling.flow_end", static_cast<long>(s.coupling.flow_end.size()), nv,
            "one per scene vehicle");
  if (s.newton.valid) {
    CheckSize("newton.q", s.newton.q.size(), n, why.str());
    CheckSize("newton.v", s.newton.v.size(), n, why.str());
    CheckSize("newton.a", s.newton.a.size(), n, why.str());
    if (sys.sea().has_waves()) CheckSize("newton.wave_q", s.newton.wave_q.size(), n, why.str());
  }
}

void Simulation::SetState(const State& state) {
  CheckStateShape(state);
  impl_->state = state;
  for (int c = 0; c < impl_->system.num_cables(); ++c)
    impl_->system.SetLayout(state.winches[c].nodes, state.winches[c].length, c);
  impl_->coupling.SizeWorkSpace(impl_->state);
  if (!impl_->integrator.RestoreNewtonMatrix(impl_->state))
    throw SolverError("SetState: the kept Newton matrix of the state cannot be factored");
  for (size_t v = 0; v < impl_->vessels.size(); ++v)
    impl_->vessel_now[v] = impl_->vessels[v].At(impl_->state.t);
}

void Simulation::StartFrom(const State& state) {
  State s = state;
  s.a = s.v;  // sized like v; recomputed below
  s.a_alpha = s.v;
  s.lambda.setZero(impl_->system.num_lambda());
  s.newton = NewtonPoint();
  s.coupling.f_previous.assign(impl_->coupling.num_attachments(), Vec3::Zero());
  s.coupling.f_second.assign(impl_->coupling.num_attachments(), Vec3::Zero());
  s.supports.resize(impl_->system.num_ends());
  s.coupling.flow_end.assign(num_vehicles(), VehicleFlow());
  CheckStateShape(s);
  impl_->state = s;
  for (int c = 0; c < impl_->system.num_cables(); ++c)
    impl_->system.SetLayout(s.winches[c].nodes, s.winches[c].length, c);
  impl_->coupling.HoldSupports(&impl_->state);
  impl_->HoldVessels();
  if (!impl_->integrator.InitializeAcceleration(&impl_->state))
    throw SolverError("StartFrom: accelerations could not be computed for the given state");
}

int Simulation::cable_dof(int node, int c) const { return impl_->system.CableDof(node, c); }
int Simulation::sphere_dof(int sphere) const { return impl_->system.SphereDof(sphere); }
int Simulation::num_nodes(int c) const { return impl_->system.num_nodes(c); }
int Simulation::num_cables() const { return impl_->system.num_cables(); }
const std::string& Simulation::cable_name(int c) const { return model().cables[c].name; }
int Simulation::num_spheres() const { return impl_->system.num_spheres(); }
int Simulation::num_vehicles() const { return static_cast<int>(model().vehicles.size()); }
int Simulation::num_vessels() const { return static_cast<int>(model().vessels.size()); }
int Simulation::num_bodies() const { return num_spheres() + num_vehicles() + num_vessels(); }
bool Simulation::body_is_sphere(int b) const { return b < num_spheres(); }
bool Simulation::body_is_vehicle(int b) const {
  return b >= num_spheres() && b < num_spheres() + num_vehicles();
}
bool Simulation::body_is_vessel(int b) const { return b >= num_spheres() + num_vehicles(); }

const std::string& Simulation::body_name(int b) const {
  if (body_is_vessel(b)) return model().vessels[b - num_spheres() - num_vehicles()].name;
  return body_is_vehicle(b) ? model().vehicles[b - num_spheres()].name : model().spheres[b].name;
}

const VesselPose& Simulation::vessel_pose(int v) const { return impl_->vessel_now[v]; }

void Simulation::SetVesselPose(int v, double t, const VesselPose& pose) {
  if (!impl_->vessels[v].external()) return;
  impl_->vessels[v].SetExternal(t, pose);
  if (t == impl_->state.t) impl_->vessel_now[v] = impl_->vessels[v].At(t);
}

Vec3 Simulation::node_position(int i, int c) const {
  return impl_->state.q.segment<3>(cable_dof(i, c));
}
Vec3 Simulation::node_velocity(int i, int c) const {
  return impl_->state.v.segment<3>(cable_dof(i, c));
}
double Simulation::NodeTension(int i, int c) const {
  // at a held end the joint force is the force the cable transmits there (exact, where the
  // element's interpolated strain misses a bend sharper than the element, e.g. at a towfish)
  const int end = i == 0 ? 0 : (i == num_nodes(c) - 1 ? 1 : -1);
  if (end >= 0 && impl_->system.end_lambda_count(end, c) > 0) return end_force(end, c).norm();
  return impl_->system.NodeTension(impl_->state.q, impl_->state.v, i, c);
}

Vec3 Simulation::body_position(int b) const {
  if (body_is_vessel(b)) return vessel_pose(b - num_spheres() - num_vehicles()).position;
  if (body_is_vehicle(b)) return vehicle_state(b - num_spheres()).p_W;
  return impl_->state.q.segment<3>(sphere_dof(b));
}

Vec3 Simulation::body_velocity(int b) const {
  if (body_is_vessel(b)) return vessel_pose(b - num_spheres() - num_vehicles()).velocity;
  if (body_is_vehicle(b)) {
    const VehicleState& vs = vehicle_state(b - num_spheres());
    return vs.q_WB * Vec3(vs.nu.head<3>());
  }
  return impl_->state.v.segment<3>(sphere_dof(b));
}

Eigen::Quaterniond Simulation::body_attitude(int b) const {
  if (body_is_vessel(b)) return vessel_pose(b - num_spheres() - num_vehicles()).attitude();
  if (body_is_vehicle(b)) return vehicle_state(b - num_spheres()).q_WB;
  return Eigen::Quaterniond::Identity();
}

Vec6 Simulation::body_twist(int b) const {
  if (body_is_vessel(b)) return vessel_pose(b - num_spheres() - num_vehicles()).twist();
  if (body_is_vehicle(b)) return vehicle_state(b - num_spheres()).nu;
  Vec6 t = Vec6::Zero();
  t.head<3>() = body_velocity(b);  // a sphere's frame stays aligned with the world
  return t;
}

int Simulation::EndBody(int end, int c) const {
  const CableEnd& e = impl_->system.End(end, c);
  if (e.kind == EndKind::kSphere) return e.body;
  if (e.kind == EndKind::kVehicle) return num_spheres() + e.body;
  if (e.kind == EndKind::kVessel) return num_spheres() + num_vehicles() + e.body;
  return -1;
}

Vec3 Simulation::BodyCableForce(int b) const {
  Vec3 f = Vec3::Zero();
  for (int c = 0; c < num_cables(); ++c)
    for (int end = 0; end < 2; ++end)
      if (EndBody(end, c) == b) f += end_force(end, c);
  return f;
}

void Simulation::BodyCableWrench(int b, Vec3* force_B, Vec3* moment_B) const {
  // F_B = R_WB^T lambda, M_B = r_attach x F_B (Eq. 29-30), summed over the attachments
  const bool rigid = !body_is_sphere(b);  // a vehicle or a vessel: the moments too
  const Eigen::Quaterniond q = body_attitude(b);
  force_B->setZero();
  moment_B->setZero();
  for (int c = 0; c < num_cables(); ++c)
    for (int end = 0; end < 2; ++end) {
      if (EndBody(end, c) != b) continue;
      const Vec3 f = q.conjugate() * end_force(end, c);
      *force_B += f;
      if (rigid) *moment_B += impl_->system.End(end, c).at_B.cross(f);
    }
}

const VehicleState& Simulation::vehicle_state(int v) const { return impl_->state.vehicles[v]; }
const VehicleCommand& Simulation::vehicle_command(int v) const { return impl_->commands[v]; }
void Simulation::SetVehicleCommand(int v, const VehicleCommand& command) {
  impl_->commands[v] = command;
}

bool Simulation::has_winch() const { return impl_->winch.has_winch(); }
int Simulation::num_winches() const { return impl_->winch.num_winches(); }
const std::string& Simulation::winch_name(int w) const { return model().cables[w].winch->name; }
void Simulation::SetWinchCommand(const WinchCommand& command, int w) {
  impl_->winch.SetCommand(command, w);
}
const WinchCommand& Simulation::winch_command(int w) const { return impl_->winch.command(w); }
double Simulation::cable_length(int c) const { return impl_->state.winches[c].length; }
double Simulation::winch_speed(int c) const { return impl_->state.winches[c].speed; }
double Simulation::DrumTension(int c) const { return NodeTension(0, c); }

Vec3 Simulation::end_force(int end, int c) const {
  const System& sys = impl_->system;
  if (sys.end_lambda_count(end, c) == 0) return Vec3::Zero();
  return impl_->state.lambda.segment<3>(sys.EndLambda(end, c));
}

double Simulation::KineticEnergy() const {
  double ke = impl_->system.KineticEnergy(impl_->state.q, impl_->state.v);
  for (int v = 0; v < num_vehicles(); ++v)
    ke += VehicleKineticEnergy(model().vehicles[v].params, vehicle_state(v));
  return ke;
}

double Simulation::PotentialEnergy() const {
  double pe = impl_->system.PotentialEnergy(impl_->state.q);
  const Environment& env = model().environment;
  for (int v = 0; v < num_vehicles(); ++v) {
    // weight at the CG, buoyancy at the CB
    const VehicleParams& p = model().vehicles[v].params;
    const VehicleState& vs = vehicle_state(v);
    pe -= p.mass * env.gravity * (vs.p_W + vs.q_WB * p.r_g).z();
    pe += env.water_density * p.volume * env.gravity * (vs.p_W + vs.q_WB * p.r_b).z();
    // the mast's waterplane is a heave spring of stiffness rho g A_wp about design_depth
    const double dz = vs.p_W.z() - p.design_depth;
    pe += 0.5 * env.water_density * env.gravity * p.waterplane_area * dz * dz;
  }
  return pe;
}

double Simulation::StrainEnergy() const { return impl_->system.StrainEnergy(impl_->state.q); }

double Simulation::BodyAltitude(int b) const {
  const EnvironmentField& sea = impl_->system.sea();
  if (!sea.has_seabed()) return std::numeric_limits<double>::quiet_NaN();
  const Vec3 p = body_position(b);
  return sea.SeabedDepth(p.x(), p.y()) - p.z();
}

double Simulation::BodyAltimeterRange(int b, double max_range) const {
  // beam u = R_WB e_z, the body's z axis in the world
  const Vec3 beam = body_attitude(b) * Vec3::UnitZ();
  return impl_->system.sea().SeabedRayRange(body_position(b), beam, max_range);
}

double Simulation::BodyDepth(int b) const {
  const Vec3 p = body_position(b);
  return p.z() + SurfaceElevationAt(b);
}

// The outputs' sea in double precision, from the wave field itself (WaveField; the loads'
// sums run in float past the phase: environment_field.h), with the same crest and ramp rules
double Simulation::SurfaceElevationAt(int b) const {
  const Vec3 p = body_position(b);
  return impl_->system.model().environment.waves.Elevation(p.x(), p.y(), time());
}

Vec3 Simulation::WaterVelocityAt(int b) const {
  const Vec3 p = body_position(b);
  const WaveField& waves = impl_->system.model().environment.waves;
  Vec3 u = impl_->system.sea().Current(p, time()).velocity;
  if (!waves.empty()) u += waves.Kinematics(p, time()).velocity;
  return u;
}

}  // namespace towsim::core
