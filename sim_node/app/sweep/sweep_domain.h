#pragma once
// The DDS domain id of a sweep case with controllers (docs/sweeps.md "Controllers"): each
// case running at once takes one of its own, the first free id from the sweep's `domain` up
// to kMaxSweepDomain. An id is taken by an exclusive lock (flock) on
// <lock dir>/towsim-dds-domain-<id>.lock, the lock files of the test fixture
// (docs/testing_controllers.md "Domain ids"), so sweeps and tests on one machine avoid each
// other; the kernel drops the lock when the process ends, however it ends. An id whose
// discovery port (participant index 0: 7400 + 250 id + 10, Cyclone's defaults) is bound on
// 127.0.0.1 is skipped too: a node started by hand uses it. The lock directory is
// TOWSIM_DOMAIN_LOCK_DIR, else the system's temporary directory.

#include <optional>
#include <string>

namespace towsim::app {

class DomainLock {
 public:
  // the first free id in [first, last]; nullopt if every one is held
  static std::optional<DomainLock> Take(int first, int last);
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

}  // namespace towsim::app
