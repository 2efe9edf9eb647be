#pragma once
// A DDS domain id of the test's own (docs/testing_controllers.md, "Domain ids"): parallel test
// processes (ctest -j) each take a different one.
//
// A DomainLease holds a wire::DomainLock (wire/domain_lock.h, the lock the sweeps take too):
// an exclusive lock on the file <lock dir>/towsim-dds-domain-<id>.lock (flock: the kernel
// drops it when the process ends, however it ends); an id taken from the range is also one
// whose discovery port (participant index 0: 7400 + 250 * id + 10) is free on 127.0.0.1, so
// programs that take no lock (sim_node started by hand) are avoided too.
//
// Ids come from TOWSIM_TEST_DOMAINS ("FIRST-LAST", default 200-231) and the lock directory
// from TOWSIM_DOMAIN_LOCK_DIR (default the system temp dir). 231 is the highest id the
// project's cyclonedds.xml can use: the user port of participant index
// MaxAutoParticipantIndex = 120 is 7400 + 250 * id + 11 + 2 * 120 <= 65535.

#include <optional>
#include <string>

#include "wire/domain_lock.h"

namespace towsim::testing {

inline constexpr int kFirstAutoDomain = 200;
inline constexpr int kLastAutoDomain = 231;

using wire::DiscoveryPort;

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

  int id() const { return lock_->id(); }

 private:
  std::optional<wire::DomainLock> lock_;  // wire/domain_lock.h: the sweeps take the same locks
};

// the id range of TOWSIM_TEST_DOMAINS (default kFirstAutoDomain-kLastAutoDomain); throws
// std::runtime_error naming the variable, its value and the rule
void AutoDomainRange(int* first, int* last);

}  // namespace towsim::testing
