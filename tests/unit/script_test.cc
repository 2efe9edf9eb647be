// core/script.h: conditions evaluated on a vehicle state, and the ScriptRunner firing each
// entry once, at its time and when its condition holds, with only its given fields.

#include "core/script.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/constants.h"
#include "core/model.h"
#include "core/simulation.h"

namespace towsim::core {
namespace {

constexpr double kDeg = kPi / 180.0;
// Euler angles go through a quaternion and back: exact to a few ulps of pi
constexpr double kAngleTolDeg = 1e-12;

// a small vehicle with a propeller and a rudder (numbers of no importance beyond stability)
VehicleParams Boat() {
  VehicleParams p;
  p.source = "test";
  p.length = 2.0;
  p.mass = 100.0;
  p.inertia = Vec3(1.0, 10.0, 10.0);
  p.volume = 100.0 / 1025.0;  // neutral
  p.added_mass.diagonal() << 5, 80, 80, 1, 9, 9;
  p.x_uu = -3.0;
  p.y_vv = p.z_ww = -100.0;
  p.m_qq = p.n_rr = p.k_pp = -20.0;
  LiftingSurface rudder;
  rudder.name = "rudder";
  rudder.channel = Channel::kRudder;
  rudder.position_B = Vec3(-1.0, 0.0, 0.0);
  rudder.normal_B = Vec3::UnitY();
  rudder.area = 0.01;
  p.surfaces.push_back(rudder);
  p.has_propeller = true;
  p.max_thrust = 400.0;
  p.thrust_time_constant = 0.5;
  return p;
}

// two boats; a 10 m cable hangs from the first one's origin, its lower end free
Model TwoBoats() {
  Model m;
  m.name = "script";
  m.time.step = 0.05;
  m.cables[0].length = 10.0;
  m.cables[0].elements = 2;
  m.cables[0].initial = InitialShape::kVertical;
  m.cables[0].start.kind = EndKind::kVehicle;
  m.cables[0].start.body = 0;
  for (const char* name : {"one", "two"}) {
    Vehicle v;
    v.name = name;
    v.params = Boat();
    m.vehicles.push_back(v);
  }
  m.vehicles[1].position = Vec3(0.0, 20.0, 0.0);
  return m;
}

ScriptEntry Entry(double at, int vehicle) {
  ScriptEntry e;
  e.at = at;
  e.vehicle = vehicle;
  e.body = vehicle == 0 ? "one" : "two";
  return e;
}

ScriptCondition Condition(ScriptCondition::Quantity q, ScriptCondition::Op op, double value) {
  ScriptCondition c;
  c.vehicle = 0;
  c.quantity = q;
  c.op = op;
  c.value = value;
  return c;
}

TEST(ConditionTest, QuantitiesOfTheState) {
  VehicleState s;
  s.p_W = Vec3(1.0, -2.0, 3.5);
  s.q_WB = QuaternionFromEulerZYX(Vec3(5 * kDeg, -10 * kDeg, 170 * kDeg));
  s.nu << 3.0, 4.0, 12.0, 0.1, -0.2, 0.3;
  using C = ScriptCondition;
  EXPECT_EQ(ConditionQuantity(C::kX, s), 1.0);
  EXPECT_EQ(ConditionQuantity(C::kY, s), -2.0);
  EXPECT_EQ(ConditionQuantity(C::kZ, s), 3.5);
  EXPECT_NEAR(ConditionQuantity(C::kRollDeg, s), 5.0, kAngleTolDeg);
  EXPECT_NEAR(ConditionQuantity(C::kPitchDeg, s), -10.0, kAngleTolDeg);
  EXPECT_NEAR(ConditionQuantity(C::kYawDeg, s), 170.0, kAngleTolDeg);
  EXPECT_EQ(ConditionQuantity(C::kU, s), 3.0);
  EXPECT_EQ(ConditionQuantity(C::kV, s), 4.0);
  EXPECT_EQ(ConditionQuantity(C::kW, s), 12.0);
  EXPECT_EQ(ConditionQuantity(C::kP, s), 0.1);
  EXPECT_EQ(ConditionQuantity(C::kQ, s), -0.2);
  EXPECT_EQ(ConditionQuantity(C::kR, s), 0.3);
  EXPECT_EQ(ConditionQuantity(C::kSpeed, s), 13.0);  // |(3, 4, 12)|
}

TEST(ConditionTest, YawWrapsToMinus180To180) {
  // 190 deg of heading reads as -170: "yaw_deg >= 170" holds from 170 up to 180 only
  VehicleState s;
  s.q_WB = QuaternionFromEulerZYX(Vec3(0.0, 0.0, 190 * kDeg));
  EXPECT_NEAR(ConditionQuantity(ScriptCondition::kYawDeg, s), -170.0, kAngleTolDeg);
}

TEST(ConditionTest, Operators) {
  VehicleState s;
  s.p_W.z() = 2.0;
  using C = ScriptCondition;
  struct Case {
    C::Op op;
    double value;
    bool holds;
  };
  const Case cases[] = {
      {C::kGreaterEqual, 2.0, true}, {C::kGreaterEqual, 2.5, false}, {C::kGreaterEqual, 1.5, true},
      {C::kLessEqual, 2.0, true},    {C::kLessEqual, 1.5, false},    {C::kLessEqual, 2.5, true},
      {C::kGreater, 2.0, false},     {C::kGreater, 1.5, true},       {C::kLess, 2.0, false},
      {C::kLess, 2.5, true},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(ConditionHolds(Condition(C::kZ, c.op, c.value), s), c.holds)
        << "op " << c.op << " value " << c.value;
  }
}

TEST(ScriptRunnerTest, EmptyScriptIsDone) {
  Model m = TwoBoats();
  Simulation sim(m);
  ScriptRunner script(m);
  EXPECT_TRUE(script.done());
  EXPECT_EQ(script.Apply(&sim), 0);
}

TEST(ScriptRunnerTest, FiresOnceAtItsTimeWithTheGivenFieldsOnly) {
  Model m = TwoBoats();
  ScriptEntry thrust = Entry(0.0, 0);
  thrust.set_thrust = true;
  thrust.thrust = 200.0;
  ScriptEntry rudder = Entry(0.1, 0);  // two steps of 0.05: t reaches 0.1 only up to rounding
  rudder.set_rudder = true;
  rudder.rudder = 10 * kDeg;
  m.script = {thrust, rudder};
  Simulation sim(m);
  ScriptRunner script(m);

  EXPECT_EQ(script.Apply(&sim), 1);
  EXPECT_EQ(sim.vehicle_command(0).thrust, 200.0);
  EXPECT_EQ(sim.vehicle_command(0).rudder, 0.0);
  EXPECT_FALSE(script.done());
  // fired entries stay fired; the next is not due yet
  EXPECT_EQ(script.Apply(&sim), 0);
  ASSERT_TRUE(sim.Step().ok());
  EXPECT_EQ(script.Apply(&sim), 0);
  ASSERT_TRUE(sim.Step().ok());
  EXPECT_NEAR(sim.time(), 0.1, 1e-12);
  EXPECT_EQ(script.Apply(&sim), 1);
  // the rudder changes, the thrust set before stays
  EXPECT_EQ(sim.vehicle_command(0).thrust, 200.0);
  EXPECT_EQ(sim.vehicle_command(0).rudder, 10 * kDeg);
  EXPECT_TRUE(script.done());
  // the other vehicle keeps its initial command
  EXPECT_EQ(sim.vehicle_command(1).thrust, 0.0);
  EXPECT_EQ(sim.vehicle_command(1).rudder, 0.0);
}

TEST(ScriptRunnerTest, EntriesDueTogetherApplyInScriptOrder) {
  Model m = TwoBoats();
  m.vehicles[1].command.thrust = 50.0;  // an initial command is kept where no field is given
  ScriptEntry a = Entry(0.0, 1);
  a.set_rudder = true;
  a.rudder = 0.2;
  ScriptEntry b = Entry(0.0, 1);
  b.set_rudder = true;
  b.rudder = -0.1;
  b.set_elevator = true;
  b.elevator = 0.05;
  m.script = {a, b};
  Simulation sim(m);
  ScriptRunner script(m);
  EXPECT_EQ(script.Apply(&sim), 2);
  EXPECT_EQ(sim.vehicle_command(1).rudder, -0.1);
  EXPECT_EQ(sim.vehicle_command(1).elevator, 0.05);
  EXPECT_EQ(sim.vehicle_command(1).thrust, 50.0);
  EXPECT_TRUE(script.done());
}

TEST(ScriptRunnerTest, ConditionFiresAtTheFirstStateWhereItHolds) {
  // the second boat moves north at 1 m/s: "two.x >= 0.3" first holds after about 0.3 s
  Model m = TwoBoats();
  m.vehicles[1].nu(0) = 1.0;
  ScriptEntry e = Entry(0.0, 1);
  e.has_condition = true;
  e.condition = Condition(ScriptCondition::kX, ScriptCondition::kGreaterEqual, 0.3);
  e.condition.vehicle = 1;
  e.set_thrust = true;
  e.thrust = 300.0;
  // a condition that never holds keeps its entry waiting
  ScriptEntry never = Entry(0.0, 0);
  never.has_condition = true;
  never.condition = Condition(ScriptCondition::kZ, ScriptCondition::kGreater, 1000.0);
  never.set_thrust = true;
  never.thrust = 400.0;
  m.script = {e, never};
  Simulation sim(m);
  ScriptRunner script(m);

  int fired_at_step = -1;
  for (int k = 0; k < 20 && fired_at_step < 0; ++k) {
    const bool holds = sim.vehicle_state(1).p_W.x() >= 0.3;
    const int fired = script.Apply(&sim);
    EXPECT_EQ(fired, holds ? 1 : 0) << "t = " << sim.time();
    if (fired == 1) fired_at_step = k;
    ASSERT_TRUE(sim.Step().ok());
  }
  ASSERT_GT(fired_at_step, 0) << "the condition should hold only after some steps";
  EXPECT_EQ(sim.vehicle_command(1).thrust, 300.0);
  EXPECT_EQ(sim.vehicle_command(0).thrust, 0.0);
  EXPECT_FALSE(script.done());  // `never` is still waiting
  EXPECT_EQ(script.Apply(&sim), 0);
}

TEST(ScriptRunnerTest, ConditionWaitsForItsTime) {
  // the condition holds from the start, but the entry is due at 0.1 s only
  Model m = TwoBoats();
  ScriptEntry e = Entry(0.1, 0);
  e.has_condition = true;
  e.condition = Condition(ScriptCondition::kSpeed, ScriptCondition::kGreaterEqual, 0.0);
  e.set_elevator = true;
  e.elevator = 0.0;
  m.script = {e};
  Simulation sim(m);
  ScriptRunner script(m);
  EXPECT_EQ(script.Apply(&sim), 0);
  ASSERT_TRUE(sim.Step().ok());
  EXPECT_EQ(script.Apply(&sim), 0);
  ASSERT_TRUE(sim.Step().ok());
  EXPECT_EQ(script.Apply(&sim), 1);
  EXPECT_TRUE(script.done());
}

}  // namespace
}  // namespace towsim::core
