#pragma once
// A body's altimeter and pressure sensor on the wire (docs/sensors.md): pure translators from
// the core's sea at a body (Simulation::BodyAltimeterRange, the waves' kinematics) to
// sensor_msgs/Range and sensor_msgs/FluidPressure; no DDS entities, no clocks
// (tests/unit/sensor_translators_test.cc).
//
//   altitude  sensor_msgs/Range: range = the distance from the body origin along its beam, the
//             body's z axis (down in the NED body frame), to the seabed [m]; ULTRASOUND (an
//             acoustic altimeter), field of view kAltimeterFieldOfView, min_range 0, max_range
//             kAltimeterMaxRange. REP 117: +inf when nothing echoes (no seabed, the beam at or
//             above the horizon over a flat bed, the bed beyond max_range), -inf when the
//             origin is below the bed
//   pressure  sensor_msgs/FluidPressure: absolute pressure [Pa] at the body origin, linear
//             theory's total pressure: kAtmosphericPressure + rho g z + p_d below the
//             instantaneous surface, p_d the waves' dynamic pressure
//             rho g sum a cosh(k(h - z)) / cosh(kh) cos(th) (core/wave_field.h); the
//             atmosphere above it; variance 0
//
// Header: stamp = simulation time, frame_id = the body's name (its body frame).

#include <string>

#include "core/simulation.h"
#include "dds/messages.h"

namespace towsim::dds {

inline constexpr float kAltimeterFieldOfView = 0.1f;      // [rad], a narrow-beam altimeter
inline constexpr float kAltimeterMaxRange = 200.0f;       // [m]
inline constexpr double kAtmosphericPressure = 101325.0;  // [Pa], standard atmosphere

class RangeMessage {
 public:
  // frame_id: the body; the altimeter's constants set once
  explicit RangeMessage(std::string frame_id);
  RangeMessage(const RangeMessage&) = delete;
  RangeMessage& operator=(const RangeMessage&) = delete;
  RangeMsg msg;

 private:
  std::string frame_id_;
};

class FluidPressureMessage {
 public:
  explicit FluidPressureMessage(std::string frame_id);
  FluidPressureMessage(const FluidPressureMessage&) = delete;
  FluidPressureMessage& operator=(const FluidPressureMessage&) = delete;
  FluidPressureMsg msg;

 private:
  std::string frame_id_;
};

// the range of body b's altimeter (above); never allocates
void ToAltitude(const core::Simulation& sim, int body, RangeMsg* msg);
// the absolute pressure at body b's origin (above); never allocates
void ToPressure(const core::Simulation& sim, int body, FluidPressureMsg* msg);

}  // namespace towsim::dds
