#include "wire/domain_lock.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace towsim::wire {
namespace {

// true if nothing in this network namespace has bound the UDP `port` on 127.0.0.1
bool PortFree(int port) {
  const int s = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (s < 0) return false;
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool free = bind(s, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0;
  close(s);
  return free;
}

}  // namespace

int DiscoveryPort(int id) { return 7400 + 250 * id + 10; }

std::string DomainLock::LockPath(int id) {
  const char* dir = std::getenv("TOWSIM_DOMAIN_LOCK_DIR");
  const std::filesystem::path base = dir != nullptr && *dir != '\0'
                                         ? std::filesystem::path(dir)
                                         : std::filesystem::temp_directory_path();
  return (base / ("towsim-dds-domain-" + std::to_string(id) + ".lock")).string();
}

std::optional<DomainLock> DomainLock::TakeExactly(int id) {
  const int fd = open(LockPath(id).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) return std::nullopt;
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    close(fd);
    return std::nullopt;
  }
  return DomainLock(id, fd);
}

std::optional<DomainLock> DomainLock::Take(int first, int last) {
  for (int id = first; id <= last; ++id) {
    std::optional<DomainLock> lock = TakeExactly(id);
    if (lock && PortFree(DiscoveryPort(id))) return lock;
  }
  return std::nullopt;
}

DomainLock::DomainLock(DomainLock&& other) noexcept : id_(other.id_), fd_(other.fd_) {
  other.fd_ = -1;
}

DomainLock& DomainLock::operator=(DomainLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) close(fd_);
    id_ = other.id_;
    fd_ = other.fd_;
    other.fd_ = -1;
  }
  return *this;
}

DomainLock::~DomainLock() {
  if (fd_ >= 0) close(fd_);
}

}  // namespace towsim::wire
