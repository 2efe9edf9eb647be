#include "core/step_sampler.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/initial_shape.h"

namespace towsim::core {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHeight = 2.0, kPeriod = 8.0, kG = 9.81, kRho = 1025.0;

// a vertical cable from a vehicle at 3 m depth (2 m/s ahead) down to a sphere, in a regular
// deep-water wave
Model WavyModel() {
  Model m;
  m.environment.waves = WaveField::Regular(kHeight, kPeriod, 0.0, 0.0,
                                           std::numeric_limits<double>::infinity(), kG, kRho);
  m.cables[0].length = 40.0;
  m.cables[0].elements = 4;
  m.cables[0].initial = InitialShape::kVertical;
  // from the vehicle (the cable's start) down to the sphere (its end)
  for (CableEnd* end : {&m.cables[0].start, &m.cables[0].end}) end->body = 0;
  m.cables[0].start.kind = EndKind::kVehicle;
  m.cables[0].end.kind = EndKind::kSphere;
  Vehicle v;
  v.name = "tow";
  v.params.length = 5.0;  // the hull stations the water is sampled at: x_B in [-2.5, 2.5] m
  v.position = Vec3(0, 0, 3.0);
  v.nu << 2.0, 0, 0, 0, 0, 0;
  m.vehicles.push_back(v);
  SphereBody s;
  s.name = "weight";
  s.position = Vec3(0, 0, 43.0);
  m.spheres.push_back(s);
  return m;
}

TEST(StepSampler, SamplesTheWavesAtTheNodesAndSpheres) {
  const System sys(WavyModel());
  State s;
  BuildInitialState(sys, &s);
  const StepSampler sampler(sys);
  StepInputs in;
  sampler.Resize(&in);
  ASSERT_EQ(in.waves.nodes.size(), 5u);
  ASSERT_EQ(in.waves.spheres.size(), 1u);
  EXPECT_FALSE(in.has_waves);
  const double t = 1.3;
  sampler.SampleWaves(s.q, t, &in);
  EXPECT_TRUE(in.has_waves);
  // each node: the sea's waves at r with their derivative along r' (exactly those bits)
  for (int n = 0; n < sys.num_nodes(); ++n) {
    const int o = sys.CableDof(n);
    const WaveSample w = sys.sea().Waves(s.q.segment<3>(o), s.q.segment<3>(o + 3), t);
    EXPECT_EQ(in.waves.nodes[n].velocity, w.velocity) << n;
    EXPECT_EQ(in.waves.nodes[n].d_velocity, w.d_velocity) << n;
    EXPECT_EQ(in.waves.nodes[n].acceleration, w.acceleration) << n;
    EXPECT_EQ(in.waves.nodes[n].d_acceleration, w.d_acceleration) << n;
  }
  // the sphere 43 m down: Airy's deep-water orbit, |u| = (H / 2) omega exp(-k z), k = omega^2/g
  const double omega = 2.0 * kPi / kPeriod, k = omega * omega / kG;
  const double speed = 0.5 * kHeight * omega * std::exp(-k * 43.0);
  // the same closed form, summed once in float past the phase (environment_field.h): a few
  // float roundings (2^-24 each) of the one term
  constexpr double kAiryRelTol = 8 * 5.960464477539063e-8;
  EXPECT_NEAR(in.waves.spheres[0].velocity.norm(), speed, kAiryRelTol * speed);
  // the material acceleration: the local one (|du/dt| = omega |u|) and the convective
  // (u . grad) u = k |u|^2 upward (wave_field.h)
  const Vec3 local = in.waves.spheres[0].acceleration - Vec3(0.0, 0.0, -k * speed * speed);
  EXPECT_NEAR(local.norm(), omega * speed, kAiryRelTol * omega * speed);
  EXPECT_EQ(in.waves.spheres[0].d_velocity, Vec3::Zero());  // d = 0 at a sphere
}

TEST(StepSampler, SamplesTheVehiclesAtTheStartAndThePredictedEnd) {
  const Model m = WavyModel();
  const System sys(m);
  State s;
  BuildInitialState(sys, &s);
  s.t = 2.0;
  s.coupling.flow_end.assign(1, VehicleFlow());
  const StepSampler sampler(sys);
  StepInputs in;
  sampler.Resize(&in);
  const double h = 0.5;
  const VehicleParams& vp = m.vehicles[0].params;
  // no earlier step: the start sampled at the pose of t_0, the end 2 m/s x 0.5 s ahead
  s.coupling.flow_time = -1.0;
  sampler.SampleVehicleFlows(s, h, &in);
  const VehicleFlow start = SampleVehicleFlow(vp, sys.sea(), Vec3(0, 0, 3), s.vehicles[0].q_WB, 2.0);
  const VehicleFlow end = SampleVehicleFlow(vp, sys.sea(), Vec3(1, 0, 3), s.vehicles[0].q_WB, 2.5);
  EXPECT_EQ(in.vehicle_flow_start[0].origin.velocity, start.origin.velocity);
  EXPECT_EQ(in.vehicle_flow_end[0].origin.velocity, end.origin.velocity);
  EXPECT_EQ(in.vehicle_flow_end[0].elevation, end.elevation);
  EXPECT_NE(in.vehicle_flow_start[0].origin.velocity, in.vehicle_flow_end[0].origin.velocity);
  // the previous step ended at t_0: its end is this step's start
  s.coupling.flow_end[0] = UniformFlow(Vec3(0.25, -0.5, 0.125));
  s.coupling.flow_time = 2.0;
  sampler.SampleVehicleFlows(s, h, &in);
  EXPECT_EQ(in.vehicle_flow_start[0].origin.velocity, Vec3(0.25, -0.5, 0.125));
  EXPECT_EQ(in.vehicle_flow_end[0].origin.velocity, end.origin.velocity);
}

TEST(StepSampler, TakesTheSupportsAndTheDrumFromTheState) {
  Model m = WavyModel();
  m.cables[0].winch = WinchParams{20.0, 60.0, 1.0, 0.5};  // the drum at the vehicle
  const System sys(m);
  State s;
  BuildInitialState(sys, &s);
  s.winches.resize(1);  // WinchDrive::Initialize's (winch_drive.h)
  s.supports[0] = {Vec3(1, 2, 3), Vec3(4, 5, 6), 0.5, 0.75, 2.0 * Mat3::Identity(), Vec3(7, 8, 9)};
  s.winches[0].drum = {0.5, 12.0, 0.25, -0.125};
  StepInputs in;
  StepSampler(sys).TakeMotions(s, &in);
  EXPECT_EQ(in.supports[0].p1, Vec3(4, 5, 6));
  EXPECT_EQ(in.supports[0].t1, 0.75);
  EXPECT_EQ(in.supports[0].compliance, 2.0 * Mat3::Identity());
  EXPECT_EQ(in.supports[0].lambda1, Vec3(7, 8, 9));
  EXPECT_EQ(in.supports[1].p1, s.supports[1].p1);
  // l_0(t) = 12 + 0.25 (t - 0.5) - 0.0625 (t - 0.5)^2
  EXPECT_EQ(in.drums[0].LengthAt(2.5), 12.0 + 0.5 - 0.25);
  EXPECT_EQ(in.drums[0].RateAt(2.5), 0.25 - 0.25);
}

}  // namespace
}  // namespace towsim::core
