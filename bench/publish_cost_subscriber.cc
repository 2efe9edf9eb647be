// publish_cost_subscriber: a plain DDS subscriber of every topic sim_node publishes, for
// bench/publish_cost.sh (cost of publishing with and without a matched reader). Uses msgs/,
// the wire library (topic names, QoS) and the Cyclone C API only.
//
//   publish_cost_subscriber --domain N --bodies a,b [--namespace /towsim] [--idle S]
//
// Reliable keep-last-1 readers (the node's QoS) on rt/clock, rt/<ns>/status,
// rt/<ns>/cable/state and rt/<ns>/<b>/odom, rt/<ns>/<b>/cable_force for every body; takes
// every sample; exits 0 after S seconds (default 3) without data once data has flowed, printing
// the number of samples taken. Needs CYCLONEDDS_URI (the loopback configuration).

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <dds/dds.h>

#include "wire/qos.h"
#include "wire/topic_names.h"

namespace {

[[noreturn]] void Fail(const std::string& m) {
  std::fprintf(stderr, "publish_cost_subscriber: %s\n", m.c_str());
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  int domain = -1;
  std::string ns = "/towsim", bodies;
  double idle = 3.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) Fail(a + ": missing value");
    const std::string v = argv[++i];
    if (a == "--domain") {
      domain = std::atoi(v.c_str());
    } else if (a == "--namespace") {
      ns = v;
    } else if (a == "--bodies") {
      bodies = v;
    } else if (a == "--idle") {
      idle = std::atof(v.c_str());
    } else {
      Fail("unknown option " + a);
    }
  }
  if (domain < 0) Fail("--domain N is required");

  const dds_entity_t participant = dds_create_participant(domain, nullptr, nullptr);
  if (participant < 0) Fail(std::string("participant: ") + dds_strretcode(-participant));
  const towsim::wire::TopicNames names(ns);
  dds_qos_t* qos = towsim::wire::ProfileQos(towsim::wire::QosProfile::kState);

  std::vector<dds_entity_t> readers;
  auto subscribe = [&](towsim::wire::Topic t, const std::string& owner = "") {
    const std::string name = names.Name(t, owner);
    const dds_entity_t topic =
        dds_create_topic(participant, towsim::wire::SpecOf(t).type, name.c_str(), nullptr, nullptr);
    if (topic < 0) Fail("topic " + name + ": " + dds_strretcode(-topic));
    const dds_entity_t reader = dds_create_reader(participant, topic, qos, nullptr);
    if (reader < 0) Fail("reader " + name + ": " + dds_strretcode(-reader));
    readers.push_back(reader);
  };
  subscribe(towsim::wire::Topic::kClock);
  subscribe(towsim::wire::Topic::kStatus);
  subscribe(towsim::wire::Topic::kCableState);
  std::stringstream list(bodies);
  for (std::string b; std::getline(list, b, ',');) {
    if (b.empty()) continue;
    subscribe(towsim::wire::Topic::kOdom, b);
    subscribe(towsim::wire::Topic::kCableForce, b);
  }
  dds_delete_qos(qos);

  // take (and free) every sample: the loans are returned, as a real consumer would
  long taken = 0;
  bool flowing = false;
  auto last = std::chrono::steady_clock::now();
  void* samples[16] = {nullptr};
  dds_sample_info_t infos[16];
  while (true) {
    bool any = false;
    for (const dds_entity_t r : readers) {
      const int n = dds_take(r, samples, infos, 16, 16);
      if (n > 0) {
        taken += n;
        any = true;
        dds_return_loan(r, samples, n);
        samples[0] = nullptr;  // loan again next time
      }
    }
    const auto now = std::chrono::steady_clock::now();
    if (any) {
      flowing = true;
      last = now;
    } else {
      if (flowing && std::chrono::duration<double>(now - last).count() > idle) break;
      if (!flowing && std::chrono::duration<double>(now - last).count() > 60.0)
        Fail("no data for 60 s");
      dds_sleepfor(DDS_USECS(200));
    }
  }
  std::printf("publish_cost_subscriber: %ld samples\n", taken);
  dds_delete(participant);
  return 0;
}
