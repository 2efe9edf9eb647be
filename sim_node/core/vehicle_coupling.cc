#include "core/vehicle_coupling.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace towsim::core {

VehicleCoupling::VehicleCoupling(const System& system, Integrator* integrator, StepInputs* inputs)
    : system_(system), integrator_(integrator), sampler_(system), inputs_(inputs) {
  const CableParams& c = system_.model().cable;
  const CableEnd* ends[2] = {&c.start, &c.end};
  for (int e = 0; e < 2; ++e) {
    if (ends[e]->kind != EndKind::kVehicle) continue;
    vehicle_end_[e] = ends[e]->body;
    // G = J M^-1 J^T, J = [I, -S(r)]: the point's acceleration per unit force at the point
    const VehicleParams& vp = system_.model().vehicles[ends[e]->body].params;
    const Mat6 m = RigidBodyMassMatrix(vp) + vp.added_mass;
    const Vec3 r = ends[e]->at_B;
    Eigen::Matrix<double, 3, 6> j;
    // J = [I, -S(r)] (point velocity v + omega x r = v - S(r) omega)
    j << Eigen::Matrix3d::Identity(),
        (Eigen::Matrix3d() << 0.0, r.z(), -r.y(), -r.z(), 0.0, r.x(), r.y(), -r.x(), 0.0)
            .finished();
    const Eigen::Matrix3d g = j * m.partialPivLu().solve(j.transpose());
    g_B_[e] = 0.5 * (g + g.transpose());
    m_inv_jt_[e] = m.partialPivLu().solve(j.transpose());
    compliance_[e] = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(0.5 * (g + g.transpose()),
                                                                    Eigen::EigenvaluesOnly)
                         .eigenvalues()
                         .cwiseAbs()
                         .maxCoeff();
  }
  const size_t nv = system_.model().vehicles.size();
  vehicles_.resize(nv);
  f0_.resize(nv);
  f1_.resize(nv);
  residual_.resize(nv);
  for (const Vehicle& v : system_.model().vehicles) inertia_.emplace_back(v.params);
}

Vec3 VehicleCoupling::AttachmentPoint(const VehicleState& vs, int end) const {
  const CableParams& c = system_.model().cable;
  const CableEnd& e = end == 0 ? c.start : c.end;
  // r_attach = p_WB + R_WB at_B (Eq. 24)
  return vs.p_W + vs.q_WB * e.at_B;
}

Vec3 VehicleCoupling::JointForce(const State& state, int v) const {
  Vec3 f = Vec3::Zero();
  for (int e = 0; e < 2; ++e)
    if (vehicle_end_[e] == v) f += state.lambda.segment<3>(system_.EndLambda(e));
  return f;
}

void VehicleCoupling::HoldSupports(State* state) {
  const size_t nv = system_.model().vehicles.size();
  CouplingHistory& history = state->coupling;
  history.have_previous = false;
  history.h_previous = 0.0;
  history.f_previous.assign(nv, Vec3::Zero());
  history.flow_time = -1.0;
  history.flow_end.assign(nv, VehicleFlow());
  for (int e = 0; e < 2; ++e) {
    state->supports[e] = SupportMotion();
    if (vehicle_end_[e] < 0) continue;
    const Vec3 p = AttachmentPoint(state->vehicles[vehicle_end_[e]], e);
    state->supports[e] = {p, p, state->t, state->t};
  }
  SizeWorkSpace(*state);
}

void VehicleCoupling::SizeWorkSpace(const State& state) {
  previous_pass_ = state;  // sizes the work space (Step does not allocate)
  start_ = state;
  newton_ = state.newton;
}

StepStatus VehicleCoupling::Accept(const State& start, double h, State* state, StepStatus* status) {
  // remember lambda_n for the next step's predictor, and the water at the end of the step
  CouplingHistory& history = state->coupling;
  const int nv = static_cast<int>(history.f_previous.size());
  for (int v = 0; v < nv; ++v) {
    history.f_previous[v] = JointForce(start, v);
    history.flow_end[v] = inputs_->vehicle_flow_end[v];
  }
  history.h_previous = h;
  history.have_previous = true;
  history.flow_time = start.t + h;
  return *status;
}

void VehicleCoupling::CorrectVehicle(int end, const Vec3& r_W, double h, VehicleState* vs) const {
  // the mean force changes by r / 2 over the step: d nu = (h / 2) M^-1 J^T R_WB^T r, the
  // displacement and rotation (body frame) (h / 2) d nu, so that the attachment point moves by
  // (h^2 / 4) R_WB G R_WB^T r = C r
  const Mat3 r_wb = vs->q_WB.toRotationMatrix();
  const Vec6 dnu = (0.5 * h) * (m_inv_jt_[end] * (r_wb.transpose() * r_W));
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
  const bool strong = model.integrator.coupling == Coupling::kStrong;
  const int max_iterations = strong ? model.integrator.max_coupling_iterations : 1;
  const double tol = model.integrator.tolerance * std::max(1.0, model.cable.length);
  start_ = *state;
  const double t0 = state->t;

  // joint forces at t_n, and the current guess for t_{n+1}
  std::vector<Vec3>& f0 = f0_;
  std::vector<Vec3>& f1 = f1_;
  std::vector<Vec3>& residual = residual_;
  // predictor of lambda_{n+1}: linear extrapolation of the last two steps (strong scheme)
  const CouplingHistory& history = start_.coupling;
  const bool predict = strong && history.have_previous && history.h_previous > 0.0;
  for (int v = 0; v < nv; ++v) {
    f0[v] = f1[v] = JointForce(start_, v);
    if (predict) f1[v] += (h / history.h_previous) * (f0[v] - history.f_previous[v]);
  }
  // the water at each vehicle over the step, sampled once (the end at the pose predicted from
  // the start; the end of one step is the start of the next, State::coupling.flow_end)
  sampler_.SampleVehicleFlows(start_, h, inputs_);
  const StepInputs& in = *inputs_;
  // strong: the attachment point's response to the joint force over the step, (h^2 / 4) G in
  // the world frame at the attitude of t_n (see the header)
  Mat3 point_compliance[2] = {Mat3::Zero(), Mat3::Zero()};
  for (int e = 0; e < 2; ++e) {
    const int v = vehicle_end_[e];
    // (both ends on one vehicle: their forces are not told apart, no compliance)
    if (!strong || v < 0 || vehicle_end_[0] == vehicle_end_[1]) continue;
    const Mat3 r_wb = start_.vehicles[v].q_WB.toRotationMatrix();
    point_compliance[e] = (0.25 * h * h) * (r_wb * g_B_[e] * r_wb.transpose());
  }
  // vehicles over [t_n, t_n + h] under the joint force (Eq. 29-30); strong: the mean of
  // lambda_n and the guess of lambda_{n+1}, constant over the step (see the header)
  std::vector<VehicleState>& vehicles = vehicles_;
  auto advance_vehicles = [&] {
    vehicles = start_.vehicles;  // same size: copies in place
    for (int v = 0; v < nv; ++v) {
      PointLoad load;
      load.force_W0 = strong ? 0.5 * (f0[v] + f1[v]) : f0[v];
      load.force_W1 = load.force_W0;
      for (int e = 0; e < 2; ++e)
        if (vehicle_end_[e] == v)
          load.point_B = (e == 0 ? model.cable.start : model.cable.end).at_B;
      AdvanceVehicle(model.vehicles[v].params, inertia_[v], model.environment,
                     in.vehicle_flow_start[v], in.vehicle_flow_end[v], commands[v], load, h,
                     &vehicles[v], &system_.sea());
    }
  };
  advance_vehicles();
  StepStatus status;
  status.iterations = 0;
  for (int k = 1; k <= max_iterations; ++k) {
    last_iterations_ = k;
    // later passes start the cable's Newton from the previous pass (its supports moved a
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
    // the cable with the attachment points as driven supports that answer the joint force
    for (int e = 0; e < 2; ++e) {
      const int v = vehicle_end_[e];
      if (v < 0) continue;
      const Vec3 p0 = AttachmentPoint(start_.vehicles[v], e);
      state->supports[e] = {p0,   AttachmentPoint(vehicles[v], e), t0, t0 + h, point_compliance[e],
                            f1[v]};
      // Newton starts from the predicted joint force
      if (!point_compliance[e].isZero()) state->lambda.segment<3>(system_.EndLambda(e)) = f1[v];
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
    // the joint force the cable found against the guess the vehicles saw
    for (int v = 0; v < nv; ++v) residual[v] = JointForce(*state, v) - f1[v];
    // converged when the force residual moves no attachment point by more than the
    // tolerance: a compliant end by C r (the cable's end already sits at p1 + C r; its
    // vehicle then takes its linear response to r, below), an end without compliance (both
    // ends on one vehicle) by at most (h^2 / 2) g |r|
    double moved = 0.0;
    for (int e = 0; e < 2; ++e) {
      const int v = vehicle_end_[e];
      if (v < 0) continue;
      moved = std::max(moved, point_compliance[e].isZero()
                                  ? 0.5 * h * h * compliance_[e] * residual[v].norm()
                                  : (point_compliance[e] * residual[v]).lpNorm<Eigen::Infinity>());
    }
    if (moved <= tol) {
      for (int e = 0; e < 2; ++e) {
        const int v = vehicle_end_[e];
        if (v < 0 || point_compliance[e].isZero()) continue;
        CorrectVehicle(e, residual[v], h, &state->vehicles[v]);
        state->supports[e].p1 += point_compliance[e] * residual[v];
        state->supports[e].lambda1 += residual[v];
      }
      return Accept(start_, h, state, &status);
    }
    // the vehicles again under the cable's force; the cable's end sits where the linearized
    // response put them, p1 + C r: within the tolerance of where they went, converged
    for (int v = 0; v < nv; ++v) f1[v] += residual[v];
    advance_vehicles();
    double mismatch = 0.0;
    for (int e = 0; e < 2; ++e) {
      const int v = vehicle_end_[e];
      if (v < 0) continue;
      const Vec3 p1 = AttachmentPoint(vehicles[v], e);
      const SupportMotion& sm = state->supports[e];
      mismatch = std::max(mismatch,
                          (p1 - (sm.p1 + sm.compliance * residual[v])).lpNorm<Eigen::Infinity>());
    }
    if (mismatch <= tol) {
      state->vehicles = vehicles;
      for (int e = 0; e < 2; ++e) {
        const int v = vehicle_end_[e];
        if (v < 0) continue;
        state->supports[e].p1 = AttachmentPoint(vehicles[v], e);
        state->supports[e].lambda1 = f1[v];
      }
      return Accept(start_, h, state, &status);
    }
  }
  status.code = StepStatus::kNotConverged;
  std::ostringstream m;
  m << "vehicle-cable coupling did not converge in " << max_iterations
    << " iterations in the step from t = " << t0 << " s (h = " << h << " s)";
  status.message = m.str();
  return status;
}

}  // namespace towsim::core
