#include "core/integrator.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/newton_convergence.h"

namespace towsim::core {

using Eigen::VectorXd;

AlphaParameters AlphaParameters::FromSettings(const IntegratorSettings& s) {
  const double rho = s.scheme == Scheme::kTrapezoidal ? 1.0 : s.rho_inf;
  AlphaParameters p;
  p.alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
  p.alpha_f = rho / (rho + 1.0);
  p.gamma = 0.5 + p.alpha_f - p.alpha_m;
  p.beta = 0.25 * (p.gamma + 0.5) * (p.gamma + 0.5);
  return p;
}

Integrator::Integrator(const System& system, StepInputs* inputs)
    : system_(system),
      sampler_(system),
      inputs_(inputs),
      ap_(AlphaParameters::FromSettings(system.model().integrator)),
      q_scale_(IncrementScale(system.model())),
      weight_scale_(WetWeightScale(system.model())),
      slopes_at_most_inf_(ShortestElement(system) >= 1.0),
      jac_(system.MakeMatrix()) {
  const int n = system_.num_q(), m = system_.num_lambda();
  r_.setZero(n);
  phi_.setZero(m);
  q_star_.setZero(n);
  v_star_.setZero(n);
  a_const_.setZero(n);
  a_hat_.setZero(n);
  rhs_.setZero(n + m);
  dq_.setZero(n);
  dl_.setZero(m);
  dq_last_.setZero(n);
  dl_last_.setZero(m);
  backup_.resize(system.model().integrator.max_substep_level + 1);
  sampler_.Resize(inputs_);
  waves_ = system.sea().has_waves();
  if (waves_) wave_q_.setZero(n);
}

bool Integrator::InitializeAcceleration(State* s) {
  const int n = system_.num_q(), m = system_.num_lambda();
  s->a.setZero(n);
  s->lambda.setZero(m);
  JacobianCoefficients cf{0.0, 0.0, 1.0};
  s->newton.valid = false;  // jac_ now holds the mass matrix, not a Newton matrix
  if (waves_) sampler_.SampleWaves(s->q, s->t, inputs_);
  wave_time_ = -1.0;
  sampler_.TakeMotions(*s, inputs_);
  system_.Evaluate({s->q, s->v, s->a, s->lambda, s->t}, *inputs_, {1.0, cf}, {&r_, &phi_, &jac_});
  // acceleration-level constraints: Phi_q a = 0 (linear joints, constant driven velocity)
  phi_.setZero();
  system_.ToBlocks(-r_, phi_, &rhs_);
  if (!jac_.Solve(&rhs_)) return false;
  system_.FromBlocks(rhs_, &s->a, &s->lambda);
  s->a_alpha = s->a;
  return s->a.allFinite();
}

Integrator::Attempt Integrator::Newton(State* s, double h, bool full, const State* guess) {
  Attempt at;
  const AlphaParameters& p = ap_;
  const IntegratorSettings& settings = system_.model().integrator;
  const double h2 = h * h;
  State& st = *s;
  const double t1 = st.t + h;
  // q_{n+1} = q* + beta h^2 a^_{n+1}, v_{n+1} = v* + gamma h a^_{n+1}
  // preallocated members: Step does not allocate
  VectorXd& q_star = q_star_;
  VectorXd& v_star = v_star_;
  VectorXd& a_const = a_const_;
  VectorXd& a_hat = a_hat_;
  q_star.noalias() = st.q + h * st.v + (h2 * (0.5 - p.beta)) * st.a_alpha;
  v_star.noalias() = st.v + (h * (1.0 - p.gamma)) * st.a_alpha;
  a_const.noalias() = (p.alpha_m * st.a_alpha - p.alpha_f * st.a) / (1.0 - p.alpha_f);
  const double a_fac = (1.0 - p.alpha_m) / (1.0 - p.alpha_f);
  if (guess) {
    a_hat = guess->a_alpha;  // the nearby solution's a^_{n+1}
    st.lambda = guess->lambda;
  } else {
    a_hat = st.a_alpha;  // predictor a^_{n+1} = a^_n
  }
  st.q = q_star + (p.beta * h2) * a_hat;
  st.v = v_star + (p.gamma * h) * a_hat;
  st.a = a_const + a_fac * a_hat;
  const JacobianCoefficients cf{1.0, p.gamma / (p.beta * h), a_fac / (p.beta * h2)};
  const double tol = settings.tolerance * q_scale_;
  // the force bound: a fraction of the joint forces at the step's start (newton_convergence.h)
  const double force_tol =
      settings.force_tolerance * JointForceScale(system_, st.lambda, weight_scale_);
  at.force_bound = force_tol;
  NewtonPoint& kept = st.newton;  // the kept matrix in jac_ (State::newton)
  // a kept matrix whose last measured rate exceeds kRefreshRate is replaced at the step's
  // first evaluation, which then costs no extra residual (see the header)
  bool refresh = full || !kept.valid || kept.h != h || kept.theta > kRefreshRate;
  // the waves at t_{n+1} at the predicted positions, once per step (see the header)
  const bool waves_each_iteration = waves_ && settings.waves_per_iteration;
  if (waves_ && (t1 != wave_time_ || full) && !waves_each_iteration) {
    sampler_.SampleWaves(st.q, t1, inputs_);
    wave_q_ = st.q;  // copies in place
    wave_time_ = t1;
  }
  // the supports and the drum the vehicle coupling and the winch set for the step
  sampler_.TakeMotions(st, inputs_);
  ++kept.theta_age;  // one more step since the kept matrix's rate was measured
  // steps a first iteration may be accepted on the last measured rate (see the header)
  const int rate_age_limit = kept.theta_steady ? kMaxThetaAgeSteady : kMaxThetaAge;
  // a re-measurement: the first increment alone may not be accepted, its rate is too old
  bool remeasure = kept.theta_age > rate_age_limit;
  double dq_prev = 0.0;
  double residual_prev = 0.0;  // |r|_inf where the last increment was taken
  int formed_at = 0;  // the iteration this step formed the kept matrix at (0: none)
  for (int it = 1; it <= settings.max_iterations; ++it) {
    at.iterations = it;
    // residual always; the Newton matrix only when it is refreshed
    if (waves_each_iteration) sampler_.SampleWaves(st.q, t1, inputs_);
    system_.Evaluate({st.q, st.v, st.a, st.lambda, t1}, *inputs_, {1.0, cf},
                     {&r_, &phi_, refresh ? &jac_ : nullptr});
    if (!r_.allFinite() || !phi_.allFinite()) {
      at.non_finite = true;
      return at;
    }
    at.residual = r_.cwiseAbs().maxCoeff(&at.worst_dof);  // |r|_inf and where
    if (refresh) {
      kept.valid = false;
      if (!jac_.Factor()) {
        at.non_finite = true;
        return at;
      }
      // the point the matrix was formed at, to rebuild it from the state (RestoreNewtonMatrix);
      // copies in place (same sizes)
      kept.valid = true;
      kept.h = h;
      kept.t = t1;
      kept.q = st.q;
      kept.v = st.v;
      kept.a = st.a;
      const int nw = system_.num_winches();
      kept.drum_length.resize(nw);  // once: no allocation after
      kept.drum_rate.resize(nw);
      for (int w = 0; w < nw; ++w) {
        kept.drum_length[w] = st.winches[w].drum.LengthAt(t1);
        kept.drum_rate[w] = st.winches[w].drum.RateAt(t1);
      }
      if (waves_) kept.wave_q = waves_each_iteration ? st.q : wave_q_;
      kept.support_compliance.resize(st.supports.size());  // once: no allocation after
      for (size_t e = 0; e < st.supports.size(); ++e)
        kept.support_compliance[e] = st.supports[e].compliance;
      kept.theta = 0.0;
      // its rate at the point it was formed: ~0 (quadratic convergence); the test below takes
      // it at least kMaxContraction, and later steps measure it
      kept.theta_age = 0;
      kept.theta_steady = false;
      remeasure = false;
      formed_at = it;
      ++tangent_refreshes_;
    } else {
      at.reused = true;
    }
    // rhs = -[R; Phi] in block order (negated in place: no temporaries)
    system_.ToBlocks(r_, phi_, &rhs_);
    rhs_ = -rhs_;
    if (!jac_.SolveFactored(&rhs_)) {
      at.non_finite = true;
      return at;
    }
    system_.FromBlocks(rhs_, &dq_, &dl_);
    // contraction rate of a kept matrix (a fresh one converges quadratically: theta = 0)
    const double dq_norm = dq_.lpNorm<Eigen::Infinity>();
    // measured: the same matrix gave this increment and the one before
    const bool measured = !refresh && it > 1;
    if (measured) {
      kept.theta = dq_prev > 0.0 ? dq_norm / dq_prev : 0.0;
      kept.theta_age = 0;
      // a re-measurement that finds the rate small lengthens the interval to the next one; any
      // measurement that finds it not small shortens it again
      if (kept.theta >= kSteadyRate) {
        kept.theta_steady = false;
      } else if (remeasure) {
        kept.theta_steady = true;
      }
    }
    // uphill: the last increment raised the residual and the kept matrix's next one is no
    // smaller: the matrix no longer describes the residual between the two iterates (a contact
    // switching on), and its increments lead away from the solution. Both are taken back and
    // the next iteration forms a fresh matrix where the last one started (see the header)
    if (measured && kept.theta >= 1.0 && at.residual > residual_prev && formed_at != it - 1) {
      st.q -= dq_last_;
      st.lambda -= dl_last_;
      a_hat -= dq_last_ / (p.beta * h2);
      st.v = v_star + (p.gamma * h) * a_hat;
      st.a = a_const + a_fac * a_hat;
      refresh = true;
      continue;
    }
    residual_prev = at.residual;
    st.q += dq_;
    st.lambda += dl_;
    a_hat += dq_ / (p.beta * h2);
    st.v = v_star + (p.gamma * h) * a_hat;
    st.a = a_const + a_fac * a_hat;
    dq_last_.swap(dq_);  // the increment just taken, for the uphill test (no copy)
    dl_last_.swap(dl_);
    dq_prev = dq_norm;
    // the error left after the increment, theta / (1 - theta) |dq|, within the tolerance,
    // with theta at least kMaxContraction (a rate measured on large increments understates the
    // one the next, smaller increments show; the refresh rule admits rates up to it). The rate
    // must be known: a fresh matrix (theta ~ 0, quadratic convergence: the floor makes the
    // test |dq| <= 2.3 tol, as for a kept matrix; the increment after such an accepted one is
    // 1e-5 tol in Case 1), or a kept one measured in this step or, for the first iteration,
    // at most kMaxThetaAge steps ago
    const bool rate_known = refresh || measured || kept.theta_age <= rate_age_limit;
    const double theta = std::max(kept.theta, kMaxContraction);
    bool converged = rate_known && theta < 1.0 && theta / (1.0 - theta) * dq_norm <= tol;
    // and the force residual the increment leaves, about theta |r_k| (newton_convergence.h);
    // an increment within its bound with a residual above it takes another iteration
    if (converged) {
      // |r|_F <= |r|_inf when every element is at least 1 m long (slope rows divided by l_e):
      // the plain norm, already known, decides most steps
      at.force_residual = theta * at.residual;
      if (!(slopes_at_most_inf_ && at.force_residual <= force_tol))
        at.force_residual = theta * ForceResidualNorm(system_, r_);
      converged = at.force_residual <= force_tol;
      if (!converged) ForceResidualNorm(system_, r_, &at.worst_force_dof);  // for the diagnosis
    }
    if (converged) {
      at.ok = true;
      st.a_alpha = a_hat;
      st.t = t1;
      return at;
    }
    // a kept matrix whose rate is unknown here (measured more than kMaxKeepAge steps ago) and
    // whose first increment is too large to be accepted is replaced for the second
    // evaluation: such a matrix would most likely not converge in that one (see the header)
    const bool stale = it == 1 && !refresh && kept.theta_age > kMaxKeepAge &&
                       !(theta < 1.0 && theta / (1.0 - theta) * dq_norm <= tol);
    // a matrix formed at the previous iterate that already fails to contract: the residual is
    // too nonlinear between two iterates for a kept matrix (a contact switching on), and one
    // formed again at the next iterate would lead back to this one (docs/physics.md, "Newton
    // convergence"): fresh matrices for the rest of the step
    if (measured && formed_at == it - 1 && kept.theta > kMaxContraction) full = true;
    refresh = full || kept.theta > kMaxContraction || stale;
  }
  return at;
}

StepStatus Integrator::Advance(State* s, double h, int level, const State* guess) {
  StepStatus status;
  backup_[level] = *s;
  Attempt at = Newton(s, h, false, guess);
  status.iterations = at.iterations;
  if (!at.ok && at.reused) {
    // the kept matrix may be what failed: retry with classic Newton before halving
    *s = backup_[level];
    s->newton.valid = false;  // jac_ may no longer hold the backup's kept matrix
    at = Newton(s, h, true, nullptr);
    status.iterations += at.iterations;
  }
  status.residual = at.residual;
  if (at.ok) return status;
  last_failure_ = at;
  *s = backup_[level];
  s->newton.valid = false;  // jac_ may no longer hold the backup's kept matrix
  if (level >= system_.model().integrator.max_substep_level) {
    status.code = at.non_finite ? StepStatus::kNonFinite : StepStatus::kNotConverged;
    return status;
  }
  StepStatus total;
  total.substeps = 0;
  total.iterations = status.iterations;
  for (int half = 0; half < 2; ++half) {
    const StepStatus sub = Advance(s, 0.5 * h, level + 1, nullptr);
    total.iterations += sub.iterations;
    total.substeps += sub.substeps;
    total.residual = std::max(total.residual, sub.residual);
    if (!sub.ok()) {
      total.code = sub.code;
      return total;
    }
  }
  return total;
}

bool Integrator::RestoreNewtonMatrix(const State& s) {
  wave_time_ = -1.0;
  const NewtonPoint& kept = s.newton;
  if (!kept.valid) return true;
  // the same evaluation as the refresh that formed it (Newton): bit for bit the same matrix
  const double h = kept.h, h2 = h * h;
  const double a_fac = (1.0 - ap_.alpha_m) / (1.0 - ap_.alpha_f);
  const JacobianCoefficients cf{1.0, ap_.gamma / (ap_.beta * h), a_fac / (ap_.beta * h2)};
  if (waves_) sampler_.SampleWaves(kept.wave_q, kept.t, inputs_);
  // the supports' compliances it was formed with, over a step ending at kept.t (the matrix
  // depends on nothing else of the supports), and the drum element as it was then (a constant
  // motion at its length and rate)
  sampler_.TakeMotions(s, inputs_);
  for (size_t e = 0; e < inputs_->supports.size(); ++e) {
    SupportMotion& support = inputs_->supports[e];
    support.compliance = kept.support_compliance[e];
    support.t0 = kept.t - h;
    support.t1 = kept.t;
  }
  for (size_t w = 0; w < kept.drum_length.size(); ++w) {
    DrumMotion& drum = inputs_->drums[w];
    drum = DrumMotion();
    drum.t0 = kept.t;
    drum.length = kept.drum_length[w];
    drum.rate = kept.drum_rate[w];
  }
  system_.Evaluate({kept.q, kept.v, kept.a, s.lambda, kept.t}, *inputs_, {1.0, cf},
                   {&r_, &phi_, &jac_});
  return jac_.Factor();
}

StepStatus Integrator::Step(State* s, double h, const State* guess) {
  const double t0 = s->t;
  StepStatus status = Advance(s, h, 0, guess);
  if (status.ok() && !(s->q.allFinite() && s->v.allFinite())) status.code = StepStatus::kNonFinite;
  if (!status.ok()) {
    const int levels = system_.model().integrator.max_substep_level;
    std::ostringstream m;
    m << (status.code == StepStatus::kNonFinite ? "non-finite state" : "Newton did not converge")
      << " in the step from t = " << t0 << " s (h = " << h << " s, halved up to " << levels
      << " times, smallest substep " << h / (1 << levels) << " s) at t = " << s->t
      << " s; last attempt: " << last_failure_.iterations << " iterations, residual "
      << last_failure_.residual << " N, largest at "
      << system_.DescribeDof(last_failure_.worst_dof, s->q);
    // an attempt whose increments met their bound but whose forces did not (a stiff cable at a
    // loose tolerance): say so, with the bound
    if (last_failure_.force_residual > last_failure_.force_bound)
      m << "; the increments met the tolerance but the force residual they left, "
        << last_failure_.force_residual << " N (at "
        << system_.DescribeDof(last_failure_.worst_force_dof, s->q)
        << "), is above its bound " << last_failure_.force_bound
        << " N (integrator.force_tolerance x the largest joint force: docs/physics.md, "
           "\"Newton convergence\")";
    status.message = m.str();
  }
  return status;
}

}  // namespace towsim::core
