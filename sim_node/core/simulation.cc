#include "core/simulation.h"

#include "core/initial_shape.h"
#include "core/integrator.h"
#include "core/state.h"
#include "core/static_solver.h"
#include "core/system.h"

namespace towsim::core {

struct Simulation::Impl {
  explicit Impl(const Model& m) : system(m), integrator(system) {}
  System system;
  Integrator integrator;
  State state;
  long steps = 0;
};

Simulation::Simulation(const Model& model) : impl_(std::make_unique<Impl>(model)) {
  const System& sys = impl_->system;
  State& s = impl_->state;
  BuildInitialState(sys, &s);
  if (model.cable.initial == InitialShape::kStatic) {
    const StaticResult r = SolveStatic(sys, model.cable.initial_velocity, &s);
    if (!r.ok) throw SolverError(r.message);
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

StepStatus Simulation::StepBy(double h) {
  StepStatus s = impl_->integrator.Step(&impl_->state, h);
  if (s.ok()) ++impl_->steps;
  return s;
}

const Model& Simulation::model() const { return impl_->system.model(); }
const System& Simulation::system() const { return impl_->system; }
const State& Simulation::state() const { return impl_->state; }
double Simulation::time() const { return impl_->state.t; }
long Simulation::step_count() const { return impl_->steps; }

void Simulation::SetState(const State& state) {
  impl_->state = state;
  if (!impl_->integrator.InitializeAcceleration(&impl_->state))
    throw SolverError("SetState: accelerations could not be computed for the given state");
}

int Simulation::cable_dof(int node) const { return impl_->system.cable_dof(node); }
int Simulation::body_dof(int body) const { return impl_->system.body_dof(body); }
int Simulation::num_nodes() const { return impl_->system.num_nodes(); }
int Simulation::num_bodies() const { return impl_->system.num_bodies(); }

Vec3 Simulation::node_position(int i) const { return impl_->state.q.segment<3>(cable_dof(i)); }
Vec3 Simulation::node_velocity(int i) const { return impl_->state.v.segment<3>(cable_dof(i)); }
double Simulation::node_tension(int i) const {
  return impl_->system.NodeTension(impl_->state.q, impl_->state.v, i);
}
Vec3 Simulation::body_position(int b) const { return impl_->state.q.segment<3>(body_dof(b)); }
Vec3 Simulation::body_velocity(int b) const { return impl_->state.v.segment<3>(body_dof(b)); }

Vec3 Simulation::body_cable_force(int b) const {
  const CableParams& c = model().cable;
  for (int end = 0; end < 2; ++end) {
    const CableEnd& e = end == 0 ? c.start : c.end;
    if (e.kind == EndKind::kBody && e.body == b) return end_force(end);
  }
  return Vec3::Zero();
}

Vec3 Simulation::end_force(int end) const {
  const System& sys = impl_->system;
  if (sys.end_lambda_count(end) == 0) return Vec3::Zero();
  return impl_->state.lambda.segment<3>(sys.end_lambda(end));
}

double Simulation::KineticEnergy() const {
  return impl_->system.KineticEnergy(impl_->state.q, impl_->state.v);
}
double Simulation::PotentialEnergy() const { return impl_->system.PotentialEnergy(impl_->state.q); }
double Simulation::StrainEnergy() const { return impl_->system.StrainEnergy(impl_->state.q); }

}  // namespace towsim::core
