// dds/port_mapping: the RTPS port mapping (DDSI-RTPS 2.x, 9.6.1.1) against numbers worked out by
// hand: PB + DG d + max(d1, d3) + PG i_max must be <= 65535.

#include <gtest/gtest.h>

#include "dds/port_mapping.h"

namespace towsim::dds {
namespace {

TEST(DdsPortMappingTest, ProjectConfigurationAllowsDomainsUpTo231) {
  const std::string config = std::string("file://") + TOWSIM_SOURCE_DIR + "/config/cyclonedds.xml";
  const PortMapping m = PortMappingOf(config);
  EXPECT_EQ(m.max_participant_index, 120);
  // 7400 + 250 * 231 + 11 + 2 * 120 = 65401; domain 232: 65651 > 65535
  EXPECT_EQ(m.HighestPort(231), 65401);
  EXPECT_EQ(m.HighestPort(232), 65651);
  EXPECT_EQ(m.MaxDomain(), 231);
  EXPECT_TRUE(CheckDomainPorts(231, config).empty());
  EXPECT_NE(CheckDomainPorts(232, config).find("the domain id must be <= 231"), std::string::npos);
}

TEST(DdsPortMappingTest, CycloneDefaultsAndInlineOverrides) {
  // no configuration: Cyclone's defaults, MaxAutoParticipantIndex 9: 7400 + 250 d + 11 + 18
  EXPECT_EQ(PortMappingOf("").MaxDomain(), (65535 - 7429) / 250);  // 232
  // an inline fragment after the file overrides it
  const PortMapping m = PortMappingOf(
      "<Discovery><Ports><BasePort>20000</BasePort></Ports>"
      "<MaxAutoParticipantIndex>30</MaxAutoParticipantIndex></Discovery>");
  EXPECT_EQ(m.base_port, 20000);
  EXPECT_EQ(m.HighestPort(0), 20000 + 11 + 60);
  EXPECT_EQ(m.MaxDomain(), (65535 - 20071) / 250);
  // a fixed participant index takes only its own ports
  EXPECT_EQ(PortMappingOf("<ParticipantIndex>3</ParticipantIndex>").HighestPort(0), 7400 + 11 + 6);
}

}  // namespace
}  // namespace towsim::dds
