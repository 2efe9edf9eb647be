#include "app/sweep/sweep_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace towsim::app {

SweepLock::SweepLock(const std::string& dir) {
  const std::string path = dir + "/.lock";
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    error_ = "--out " + dir + ": cannot open its lock " + path + ": " + std::strerror(errno);
    return;
  }
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int why = errno;
    // the holder wrote its pid when it took the lock
    char text[32] = {};
    const ssize_t n = pread(fd, text, sizeof text - 1, 0);
    std::string pid(text, n > 0 ? static_cast<size_t>(n) : 0);
    while (!pid.empty() && (pid.back() == '\n' || pid.back() == '\0')) pid.pop_back();
    close(fd);
    error_ = why == EWOULDBLOCK
                 ? "--out " + dir + ": another towsim_sweep (pid " + (pid.empty() ? "?" : pid) +
                       ") runs in it (" + path + "); wait for it to end or choose another folder"
                 : "--out " + dir + ": cannot lock " + path + ": " + std::strerror(why);
    return;
  }
  const std::string pid = std::to_string(getpid()) + "\n";
  if (ftruncate(fd, 0) != 0 || pwrite(fd, pid.data(), pid.size(), 0) < 0) {
    error_ = "--out " + dir + ": cannot write its lock " + path + ": " + std::strerror(errno);
    close(fd);
    return;
  }
  fd_ = fd;
}

SweepLock::~SweepLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

}  // namespace towsim::app
