// ScaleVehicle (core/vehicle_scaling.h) against the units of every field (vehicle_fields.h:
// Froude similarity scales a quantity of unit kg^a m^b s^c by lambda^(3a + b + c/2)), and the
// vehicle model's right-hand side against Froude similarity itself: the scaled vehicle in the
// scaled state feels lambda^3 the forces and lambda^4 the moments, in every term.

#include "core/vehicle_scaling.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"
#include "core/vehicle_model.h"
#include "vehicle_fields.h"
#include "vehicle_file.h"

namespace towsim::core {
namespace {

using test::VehicleField;
using test::VehicleFields;

std::uint64_t Bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// the two shipped vehicles
std::vector<VehicleParams> ShippedVehicles() {
  return {test::ReadProjectVehicle("tow_vehicle"), test::ReadProjectVehicle("towfish")};
}

// a vehicle with every number non-zero and distinct (the shipped files leave some at 0, where a
// wrong exponent would not show): the towing vehicle with its zeros filled in
VehicleParams EveryFieldSet() {
  VehicleParams p = test::ReadProjectVehicle("tow_vehicle");
  std::vector<VehicleField> fields = VehicleFields(p);
  for (size_t i = 0; i < fields.size(); ++i) {
    double& x = fields[i].get(p);
    if (x == 0.0) x = 0.1 + 0.01 * static_cast<double>(i);
  }
  return p;
}

// 1. scale 1 changes nothing: every number bit for bit, every other field equal
TEST(ScaleVehicle, ScaleOneChangesNothing) {
  std::vector<VehicleParams> models = ShippedVehicles();
  models.push_back(EveryFieldSet());
  for (const VehicleParams& model : models) {
    VehicleParams a = model;
    VehicleParams b = ScaleVehicle(model, 1.0);
    EXPECT_TRUE(test::SameNonNumericFields(a, b));
    const std::vector<VehicleField> fields = VehicleFields(model);
    ASSERT_GT(fields.size(), 100u);
    for (const VehicleField& f : fields) {
      EXPECT_EQ(Bits(f.get(a)), Bits(f.get(b))) << f.name << ": " << f.get(a) << " -> " << f.get(b);
    }
  }
}

// 2. each number scales by lambda^n with n from its unit; the factor is one pow of an exact
// exponent, so the product is within a few ulps: kExponentRelTol = 1e-14
TEST(ScaleVehicle, EveryFieldScalesByTheFroudeExponentOfItsUnit) {
  constexpr double kExponentRelTol = 1e-14;
  VehicleParams model = EveryFieldSet();
  for (const double lambda : {2.0, 0.37, 3.0, 25.0}) {
    VehicleParams scaled = ScaleVehicle(model, lambda);
    EXPECT_TRUE(test::SameNonNumericFields(model, scaled));
    for (const VehicleField& f : VehicleFields(model)) {
      const double expected = f.get(model) * std::pow(lambda, f.exponent());
      EXPECT_NEAR(f.get(scaled), expected, kExponentRelTol * std::abs(expected))
          << f.name << " (unit kg^" << f.kg << " m^" << f.m << " s^" << f.s << ", lambda^"
          << f.exponent() << ") at lambda = " << lambda;
    }
  }
  // the exponents the docs' table states, spot-checked by value (lambda = 2)
  const VehicleParams two = ScaleVehicle(model, 2.0);
  EXPECT_DOUBLE_EQ(two.mass / model.mass, 8.0);
  EXPECT_DOUBLE_EQ(two.inertia.y() / model.inertia.y(), 32.0);
  EXPECT_DOUBLE_EQ(two.added_mass(1, 5) / model.added_mass(1, 5), 16.0);
  EXPECT_DOUBLE_EQ(two.x_uu / model.x_uu, 4.0);
  EXPECT_DOUBLE_EQ(two.k_p / model.k_p, std::pow(2.0, 4.5));
  EXPECT_DOUBLE_EQ(two.thrust_time_constant / model.thrust_time_constant, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(two.rudder.max_rate / model.rudder.max_rate, 1.0 / std::sqrt(2.0));
  EXPECT_EQ(two.rudder.max_deflection, model.rudder.max_deflection);
  EXPECT_DOUBLE_EQ(two.surfaces[0].area / model.surfaces[0].area, 4.0);
}

// 3. scaling by 2 then by 0.5 gives the model back, and by 2 then 3 the same as by 6, within
// kRoundTripRelTol = 1e-12 (two roundings per factor)
TEST(ScaleVehicle, ScalingComposes) {
  constexpr double kRoundTripRelTol = 1e-12;
  std::vector<VehicleParams> models = ShippedVehicles();
  models.push_back(EveryFieldSet());
  for (VehicleParams model : models) {
    VehicleParams back = ScaleVehicle(ScaleVehicle(model, 2.0), 0.5);
    VehicleParams six = ScaleVehicle(ScaleVehicle(model, 2.0), 3.0);
    VehicleParams direct = ScaleVehicle(model, 6.0);
    for (const VehicleField& f : VehicleFields(model)) {
      EXPECT_NEAR(f.get(back), f.get(model), kRoundTripRelTol * std::abs(f.get(model))) << f.name;
      EXPECT_NEAR(f.get(six), f.get(direct), kRoundTripRelTol * std::abs(f.get(direct))) << f.name;
    }
  }
}

// 4. M' = D M D with D = diag(lambda^1.5 I3, lambda^2.5 I3) for M_RB and M_A alike (the header's
// congruence): the scaled mass matrix stays symmetric positive definite
TEST(ScaleVehicle, MassMatricesScaleByCongruence) {
  constexpr double kRelTol = 1e-13;
  for (const VehicleParams& model : ShippedVehicles()) {
    for (const double lambda : {0.5, 2.0, 3.0}) {
      const VehicleParams scaled = ScaleVehicle(model, lambda);
      Vec6 d;
      d << Vec3::Constant(std::pow(lambda, 1.5)), Vec3::Constant(std::pow(lambda, 2.5));
      const Mat6 expected_rb = d.asDiagonal() * RigidBodyMassMatrix(model) * d.asDiagonal();
      const Mat6 expected_a = d.asDiagonal() * model.added_mass * d.asDiagonal();
      EXPECT_LE((RigidBodyMassMatrix(scaled) - expected_rb).norm(), kRelTol * expected_rb.norm());
      EXPECT_LE((scaled.added_mass - expected_a).norm(), kRelTol * expected_a.norm());
    }
  }
}

// 5. Froude similarity of the model itself. A state of the model maps to the scaled vehicle's
// state p_W -> lambda p_W, v -> lambda^0.5 v, omega -> lambda^-0.5 omega, thrust -> lambda^3
// thrust (fin angles and attitude unchanged), the water's velocity -> lambda^0.5, its
// acceleration unchanged, the wave elevation -> lambda. Then every force term scales by
// lambda^3 and every moment by lambda^4 (header of vehicle_scaling.h), so
//   HydrodynamicForces -> [lambda^3; lambda^4],  nu_dot -> [lambda^0; lambda^-1],
//   p_dot -> lambda^0.5, thrust_dot -> lambda^2.5 (N/s).
// The fin servos' rates are not compared: their fixed 0.05 s lag (actuator.h) is the one term
// that is not similar (docs/vehicles.md §9). Tolerance: the forces are sums of terms of mixed sign
// (thrust against drag, weight against buoyancy), each exact to ~1e-16 relative, so the sum
// is exact to ~1e-16 of its largest term: kSimilarityTol = 1e-11 of the largest term's scale
// (the norm of the gravity and thrust terms, ~1e5 N for the towing vehicle).
struct Sample {
  VehicleState state;
  VehicleCommand command;
  VehicleFlow flow;
};

Sample RandomSample(const VehicleParams& p, std::mt19937* rng, bool current, bool waves) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Sample s;
  s.state.p_W = Vec3(10 * u(*rng), 10 * u(*rng), p.design_depth + 0.3 * u(*rng));
  s.state.q_WB = QuaternionFromEulerZYX(Vec3(0.3 * u(*rng), 0.3 * u(*rng), kPi * u(*rng)));
  s.state.nu << 3 + 2 * u(*rng), u(*rng), 0.5 * u(*rng), 0.3 * u(*rng), 0.2 * u(*rng),
      0.2 * u(*rng);
  s.state.actuator[kThrust] = p.has_propeller ? 0.5 * p.max_thrust * (1 + u(*rng)) : 0.0;
  s.state.actuator[kRudder] = 0.3 * u(*rng);
  s.state.actuator[kElevator] = 0.3 * u(*rng);
  s.command.thrust = p.has_propeller ? 0.4 * p.max_thrust * (1 + u(*rng)) : 0.0;
  s.command.rudder = 0.4 * u(*rng);
  s.command.elevator = 0.4 * u(*rng);
  if (current) s.flow.origin.velocity = Vec3(u(*rng), u(*rng), 0.1 * u(*rng));
  if (waves) {
    s.flow.accelerating = true;
    for (Vec3& a : s.flow.hull_acceleration_W) a = Vec3(u(*rng), u(*rng), u(*rng));
    s.flow.origin.acceleration = s.flow.hull_acceleration_W[VehicleFlow::kHullStations / 2];
    s.flow.waves = true;
    for (double& e : s.flow.elevation) e = 0.5 * u(*rng);
  }
  return s;
}

Sample Scaled(const Sample& s, double lambda) {
  const double sq = std::sqrt(lambda);
  Sample t = s;
  t.state.p_W *= lambda;
  t.state.nu.head<3>() *= sq;
  t.state.nu.tail<3>() /= sq;
  t.state.actuator[kThrust] *= lambda * lambda * lambda;
  t.command.thrust *= lambda * lambda * lambda;
  t.flow.origin.velocity *= sq;
  for (double& e : t.flow.elevation) e *= lambda;
  return t;
}

TEST(ScaleVehicle, VehicleModelIsFroudeSimilar) {
  constexpr double kSimilarityTol = 1e-11;
  const Environment env;
  std::mt19937 rng(31);
  std::vector<VehicleParams> models = ShippedVehicles();
  // the towing vehicle with the terms the files leave at zero switched on
  VehicleParams full = models[0];
  full.k_p = -300.0;
  full.y_ur = 500.0;
  full.z_uq = -500.0;
  full.m_uq = -2000.0;
  full.n_ur = -2000.0;
  full.r_b = Vec3(0.1, 0.02, -0.05);
  models.push_back(full);
  double worst = 0.0;
  for (const VehicleParams& model : models) {
    for (const double lambda : {0.5, 2.0, 3.0}) {
      const VehicleParams scaled = ScaleVehicle(model, lambda);
      const double sq = std::sqrt(lambda), l3 = lambda * lambda * lambda;
      for (int k = 0; k < 20; ++k) {
        const Sample a = RandomSample(model, &rng, k % 2 == 1, k % 4 >= 2);
        const Sample b = Scaled(a, lambda);
        SCOPED_TRACE("lambda " + std::to_string(lambda) + ", sample " + std::to_string(k));
        // forces lambda^3, moments lambda^4
        const Vec6 f_a = HydrodynamicForces(model, env, a.state, a.flow);
        const Vec6 f_b = HydrodynamicForces(scaled, env, b.state, b.flow);
        const double force_scale = model.mass * env.gravity + std::abs(model.max_thrust);
        const double moment_scale = force_scale * model.length;
        const double e_force = (f_b.head<3>() / l3 - f_a.head<3>()).norm() / force_scale;
        const double e_moment =
            (f_b.tail<3>() / (l3 * lambda) - f_a.tail<3>()).norm() / moment_scale;
        EXPECT_LT(e_force, kSimilarityTol);
        EXPECT_LT(e_moment, kSimilarityTol);
        worst = std::max({worst, e_force, e_moment});
        // the rates, with an external load at a body point (a cable) scaled likewise
        const Vec3 force_B(200 * l3, -50 * l3, 80 * l3);
        const Vec3 at_B(1.0, 0.0, 0.2);
        const VehicleDerivative d_a = VehicleRates(model, env, a.state, a.command, force_B / l3,
                                                   at_B.cross(force_B / l3), a.flow);
        const VehicleDerivative d_b = VehicleRates(scaled, env, b.state, b.command, force_B,
                                                   (lambda * at_B).cross(force_B), b.flow);
        const double acc = env.gravity, ang = env.gravity / model.length;
        EXPECT_LT((d_b.nu_dot.head<3>() - d_a.nu_dot.head<3>()).norm() / acc, kSimilarityTol);
        EXPECT_LT((d_b.nu_dot.tail<3>() * lambda - d_a.nu_dot.tail<3>()).norm() / ang,
                  kSimilarityTol);
        EXPECT_LT((d_b.p_dot_W / sq - d_a.p_dot_W).norm(), kSimilarityTol * 10.0);
        if (model.has_propeller) {
          EXPECT_NEAR(d_b.actuator_dot[kThrust] / (l3 / sq), d_a.actuator_dot[kThrust],
                      kSimilarityTol * model.max_thrust);
        }
      }
    }
  }
  std::printf("Froude similarity of the vehicle model: largest relative difference %.2e\n", worst);
}

}  // namespace
}  // namespace towsim::core
