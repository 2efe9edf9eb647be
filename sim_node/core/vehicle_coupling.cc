#include "core/vehicle_coupling.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "core/newton_convergence.h"

namespace towsim::core {

VehicleCoupling::VehicleCoupling(const System& system, Integrator* integrator, StepInputs* inputs)
    : system_(system),
      integrator_(integrator),
      sampler_(system),
      inputs_(inputs),
      weight_scale_(WetWeightScale(system.model())) {
  const Model& model = system_.model();
  const int nv = static_cast<int>(model.vehicles.size());
  first_.assign(nv + 1, 0);
  for (int v = 0; v < nv; ++v) {
    first_[v] = static_cast<int>(attachments_.size());
    const VehicleParams& vp = model.vehicles[v].params;
    const Mat6 m = RigidBodyMassMatrix(vp) + vp.added_mass;
    for (const int end : system_.VehicleEnds(v)) {
      const CableEnd& e = system_.End(end % 2, end / 2);
      // G = J M^-1 J^T, J = [I, -S(r)]: the point's acceleration per unit force at the point
      // (point velocity v + omega x r = v - S(r) omega)
      Attachment at;
      at.end = end;
      at.vehicle = v;
      at.at_B = e.at_B;
      const Vec3 r = e.at_B;
      at.j << Eigen::Matrix3d::Identity(),
          (Eigen::Matrix3d() << 0.0, r.z(), -r.y(), -r.z(), 0.0, r.x(), r.y(), -r.x(), 0.0)
              .finished();
      const Eigen::Matrix3d g = at.j * m.partialPivLu().solve(at.j.transpose());
      at.g_B = 0.5 * (g + g.transpose());
      at.m_inv_jt = m.partialPivLu().solve(at.j.transpose());
      attachments_.push_back(at);
    }
  }
  first_[nv] = static_cast<int>(attachments_.size());
  const size_t na = attachments_.size();
  vehicles_.resize(nv);
  f0_.resize(na);
  f1_.resize(na);
  residual_.resize(na);
  linear_.resize(na);
  quadratic_.resize(na);
  point_compliance_.assign(na, Mat3::Zero());
  end_stiffness_.assign(na, 0.0);
  loads_.resize(na);
  for (const Vehicle& v : model.vehicles) inertia_.emplace_back(v.params);
}

Vec3 VehicleCoupling::AttachmentPoint(const VehicleState& vs, int a) const {
  // r_attach = p_WB + R_WB at_B (Eq. 24)
  return vs.p_W + vs.q_WB * attachments_[a].at_B;
}

namespace {

// the quadratic predictor is taken when its recent error is below this fraction of the linear
// one's (see the header)
constexpr double kQuadraticMargin = 0.5;

// the joint force of cable end `end` (2 c + k) in `state`
Vec3 EndForce(const System& system, const State& state, int end) {
  return state.lambda.segment<3>(system.EndLambda(end % 2, end / 2));
}

}  // namespace

void VehicleCoupling::HoldSupports(State* state) {
  const size_t nv = system_.model().vehicles.size();
  CouplingHistory& history = state->coupling;
  history.have_previous = false;
  history.h_previous = 0.0;
  history.f_previous.assign(attachments_.size(), Vec3::Zero());
  history.have_second = false;
  history.f_second.assign(attachments_.size(), Vec3::Zero());
  history.error_linear = history.error_quadratic = 0.0;
  history.flow_time = -1.0;
  history.flow_end.assign(nv, VehicleFlow());
  state->supports.assign(system_.num_ends(), SupportMotion());
  for (int a = 0; a < num_attachments(); ++a) {
    const Vec3 p = AttachmentPoint(state->vehicles[attachments_[a].vehicle], a);
    state->supports[attachments_[a].end] = {p, p, state->t, state->t};
  }
  SizeWorkSpace(*state);
}

void VehicleCoupling::SizeWorkSpace(const State& state) {
  previous_pass_ = state;  // sizes the work space (Step does not allocate)
  start_ = state;
  newton_ = state.newton;
}

StepStatus VehicleCoupling::Accept(const State& start, double h, State* state, StepStatus* status) {
  // remember lambda_n and lambda_{n-1} for the next step's predictor, and the water at the end
  // of the step
  CouplingHistory& history = state->coupling;
  // how far each predictor was from lambda_{n+1} (max over the attachments), kept as
  // e <- (e + e_new) / 2
  if (predicted_) {
    double e_linear = 0.0, e_quadratic = 0.0;
    for (int a = 0; a < num_attachments(); ++a) {
      const Vec3 f = EndForce(system_, *state, attachments_[a].end);
      e_linear = std::max(e_linear, (linear_[a] - f).lpNorm<Eigen::Infinity>());
      e_quadratic = std::max(e_quadratic, (quadratic_[a] - f).lpNorm<Eigen::Infinity>());
    }
    history.error_linear = 0.5 * (history.error_linear + e_linear);
    history.error_quadratic = 0.5 * (history.error_quadratic + e_quadratic);
  }
  // lambda_{n-1}, lambda_n at equal steps before the next one
  history.have_second = history.have_previous && history.h_previous == h;
  for (int a = 0; a < num_attachments(); ++a) {
    history.f_second[a] = history.f_previous[a];
    history.f_previous[a] = EndForce(system_, start, attachments_[a].end);
  }
  for (size_t v = 0; v < history.flow_end.size(); ++v)
    history.flow_end[v] = inputs_->vehicle_flow_end[v];
  history.h_previous = h;
  history.have_previous = true;
  history.flow_time = start.t + h;
  return *status;
}

void VehicleCoupling::CorrectVehicle(int a, const Vec3& r_W, double h, VehicleState* vs) const {
  // the mean force changes by r / 2 over the step: d nu = (h / 2) M^-1 J^T R_WB^T r, the
  // displacement and rotation (body frame) (h / 2) d nu, so that the attachment point moves by
  // (h^2 / 4) R_WB G R_WB^T r = C r
  const Mat3 r_wb = vs->q_WB.toRotationMatrix();
  const Vec6 dnu = (0.5 * h) * (attachments_[a].m_inv_jt * (r_wb.transpose() * r_W));
  const Vec6 dx = (0.5 * h) * dnu;
  vs->nu += dnu;
  vs->p_W += r_wb * dx.head<3>();
  const double angle = dx.tail<3>().norm();
  if (angle > 0.0) {
    const Eigen::Quaterniond dq(Eigen::AngleAxisd(angle, dx.tail<3>() / angle));
    vs->q_WB = (vs->q_WB * dq).normalized();
  }
}

StepStatus VehicleCoupling::Step(State* state, const std::vector<VehicleCommand>& commands,
                                 double h) {
  const Model& model = system_.model();
  const int nv = static_cast<int>(model.vehicles.size());
  const int na = num_attachments();
  const bool strong = model.integrator.coupling == Coupling::kStrong;
  const int max_iterations = strong ? model.integrator.max_coupling_iterations : 1;
  const double tol = model.integrator.tolerance * IncrementScale(model);
  start_ = *state;
  // the force bound on the joint-force residuals: the cables' Newton's (newton_convergence.h),
  // a fraction of the largest joint force at the step's start
  const double force_tol = model.integrator.force_tolerance *
                           JointForceScale(system_, start_.lambda, weight_scale_);
  // each attachment's end element's axial stiffness EA / l_e (a drum element's length is the
  // drum's now)
  for (int a = 0; a < na; ++a) {
    const int c = attachments_[a].end / 2;
    const int e = attachments_[a].end % 2 == 0 ? 0 : system_.NumElements(c) - 1;
    end_stiffness_[a] = model.cables[c].axial_stiffness / system_.RestLength(e, c);
  }
  const double t0 = state->t;

  // joint forces at t_n, and the current guess for t_{n+1}, per attachment
  std::vector<Vec3>& f0 = f0_;
  std::vector<Vec3>& f1 = f1_;
  std::vector<Vec3>& residual = residual_;
  // predictor of lambda_{n+1} (strong scheme): extrapolation of the last steps, linear or, at
  // equal steps, quadratic, whichever has lately predicted the joint forces better (see the
  // header)
  const CouplingHistory& history = start_.coupling;
  const bool predict = strong && history.have_previous && history.h_previous > 0.0;
  const bool quadratic = predict && history.have_second && history.h_previous == h;
  for (int a = 0; a < na; ++a) {
    f0[a] = EndForce(system_, start_, attachments_[a].end);
    const Vec3& f_1 = history.f_previous[a];
    linear_[a] = predict ? Vec3(f0[a] + (h / history.h_previous) * (f0[a] - f_1)) : f0[a];
    quadratic_[a] = quadratic ? Vec3(3.0 * f0[a] - 3.0 * f_1 + history.f_second[a]) : linear_[a];
    f1[a] = quadratic && history.error_quadratic < kQuadraticMargin * history.error_linear
                ? quadratic_[a]
                : linear_[a];
  }
  predicted_ = quadratic;
  // the water at each vehicle over the step, sampled once (the end at the pose predicted from
  // the start; the end of one step is the start of the next, State::coupling.flow_end)
  sampler_.SampleVehicleFlows(start_, h, inputs_);
  const StepInputs& in = *inputs_;
  // strong: each attachment point's response to its joint force over the step, (h^2 / 4) G in
  // the world frame at the attitude of t_n (see the header)
  std::vector<Mat3>& point_compliance = point_compliance_;
  for (int a = 0; a < na; ++a) {
    const Mat3 r_wb = start_.vehicles[attachments_[a].vehicle].q_WB.toRotationMatrix();
    point_compliance[a].setZero();
    if (strong) point_compliance[a] = (0.25 * h * h) * (r_wb * attachments_[a].g_B * r_wb.transpose());
  }
  // vehicles over [t_n, t_n + h] under the joint forces (Eq. 29-30), each at its point;
  // strong: the mean of lambda_n and the guess of lambda_{n+1}, constant over the step (see
  // the header)
  std::vector<VehicleState>& vehicles = vehicles_;
  auto advance_vehicles = [&] {
    vehicles = start_.vehicles;  // same size: copies in place
    for (int v = 0; v < nv; ++v) {
      PointLoad none;
      const int a0 = first_[v], n = first_[v + 1] - first_[v];
      for (int a = a0; a < a0 + n; ++a) {
        PointLoad& load = loads_[a];
        load.force_W0 = strong ? 0.5 * (f0[a] + f1[a]) : f0[a];
        load.force_W1 = load.force_W0;
        load.point_B = attachments_[a].at_B;
      }
      PointLoad* load = n > 0 ? &loads_[a0] : &none;
      if (n > 1) {
        load->more = &loads_[a0 + 1];
        load->more_count = n - 1;
      }
      AdvanceVehicle(model.vehicles[v].params, inertia_[v], model.environment,
                     in.vehicle_flow_start[v], in.vehicle_flow_end[v], commands[v], *load, h,
                     &vehicles[v], &system_.sea());
    }
  };
  // how far the joint-force residuals move attachment a's point: its own C_a r_a, and the
  // other attachments' of its vehicle, (h^2 / 4) R J_a M^-1 J_b^T R^T r_b
  auto moved_by_residual = [&](int a) {
    Vec3 d = point_compliance[a] * residual[a];
    const int v = attachments_[a].vehicle;
    if (!strong || first_[v + 1] - first_[v] < 2) return d;
    const Mat3 r_wb = start_.vehicles[v].q_WB.toRotationMatrix();
    for (int b = first_[v]; b < first_[v + 1]; ++b) {
      if (b == a) continue;
      d += (0.25 * h * h) * (r_wb * (attachments_[a].j * (attachments_[b].m_inv_jt *
                                                          (r_wb.transpose() * residual[b]))));
    }
    return d;
  };
  advance_vehicles();
  StepStatus status;
  status.iterations = 0;
  for (int k = 1; k <= max_iterations; ++k) {
    last_iterations_ = k;
    // later passes start the cables' Newton from the previous pass (its supports moved a
    // little); a pass that needed substeps is no such guess
    const bool warm = k > 1 && previous_pass_substeps_ == 1;
    if (warm) previous_pass_ = *state;  // same sizes: copies in place
    // every pass starts from the step's start (the first: *state is start_), but the
    // integrator's kept Newton matrix is the one the previous pass left (State::newton; swaps
    // move buffers, no allocation)
    if (k > 1) {
      std::swap(newton_, state->newton);
      *state = start_;
      std::swap(newton_, state->newton);
    }
    // the cables with the attachment points as driven supports that answer the joint force
    for (int a = 0; a < na; ++a) {
      const int v = attachments_[a].vehicle, end = attachments_[a].end;
      const Vec3 p0 = AttachmentPoint(start_.vehicles[v], a);
      state->supports[end] = {p0,    AttachmentPoint(vehicles[v], a), t0, t0 + h,
                              point_compliance[a], f1[a]};
      // Newton starts from the predicted joint force
      if (strong) state->lambda.segment<3>(system_.EndLambda(end % 2, end / 2)) = f1[a];
    }
    const StepStatus cable = integrator_->Step(state, h, warm ? &previous_pass_ : nullptr);
    previous_pass_substeps_ = cable.substeps;
    status.iterations += cable.iterations;
    status.substeps = std::max(status.substeps, cable.substeps);
    status.residual = cable.residual;
    if (!cable.ok()) {
      status.code = cable.code;
      status.message = cable.message;
      *state = start_;
      state->newton.valid = false;  // the integrator's cache is no longer start_'s matrix
      return status;
    }
    state->vehicles = vehicles;
    bool finite = true;
    for (const VehicleState& vs : vehicles)
      finite = finite && vs.p_W.allFinite() && vs.nu.allFinite() && vs.q_WB.coeffs().allFinite();
    if (!finite) {
      status.code = StepStatus::kNonFinite;
      std::ostringstream m;
      m << "non-finite vehicle state in the step from t = " << t0 << " s (h = " << h << " s)";
      status.message = m.str();
      return status;
    }
    if (!strong) return Accept(start_, h, state, &status);
    // the joint forces the cables found against the guesses the vehicles saw
    for (int a = 0; a < na; ++a) residual[a] = EndForce(system_, *state, attachments_[a].end) - f1[a];
    // converged when the force residuals move no attachment point by more than the tolerance
    // (the cable's end already sits at p1 + C r; its vehicle then takes its linear response
    // to r, below)
    // and the force residual left within the force bound (a heavy vehicle or a short step moves
    // little under a large force error): the vehicles take r to first order (CorrectVehicle),
    // so what is left is estimated as theta |r| with the cables' Newton's floor on theta
    // (integrator.h, kMaxContraction; newton_convergence.h)
    double moved = 0.0, force = 0.0;
    for (int a = 0; a < na; ++a) {
      moved = std::max(moved, moved_by_residual(a).lpNorm<Eigen::Infinity>());
      force = std::max(force, residual[a].lpNorm<Eigen::Infinity>());
    }
    force *= Integrator::kMaxContraction;
    last_force_residual_ = force;
    last_force_bound_ = force_tol;
    const bool forces_met = force <= force_tol;
    if (moved <= tol && forces_met) {
      for (int a = 0; a < na; ++a) {
        const int v = attachments_[a].vehicle, end = attachments_[a].end;
        CorrectVehicle(a, residual[a], h, &state->vehicles[v]);
        state->supports[end].p1 += point_compliance[a] * residual[a];
        state->supports[end].lambda1 += residual[a];
      }
      return Accept(start_, h, state, &status);
    }
    // the vehicles again under the cables' forces; each cable end sits where the linearized
    // response put it, p1 + C r: within the tolerance of where it went, converged
    for (int a = 0; a < na; ++a) f1[a] += residual[a];
    advance_vehicles();
    // and the force that mismatch leaves: the end element answers a displacement d of its
    // support with up to EA d / l_e (its axial stiffness; newton_convergence.h), within the
    // force bound
    double mismatch = 0.0, mismatch_force = 0.0;
    for (int a = 0; a < na; ++a) {
      const Vec3 p1 = AttachmentPoint(vehicles[attachments_[a].vehicle], a);
      const SupportMotion& sm = state->supports[attachments_[a].end];
      const double d = (p1 - (sm.p1 + sm.compliance * residual[a])).lpNorm<Eigen::Infinity>();
      mismatch = std::max(mismatch, d);
      mismatch_force = std::max(mismatch_force, end_stiffness_[a] * d);
    }
    if (mismatch_force > force_tol) {
      last_force_residual_ = mismatch_force;
      last_force_bound_ = force_tol;
    }
    if (mismatch <= tol && mismatch_force <= force_tol) {
      state->vehicles = vehicles;
      for (int a = 0; a < na; ++a) {
        const int end = attachments_[a].end;
        state->supports[end].p1 = AttachmentPoint(vehicles[attachments_[a].vehicle], a);
        state->supports[end].lambda1 = f1[a];
      }
      return Accept(start_, h, state, &status);
    }
  }
  status.code = StepStatus::kNotConverged;
  std::ostringstream m;
  m << "vehicle-cable coupling did not converge in " << max_iterations
    << " iterations in the step from t = " << t0 << " s (h = " << h << " s); last joint-force "
    << "residual " << last_force_residual_ << " N (bound " << last_force_bound_
    << " N, integrator.force_tolerance x the largest joint force)";
  status.message = m.str();
  return status;
}

}  // namespace towsim::core
