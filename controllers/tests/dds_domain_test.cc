// testing/dds_domain.h: leases taken at once get different ids; an id whose discovery port is
// bound (a participant outside the lock protocol) is skipped; a held fixed id is refused; the
// range variable is checked. Locks go to a directory of this test's own
// (TOWSIM_DOMAIN_LOCK_DIR) and the range is one nobody else uses in this process.

#include "testing/dds_domain.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>

#include <gtest/gtest.h>

#include "temp_dir.h"

namespace towsim::testing {
namespace {

class DomainLeaseTest : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("TOWSIM_DOMAIN_LOCK_DIR", tmp_.path().c_str(), 1);
    setenv("TOWSIM_TEST_DOMAINS", "220-222", 1);
  }
  void TearDown() override {
    unsetenv("TOWSIM_DOMAIN_LOCK_DIR");
    unsetenv("TOWSIM_TEST_DOMAINS");
  }
  test::TempDir tmp_;
};

TEST_F(DomainLeaseTest, DistinctIdsUntilTheRangeIsUsedUp) {
  const DomainLease a, b, c;
  EXPECT_EQ(a.id(), 220);
  EXPECT_EQ(b.id(), 221);
  EXPECT_EQ(c.id(), 222);
  try {
    const DomainLease d;
    FAIL() << "a fourth lease of three ids: " << d.id();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no free DDS domain id in 220-222"), std::string::npos)
        << e.what();
  }
}

TEST_F(DomainLeaseTest, AReleasedIdIsTakenAgain) {
  {
    const DomainLease a;
    EXPECT_EQ(a.id(), 220);
  }
  const DomainLease b;
  EXPECT_EQ(b.id(), 220);
}

TEST_F(DomainLeaseTest, ABoundDiscoveryPortIsSkipped) {
  // the port of participant index 0 on domain 220 (Cyclone: 7400 + 250 * 220 + 10 = 62410)
  ASSERT_EQ(DiscoveryPort(220), 62410);
  const int s = socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(DiscoveryPort(220)));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(bind(s, reinterpret_cast<const sockaddr*>(&addr), sizeof addr), 0);
  const DomainLease a;
  EXPECT_EQ(a.id(), 221);
  close(s);
}

TEST_F(DomainLeaseTest, AFixedIdHeldElsewhereIsRefused) {
  const DomainLease a(221);
  EXPECT_THROW(DomainLease(221), std::runtime_error);
  const DomainLease b;
  EXPECT_EQ(b.id(), 220);
}

TEST_F(DomainLeaseTest, TheRangeIsChecked) {
  setenv("TOWSIM_TEST_DOMAINS", "200-250", 1);
  try {
    const DomainLease a;
    FAIL() << "took " << a.id();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("TOWSIM_TEST_DOMAINS = 200-250: must be FIRST-LAST with "
                                         "0 <= FIRST <= LAST <= 231"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace towsim::testing
