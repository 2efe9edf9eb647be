#pragma once
// Altitude mode of the towfish depth controller (pure, no DDS): hold the towfish at a
// commanded altitude A above the seabed, i.e. at the target depth
//   z_d(s) = seabed(s) - A
// with seabed(s) the seabed depth [m] (z down) along track: a flat seabed (one point), or a
// piecewise-linear profile through (s_i, d_i), s_i strictly increasing, held constant before
// the first and after the last point. s is the horizontal distance the towfish has run since
// the controller's first step (AlongTrack integrates |(dx, dy)| between answered steps).

#include <string>
#include <vector>

namespace towsim::controllers {

struct SeabedProfile {
  std::vector<double> s;      // along-track distance [m], strictly increasing
  std::vector<double> depth;  // seabed depth there [m], > 0
};

// a flat seabed at `depth` [m]
SeabedProfile FlatSeabed(double depth);

// parses "s0:d0,s1:d1,..." (throws std::runtime_error naming `what`, the text and the rule)
SeabedProfile ParseSeabedProfile(const std::string& text, const std::string& what);

// the seabed depth at along-track distance s [m]
double SeabedDepth(const SeabedProfile& profile, double s);

// the commanded depth [m] holding `altitude` [m] above the seabed at s
inline double AltitudeTargetDepth(const SeabedProfile& profile, double s, double altitude) {
  return SeabedDepth(profile, s) - altitude;
}

// horizontal distance run since the first sample [m]
struct AlongTrack {
  bool started = false;
  double x = 0.0, y = 0.0, s = 0.0;
  double Update(double x_now, double y_now);
};

}  // namespace towsim::controllers
