// heading_hold: the example controller as a program (one DDS participant, lockstep client):
//   heading_hold --heading-deg H [--from S] [--thrust N] [--kp K] [--kd S] [--body tow_vehicle]
//                [--domain 0] [--namespace /towsim] [--timeout 30]
// Needs CYCLONEDDS_URI (the installed share/towsim/cyclonedds.xml). Exit 0 at the end of the
// node's run, 1 on an error or a timeout, 2 on a bad command line.

#include <cstdio>
#include <exception>

#include "common/client.h"
#include "common/flags.h"
#include "common/laws.h"
#include "heading_hold.h"

using towsim::controllers::ClientOptions;
using towsim::controllers::Flags;

int main(int argc, char** argv) {
  ClientOptions opt;
  opt.name = "heading_hold";
  controller_ci::HeadingHoldParams p;
  try {
    const Flags f(
        argc, argv,
        {"heading-deg", "from", "thrust", "kp", "kd", "body", "domain", "namespace", "timeout"});
    if (!f.Has("heading-deg")) throw std::runtime_error("--heading-deg H is required");
    p.heading = towsim::controllers::Rad(f.Number("heading-deg", 0.0));
    p.heading_from = f.Number("from", 0.0);
    p.thrust = f.Number("thrust", p.thrust);
    p.kp = f.Number("kp", p.kp);
    p.kd = f.Number("kd", p.kd);
    opt.body = f.String("body", "tow_vehicle");
    opt.domain = static_cast<uint32_t>(f.Number("domain", 0));
    opt.ns = f.String("namespace", opt.ns);
    opt.timeout = f.Number("timeout", opt.timeout);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "heading_hold: error: %s\n", e.what());
    return 2;
  }
  try {
    towsim::controllers::InstallStopHandlers();
    towsim::controllers::LockstepClient client(opt);
    return client.Run(
        [&p](const towsim::controllers::BodyState& s) { return controller_ci::HeadingHold(p, s); });
  } catch (const std::exception& e) {
    std::fprintf(stderr, "heading_hold: error: %s\n", e.what());
    return 1;
  }
}
