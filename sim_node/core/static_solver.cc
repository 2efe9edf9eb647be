#include "core/static_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/fold_check.h"
#include "core/gauss_quadrature.h"
#include "core/initial_shape.h"
#include "core/newton_convergence.h"

namespace towsim::core {

using Eigen::VectorXd;

namespace {

// the pseudo time step squared above which the iteration is plain Newton [s^2]
constexpr double kPlainNewton = 1e13;
// the least factor by which the pseudo time step grows after an iteration that did not raise
// the residual. Switched evolution relaxation alone (delta times |R_{k-1}| / |R_k|) stalls
// where the residual is held by a force that stays while the shape travels toward equilibrium
// (a towed body swinging back from where the scene puts it: |R| falls 10 % in 30 iterations
// and the shape moves 0.25 m an iteration, 634 iterations for winch_payout's 150 m); growing
// delta geometrically meanwhile reaches plain Newton in tens of iterations (winch_payout's
// start-up: 345 M -> 36 M instructions), and a residual that then rises shrinks it again
constexpr double kMinGrowth = 1.5;
// a chord iteration (SolveChord) ends at this measured contraction rate, or after this many
// iterations: a small move of the supports contracts at ~1e-3 and needs 2-3
constexpr double kChordMaxRate = 0.5;
constexpr int kChordIterations = 8;
// plain Newton iterations a warm start may take (quadratic convergence from a nearby root
// takes 2-4) before the solve starts again from the pseudo-transient's first step
constexpr int kWarmIterations = 8;
// iterations whose increments are within their bound while the residual, above its own, does
// not halve: the residual has reached the round-off of the cable's forces (a long stiff cable
// on the seabed: its elastic and contact forces, 1e5-1e6 N, leave residuals of 1e-8 N however
// far Newton goes, while its increments are 1e-13 m), and the solve stops with that diagnosis
// instead of iterating on to kMaxIterations
constexpr int kRoundOffIterations = 10;

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
  double f = WetWeight(m);  // newton_convergence.h
  for (const CableParams& c : m.cables) {
    // C_n: the line type's, or about Choo & Casarella's (1.1-1.2)
    const double c_n = c.drag.kind == CableDragLaw::kConstant ? c.drag.normal : 1.2;
    f += 0.5 * env.water_density * c.diameter * c_n * rel * rel * c.length;
  }
  for (const SphereBody& b : m.spheres)
    f += 0.5 * env.water_density * b.drag_coefficient * rel * rel * std::pow(b.volume, 2.0 / 3.0) *
         1.21;
  return std::max(f, kMinForceScale);
}

// why the converged shape at *s is not a cable's (fold_check.h, the tension bound of
// static_solver.h), or empty
std::string CheckShape(const System& sys, const Eigen::Vector3d& frame_velocity, const State& s) {
  const FoldReport fold = FindFold(sys, s.q);
  if (fold.folded) return fold.Describe(sys);
  for (int c = 0; c < sys.num_cables(); ++c) {
    const double turning = TotalTurning(sys, s.q, c);
    if (turning <= kMaxStaticTurning) continue;
    std::ostringstream msg;
    msg << "cable '" << sys.model().cables[c].name << "' is looped: its tangent turns through "
        << turning * 180.0 / M_PI << " deg from end to end (a cable at rest: less than 180 deg, "
        << "at most " << kMaxStaticTurning * 180.0 / M_PI << ")";
    return msg.str();
  }
  double support = 0.0;  // the largest support force
  for (int c = 0; c < sys.num_cables(); ++c)
    for (int end = 0; end < 2; ++end)
      if (sys.end_lambda_count(end, c) >= 3)
        support = std::max(support, s.lambda.segment<3>(sys.EndLambda(end, c)).norm());
  const double bound = kTensionBoundFactor * (support + ForceScale(sys, frame_velocity, s));
  // each element's mean axial force EA (l_s / l - 1) from its stretched length
  // l_s = int_0^1 |dr/dxi| dxi (3-point Gauss on the cubic Hermite shape, Eq. 4): the node values
  // of the Green strain carry the coarse elements' curvature error, the length does not
  const GaussRule<3> gauss = Gauss3();
  for (int c = 0; c < sys.num_cables(); ++c) {
    const double ea = sys.model().cables[c].axial_stiffness;
    for (int e = 0; e < sys.NumElements(c); ++e) {
      const int o = sys.CableDof(e, c);
      const double l = sys.RestLength(e, c);
      const Vec3 ra = s.q.segment<3>(o), da = s.q.segment<3>(o + 3);
      const Vec3 rb = s.q.segment<3>(o + 6), db = s.q.segment<3>(o + 9);
      double stretched = 0.0;
      for (int g = 0; g < 3; ++g) {
        const double x = gauss.xi[g];
        // d/dxi of the Hermite functions h00, l h10, h01, l h11
        const Vec3 d = (6.0 * x * x - 6.0 * x) * (ra - rb) +
                       l * ((3.0 * x * x - 4.0 * x + 1.0) * da + (3.0 * x * x - 2.0 * x) * db);
        stretched += gauss.weight[g] * d.norm();
      }
      const double strain = stretched / l - 1.0;
      const double force = ea * strain;
      if (std::abs(force) <= bound) continue;
      std::ostringstream msg;
      msg << "cable '" << sys.model().cables[c].name << "' element " << e << " (nodes " << e
          << "-" << e + 1 << "): mean axial force " << force << " N (strain " << strain
          << "), beyond what the loads can give (" << bound << " N: " << kTensionBoundFactor
          << " x (largest support force " << support << " N + external loads "
          << bound / kTensionBoundFactor - support << " N))";
      return msg.str();
    }
  }
  return {};
}

// the frame's velocity on every node position and body, no acceleration (the static state's
// v and a)
void SetFrameMotion(const System& sys, const Eigen::Vector3d& frame_velocity, State* s) {
  const int n = sys.num_q();
  s->v.setZero(n);
  for (int k = 0; k < sys.num_cables(); ++k)
    for (int i = 0; i < sys.num_nodes(k); ++i)
      s->v.segment<3>(sys.CableDof(i, k)) = frame_velocity;
  for (int b = 0; b < sys.num_spheres(); ++b) s->v.segment<3>(sys.SphereDof(b)) = frame_velocity;
  s->a.setZero(n);
}

// the inputs of a static evaluation: calm water (no wave samples), the supports as the state
// holds them and the drum element at its rest length now (held: no rate)
StepInputs StaticInputs(const System& sys, const State& s) {
  StepInputs inputs;
  inputs.supports = s.supports;
  inputs.drums.resize(sys.num_winches());
  for (int w = 0; w < sys.num_winches(); ++w) {
    inputs.drums[w].t0 = s.t;
    inputs.drums[w].length = sys.drum_length(w);
  }
  return inputs;
}

// a chord iteration from the nearby equilibrium in *s (its multipliers kept) with the factors
// of a Newton matrix formed near it: residuals only, x_{k+1} = x_k - A^-1 [R; Phi](x_k). It
// contracts at a rate theta = |dq_{k+1}| / |dq_k| (small for a small move of the supports);
// the distance to the root is about |dq| / (1 - theta), so it is accepted at the current
// iterate when the residual is met and |dq| / (1 - theta) is within the increment bound, theta
// taken as kChordMaxRate until measured. A rate above kChordMaxRate, or kChordIterations
// without convergence, end it (not ok: the caller solves with fresh matrices)
StaticResult SolveChord(const System& sys, const Eigen::Vector3d& frame_velocity, State* s,
                        NetworkMatrix* chord, double tol) {
  StaticResult res;
  const int m = sys.num_lambda();
  if (s->lambda.size() != m) return res;
  const double f_tol = tol * ForceScale(sys, frame_velocity, *s);
  const double q_scale = IncrementScale(sys.model());
  SetFrameMotion(sys, frame_velocity, s);
  const StepInputs inputs = StaticInputs(sys, *s);
  const JacobianCoefficients cf{1.0, 0.0, 0.0};
  VectorXd r, phi, rhs, dq, dl;
  double prev_step = 0.0, theta = kChordMaxRate;
  for (int it = 1; it <= kChordIterations; ++it) {
    res.iterations = it;
    sys.Evaluate({s->q, s->v, s->a, s->lambda, s->t}, inputs, {1.0, cf}, {&r, &phi, nullptr});
    const double norm = r.lpNorm<Eigen::Infinity>();
    res.residual = norm;
    if (!std::isfinite(norm) || !phi.allFinite()) return res;
    const bool residual_met = norm <= f_tol && phi.lpNorm<Eigen::Infinity>() <= tol * q_scale;
    sys.ToBlocks(-r, -phi, &rhs);
    if (!chord->SolveFactored(&rhs)) return res;
    sys.FromBlocks(rhs, &dq, &dl);
    const double step = dq.lpNorm<Eigen::Infinity>();
    if (it > 1) {
      theta = step / prev_step;
      if (!(theta < kChordMaxRate)) return res;
    }
    if (residual_met && step / (1.0 - theta) <= tol * q_scale) {
      // the increment already solved for is taken too: it costs nothing and removes all but
      // about theta of the error left
      s->q += dq;
      s->lambda += dl;
      res.ok = true;
      return res;
    }
    if (!(step <= 0.1 * q_scale)) return res;  // a move this far is no chord's
    s->q += dq;
    s->lambda += dl;
    prev_step = step;
  }
  return res;
}

// one pseudo-transient Newton solve from *s; slope_limit bounds the change of every slope
// component per iteration (infinite: no bound). `warm`: *s is an equilibrium of nearby
// supports, its multipliers kept: plain Newton from the first iteration, at most
// kWarmIterations of them, the increment shrinking in each (else not ok, res.message empty).
// A converged solve leaves its last matrix's factors in *factors_out (if set)
StaticResult Solve(const System& sys, const Eigen::Vector3d& frame_velocity, State* s,
                   const std::function<bool()>& stop, double slope_limit, double tol,
                   bool warm = false, StaticFactors* factors_out = nullptr) {
  StaticResult res;
  const int m = sys.num_lambda();
  const double force_scale = ForceScale(sys, frame_velocity, *s);
  const double f_tol = tol * force_scale;
  const double q_scale = IncrementScale(sys.model());
  SetFrameMotion(sys, frame_velocity, s);
  if (!warm || s->lambda.size() != m) s->lambda.setZero(m);

  NetworkMatrix jac = sys.MakeMatrix();
  const StepInputs inputs = StaticInputs(sys, *s);
  VectorXd r, phi, rhs, dq, dl;
  constexpr int kMaxIterations = 2000;
  double delta = warm ? kPlainNewton : 1.0e-2;  // pseudo time step squared [s^2]
  double prev_norm = -1.0;
  double prev_step = std::numeric_limits<double>::infinity();  // |dq| of the last iteration
  int at_round_off = 0;     // iterations in a row with the increment met, the residual not
  double round_off = 0.0;   // ... and the residual when they began
  bool stalled = false;     // ended there: the residual is the round-off of the forces
  for (int it = 1; it <= (warm ? kWarmIterations : kMaxIterations); ++it) {
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
    // converged: the residual within the force bound and the constraints within the length
    // bound, and the increment this residual asks for within the length bound too (below: a
    // soft direction, e.g. a slack span, can hold a small residual far from equilibrium);
    // accepted at the current iterate
    const bool residual_met = norm <= f_tol && phi.lpNorm<Eigen::Infinity>() <= tol * q_scale;
    // switched evolution relaxation for the next iteration
    if (prev_norm > 0.0) {
      // ... growing by at least kMinGrowth after an iteration that did not raise the residual
      double grow = std::clamp(prev_norm / norm, 0.2, 100.0);
      if (grow >= 1.0) grow = std::max(grow, kMinGrowth);
      delta *= grow;
    }
    prev_norm = norm;
    sys.ToBlocks(-r, -phi, &rhs);
    if (!jac.Solve(&rhs)) {
      if (warm) return res;
      // singular (e.g. a slack cable without bending): damp harder
      delta = std::min(delta, 1e6) * 0.01;
      prev_norm = -1.0;
      continue;
    }
    sys.FromBlocks(rhs, &dq, &dl);
    if (residual_met && dq.lpNorm<Eigen::Infinity>() <= tol * q_scale) {
      // the increment already solved for is taken too: near the root Newton's error after it
      // is of the order of |dq|^2 (for a plain Newton matrix), against |dq| before; it costs
      // no evaluation, and the acceptance is unchanged (docs/physics.md, "Initial shapes")
      s->q += dq;
      s->lambda += dl;
      res.ok = true;
      if (factors_out) {
        // the factors of the last matrix, formed at this iterate: a chord for nearby solves
        std::swap(factors_out->matrix, jac);
        factors_out->valid = true;
      }
      return res;
    }
    // limit the step to a tenth of the cable length per iteration
    const double step = dq.lpNorm<Eigen::Infinity>();
    // the increments within their bound but the residual not: once it no longer halves, it
    // is the round-off of the forces (kRoundOffIterations)
    if (!warm && norm > f_tol && step <= tol * q_scale) {
      if (at_round_off == 0 || norm <= 0.5 * round_off) {
        at_round_off = 0;
        round_off = norm;
      }
      if (++at_round_off > kRoundOffIterations) {
        stalled = true;
        break;
      }
    } else {
      at_round_off = 0;
    }
    // plain Newton near a root shrinks its increment at every iteration (the first is the
    // supports' move: the residual alone does not see a moved support); one that does not is
    // not near enough (the caller solves again from the start)
    if (warm && !(step < prev_step)) return res;
    prev_step = step;
    const double limit = 0.1 * q_scale;
    double scale = step > limit ? limit / step : 1.0;
    if (std::isfinite(slope_limit)) {
      double slope_step = 0.0;
      for (int c = 0; c < sys.num_cables(); ++c)
        for (int i = 0; i < sys.num_nodes(c); ++i)
          slope_step =
              std::max(slope_step, dq.segment<3>(sys.CableDof(i, c) + 3).lpNorm<Eigen::Infinity>());
      if (scale * slope_step > slope_limit) scale = slope_limit / slope_step;
    }
    s->q += scale * dq;
    s->lambda += scale * dl;
    if (!s->q.allFinite()) break;
  }
  if (warm) return res;
  std::ostringstream msg;
  int worst = 0;
  if (r.size()) r.cwiseAbs().maxCoeff(&worst);
  msg << "static equilibrium not found after " << res.iterations << " iterations: residual "
      << res.residual << " N (tolerance " << f_tol << " N), largest at "
      << sys.DescribeDof(worst, s->q);
  if (stalled) {
    // the tolerance the residual would meet: the next power of ten above twice its floor
    const double floor = 2.0 * res.residual / force_scale;
    const double met = std::pow(10.0, std::ceil(std::log10(floor)));
    msg << "; the increments met their bound but the residual stopped falling: it is the "
           "round-off of the forces, and integrator.tolerance "
        << tol << " asks for less (about " << met << " would be met)";
  }
  res.message = msg.str();
  return res;
}

}  // namespace

StaticResult SolveStatic(const System& sys, const Eigen::Vector3d& frame_velocity, State* s,
                         const std::function<bool()>& stop, double tolerance, StaticStart start,
                         StaticFactors* chord, StaticFactors* factors_out) {
  const State guess = *s;
  const double tol = tolerance > 0.0 ? tolerance : sys.model().integrator.tolerance;
  // factors only from a solve that ends with an accepted equilibrium
  auto without_factors = [&](StaticResult r) {
    if (factors_out && factors_out != chord) factors_out->valid = false;
    return r;
  };
  if (factors_out && factors_out != chord) factors_out->valid = false;
  constexpr double kNoSlopeLimit = std::numeric_limits<double>::infinity();
  int warm_iterations = 0;
  if (start == StaticStart::kNearEquilibrium) {
    // the chord with the nearby equilibrium's factors, then plain Newton from it; each shape
    // checked like any other
    if (chord && chord->valid) {
      StaticResult c = SolveChord(sys, frame_velocity, s, &chord->matrix, tol);
      c.attempts = 1;
      if (c.ok && CheckShape(sys, frame_velocity, *s).empty()) {
        if (factors_out && factors_out != chord) *factors_out = *chord;
        return c;
      }
      *s = guess;
      warm_iterations = c.iterations;
    }
    StaticResult warm = Solve(sys, frame_velocity, s, stop, kNoSlopeLimit, tol, true, factors_out);
    warm.attempts = 1;
    warm.iterations += warm_iterations;
    if (warm.stopped) return without_factors(warm);
    if (warm.ok && CheckShape(sys, frame_velocity, *s).empty()) return warm;
    *s = guess;
    warm_iterations = warm.iterations;
  }
  StaticResult first = Solve(sys, frame_velocity, s, stop, kNoSlopeLimit, tol, false, factors_out);
  first.iterations += warm_iterations;
  first.attempts = 1;
  if (first.stopped) return without_factors(first);
  std::string why = first.ok ? CheckShape(sys, frame_velocity, *s) : first.message;
  if (first.ok && why.empty()) return first;
  // the second attempt: the slack-free catenary guess for every cable with two known ends,
  // slopes limited per iteration
  *s = guess;
  for (int c = 0; c < sys.num_cables(); ++c) LayOutCatenary(sys, c, s);
  StaticResult second = Solve(sys, frame_velocity, s, stop, kMaxSlopeStep, tol, false, factors_out);
  second.attempts = 2;
  second.iterations += first.iterations;
  second.rejected = (first.ok ? "converged to a shape that is not a cable's: " : "") + why;
  if (second.stopped) return without_factors(second);
  const std::string why2 = second.ok ? CheckShape(sys, frame_velocity, *s) : second.message;
  if (second.ok && why2.empty()) return second;
  second.ok = false;
  second.message = "static equilibrium not found: from the initial guess " + second.rejected +
                   "; from the catenary guess " +
                   (second.ok || why2 != second.message
                        ? "converged to a shape that is not a cable's: " + why2
                        : why2) +
                   " (docs/physics.md, \"Initial shapes\")";
  return without_factors(second);
}

}  // namespace towsim::core
