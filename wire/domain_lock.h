#pragma once
// A DDS domain id of a process's own, on one machine: the test fixture's DomainLease
// (docs/testing_controllers.md "Domain ids") and a sweep's cases with controllers
// (docs/sweeps.md "Controllers") take their ids through this one lock, so that sweeps and
// tests on one machine avoid each other. An id is taken by an exclusive lock (flock) on
// <lock dir>/towsim-dds-domain-<id>.lock; the kernel drops the lock when the process ends,
// however it ends. Take() also skips an id whose discovery port (participant index 0:
// 7400 + 250 id + 10, Cyclone's defaults) is bound on 127.0.0.1: a participant outside the
// lock protocol (a node started by hand) uses it. The lock directory is
// TOWSIM_DOMAIN_LOCK_DIR, else the system's temporary directory.

#include <optional>
#include <string>

namespace towsim::wire {

// the UDP port of discovery for participant index 0 on domain `id` (Cyclone's defaults:
// base 7400, domain gain 250, d1 10)
int DiscoveryPort(int id);

class DomainLock {
 public:
  // the first id in [first, last] whose lock is free and whose discovery port is unbound;
  // nullopt if none
  static std::optional<DomainLock> Take(int first, int last);
  // exactly `id`, by its lock only (a fixed id is the caller's choice); nullopt if another
  // process holds it
  static std::optional<DomainLock> TakeExactly(int id);
  DomainLock(DomainLock&& other) noexcept;
  DomainLock& operator=(DomainLock&& other) noexcept;
  DomainLock(const DomainLock&) = delete;
  DomainLock& operator=(const DomainLock&) = delete;
  ~DomainLock();

  int id() const { return id_; }
  // the lock file of `id`
  static std::string LockPath(int id);

 private:
  DomainLock(int id, int fd) : id_(id), fd_(fd) {}
  int id_ = -1;
  int fd_ = -1;
};

}  // namespace towsim::wire
