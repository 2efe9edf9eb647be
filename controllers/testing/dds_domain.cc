#include "testing/dds_domain.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace towsim::testing {
namespace {

std::string LockPath(int id) {
  const char* dir = std::getenv("TOWSIM_DOMAIN_LOCK_DIR");
  const std::filesystem::path base = dir != nullptr && *dir != '\0'
                                         ? std::filesystem::path(dir)
                                         : std::filesystem::temp_directory_path();
  return (base / ("towsim-dds-domain-" + std::to_string(id) + ".lock")).string();
}

// true if nothing in this network namespace has bound the UDP port on 127.0.0.1
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

void AutoDomainRange(int* first, int* last) {
  *first = kFirstAutoDomain;
  *last = kLastAutoDomain;
  const char* text = std::getenv("TOWSIM_TEST_DOMAINS");
  if (text == nullptr || *text == '\0') return;
  int a = 0, b = 0;
  char end = 0;
  if (std::sscanf(text, "%d-%d%c", &a, &b, &end) != 2 || a < 0 || b < a || b > kLastAutoDomain) {
    throw std::runtime_error(
        "TOWSIM_TEST_DOMAINS = " + std::string(text) +
        ": must be FIRST-LAST with 0 <= FIRST <= LAST <= " + std::to_string(kLastAutoDomain));
  }
  *first = a;
  *last = b;
}

DomainLease::DomainLease() {
  int first = 0, last = 0;
  AutoDomainRange(&first, &last);
  for (int id = first; id <= last; ++id) {
    if (!TryLock(id)) continue;
    if (PortFree(DiscoveryPort(id))) return;
    close(fd_);  // a participant outside the lock protocol uses it
    fd_ = -1;
    id_ = -1;
  }
  throw std::runtime_error("no free DDS domain id in " + std::to_string(first) + "-" +
                           std::to_string(last) + " (TOWSIM_TEST_DOMAINS; locks in " +
                           std::filesystem::path(LockPath(first)).parent_path().string() + ")");
}

DomainLease::DomainLease(int id) {
  if (!TryLock(id)) {
    throw std::runtime_error("DDS domain " + std::to_string(id) + " is taken by another test (" +
                             LockPath(id) + ")");
  }
}

DomainLease::~DomainLease() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

bool DomainLease::TryLock(int id) {
  const std::string path = LockPath(id);
  const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) return false;
  if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
    close(fd);
    return false;
  }
  fd_ = fd;
  id_ = id;
  return true;
}

}  // namespace towsim::testing
