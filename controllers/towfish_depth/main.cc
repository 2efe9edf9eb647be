// towfish_depth: holds a towed body at a commanded depth with its elevators (PID with
// anti-windup and rate limit, towfish_depth/depth_law.h):
//   towfish_depth [--body towfish] --depth D [--kp 0.15] [--ki 0.01] [--kd 0.5] [--max-elevator-deg 25]
//                 [--rate-deg 20] [--max-pitch-deg 30]
//                 [--elevator-sign -1] [--hold] [--domain 0] [--namespace /towsim] [--timeout 30]
//                 [--log FILE]
// --elevator-sign 1 for a body that dives on positive elevator (-1: it rises, the towfish); --hold commands zero elevator (the uncontrolled reference). --log writes "t z elevator" per
// step. Needs CYCLONEDDS_URI. Exit 0 at the end of the node's run or on SIGINT/SIGTERM, 1 on
// an error or a timeout, 2 on a bad command line.

#include <cstdio>
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>

#include "common/client.h"
#include "common/flags.h"
#include "common/laws.h"
#include "towfish_depth/depth_law.h"

using namespace towsim::controllers;

int main(int argc, char** argv) {
  ClientOptions opt;
  opt.name = "towfish_depth";
  DepthParams p;
  std::string log_path;
  try {
    const Flags f(argc, argv,
                  {"body", "depth", "kp", "ki", "kd", "max-elevator-deg", "rate-deg", "max-pitch-deg", "elevator-sign", "domain",
                   "namespace", "timeout", "log"},
                  {"hold"});
    if (!f.Has("depth") && !f.Has("hold")) throw std::runtime_error("--depth D is required");
    opt.body = f.String("body", "towfish");
    opt.domain = static_cast<uint32_t>(f.Number("domain", 0));
    opt.ns = f.String("namespace", "/towsim");
    opt.timeout = f.Number("timeout", 30.0);
    p.depth = f.Number("depth", 0.0);
    p.kp = f.Number("kp", p.kp);
    p.ki = f.Number("ki", p.ki);
    p.kd = f.Number("kd", p.kd);
    p.max_elevator = Rad(f.Number("max-elevator-deg", Deg(p.max_elevator)));
    p.rate_limit = Rad(f.Number("rate-deg", Deg(p.rate_limit)));
    p.sign = f.Number("elevator-sign", -1.0) >= 0.0 ? 1.0 : -1.0;
    p.max_pitch = Rad(f.Number("max-pitch-deg", Deg(p.max_pitch)));
    p.hold = f.Has("hold");
    log_path = f.String("log", "");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "towfish_depth: error: %s\n", e.what());
    return 2;
  }
  std::FILE* log = nullptr;
  try {
    RequireDdsUri();
    InstallStopHandlers();
    if (!log_path.empty()) {
      log = std::fopen(log_path.c_str(), "w");
      if (log == nullptr) throw std::runtime_error("cannot write " + log_path);
    }
    LockstepClient client(opt);
    PidState state;
    const int rc = client.Run([&](const BodyState& b) {
      const double elevator = DepthStep(p, state, b.z, b.z_dot, b.pitch, b.dt);
      if (log != nullptr) std::fprintf(log, "%.6f %.6f %.6f\n", b.t, b.z, elevator);
      return Actuation{0.0, 0.0, elevator};
    });
    if (log != nullptr) std::fclose(log);
    std::printf("towfish_depth: %llu steps answered\n",
                static_cast<unsigned long long>(client.steps_answered()));
    return rc;
  } catch (const std::exception& e) {
    if (log != nullptr) std::fclose(log);
    std::fprintf(stderr, "towfish_depth: error: %s\n", e.what());
    return 1;
  }
}
