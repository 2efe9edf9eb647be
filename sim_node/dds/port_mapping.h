#pragma once
// Which DDS domain ids have ports with a Cyclone DDS configuration (docs/command_line.md).
//
// Cyclone maps a domain d and a participant index i to UDP ports as the RTPS specification
// (DDSI-RTPS 2.x, section 9.6.1.1) does: PB + DG d + offset, and + PG i for the unicast ports,
// with PB = BasePort (7400), DG = DomainGain (250), PG = ParticipantGain (2) and the offsets
// d0..d3 = 0, 10, 1, 11 (Discovery/Ports). Without multicast every participant takes an
// index up to MaxAutoParticipantIndex (9 by default; config/cyclonedds.xml raises it to
// 120), and unicast discovery probes every index of the peers, so the highest port of a
// domain is PB + DG d + max(d1, d3) + PG MaxAutoParticipantIndex; it must be <= 65535. With
// config/cyclonedds.xml that allows domains 0 to 231 (232 would need port 65651).

#include <cstdint>
#include <string>

namespace towsim::dds {

struct PortMapping {
  long base_port = 7400;
  long domain_gain = 250;
  long participant_gain = 2;
  long multicast_meta_offset = 0;
  long unicast_meta_offset = 10;
  long multicast_data_offset = 1;
  long unicast_data_offset = 11;
  long max_participant_index = 9;  // MaxAutoParticipantIndex, or a fixed ParticipantIndex

  // the highest UDP port domain `domain` uses
  long HighestPort(uint32_t domain) const;
  // the largest domain id whose ports all exist (<= 65535); -1 if none
  long MaxDomain() const;
};

// The mapping of a configuration as CYCLONEDDS_URI gives it: a comma-separated list of
// file:// URIs and XML fragments, later ones overriding earlier ones (only the elements
// above are read; a file that cannot be read is skipped: Cyclone reports it).
PortMapping PortMappingOf(const std::string& config);

// empty if `domain` has all its ports with `config`, else the rule broken, e.g.
// "--domain 232: its ports go up to 65651 > 65535 with this configuration (BasePort 7400,
// DomainGain 250, MaxAutoParticipantIndex 120): the domain id must be <= 231"
std::string CheckDomainPorts(uint32_t domain, const std::string& config);

}  // namespace towsim::dds
