#include "testing/assertions.h"

#include <cmath>
#include <sstream>

#include "common/laws.h"

namespace towsim::testing {

::testing::AssertionResult StaysWithin(const std::vector<OdometrySample>& samples, double after,
                                       const Signal& signal, double lo, double hi,
                                       const std::string& what, int run) {
  int checked = 0;
  double low = HUGE_VAL, high = -HUGE_VAL;
  for (const OdometrySample& s : samples) {
    if (s.run != run || s.t < after - 1e-9) continue;
    const double x = signal(s);
    ++checked;
    low = std::min(low, x);
    high = std::max(high, x);
    if (!(x >= lo && x <= hi)) {  // a NaN fails too
      return ::testing::AssertionFailure()
             << what << " = " << x << " at t = " << s.t << " s (run " << run << "): outside [" << lo
             << ", " << hi << "] required from t = " << after << " s";
    }
  }
  if (checked == 0) {
    return ::testing::AssertionFailure() << what << ": no sample at t >= " << after << " s (run "
                                         << run << ", " << samples.size() << " samples in all)";
  }
  return ::testing::AssertionSuccess() << what << " in [" << low << ", " << high << "] over "
                                       << checked << " samples from t = " << after << " s";
}

::testing::AssertionResult NoFailsafe(const std::vector<StatusSample>& statuses) {
  if (statuses.empty()) return ::testing::AssertionFailure() << "no status received";
  for (const StatusSample& s : statuses) {
    if (s.failsafe()) {
      std::string names;
      for (const std::string& b : s.failsafe_bodies) names += (names.empty() ? "" : ", ") + b;
      return ::testing::AssertionFailure() << "failsafe at t = " << s.t << " s (step " << s.step
                                           << "): " << names << ": " << s.message;
    }
  }
  if (statuses.back().failsafe_count != 0) {
    return ::testing::AssertionFailure()
           << "the last status counts " << statuses.back().failsafe_count << " failsafe entries";
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult TensionBelow(const std::vector<SimNode::TensionSample>& tensions,
                                        double max_tension) {
  if (tensions.empty()) return ::testing::AssertionFailure() << "no cable state received";
  const SimNode::TensionSample* worst = &tensions.front();
  for (const SimNode::TensionSample& s : tensions) {
    if (s.max > worst->max) worst = &s;
  }
  std::ostringstream where;
  where << "max tension " << worst->max << " N at node " << worst->node << ", t = " << worst->t
        << " s (run " << worst->run << ", " << tensions.size() << " cable states)";
  if (!(worst->max <= max_tension)) {
    return ::testing::AssertionFailure() << where.str() << " > " << max_tension << " N";
  }
  return ::testing::AssertionSuccess() << where.str();
}

Signal HeadingError(double target) {
  return [target](const OdometrySample& s) { return controllers::WrapPi(s.yaw - target); };
}

}  // namespace towsim::testing
