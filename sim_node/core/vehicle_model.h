#pragma once
// 6-DOF vehicle: parameters, state and dynamics (paper Eq. 27-28, Kirchhoff form).
//
// Frames: world W is NED (z down); body B has x forward, y starboard, z down, its origin O at
// the centre of buoyancy; r_g, r_b are the CG and CB in B. nu = [u v w p q r] is the velocity
// of O in W expressed in B, and the angular velocity of B in W expressed in B.
// Equations (Fossen 2011 form, identical to Kirchhoff's, see
// docs/vehicles.md §1):
//   (M_RB + M_A) nu_dot + C_RB(nu) nu + C_A(nu_r) nu_r + D(nu_r) nu_r + g(eta)
//       = tau_prop + tau_surfaces + tau_cable,
//   p_dot_W = R_WB nu_lin,  q_dot_WB = 1/2 q_WB (x) [0, omega_B],
// with nu_r = nu - [R_WB^T u_W(O); 0] the velocity relative to the local water u_W at the origin
// (the added mass moves with the water: M_A nu_r_dot = M_A nu_dot + M_A [omega x R_WB^T u_W; 0];
// Fossen ch. 10).
// In accelerating water (waves, an unsteady current; docs/environment.md) the hull also feels
// Morison's fluid-inertia force, by strips along the hull (slender-body sections; the hull as a
// prism of length L, section V / L and translational added mass diag(M_A)_{11..33} / L):
//   dF = (rho V / L + diag(M_A) / L) R_WB^T a_W(x) dx at x_B = (x, 0, 0), x in [-L/2, L/2],
// a_W the water's material acceleration Du/Dt (environment_field.h),
// with its moment about O, and a surface-piercing vehicle the hydrostatic force of the wave
// elevation eta along its waterline (a rectangle of length L_w = sqrt(12 I_L / A_wp) about
// waterplane_point_B):
//   dF = -rho g (A_wp / L_w) eta(x) dx down_B,
// with its moment, so it heaves and pitches in waves. Radiation and diffraction (memory
// effects, wave drift) are not modelled. Both are sampled at a few Gauss stations
// (VehicleFlow) once at the start and once at the end of a step and interpolated linearly in
// time for the RK4 stages.
// Dimensional coefficients (SI), as written in config/vehicles/*.yaml.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "core/flow_sample.h"

namespace towsim::core {

using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

// actuator channels a command can drive
enum class Channel { kNone, kRudder, kElevator };

// A fin or a wing: lift and drag on the local flow at its centre of pressure.
//   alpha = angle of the local relative flow in the surface's (chord, normal) plane
//           + incidence + deflection_sign * delta(channel)
//   CL = lift_slope * alpha, limited by stall (|alpha| > stall_angle: CL falls back linearly
//        to 0 at 2 * stall_angle, then stays 0 (flat-plate drag takes over))
//   L = 1/2 rho S CL U_p^2 along the normal of the flow in that plane,
//   D = 1/2 rho S (cd0 + CL^2 / (pi e AR)) U_p^2 against the flow,
// U_p the local speed in the plane (spanwise flow ignored).
struct LiftingSurface {
  std::string name;
  Channel channel = Channel::kNone;
  Vec3 position_B = Vec3::Zero();  // centre of pressure (quarter chord) [m]
  Vec3 normal_B = Vec3::UnitZ();   // unit normal: lift direction at zero angle (rudder: +y)
  double area = 0.0;               // planform area S [m^2]
  double aspect_ratio = 2.0;       // effective AR
  double lift_slope = 0.0;         // dCL/dalpha [1/rad]; 0: Helmbold 2 pi AR/(2+sqrt(AR^2+4))
  double oswald = 0.8;             // span efficiency e
  double cd0 = 0.01;               // zero-lift drag coefficient
  double stall_angle = 0.35;       // [rad]
  double incidence = 0.0;          // fixed incidence [rad]
  double deflection_sign = 1.0;    // +1 or -1: maps the channel command to alpha
};

// a fin channel's limits (its servo: actuator.h)
struct ActuatorLimits {
  double max_deflection = 0.5236;  // [rad]
  double max_rate = 0.5236;        // [rad/s]
};

struct VehicleParams {
  std::string source;   // where the numbers come from
  double length = 1.0;  // [m]
  // hull diameter [m], for drawing only (3D markers); 0: that of the cylinder of length
  // `length` and volume `volume`
  double diameter = 0.0;
  double mass = 1.0;    // [kg]
  Vec3 inertia = Vec3::Ones();  // principal inertia about the CG, [Ixx Iyy Izz] [kg m^2]
  Vec3 r_g = Vec3::Zero();      // CG in B [m]
  Vec3 r_b = Vec3::Zero();      // CB in B [m] (origin: usually zero)
  double volume = 0.0;          // displaced volume [m^3] (buoyancy rho g V at r_b)
  // Semi-submersible hydrostatics: a surface-piercing fairing of waterplane area A_wp adds the
  // buoyancy rho g A_wp (z_O - design_depth), vertical in W, at waterplane_point_B, as the
  // origin O sinks below design_depth (it loses it as O rises; at most the volume V). 0: the
  // vehicle is fully submerged and its buoyancy does not depend on depth.
  double waterplane_area = 0.0;                // A_wp [m^2]
  Vec3 waterplane_point_B = Vec3::Zero();      // where the mast meets the hull, in B [m]
  double design_depth = 0.0;                   // depth of O at which V is the displacement [m]
  // second moments of the waterplane about its centroid (Fossen 2011 §4.2: restoring moments
  // -rho g I_L sin(theta), -rho g I_T sin(phi) of a surface-piercing structure) [m^4]
  double waterplane_inertia_long = 0.0;
  double waterplane_inertia_trans = 0.0;
  Mat6 added_mass = Mat6::Zero();  // M_A (positive: -X_udot, -Y_vdot, ...)
  bool munk_moment = true;  // false: C_A without the Munk moment terms (Fossen's recipe)
  // viscous damping, dimensional, sign as in the force (X = x_uu u|u| ...):
  double x_uu = 0.0;                    // [kg/m]
  double y_vv = 0.0, z_ww = 0.0;        // crossflow [kg/m]
  double y_rr = 0.0, z_qq = 0.0;        // [kg m / rad^2]
  double m_ww = 0.0, n_vv = 0.0;        // [kg]
  double m_qq = 0.0, n_rr = 0.0, k_pp = 0.0;  // [kg m^2 / rad^2]
  double y_uv = 0.0, z_uw = 0.0;        // body lift [kg/m]
  double m_uw = 0.0, n_uv = 0.0;        // body lift moment (viscous part) [kg]
  double y_ur = 0.0, z_uq = 0.0;        // [kg / rad]
  double m_uq = 0.0, n_ur = 0.0;        // [kg m / rad]
  double k_p = 0.0;                     // linear roll damping [N m s]
  std::vector<LiftingSurface> surfaces;  // fins and wings
  ActuatorLimits rudder, elevator;
  // propeller (towing vehicle only): thrust along +x_B through the origin, first-order lag
  // (actuator.h, ThrustActuator)
  bool has_propeller = false;
  double max_thrust = 0.0;             // ahead limit [N] (the range: actuator.h)
  double thrust_time_constant = 1.0;   // [s]
};

struct VehicleCommand {
  double thrust = 0.0;    // [N]
  double rudder = 0.0;    // [rad], positive turns the bow to starboard
  double elevator = 0.0;  // [rad], positive pitches the bow up... see the surface signs
};

// The vehicle's actuator states, in this order in VehicleState::actuator; their laws, one row
// each: actuator.h, kVehicleActuators. A new actuator is one entry here and one row there.
enum VehicleActuator : int {
  kThrust,    // propeller thrust [N]
  kRudder,    // rudder position [rad]
  kElevator,  // elevator position [rad]
  kVehicleActuatorCount
};

struct VehicleState {
  Vec3 p_W = Vec3::Zero();                               // origin O in W [m]
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  Vec6 nu = Vec6::Zero();                                // [u v w p q r], body frame
  std::array<double, kVehicleActuatorCount> actuator{};  // indexed by VehicleActuator
};

// VehicleState packed as the one vector the RK4 integrates (runge_kutta.h), (kSize x 1):
//   [ p_W (3) | q_WB as (w, x, y, z) (4) | nu (6) | actuator (kVehicleActuatorCount) ]
// Its derivative has the same layout, with q_dot = 1/2 q (x) [0, omega_B] in the quaternion's
// four entries (integrated like the others, renormalized after the step).
struct VehicleStateLayout {
  static constexpr int kPosition = 0;
  static constexpr int kQuaternion = 3;
  static constexpr int kNu = 7;
  static constexpr int kActuator = 13;
  static constexpr int kSize = kActuator + kVehicleActuatorCount;
};
using VehicleVector = Eigen::Matrix<double, VehicleStateLayout::kSize, 1>;

VehicleVector PackVehicleState(const VehicleState& s);
// the inverse of PackVehicleState (the quaternion as stored, not renormalized)
VehicleState UnpackVehicleState(const VehicleVector& x);

// External force at a body-fixed point: the cable's joint reaction (Eq. 29-30).
struct PointLoad {
  Vec3 force_W0 = Vec3::Zero();  // world-frame force at the start of the step [N]
  Vec3 force_W1 = Vec3::Zero();  // at the end of the step (linear in between)
  Vec3 point_B = Vec3::Zero();   // application point in B [m]
  // further loads of the same kind at other points (a vehicle holding several cable ends;
  // their `more` unused): their forces and moments add to this one's
  const PointLoad* more = nullptr;
  int more_count = 0;
};

struct VehicleDerivative {
  Vec3 p_dot_W;
  Vec3 omega_B;  // attitude rate: q_dot = 1/2 q (x) [0, omega_B]
  Vec6 nu_dot;
  std::array<double, kVehicleActuatorCount> actuator_dot{};  // indexed by VehicleActuator
};

struct Environment;      // model.h
class EnvironmentField;  // environment_field.h

// The water at a vehicle at one instant and pose: at the hull's Gauss stations (the middle one
// is the origin O, where the relative velocity is taken) and, for a surface-piercing vehicle,
// the wave elevation at the waterline's stations.
struct VehicleFlow {
  static constexpr int kHullStations = 3;       // Gauss points along x_B in [-L/2, L/2]
  static constexpr int kWaterlineStations = 4;  // Gauss points along the waterline
  FlowSample origin;                            // at O
  bool accelerating = false;  // hull_acceleration_W set (the water accelerates somewhere)
  std::array<Vec3, kHullStations> hull_acceleration_W{};
  bool waves = false;                                  // elevation set
  std::array<double, kWaterlineStations> elevation{};  // eta [m], positive up
  // (1 - c) *this + c other
  VehicleFlow Lerp(const VehicleFlow& other, double c) const;
};

// still water, or a uniform steady current U_W (VehicleFlow::origin.velocity = U_W)
VehicleFlow UniformFlow(const Vec3& current_W);
// the water at a vehicle with origin p_W and attitude q_WB at time t
VehicleFlow SampleVehicleFlow(const VehicleParams& p, const EnvironmentField& sea, const Vec3& p_W,
                              const Eigen::Quaterniond& q_WB, double t);

// the right-hand side of the vehicle ODE, with the external wrench (force_B, moment_B about O),
// in the water `flow` (default: still)
VehicleDerivative VehicleRates(const VehicleParams& p, const Environment& env,
                               const VehicleState& s, const VehicleCommand& cmd,
                               const Vec3& force_B, const Vec3& moment_B,
                               const VehicleFlow& flow = VehicleFlow());

// Contact of the hull with the seabed (seabed_contact.h) at its contact points, the nose
// (L/2, 0, 0), the tail (-L/2, 0, 0) and every lifting surface's centre of pressure (fins,
// wings), each on a contact area of one hull section V / L: the wrench in B about O (zero
// without a seabed).
Vec6 SeabedContactWrench(const VehicleParams& p, const EnvironmentField& sea,
                         const VehicleState& s);

// The constant mass properties the RK4 stages read: M_RB and the LU of M_RB + M_A, factored
// once per vehicle (not once per step)
struct VehicleInertia {
  explicit VehicleInertia(const VehicleParams& p);
  Mat6 m_rb;
  Eigen::PartialPivLU<Mat6> mass_lu;
};

// one explicit RK4 step of length h with the point load interpolated linearly in time and the
// water interpolated linearly from flow0 (at the start) to flow1 (at the end); with `sea`, the
// seabed contact at every stage (not lagged); the quaternion is renormalized
void AdvanceVehicle(const VehicleParams& p, const Environment& env, const VehicleFlow& flow0,
                    const VehicleFlow& flow1, const VehicleCommand& cmd, const PointLoad& load,
                    double h, VehicleState* s, const EnvironmentField* sea = nullptr);
// the same with the vehicle's inertia factored beforehand (VehicleInertia(p))
void AdvanceVehicle(const VehicleParams& p, const VehicleInertia& inertia, const Environment& env,
                    const VehicleFlow& flow0, const VehicleFlow& flow1, const VehicleCommand& cmd,
                    const PointLoad& load, double h, VehicleState* s,
                    const EnvironmentField* sea = nullptr);
// the same in still water
void AdvanceVehicle(const VehicleParams& p, const Environment& env, const VehicleCommand& cmd,
                    const PointLoad& load, double h, VehicleState* s);

// generalized forces for diagnostics and tests, body frame, about O
Mat6 RigidBodyMassMatrix(const VehicleParams& p);  // M_RB
// everything on the right of (M_RB + M_A) nu_dot + C_RB(nu) nu = tau_hyd + tau_ext except the
// external wrench: -C_A(nu_r) nu_r (and the current term above), -D(nu_r) nu_r, -g(eta), the
// surfaces at the state's fin angles, and the propeller at the state's thrust
Vec6 HydrodynamicForces(const VehicleParams& p, const Environment& env, const VehicleState& s,
                        const VehicleFlow& flow = VehicleFlow());
double VehicleKineticEnergy(const VehicleParams& p, const VehicleState& s);  // 1/2 nu^T M nu

// Euler angles (roll, pitch, yaw) [rad] of q_WB, ZYX convention
Vec3 EulerZYX(const Eigen::Quaterniond& q_WB);
Eigen::Quaterniond QuaternionFromEulerZYX(const Vec3& rpy);

}  // namespace towsim::core
