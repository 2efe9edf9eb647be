#include "core/vehicle_balance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Dense>

#include "core/actuator.h"
#include "core/constants.h"

namespace towsim::core {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

constexpr int kMaxIterations = 100;     // Levenberg-Marquardt iterations
constexpr int kMaxTries = 16;           // damping increases within one iteration
constexpr int kStallWindow = 10;        // iterations over which |R| must fall ...
constexpr double kStall = 0.9;          // ... below this fraction of its value
constexpr int kLimitIterations = 3;     // iterations a thrust may sit at its limit
constexpr double kMaxTurn = 0.2;        // largest attitude change per step [rad]
constexpr double kMaxShift = 0.1;       // largest position change per step, of the cable [-]
constexpr double kStepPosition = 1e-4;  // difference steps: of the vehicle's length [m / m],
constexpr double kStepAngle = 1e-5;     // [rad]
constexpr double kStepThrust = 1e-5;    // of max_thrust [N / N]
// the cables' static solves inside the balance converge to this relative tolerance: the
// difference quotients divide their errors by the steps above (1e-5 relative), so a solve
// converged only to the run's tolerance (1e-8) would leave them 0.1 % noisy (1e-12 is
// below the round-off of a stiff cable's elastic forces, EA eps L / l)
constexpr double kCableTolerance = 1e-10;

// the unknowns of one vehicle, in this order; a towing vehicle has no kX, kY but kThrust
enum Unknown { kX, kY, kZ, kRoll, kPitch, kYaw, kThrustUnknown };

struct Variable {
  int vehicle = 0;
  Unknown unknown = kX;
};

struct VehiclePose {
  Vec3 p = Vec3::Zero();
  Vec3 rpy = Vec3::Zero();
  double thrust = 0.0;
};

class Balance {
 public:
  Balance(const System& sys, const Vec3& frame_velocity, std::vector<VehicleCommand>* commands)
      : sys_(sys), vf_(frame_velocity), commands_(*commands), held_(HeldVehicles(sys)) {
    const Model& m = sys.model();
    min_length_ = std::numeric_limits<double>::infinity();
    for (const CableParams& c : m.cables) min_length_ = std::min(min_length_, c.length);
    const int nv = static_cast<int>(m.vehicles.size());
    towing_.assign(nv, false);
    ends_.resize(nv);
    for (int v : held_) {
      towing_[v] = IsTowingVehicle(sys, v);
      ends_[v] = sys.VehicleEnds(v);
      for (int u = towing_[v] ? kZ : kX; u <= kYaw; ++u)
        vars_.push_back({v, static_cast<Unknown>(u)});
      if (towing_[v]) vars_.push_back({v, kThrustUnknown});
    }
  }

  const std::vector<int>& held() const { return held_; }
  int size() const { return static_cast<int>(vars_.size()); }

  // the unknowns' values from the vehicles' poses of *s and the commands
  void Read(const State& s, std::vector<VehiclePose>* poses) const {
    poses->assign(sys_.model().vehicles.size(), VehiclePose());
    for (int v : held_) {
      (*poses)[v].p = s.vehicles[v].p_W;
      (*poses)[v].rpy = EulerZYX(s.vehicles[v].q_WB);
      (*poses)[v].thrust = commands_[v].thrust;
    }
  }

  // Each vehicle's position is an unknown in spherical coordinates about the far end c of the
  // first cable it holds (range rho = |p - c|, azimuth, elevation), c taken from the current
  // equilibrium *s: a taut cable makes R stiff along its chord and soft across it, and the
  // valley of small |R| is a sphere about c, straight in these coordinates (in Cartesian ones
  // every straight step leaves it, and Levenberg-Marquardt crawls).
  void SetPivots(const State& s) {
    pivot_.assign(sys_.model().vehicles.size(), Vec3::Zero());
    for (int v : held_) {
      const int end = ends_[v].front(), c = end / 2;
      const int far = end % 2 == 0 ? sys_.num_nodes(c) - 1 : 0;
      pivot_[v] = s.q.segment<3>(sys_.CableDof(far, c));
    }
  }
  // the range of vehicle v from its pivot [m]
  double Range(int v, const std::vector<VehiclePose>& poses) const {
    return std::max(1.0, (poses[v].p - pivot_[v]).norm());
  }

  VectorXd Pack(const std::vector<VehiclePose>& poses) const {
    VectorXd x(size());
    for (int i = 0; i < size(); ++i) {
      const int v = vars_[i].vehicle;
      const Vec3 d = poses[v].p - pivot_[v];
      switch (vars_[i].unknown) {
        case kX: x[i] = d.norm(); break;
        case kY: x[i] = std::atan2(d.y(), d.x()); break;
        case kZ:
          // a towing vehicle keeps x, y: its depth is its own
          x[i] = towing_[v] ? poses[v].p.z() : std::atan2(d.z(), d.head<2>().norm());
          break;
        case kRoll: x[i] = poses[v].rpy.x(); break;
        case kPitch: x[i] = poses[v].rpy.y(); break;
        case kYaw: x[i] = poses[v].rpy.z(); break;
        default: x[i] = poses[v].thrust;
      }
    }
    return x;
  }
  void Unpack(const VectorXd& x, std::vector<VehiclePose>* poses) const {
    for (int i = 0; i < size(); ++i) {
      const int v = vars_[i].vehicle;
      VehiclePose& pose = (*poses)[v];
      switch (vars_[i].unknown) {
        case kX: {  // range, azimuth and elevation come in this order
          const double rho = x[i], az = x[i + 1], el = x[i + 2];
          pose.p = pivot_[v] + rho * Vec3(std::cos(el) * std::cos(az),
                                          std::cos(el) * std::sin(az), std::sin(el));
          i += 2;
          break;
        }
        case kZ: pose.p.z() = x[i]; break;  // a towing vehicle's depth
        case kRoll: pose.rpy.x() = x[i]; break;
        case kPitch: pose.rpy.y() = x[i]; break;
        case kYaw: pose.rpy.z() = x[i]; break;
        default: pose.thrust = x[i];
      }
    }
  }
  // whether unknown i is an angle of a position (azimuth, elevation)
  bool PositionAngle(int i) const {
    const Unknown u = vars_[i].unknown;
    return u == kY || (u == kZ && !towing_[vars_[i].vehicle]);
  }

  // the difference step of unknown i (about the poses `at`)
  double Step(int i, const std::vector<VehiclePose>& at) const {
    const int v = vars_[i].vehicle;
    const VehicleParams& p = sys_.model().vehicles[v].params;
    if (PositionAngle(i)) return kStepPosition * std::max(1.0, p.length) / Range(v, at);
    switch (vars_[i].unknown) {
      case kX: case kZ: return kStepPosition * std::max(1.0, p.length);
      case kThrustUnknown: return kStepThrust * std::max(1.0, p.max_thrust);
      default: return kStepAngle;
    }
  }
  // scales the step dx so that no position moves by more than kMaxShift of the shortest
  // cable, no angle by more than kMaxTurn and no thrust by more than half its range
  void Limit(VectorXd* dx, const std::vector<VehiclePose>& at) const {
    double f = 1.0;
    for (int i = 0; i < size(); ++i) {
      const double d = std::abs((*dx)[i]);
      double cap = kMaxTurn;
      if (vars_[i].unknown <= kZ) cap = kMaxShift * min_length_;
      if (PositionAngle(i)) cap /= Range(vars_[i].vehicle, at);
      if (vars_[i].unknown == kThrustUnknown)
        cap = 0.5 * std::max(1.0, sys_.model().vehicles[vars_[i].vehicle].params.max_thrust);
      if (d > cap) f = std::min(f, cap / d);
    }
    *dx *= f;
  }

  // The vehicles at `poses`, the cables solved against them (s in: the guess, or with `chord`
  // the equilibrium at nearby poses and its Newton matrix's factors; out: the equilibrium,
  // its factors into *factors if set), and the vehicles' residuals r (6 per held vehicle:
  // (M_RB + M_A) nu_dot). False if the cables' static solve fails (its message in *why).
  bool Evaluate(const std::vector<VehiclePose>& poses, State* s, VectorXd* r, std::string* why,
                const std::function<bool()>& stop, bool* stopped, StaticFactors* chord,
                StaticFactors* factors) {
    const Model& m = sys_.model();
    for (int v : held_) Place(v, poses[v], s);
    ++solves_;
    const StaticResult res =
        SolveStatic(sys_, vf_, s, stop, kCableTolerance,
                    chord ? StaticStart::kNearEquilibrium : StaticStart::kGuess, chord, factors);
    if (res.stopped) *stopped = true;
    if (!res.ok) {
      *why = res.message;
      return false;
    }
    r->resize(6 * static_cast<int>(held_.size()));
    for (size_t k = 0; k < held_.size(); ++k) {
      const int v = held_[k];
      const VehicleParams& p = m.vehicles[v].params;
      const VehicleState& vs = s->vehicles[v];
      const Mat3 r_wb = vs.q_WB.toRotationMatrix();
      Vec3 force_B = Vec3::Zero(), moment_B = Vec3::Zero();
      for (const int end : ends_[v]) {
        // the joint force on the vehicle is the end's multiplier (Eq. 29-30)
        const Vec3 f_B = r_wb.transpose() * s->lambda.segment<3>(sys_.EndLambda(end % 2, end / 2));
        force_B += f_B;
        moment_B += sys_.End(end % 2, end / 2).at_B.cross(f_B);
      }
      if (sys_.sea().has_seabed()) {
        const Vec6 w = SeabedContactWrench(p, sys_.sea(), vs);
        force_B += w.head<3>();
        moment_B += w.tail<3>();
      }
      const VehicleFlow flow = UniformFlow(sys_.sea().Current(vs.p_W, s->t).velocity);
      const VehicleDerivative d =
          VehicleRates(p, m.environment, vs, Command(v, poses[v]), force_B, moment_B, flow);
      r->segment<6>(6 * k) = (RigidBodyMassMatrix(p) + p.added_mass) * d.nu_dot;
      if (cable_force_.size() < held_.size()) cable_force_.push_back(force_B.norm());
    }
    return true;
  }

  // r weighted: forces by 1 / F_v, moments by 1 / (F_v L_v), F_v the vehicle's force scale
  VectorXd Weigh(const VectorXd& r) const {
    VectorXd w = r;
    for (size_t k = 0; k < held_.size(); ++k) {
      const double f = ForceScale(k), l = std::max(1.0, Length(k));
      w.segment<3>(6 * k) /= f;
      w.segment<3>(6 * k + 3) /= f * l;
    }
    return w;
  }
  double ForceScale(size_t k) const {
    const VehicleParams& p = sys_.model().vehicles[held_[k]].params;
    const double g = sys_.model().environment.gravity;
    return std::max({1.0, p.mass * g, k < cable_force_.size() ? cable_force_[k] : 0.0});
  }
  double Length(size_t k) const { return sys_.model().vehicles[held_[k]].params.length; }

  // shortens dx so that no thrust leaves its propeller's range (past it the actuator saturates
  // and the thrust has no effect on R: a flat direction)
  void Clamp(const VectorXd& x, VectorXd* dx) const {
    for (int i = 0; i < size(); ++i) {
      if (vars_[i].unknown != kThrustUnknown) continue;
      const Actuator law = ThrustActuator(sys_.model().vehicles[vars_[i].vehicle].params);
      (*dx)[i] = std::clamp(x[i] + (*dx)[i], law.min, law.max) - x[i];
    }
  }
  // whether a thrust unknown sits at its propeller's limit
  bool AtThrustLimit(const VectorXd& x) const {
    for (int i = 0; i < size(); ++i) {
      if (vars_[i].unknown != kThrustUnknown) continue;
      const Actuator law = ThrustActuator(sys_.model().vehicles[vars_[i].vehicle].params);
      if (x[i] >= law.max || x[i] <= law.min) return true;
    }
    return false;
  }

  // the vehicle's command at the pose (a towing vehicle's thrust is the unknown's)
  VehicleCommand Command(int v, const VehiclePose& pose) const {
    VehicleCommand c = commands_[v];
    if (towing_[v]) c.thrust = pose.thrust;
    return c;
  }
  int solves() const { return solves_; }
  const std::vector<Variable>& vars() const { return vars_; }

  // vehicle v at `pose`: attitude, nu = [R^T V_f; 0], actuators at their commands, and the
  // cable ends it holds as supports at their points
  void Place(int v, const VehiclePose& pose, State* s) const {
    const VehicleParams& p = sys_.model().vehicles[v].params;
    VehicleState& vs = s->vehicles[v];
    vs.p_W = pose.p;
    vs.q_WB = QuaternionFromEulerZYX(pose.rpy);
    const Mat3 r_wb = vs.q_WB.toRotationMatrix();
    vs.nu.head<3>() = r_wb.transpose() * vf_;
    vs.nu.tail<3>().setZero();
    const VehicleCommand c = Command(v, pose);
    for (int a = 0; a < kVehicleActuatorCount; ++a) {
      const Actuator law = kVehicleActuators[a].law(p);
      vs.actuator[a] = law.fitted ? law.Target(c.*kVehicleActuators[a].command) : 0.0;
    }
    for (const int end : ends_[v]) {
      const Vec3 point = vs.p_W + r_wb * sys_.End(end % 2, end / 2).at_B;
      SupportMotion& sm = s->supports[end];
      sm = SupportMotion();
      sm.p0 = sm.p1 = point;
      sm.t0 = sm.t1 = s->t;
    }
  }

 private:
  const System& sys_;
  Vec3 vf_;
  const std::vector<VehicleCommand>& commands_;
  std::vector<int> held_;
  std::vector<Variable> vars_;
  std::vector<bool> towing_;            // per vehicle: IsTowingVehicle
  std::vector<std::vector<int>> ends_;  // per vehicle: System::VehicleEnds
  std::vector<Vec3> pivot_;
  double min_length_ = 1.0;
  int solves_ = 0;
  std::vector<double> cable_force_;  // |cable force| at the first evaluation [N]
};

// the worst balance left: "vehicle towfish: force [..] N, moment [..] N m"
std::string DescribeResidual(const System& sys, const std::vector<int>& held, const VectorXd& r,
                             const VectorXd& w) {
  int worst = 0;
  w.cwiseAbs().maxCoeff(&worst);
  const int k = worst / 6;
  std::ostringstream o;
  o.precision(4);
  const Vec6 rk = r.segment<6>(6 * k);
  o << "vehicle " << sys.model().vehicles[held[k]].name << " out of balance by force ["
    << rk[0] << ", " << rk[1] << ", " << rk[2] << "] N, moment [" << rk[3] << ", " << rk[4]
    << ", " << rk[5] << "] N m (body frame)";
  return o.str();
}

}  // namespace

std::vector<int> HeldVehicles(const System& sys) {
  std::vector<int> held;
  for (int v = 0; v < static_cast<int>(sys.model().vehicles.size()); ++v)
    if (!sys.VehicleEnds(v).empty()) held.push_back(v);
  return held;
}

bool IsTowingVehicle(const System& sys, int v) {
  if (!sys.model().vehicles[v].params.has_propeller) return false;
  for (int end = 0; end < sys.num_ends(); ++end) {
    const EndKind k = sys.End(end % 2, end / 2).kind;
    if (k == EndKind::kFixed || k == EndKind::kDriven || k == EndKind::kVessel) return false;
  }
  return true;
}

BalanceResult SolveStaticWithVehicles(const System& sys, const Vec3& frame_velocity,
                                      std::vector<VehicleCommand>* commands, State* s,
                                      const std::function<bool()>& stop) {
  BalanceResult res;
  Balance b(sys, frame_velocity, commands);
  const double tol = kBalanceTolerance;
  std::vector<VehiclePose> poses, trial;
  b.Read(*s, &poses);
  b.SetPivots(*s);
  VectorXd x = b.Pack(poses), r, w, r_try, w_try;
  std::string why;
  bool stopped = false;
  auto finish = [&](bool ok, const std::string& message) {
    res.ok = ok;
    res.stopped = stopped;
    res.static_solves = b.solves();
    res.message = message;
    return res;
  };
  // the factors of the Newton matrix at the current equilibrium (the chord of the solves from
  // it) and at a trial's
  StaticFactors base_factors, trial_factors;
  if (!b.Evaluate(poses, s, &r, &why, stop, &stopped, nullptr, &base_factors))
    return finish(false, "the cables' static solve with the vehicles where the scene puts them "
                         "failed: " + why);
  w = b.Weigh(r);
  double mu = 1e-3;
  const int n = b.size();
  State base = *s, work = *s;
  std::vector<double> history;  // |w| per iteration
  int at_limit = 0;              // iterations in a row with a thrust at its limit
  for (int it = 1; it <= kMaxIterations; ++it) {
    res.iterations = it;
    res.residual = w.lpNorm<Eigen::Infinity>();
    history.push_back(w.norm());
    at_limit = b.AtThrustLimit(x) ? at_limit + 1 : 0;
    // no progress: a thrust held at its limit, or |w| down by less than kStall in
    // kStallWindow iterations (a residual that only creeps has no zero nearby)
    if (res.residual > tol &&
        (at_limit >= kLimitIterations ||
         (it > kStallWindow && history[it - 1] > kStall * history[it - 1 - kStallWindow])))
      break;
    if (res.residual <= tol) {
      std::ostringstream report;
      report.precision(6);
      report << "balanced " << b.held().size() << (b.held().size() == 1 ? " vehicle" : " vehicles")
             << " in " << it - 1 << " iterations (" << b.solves() << " static solves)";
      for (int v : b.held()) {
        (*commands)[v] = b.Command(v, poses[v]);
        if (IsTowingVehicle(sys, v))
          report << "; " << sys.model().vehicles[v].name << "'s thrust " << (*commands)[v].thrust
                 << " N";
      }
      res.report = report.str();
      *s = base;
      return finish(true, "");
    }
    if (stopped || (stop && stop())) {
      stopped = true;
      return finish(false, "stopped");
    }
    // J by forward differences, each column a static solve from the current equilibrium
    b.SetPivots(base);
    x = b.Pack(poses);
    MatrixXd jac(w.size(), n);
    for (int i = 0; i < n; ++i) {
      const double h = b.Step(i, poses);
      VectorXd xi = x;
      xi[i] += h;
      trial = poses;
      b.Unpack(xi, &trial);
      work = base;
      if (!b.Evaluate(trial, &work, &r_try, &why, stop, &stopped, &base_factors, nullptr))
        return finish(false, "the cables' static solve failed while balancing: " + why);
      jac.col(i) = (b.Weigh(r_try) - w) / h;
    }
    // (J^T J + mu diag(J^T J)) dx = -J^T w, mu raised until the residual falls
    const MatrixXd a = jac.transpose() * jac;
    const VectorXd g = jac.transpose() * w;
    VectorXd d = a.diagonal();
    const double floor = 1e-12 * std::max(d.maxCoeff(), 1e-300);
    d = d.cwiseMax(floor);
    bool accepted = false;
    for (int k = 0; k < kMaxTries && !accepted; ++k) {
      MatrixXd am = a;
      am.diagonal() += mu * d;
      VectorXd dx = am.ldlt().solve(-g);
      if (!dx.allFinite()) {
        mu *= 10.0;
        continue;
      }
      b.Limit(&dx, poses);
      b.Clamp(x, &dx);
      trial = poses;
      b.Unpack(x + dx, &trial);
      work = base;
      if (b.Evaluate(trial, &work, &r_try, &why, stop, &stopped, &base_factors, &trial_factors)) {
        w_try = b.Weigh(r_try);
        if (w_try.squaredNorm() < w.squaredNorm()) {
          x += dx;
          poses = trial;
          base = work;
          std::swap(base_factors, trial_factors);
          r = r_try;
          w = w_try;
          mu = std::max(mu / 3.0, 1e-9);
          accepted = true;
          break;
        }
      }
      if (stopped) return finish(false, "stopped");
      mu *= 5.0;
    }
    if (!accepted) break;
  }
  std::ostringstream msg;
  msg << "no static equilibrium of the vehicles found after " << res.iterations
      << " iterations (" << b.solves() << " static solves of the cables): "
      << DescribeResidual(sys, b.held(), r, w) << ", " << res.residual
      << " of its force scale (tolerance " << tol << ")";
  // a towing vehicle whose thrust sits at a limit cannot hold the speed
  for (int i = 0; i < n; ++i) {
    if (b.vars()[i].unknown != kThrustUnknown) continue;
    const int v = b.vars()[i].vehicle;
    const Actuator law = ThrustActuator(sys.model().vehicles[v].params);
    if (x[i] >= law.max || x[i] <= law.min)
      msg << "; " << sys.model().vehicles[v].name << "'s propeller (thrust " << x[i]
          << " N, range [" << law.min << ", " << law.max << "] N) cannot hold the speed";
  }
  msg << "; a buoyant vehicle on a slack line, or one its cable cannot hold, has none";
  *s = base;
  return finish(false, msg.str());
}

}  // namespace towsim::core
