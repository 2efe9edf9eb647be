#pragma once
// The lock of a sweep's folder (docs/sweeps.md): DIR/.lock, held with flock(LOCK_EX) for the
// sweep's life, so that two sweeps never write one folder (they contradicted each other and
// marked good cases failed). The holder writes its pid into the file; the lock goes with the
// process (also when it is killed), the file stays. The descriptor is close-on-exec: the
// sim_node processes of the cases do not inherit it.

#include <string>

namespace towsim::app {

class SweepLock {
 public:
  // takes the lock of `dir` (which exists) without waiting; on failure locked() is false and
  // error() says why: "--out DIR: another towsim_sweep (pid 1234) runs in it (DIR/.lock);
  // wait for it to end or choose another folder"
  explicit SweepLock(const std::string& dir);
  ~SweepLock();
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;

  bool locked() const { return fd_ >= 0; }
  const std::string& error() const { return error_; }

 private:
  int fd_ = -1;
  std::string error_;
};

}  // namespace towsim::app
