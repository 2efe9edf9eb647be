// maneuver_runner: plays the paper's Case 2 (U-turn) against the live state of a node:
//   maneuver_runner [--body tow_vehicle] [--thrust 4165] [--rudder-deg 20] [--start 55]
//                   [--until-yaw-deg 170] [--domain 0] [--namespace /towsim] [--timeout 30]
// Thrust T from the first step; from t >= start the rudder at rudder-deg until the body's yaw
// reaches until-yaw-deg, then 0. Case 1 (constant thrust): --rudder-deg 0. Needs
// CYCLONEDDS_URI. Exit 0 at the end of the node's run or on SIGINT/SIGTERM, 1 on an error or a
// timeout, 2 on a bad command line. Prints the time the turn ended.

#include <cstdio>
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>

#include "common/client.h"
#include "common/flags.h"
#include "common/laws.h"
#include "maneuver_runner/uturn.h"

using namespace towsim::controllers;

int main(int argc, char** argv) {
  ClientOptions opt;
  opt.name = "maneuver_runner";
  UTurnParams p;
  try {
    const Flags f(argc, argv,
                  {"body", "thrust", "rudder-deg", "start", "until-yaw-deg", "domain", "namespace",
                   "timeout"});
    opt.body = f.String("body", "tow_vehicle");
    opt.domain = static_cast<uint32_t>(f.Number("domain", 0));
    opt.ns = f.String("namespace", "/towsim");
    opt.timeout = f.Number("timeout", 30.0);
    p.thrust = f.Number("thrust", 4165.0);
    p.rudder = Rad(f.Number("rudder-deg", 20.0));
    p.start = f.Number("start", 55.0);
    p.until_yaw = Rad(f.Number("until-yaw-deg", 170.0));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "maneuver_runner: error: %s\n", e.what());
    return 2;
  }
  try {
    RequireDdsUri();
    InstallStopHandlers();
    LockstepClient client(opt);
    UTurnState state;
    double turn_end = -1.0, yaw_max = -1e9;
    const int rc = client.Run([&](const BodyState& b) {
      const bool before = state.turned;
      const ManeuverCommand c = UTurnStep(p, state, b.t, b.yaw);
      if (!before && state.turned) turn_end = b.t;
      if (b.t >= p.start) yaw_max = std::max(yaw_max, Deg(b.yaw));
      return Actuation{c.thrust, c.rudder, c.elevator};
    });
    std::printf("maneuver_runner: %llu steps answered, turn ended at t = %g s\n",
                static_cast<unsigned long long>(client.steps_answered()), turn_end);
    return rc;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "maneuver_runner: error: %s\n", e.what());
    return 1;
  }
}
