#include "core/static_solver.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace towsim::core {

using Eigen::VectorXd;

namespace {

// force scale for the convergence test: weight of cable and spheres plus a drag scale on the
// largest speed relative to the water at the initial node positions
double ForceScale(const System& sys, const Eigen::Vector3d& frame_velocity, const State& s) {
  const Model& m = sys.model();
  const Environment& env = m.environment;
  double rel = 0.0;
  for (int k = 0; k < sys.num_cables(); ++k)
    for (int i = 0; i < sys.num_nodes(k); ++i) {
      const FlowSample flow = sys.sea().Current(s.q.segment<3>(sys.CableDof(i, k)), s.t);
      rel = std::max(rel, RelativeVelocity(frame_velocity, flow).norm());
    }
  double f = 0.0;
  for (const CableParams& c : m.cables) {
    f += std::abs(c.mass_per_length - env.water_density * c.area()) * env.gravity * c.length;
    // C_n: the line type's, or about Choo & Casarella's (1.1-1.2)
    const double c_n = c.drag.kind == CableDragLaw::kConstant ? c.drag.normal : 1.2;
    f += 0.5 * env.water_density * c.diameter * c_n * rel * rel * c.length;
  }
  for (const SphereBody& b : m.spheres)
    f += std::abs(b.mass - env.water_density * b.volume) * env.gravity +
         0.5 * env.water_density * b.drag_coefficient * rel * rel * std::pow(b.volume, 2.0 / 3.0) *
             1.21;
  return std::max(f, 1.0);
}

}  // namespace

StaticResult SolveStatic(const System& sys, const Eigen::Vector3d& frame_velocity, State* s,
                         const std::function<bool()>& stop) {
  StaticResult res;
  const int n = sys.num_q(), m = sys.num_lambda();
  const double tol = sys.model().integrator.tolerance;
  const double f_tol = tol * ForceScale(sys, frame_velocity, *s);
  double q_scale = 1.0;
  for (const CableParams& c : sys.model().cables) q_scale = std::max(q_scale, c.length);
  s->v.setZero(n);
  for (int k = 0; k < sys.num_cables(); ++k)
    for (int i = 0; i < sys.num_nodes(k); ++i)
      s->v.segment<3>(sys.CableDof(i, k)) = frame_velocity;
  for (int b = 0; b < sys.num_spheres(); ++b) s->v.segment<3>(sys.SphereDof(b)) = frame_velocity;
  s->a.setZero(n);
  s->lambda.setZero(m);

  NetworkMatrix jac = sys.MakeMatrix();
  // calm water (no wave samples), the supports as the state holds them and the drum element
  // at its rest length now (held: no rate)
  StepInputs inputs;
  inputs.supports = s->supports;
  inputs.drums.resize(sys.num_winches());
  for (int w = 0; w < sys.num_winches(); ++w) {
    inputs.drums[w].t0 = s->t;
    inputs.drums[w].length = sys.drum_length(w);
  }
  VectorXd r, phi, rhs, dq, dl;
  constexpr int kMaxIterations = 2000;
  double delta = 1.0e-2;  // pseudo time step squared [s^2]
  double prev_norm = -1.0;
  for (int it = 1; it <= kMaxIterations; ++it) {
    if (stop && stop()) {
      res.stopped = true;
      return res;
    }
    res.iterations = it;
    // J = K + M_eff / delta (c_a = 1/delta, a = 0 in R); plain Newton once delta is huge
    const JacobianCoefficients cf{1.0, 0.0, delta > 1e12 ? 0.0 : 1.0 / delta};
    sys.Evaluate({s->q, s->v, s->a, s->lambda, s->t}, inputs, {1.0, cf}, {&r, &phi, &jac});
    const double norm = r.lpNorm<Eigen::Infinity>();
    res.residual = norm;
    if (!std::isfinite(norm) || !phi.allFinite()) break;
    if (norm <= f_tol && phi.lpNorm<Eigen::Infinity>() <= tol * q_scale) {
      res.ok = true;
      return res;
    }
    // switched evolution relaxation for the next iteration
    if (prev_norm > 0.0) delta *= std::clamp(prev_norm / norm, 0.2, 100.0);
    prev_norm = norm;
    sys.ToBlocks(-r, -phi, &rhs);
    if (!jac.Solve(&rhs)) {
      // singular (e.g. a slack cable without bending): damp harder
      delta = std::min(delta, 1e6) * 0.01;
      prev_norm = -1.0;
      continue;
    }
    sys.FromBlocks(rhs, &dq, &dl);
    // limit the step to a tenth of the cable length per iteration
    const double step = dq.lpNorm<Eigen::Infinity>();
    const double limit = 0.1 * q_scale;
    const double scale = step > limit ? limit / step : 1.0;
    s->q += scale * dq;
    s->lambda += scale * dl;
    if (!s->q.allFinite()) break;
  }
  std::ostringstream msg;
  int worst = 0;
  if (r.size()) r.cwiseAbs().maxCoeff(&worst);
  msg << "static equilibrium not found after " << res.iterations << " iterations: residual "
      << res.residual << " N (tolerance " << f_tol << " N), largest at "
      << sys.DescribeDof(worst, s->q);
  res.message = msg.str();
  return res;
}

}  // namespace towsim::core
