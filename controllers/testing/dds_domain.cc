#include "testing/dds_domain.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace towsim::testing {

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
  lock_ = wire::DomainLock::Take(first, last);
  if (!lock_) {
    throw std::runtime_error(
        "no free DDS domain id in " + std::to_string(first) + "-" + std::to_string(last) +
        " (TOWSIM_TEST_DOMAINS; locks in " +
        std::filesystem::path(wire::DomainLock::LockPath(first)).parent_path().string() + ")");
  }
}

DomainLease::DomainLease(int id) : lock_(wire::DomainLock::TakeExactly(id)) {
  if (!lock_) {
    throw std::runtime_error("DDS domain " + std::to_string(id) + " is taken by another test (" +
                             wire::DomainLock::LockPath(id) + ")");
  }
}

DomainLease::~DomainLease() = default;  // the lock's destructor releases it

}  // namespace towsim::testing
