#include "towfish_depth/seabed.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace towsim::controllers {

SeabedProfile FlatSeabed(double depth) { return SeabedProfile{{0.0}, {depth}}; }

SeabedProfile ParseSeabedProfile(const std::string& text, const std::string& what) {
  SeabedProfile p;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    double s = 0, d = 0;
    char tail = 0;
    if (std::sscanf(item.c_str(), "%lf:%lf%c", &s, &d, &tail) != 2 || !std::isfinite(s) ||
        !std::isfinite(d)) {
      throw std::runtime_error(what + " " + text + ": '" + item +
                               "' is not s:depth (e.g. 0:60,500:45 [m])");
    }
    if (!p.s.empty() && !(s > p.s.back())) {
      throw std::runtime_error(what + " " + text + ": along-track distances must increase");
    }
    if (!(d > 0.0)) throw std::runtime_error(what + " " + text + ": seabed depths must be > 0");
    p.s.push_back(s);
    p.depth.push_back(d);
  }
  if (p.s.empty()) throw std::runtime_error(what + " " + text + ": needs at least one s:depth");
  return p;
}

double SeabedDepth(const SeabedProfile& p, double s) {
  if (s <= p.s.front()) return p.depth.front();
  if (s >= p.s.back()) return p.depth.back();
  size_t i = 1;
  while (p.s[i] < s) ++i;
  const double w = (s - p.s[i - 1]) / (p.s[i] - p.s[i - 1]);
  return p.depth[i - 1] + w * (p.depth[i] - p.depth[i - 1]);
}

double AlongTrack::Update(double x_now, double y_now) {
  if (started) s += std::hypot(x_now - x, y_now - y);
  started = true;
  x = x_now;
  y = y_now;
  return s;
}

}  // namespace towsim::controllers
