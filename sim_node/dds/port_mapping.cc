#include "dds/port_mapping.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

namespace towsim::dds {
namespace {

constexpr long kMaxPort = 65535;

// the text of the last <name>text</name> in `xml`, if any
bool LastElement(const std::string& xml, const std::string& name, std::string* text) {
  const std::string open = "<" + name + ">", close = "</" + name + ">";
  const size_t at = xml.rfind(open);
  if (at == std::string::npos) return false;
  const size_t begin = at + open.size();
  const size_t end = xml.find(close, begin);
  if (end == std::string::npos) return false;
  *text = xml.substr(begin, end - begin);
  const size_t first = text->find_first_not_of(" \t\r\n");
  const size_t last = text->find_last_not_of(" \t\r\n");
  *text = first == std::string::npos ? "" : text->substr(first, last - first + 1);
  return true;
}

void ReadLong(const std::string& xml, const std::string& name, long* value) {
  std::string text;
  if (!LastElement(xml, name, &text)) return;
  char* end = nullptr;
  const long x = std::strtol(text.c_str(), &end, 10);
  if (end != text.c_str() && *end == '\0' && x >= 0) *value = x;
}

std::vector<std::string> SplitUri(const std::string& config) {
  // commas separate the entries; XML fragments hold no commas in the elements read here
  std::vector<std::string> parts;
  std::string part;
  std::stringstream in(config);
  while (std::getline(in, part, ',')) parts.push_back(part);
  return parts;
}

}  // namespace

long PortMapping::HighestPort(uint32_t domain) const {
  const long unicast =
      std::max(unicast_meta_offset, unicast_data_offset) + participant_gain * max_participant_index;
  const long multicast = std::max(multicast_meta_offset, multicast_data_offset);
  return base_port + domain_gain * static_cast<long>(domain) + std::max(unicast, multicast);
}

long PortMapping::MaxDomain() const {
  const long at_zero = HighestPort(0);
  if (at_zero > kMaxPort) return -1;
  if (domain_gain <= 0) return 230;  // every domain on the same ports; Cyclone's own limit
  return (kMaxPort - at_zero) / domain_gain;
}

PortMapping PortMappingOf(const std::string& config) {
  PortMapping m;
  for (const std::string& part : SplitUri(config)) {
    std::string xml = part;
    if (part.rfind("file://", 0) == 0) {
      std::ifstream in(part.substr(7));
      if (!in) continue;
      std::stringstream text;
      text << in.rdbuf();
      xml = text.str();
    }
    ReadLong(xml, "BasePort", &m.base_port);
    ReadLong(xml, "DomainGain", &m.domain_gain);
    ReadLong(xml, "ParticipantGain", &m.participant_gain);
    ReadLong(xml, "MulticastMetaOffset", &m.multicast_meta_offset);
    ReadLong(xml, "UnicastMetaOffset", &m.unicast_meta_offset);
    ReadLong(xml, "MulticastDataOffset", &m.multicast_data_offset);
    ReadLong(xml, "UnicastDataOffset", &m.unicast_data_offset);
    ReadLong(xml, "MaxAutoParticipantIndex", &m.max_participant_index);
    // a fixed index takes the ports of that index only
    long fixed = -1;
    ReadLong(xml, "ParticipantIndex", &fixed);
    if (fixed >= 0) m.max_participant_index = fixed;
  }
  return m;
}

std::string CheckDomainPorts(uint32_t domain, const std::string& config) {
  const PortMapping m = PortMappingOf(config);
  const long highest = m.HighestPort(domain);
  if (highest <= kMaxPort) return {};
  return "--domain " + std::to_string(domain) + ": its ports go up to " + std::to_string(highest) +
         " > 65535 with this DDS configuration (BasePort " + std::to_string(m.base_port) +
         ", DomainGain " + std::to_string(m.domain_gain) + ", MaxAutoParticipantIndex " +
         std::to_string(m.max_participant_index) +
         "): the domain id must be <= " + std::to_string(m.MaxDomain());
}

}  // namespace towsim::dds
