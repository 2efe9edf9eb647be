#pragma once
// The slow half of towfish_depth's winch mode (docs/controllers.md "towfish_depth"), a pure
// function (no DDS): the drum speed that moves the towfish's steady depth to the commanded one
// while the elevators (towfish_depth/depth_law.h) take the fast part.
//
// A towed body's steady depth grows with the paid-out length L (for a cable towed at a steady
// speed, dz/dL is the sine of the cable's mean angle below the horizontal, 0.1 .. 0.6 for the
// scenes here), so paying out at v moves the depth at about (dz/dL) v: the length is an
// integrator of the drum speed and a proportional law on the depth error suffices,
//   e_f' = (e - e_f) / T_f,                e = commanded depth - z  (> 0: too shallow)
//   v    = 0                                if |e_f| < deadband (the elevators hold it there)
//          clamp(k (e_f -+ deadband), -v_max, v_max)   otherwise
// rate-limited to |dv/dt| <= a_max, with v_max and a_max the winch's max_speed and
// max_acceleration (SceneInfo) or less. The filter T_f (default 10 s, against the elevator
// loop's few seconds) keeps the drum from answering the depth excursions the elevators correct
// within seconds; the closed loop of the slow part has the time constant 1 / (k dz/dL), about
// 30 s for k = 0.1 1/s and dz/dL = 0.3, slow against the elevators and within the winch's
// limits for depth changes up to v_max / (k dz/dL).

namespace towsim::controllers {

struct WinchDepthParams {
  double gain = 0.1;           // k: drum speed per metre of depth error [1/s]
  double deadband = 0.5;       // [m]
  double filter = 10.0;        // T_f [s], > 0
  double max_speed = 1.0;      // v_max [m/s], > 0
  double max_acceleration = 0.2;  // a_max [m/s^2], > 0
};

struct WinchDepthState {
  bool initialized = false;
  double error = 0.0;  // e_f [m]
  double speed = 0.0;  // the last drum speed commanded [m/s]
};

// the drum speed [m/s] (+ pays out, the towfish goes deeper) answering the commanded depth
// `target` and the depth z [m] (world NED, down positive), step dt [s]
double WinchDepthStep(const WinchDepthParams& p, WinchDepthState& state, double target, double z,
                      double dt);

}  // namespace towsim::controllers
