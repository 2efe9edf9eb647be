#pragma once
// A DDS domain id of the test's own (docs/testing_controllers.md, "Domain ids"): parallel test
// processes (ctest -j) each take a different one.
//
// A DomainLease holds an exclusive lock on the file <lock dir>/towsim-dds-domain-<id>.lock
// (flock: the kernel drops it when the process ends, however it ends) and, before taking an
// id, checks that no DDS participant of this network namespace already uses it: the UDP port
// of participant index 0 of that domain (Cyclone DDS port mapping, unicast discovery:
// 7400 + 250 * id + 10) must be free on 127.0.0.1. So programs that take no lock (sim_node
// started by hand) are avoided too.
//
// Ids come from TOWSIM_TEST_DOMAINS ("FIRST-LAST", default 200-231) and the lock directory
// from TOWSIM_DOMAIN_LOCK_DIR (default the system temp dir). 231 is the highest id the
// project's cyclonedds.xml can use: the user port of participant index
// MaxAutoParticipantIndex = 120 is 7400 + 250 * id + 11 + 2 * 120 <= 65535.

#include <string>

namespace towsim::testing {

inline constexpr int kFirstAutoDomain = 200;
inline constexpr int kLastAutoDomain = 231;

// the UDP port of discovery for participant index 0 on domain `id` (Cyclone's defaults:
// base 7400, domain gain 250, d1 10)
int DiscoveryPort(int id);

class DomainLease {
 public:
  // takes the first free id of the range (TOWSIM_TEST_DOMAINS); throws std::runtime_error if
  // every id is taken or the range is malformed
  DomainLease();
  // takes exactly `id` (lock only, no port check: a fixed id is the caller's choice); throws
  // if another process holds it
  explicit DomainLease(int id);
  ~DomainLease();
  DomainLease(const DomainLease&) = delete;
  DomainLease& operator=(const DomainLease&) = delete;

  int id() const { return id_; }

 private:
  bool TryLock(int id);
  int id_ = -1;
  int fd_ = -1;
};

// the id range of TOWSIM_TEST_DOMAINS (default kFirstAutoDomain-kLastAutoDomain); throws
// std::runtime_error naming the variable, its value and the rule
void AutoDomainRange(int* first, int* last);

}  // namespace towsim::testing
