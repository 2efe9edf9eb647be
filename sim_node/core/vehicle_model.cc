#include "core/vehicle_model.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

#include "core/actuator.h"
#include "core/environment_field.h"
#include "core/gauss_quadrature.h"
#include "core/lifting_surface.h"
#include "core/model.h"
#include "core/runge_kutta.h"
#include "core/seabed_contact.h"

namespace towsim::core {
namespace {

using Mat3 = Eigen::Matrix3d;

// S(a) b = a x b
Mat3 Skew(const Vec3& a) {
  Mat3 s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

// C(nu) nu for Fossen's m2c (Fossen 2011 ch. 3 and 6; MSS m2c.m), the Kirchhoff
// Coriolis-centripetal matrix of a kinetic energy 1/2 nu^T M nu, given M_sym = (M + M^T) / 2:
//   C(nu) = [ 0       -S(a) ]     [a; b] = M_sym nu,
//           [ -S(a)   -S(b) ]
// so C(nu) nu = [nu2 x a; nu1 x a + nu2 x b] (the 6 x 6 matrix is never formed). munk = false
// drops the moment rows' terms in nu1 of C's lower left block (HydrodynamicForces).
Vec6 CoriolisTimes(const Mat6& m_sym, const Vec6& nu, bool munk = true) {
  const Vec6 ab = m_sym * nu;
  const Vec3 a = ab.head<3>(), b = ab.tail<3>();
  const Vec3 nu1 = nu.head<3>(), nu2 = nu.tail<3>();
  Vec6 c_nu;
  c_nu.head<3>() = nu2.cross(a);
  c_nu.tail<3>() = nu2.cross(b);
  const Vec3 c21 = nu1.cross(a);
  c_nu(3) += c21.x();
  if (munk) {
    c_nu(4) += c21.y();
    c_nu(5) += c21.z();
  }
  return c_nu;
}

Mat6 TotalMass(const VehicleParams& p) { return RigidBodyMassMatrix(p) + p.added_mass; }

double Deflection(const VehicleState& s, Channel channel) {
  switch (channel) {
    case Channel::kRudder:
      return s.actuator[kRudder];
    case Channel::kElevator:
      return s.actuator[kElevator];
    case Channel::kNone:
      break;
  }
  return 0.0;
}

}  // namespace

Mat6 RigidBodyMassMatrix(const VehicleParams& p) {
  // M_RB = [ m I        -m S(r_g) ]    I_O = I_g - m S(r_g)^2   (Fossen 2011 ch. 3)
  //        [ m S(r_g)    I_O      ]    I_g = diag(inertia) about the CG
  const Mat3 s = Skew(p.r_g);
  Mat6 m = Mat6::Zero();
  m.topLeftCorner<3, 3>() = p.mass * Mat3::Identity();
  m.topRightCorner<3, 3>() = -p.mass * s;
  m.bottomLeftCorner<3, 3>() = p.mass * s;
  m.bottomRightCorner<3, 3>() = Mat3(p.inertia.asDiagonal()) - p.mass * s * s;
  return m;
}

namespace {

// waterline length of a surface-piercing vehicle: the rectangle of area A_wp and second
// moment I_L = A_wp L_w^2 / 12 (vehicle_model.h); the hull length without I_L
double WaterlineLength(const VehicleParams& p) {
  if (p.waterplane_inertia_long > 0.0 && p.waterplane_area > 0.0)
    return std::sqrt(12.0 * p.waterplane_inertia_long / p.waterplane_area);
  return p.length;
}

}  // namespace

VehicleVector PackVehicleState(const VehicleState& s) {
  using L = VehicleStateLayout;
  VehicleVector x;
  x.segment<3>(L::kPosition) = s.p_W;
  x.segment<4>(L::kQuaternion) = Eigen::Vector4d(s.q_WB.w(), s.q_WB.x(), s.q_WB.y(), s.q_WB.z());
  x.segment<6>(L::kNu) = s.nu;
  for (int i = 0; i < kVehicleActuatorCount; ++i) x(L::kActuator + i) = s.actuator[i];
  return x;
}

VehicleState UnpackVehicleState(const VehicleVector& x) {
  using L = VehicleStateLayout;
  VehicleState s;
  s.p_W = x.segment<3>(L::kPosition);
  const int q = L::kQuaternion;
  s.q_WB = Eigen::Quaterniond(x(q), x(q + 1), x(q + 2), x(q + 3));
  s.nu = x.segment<6>(L::kNu);
  for (int i = 0; i < kVehicleActuatorCount; ++i) s.actuator[i] = x(L::kActuator + i);
  return s;
}

VehicleFlow VehicleFlow::Lerp(const VehicleFlow& o, double c) const {
  if (c == 0.0) return *this;
  VehicleFlow f = *this;
  f.origin.velocity += c * (o.origin.velocity - origin.velocity);
  f.origin.acceleration += c * (o.origin.acceleration - origin.acceleration);
  for (int i = 0; i < kHullStations; ++i)
    f.hull_acceleration_W[i] += c * (o.hull_acceleration_W[i] - hull_acceleration_W[i]);
  for (int i = 0; i < kWaterlineStations; ++i)
    f.elevation[i] += c * (o.elevation[i] - elevation[i]);
  return f;
}

VehicleFlow UniformFlow(const Vec3& current_W) {
  VehicleFlow f;
  f.origin.velocity = current_W;
  return f;
}

VehicleFlow SampleVehicleFlow(const VehicleParams& p, const EnvironmentField& sea, const Vec3& p_W,
                              const Eigen::Quaterniond& q_WB, double t) {
  if (sea.uniform()) return UniformFlow(sea.uniform_current());
  VehicleFlow f;
  const Mat3 r_wb = q_WB.normalized().toRotationMatrix();
  // hull stations x_B = L (xi - 1/2), symmetric about the origin (xi = 1/2, the middle one):
  // O -+ R (L (xi_2 - 1/2), 0, 0), sampled together (EnvironmentField::FlowsAbout)
  const GaussRule<VehicleFlow::kHullStations> hull = Gauss3();
  static_assert(VehicleFlow::kHullStations == 3);
  FlowSample fs[3];
  sea.FlowsAbout(p_W, r_wb * Vec3(p.length * (hull.xi[2] - 0.5), 0.0, 0.0), t, fs);
  for (int i = 0; i < VehicleFlow::kHullStations; ++i)
    f.hull_acceleration_W[i] = fs[i].acceleration;
  f.origin = fs[1];
  f.accelerating = true;
  if (sea.has_waves() && p.waterplane_area > 0.0) {
    // stations x_B = waterplane point + (lw (xi - 1/2), 0, 0), two pairs symmetric about the
    // waterplane point (xi_0 = 1 - xi_3, xi_1 = 1 - xi_2; EnvironmentField::ElevationPairs)
    const GaussRule<VehicleFlow::kWaterlineStations> wl = Gauss4();
    static_assert(VehicleFlow::kWaterlineStations == 4);
    const double lw = WaterlineLength(p);
    const Vec3 c_W = p_W + r_wb * p.waterplane_point_B;
    const Vec3 o3 = r_wb * Vec3(lw * (wl.xi[3] - 0.5), 0, 0);
    const Vec3 o2 = r_wb * Vec3(lw * (wl.xi[2] - 0.5), 0, 0);
    const double offsets[2][2] = {{o3.x(), o3.y()}, {o2.x(), o2.y()}};
    double eta[4];
    sea.ElevationPairs(c_W.x(), c_W.y(), offsets, 2, t, eta);
    f.elevation[3] = eta[0], f.elevation[0] = eta[1];
    f.elevation[2] = eta[2], f.elevation[1] = eta[3];
    f.waves = true;
  }
  return f;
}

namespace {

// HydrodynamicForces with the state's rotation matrix r_wb = R_WB (computed once per stage)
Vec6 HydrodynamicForcesAt(const VehicleParams& p, const Environment& env, const VehicleState& s,
                          const Mat3& r_wb, const VehicleFlow& flow) {
  const Vec3 omega = s.nu.tail<3>();
  // nu_r = nu - [R^T u_W(O); 0]: velocity relative to the water at the origin, and v_c the
  // water's velocity there in B
  Vec6 nu_r = s.nu;
  nu_r.head<3>() = r_wb.transpose() * RelativeVelocity(r_wb * s.nu.head<3>(), flow.origin);
  const Vec3 v_c = s.nu.head<3>() - nu_r.head<3>();
  const double u = nu_r(0), v = nu_r(1), w = nu_r(2);
  const double pr = nu_r(3), q = nu_r(4), r = nu_r(5);
  Vec6 tau = Vec6::Zero();

  // -C_A(nu_r) nu_r, C_A = m2c(M_A, nu_r) (Kirchhoff; Fossen 2011 ch. 6). Without the Munk
  // moment, as in Fossen's MSS torpedo/remus100: CA(6,1:2) = CA(5,1:3) = 0 (1-based), i.e. the
  // yaw and pitch moments proportional to the linear velocities, (X_udot - Y_vdot) u v,
  // (Z_wdot - X_udot) u w and the coupling terms Y_rdot u r, Z_qdot u q, are dropped.
  // (CA(5,1:3) is row y of -S(a) nu1, CA(6,1:2) row z: both dropped whole, S(a)_zz = 0)
  tau -= CoriolisTimes(0.5 * (p.added_mass + p.added_mass.transpose()), nu_r, p.munk_moment);

  // the added mass accelerates with the relative velocity: M_A nu_r_dot = M_A nu_dot
  // + M_A [omega x v_c; 0] for a current steady in W (v_c_dot = -omega x v_c, Fossen 2011 ch. 10)
  Vec6 nu_c_dot = Vec6::Zero();
  nu_c_dot.head<3>() = -omega.cross(v_c);
  tau += p.added_mass * nu_c_dot;
  if (flow.accelerating) {
    // accelerating water: Froude-Krylov + added mass by strips along the hull (the header),
    // dF = w_i (rho V + diag(M_A)) R^T a_W(x_i), dM = x_i x dF
    const GaussRule<VehicleFlow::kHullStations> hull = Gauss3();
    const Vec3 inertia = env.water_density * p.volume * Vec3::Ones() +
                         Vec3(p.added_mass(0, 0), p.added_mass(1, 1), p.added_mass(2, 2));
    for (int i = 0; i < VehicleFlow::kHullStations; ++i) {
      const Vec3 f_i =
          hull.weight[i] * inertia.cwiseProduct(r_wb.transpose() * flow.hull_acceleration_W[i]);
      tau.head<3>() += f_i;
      tau.tail<3>() += Vec3(p.length * (hull.xi[i] - 0.5), 0.0, 0.0).cross(f_i);
    }
  }

  // -D(nu_r) nu_r: dimensional viscous coefficients (Prestero 2001 names; forces carry the sign)
  tau(0) += p.x_uu * u * std::abs(u);
  tau(1) += p.y_vv * v * std::abs(v) + p.y_rr * r * std::abs(r) + p.y_uv * u * v + p.y_ur * u * r;
  tau(2) += p.z_ww * w * std::abs(w) + p.z_qq * q * std::abs(q) + p.z_uw * u * w + p.z_uq * u * q;
  tau(3) += p.k_pp * pr * std::abs(pr) + p.k_p * pr;
  tau(4) += p.m_ww * w * std::abs(w) + p.m_qq * q * std::abs(q) + p.m_uw * u * w + p.m_uq * u * q;
  tau(5) += p.n_vv * v * std::abs(v) + p.n_rr * r * std::abs(r) + p.n_uv * u * v + p.n_ur * u * r;

  // -g(eta): weight m g at r_g, buoyancy rho V g at r_b, gravity along +z_W (Fossen 2011 ch. 4)
  const Vec3 down_B = r_wb.transpose() * Vec3::UnitZ();
  const Vec3 f_weight = p.mass * env.gravity * down_B;
  const Vec3 f_buoyancy = -env.water_density * p.volume * env.gravity * down_B;
  tau.head<3>() += f_weight + f_buoyancy;
  tau.tail<3>() += p.r_g.cross(f_weight) + p.r_b.cross(f_buoyancy);
  if (p.waterplane_area > 0.0) {
    // fairing waterplane: extra displaced volume A_wp (z_O - design_depth), bounded below by -V
    const double dv = std::max(p.waterplane_area * (s.p_W.z() - p.design_depth), -p.volume);
    const Vec3 f_mast = -env.water_density * dv * env.gravity * down_B;
    tau.head<3>() += f_mast;
    tau.tail<3>() += p.waterplane_point_B.cross(f_mast);
    // waterplane moments: the fairing resists roll and pitch (small-angle hydrostatics in the
    // body frame; sin of the Euler angles from the down vector: down_B = [-sin th, sin ph cos th,
    // cos ph cos th])
    const double rho_g = env.water_density * env.gravity;
    tau(3) -= rho_g * p.waterplane_inertia_trans * down_B.y();
    tau(4) -= rho_g * p.waterplane_inertia_long * (-down_B.x());
    if (flow.waves) {
      // the wave elevation along the waterline: dF = -rho g (A_wp / L_w) eta(x) dx down_B
      const GaussRule<VehicleFlow::kWaterlineStations> wl = Gauss4();
      const double lw = WaterlineLength(p);
      for (int i = 0; i < VehicleFlow::kWaterlineStations; ++i) {
        const Vec3 f_i = -rho_g * p.waterplane_area * wl.weight[i] * flow.elevation[i] * down_B;
        tau.head<3>() += f_i;
        tau.tail<3>() += (p.waterplane_point_B + Vec3(lw * (wl.xi[i] - 0.5), 0.0, 0.0)).cross(f_i);
      }
    }
  }

  // propeller: thrust along +x_B through O
  if (p.has_propeller) tau(0) += s.actuator[kThrust];

  // lifting surfaces on the local relative flow v_O + omega x r - v_c
  for (const LiftingSurface& surf : p.surfaces) {
    const Vec3 v_point = nu_r.head<3>() + omega.cross(surf.position_B);
    const SurfaceLoad load =
        SurfaceForce(surf, env.water_density, v_point, Deflection(s, surf.channel));
    tau.head<3>() += load.force_B;
    tau.tail<3>() += load.moment_B;
  }
  return tau;
}

}  // namespace

Vec6 HydrodynamicForces(const VehicleParams& p, const Environment& env, const VehicleState& s,
                        const VehicleFlow& flow) {
  return HydrodynamicForcesAt(p, env, s, s.q_WB.normalized().toRotationMatrix(), flow);
}

namespace {

// the right-hand side with the factored total mass M_RB + M_A (constant: factored once per RK4
// step instead of once per stage) and the state's R_WB (computed once per stage)
VehicleDerivative Rates(const VehicleParams& p, const Environment& env, const VehicleState& s,
                        const Mat3& r_wb, const VehicleFlow& flow, const VehicleCommand& cmd,
                        const Vec3& force_B, const Vec3& moment_B, const Mat6& m_rb,
                        const Eigen::PartialPivLU<Mat6>& mass_lu,
                        const EnvironmentField* sea = nullptr) {
  VehicleDerivative d;
  // p_dot_W = R_WB nu_1, attitude rate omega_B
  d.p_dot_W = r_wb * s.nu.head<3>();
  d.omega_B = s.nu.tail<3>();

  // (M_RB + M_A) nu_dot = tau_hyd + tau_ext - C_RB(nu) nu   (paper Eq. 27-28, Fossen form)
  Vec6 rhs = HydrodynamicForcesAt(p, env, s, r_wb, flow);
  if (sea && sea->has_seabed()) rhs += SeabedContactWrench(p, *sea, s);
  rhs.head<3>() += force_B;
  rhs.tail<3>() += moment_B;
  rhs -= CoriolisTimes(m_rb, s.nu);  // M_RB is symmetric
  d.nu_dot = mass_lu.solve(rhs);

  // actuators (actuator.h): x_dot = clamp((clamp(u, range) - x) / T, +-max_rate)
  d.actuator_dot = ActuatorRates(p, cmd, s);
  return d;
}

}  // namespace

VehicleDerivative VehicleRates(const VehicleParams& p, const Environment& env,
                               const VehicleState& s, const VehicleCommand& cmd,
                               const Vec3& force_B, const Vec3& moment_B, const VehicleFlow& flow) {
  const Mat6 m_rb = RigidBodyMassMatrix(p);
  const Eigen::PartialPivLU<Mat6> lu(m_rb + p.added_mass);
  return Rates(p, env, s, s.q_WB.normalized().toRotationMatrix(), flow, cmd, force_B, moment_B,
               m_rb, lu);
}

void AdvanceVehicle(const VehicleParams& p, const Environment& env, const VehicleCommand& cmd,
                    const PointLoad& load, double h, VehicleState* s) {
  // the scene's current at the vehicle's depth, steady over the step (tests and tools; the
  // simulation samples the whole sea, SampleVehicleFlow)
  const VehicleFlow flow = UniformFlow(env.current.Velocity(s->p_W.z(), 0.0));
  AdvanceVehicle(p, env, flow, flow, cmd, load, h, s);
}

Vec6 SeabedContactWrench(const VehicleParams& p, const EnvironmentField& sea,
                         const VehicleState& s) {
  Vec6 tau = Vec6::Zero();
  if (!sea.has_seabed()) return tau;
  // no contact point reaches deeper than the origin's depth plus its distance from O: a hull
  // above the shallowest bed touches nothing (the margin covers the rounding of x_W below)
  double reach = 0.5 * p.length;
  for (const LiftingSurface& surf : p.surfaces) reach = std::max(reach, surf.position_B.norm());
  if (s.p_W.z() + 1.001 * reach + 1e-6 < sea.SeabedShallowest()) return tau;
  const Mat3 r_wb = s.q_WB.normalized().toRotationMatrix();
  const Vec3 v_o = s.nu.head<3>(), omega = s.nu.tail<3>();
  const double area = p.length > 0.0 ? p.volume / p.length : 0.0;  // one hull section
  auto contact = [&](const Vec3& r_B) {
    const Vec3 x_W = s.p_W + r_wb * r_B;
    if (!(x_W.z() > sea.SeabedDepth(x_W.x(), x_W.y()))) return;  // above the bed
    const Vec3 v_W = r_wb * (v_o + omega.cross(r_B));
    const ContactLoad c = SeabedContactLoad(sea, area, x_W, v_W, Vec3::Zero(), false);
    if (!c.active) return;
    const Vec3 f_B = r_wb.transpose() * c.f;
    tau.head<3>() += f_B;
    tau.tail<3>() += r_B.cross(f_B);
  };
  contact(Vec3(0.5 * p.length, 0.0, 0.0));
  contact(Vec3(-0.5 * p.length, 0.0, 0.0));
  for (const LiftingSurface& surf : p.surfaces) contact(surf.position_B);
  return tau;
}

VehicleInertia::VehicleInertia(const VehicleParams& p)
    : m_rb(RigidBodyMassMatrix(p)), mass_lu(m_rb + p.added_mass) {}

void AdvanceVehicle(const VehicleParams& p, const Environment& env, const VehicleFlow& flow0,
                    const VehicleFlow& flow1, const VehicleCommand& cmd, const PointLoad& load,
                    double h, VehicleState* s, const EnvironmentField* sea) {
  AdvanceVehicle(p, VehicleInertia(p), env, flow0, flow1, cmd, load, h, s, sea);
}

void AdvanceVehicle(const VehicleParams& p, const VehicleInertia& inertia, const Environment& env,
                    const VehicleFlow& flow0, const VehicleFlow& flow1, const VehicleCommand& cmd,
                    const PointLoad& load, double h, VehicleState* s,
                    const EnvironmentField* sea) {
  // classical RK4; stage c in {0, 1/2, 1}: f_W(c) = f_W0 + c (f_W1 - f_W0), applied at point_B
  // with the stage attitude: force_B = R^T f_W, moment_B = point_B x force_B (paper Eq. 29-30)
  const VehicleState s0 = *s;
  const Mat6& m_rb = inertia.m_rb;
  const Eigen::PartialPivLU<Mat6>& mass_lu = inertia.mass_lu;
  // the same water all through the step (still water, a steady uniform current): no blending
  const bool steady_flow = !flow0.accelerating && !flow1.accelerating && !flow0.waves &&
                           !flow1.waves && flow0.origin.velocity == flow1.origin.velocity;
  auto rates = [&](const VehicleState& x, double c) {
    const Vec3 f_w = load.force_W0 + c * (load.force_W1 - load.force_W0);
    const Mat3 r_wb = x.q_WB.normalized().toRotationMatrix();
    Vec3 f_b = r_wb.transpose() * f_w;
    if (load.more_count == 0) {
      if (steady_flow)
        return Rates(p, env, x, r_wb, flow0, cmd, f_b, load.point_B.cross(f_b), m_rb, mass_lu,
                     sea);
      return Rates(p, env, x, r_wb, flow0.Lerp(flow1, c), cmd, f_b, load.point_B.cross(f_b),
                   m_rb, mass_lu, sea);
    }
    Vec3 m_b = load.point_B.cross(f_b);
    for (int k = 0; k < load.more_count; ++k) {
      const PointLoad& l = load.more[k];
      const Vec3 f_k = r_wb.transpose() * (l.force_W0 + c * (l.force_W1 - l.force_W0));
      f_b += f_k;
      m_b += l.point_B.cross(f_k);
    }
    if (steady_flow) return Rates(p, env, x, r_wb, flow0, cmd, f_b, m_b, m_rb, mass_lu, sea);
    return Rates(p, env, x, r_wb, flow0.Lerp(flow1, c), cmd, f_b, m_b, m_rb, mass_lu, sea);
  };
  // the packed state's derivative (vehicle_model.h, VehicleStateLayout), the quaternion's four
  // components integrated like the other states and renormalized at the end
  using L = VehicleStateLayout;
  auto derivative = [&](const VehicleVector& xv, double c) {
    const VehicleState x = UnpackVehicleState(xv);
    const VehicleDerivative d = rates(x, c);
    // q_dot = 1/2 q (x) [0, omega_B]
    const Eigen::Quaterniond w(0.0, d.omega_B.x(), d.omega_B.y(), d.omega_B.z());
    const Eigen::Quaterniond prod = x.q_WB * w;
    VehicleVector k;
    k.segment<3>(L::kPosition) = d.p_dot_W;
    k.segment<4>(L::kQuaternion) = 0.5 * Eigen::Vector4d(prod.w(), prod.x(), prod.y(), prod.z());
    k.segment<6>(L::kNu) = d.nu_dot;
    for (int i = 0; i < kVehicleActuatorCount; ++i) k(L::kActuator + i) = d.actuator_dot[i];
    return k;
  };
  VehicleState x = UnpackVehicleState(RungeKutta4(PackVehicleState(s0), h, derivative));
  x.q_WB = x.q_WB.normalized();
  *s = x;
}

double VehicleKineticEnergy(const VehicleParams& p, const VehicleState& s) {
  // T = 1/2 nu^T (M_RB + M_A) nu (still water)
  return 0.5 * s.nu.dot(TotalMass(p) * s.nu);
}

Vec3 EulerZYX(const Eigen::Quaterniond& q_WB) {
  // R = Rz(psi) Ry(theta) Rx(phi) (Fossen 2011 ch. 2); theta = -asin(R_20)
  const Mat3 r = q_WB.normalized().toRotationMatrix();
  const double phi = std::atan2(r(2, 1), r(2, 2));
  const double theta = -std::asin(std::clamp(r(2, 0), -1.0, 1.0));
  const double psi = std::atan2(r(1, 0), r(0, 0));
  return Vec3(phi, theta, psi);
}

Eigen::Quaterniond QuaternionFromEulerZYX(const Vec3& rpy) {
  // q = q_z(psi) q_y(theta) q_x(phi)
  return Eigen::Quaterniond(Eigen::AngleAxisd(rpy.z(), Vec3::UnitZ()) *
                            Eigen::AngleAxisd(rpy.y(), Vec3::UnitY()) *
                            Eigen::AngleAxisd(rpy.x(), Vec3::UnitX()));
}

}  // namespace towsim::core
