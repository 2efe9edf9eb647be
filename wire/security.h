#pragma once
// DDS Security (OMG DDS Security 1.1, docs/security.md) for every towsim DDS program: the one
// place that turns `--security DIR/NAME` into a participant with that identity. sim_node,
// towsim_record, towsim_replay and the controllers' client library call it; a new tool gets
// security with one call:
//
//   const dds_entity_t p = CreateSecureParticipant(domain, "/keys/towfish_depth", "tool");
//
// DIR/NAME is an identity made by scripts/security.sh:
//   DIR/identity_ca.pem, DIR/permissions_ca.pem, DIR/governance.p7s,
//   DIR/NAME/cert.pem, DIR/NAME/key.pem, DIR/NAME/permissions.p7s
// and the participant runs Cyclone's three builtin plugins (authentication, access control,
// cryptography; libddsc0debian) configured through its QoS properties (dds.sec.*), so that one
// process may hold several identities. The domain configuration stays $CYCLONEDDS_URI
// (config/cyclonedds.xml) or what the caller gives.
//
// Failures never fall back to a participant without security: a missing file throws
// SecurityError naming the file; a participant the plugins refuse (bad or expired
// certificate, a document that does not verify against its CA or does not parse) throws
// SecurityError with Cyclone's reason, captured from its log while the participant is made.

#include <cstdint>
#include <stdexcept>
#include <string>

#include "dds/dds.h"

namespace towsim::wire {

// bad --security input; the programs exit 2 with what() on stderr
class SecurityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// the files of one identity (absolute paths)
struct SecurityFiles {
  std::string identity_ca;     // DIR/identity_ca.pem
  std::string permissions_ca;  // DIR/permissions_ca.pem
  std::string governance;      // DIR/governance.p7s
  std::string certificate;     // DIR/NAME/cert.pem
  std::string private_key;     // DIR/NAME/key.pem
  std::string permissions;     // DIR/NAME/permissions.p7s
};

// What a participant admits besides authenticated ones.
enum class Admit {
  kAuthenticated,  // DIR/governance.p7s: only participants with a valid identity
  kOpenOutputs,    // DIR/governance_open.p7s (scripts/security.sh --open-outputs): also
                   // participants without a certificate, on the unprotected outputs only
};

// The files of `identity` (DIR/NAME). Throws SecurityError if DIR/NAME is not a directory or a
// file is missing or unreadable: "--security /k/ctl: /k/ctl/cert.pem: no such file".
SecurityFiles FindSecurityFiles(const std::string& identity, Admit admit = Admit::kAuthenticated);

// Adds the dds.sec.* properties of `files` and of the builtin plugins to `qos`.
void AddSecurityProperties(const SecurityFiles& files, dds_qos_t* qos);

// A participant on `domain`; with security as `identity` (DIR/NAME) unless it is empty.
// `qos` (may be null) is copied and extended. The domain must already exist or is made from
// $CYCLONEDDS_URI. Throws SecurityError (refused by the plugins: Cyclone's reason) or
// std::runtime_error (other DDS failures, with Cyclone's return-code text).
dds_entity_t CreateSecureParticipant(uint32_t domain, const std::string& identity,
                                     const dds_qos_t* qos = nullptr,
                                     Admit admit = Admit::kAuthenticated);

// the directory of Cyclone's security plugins found at build time ("" if none)
const char* SecurityPluginDirectory();

}  // namespace towsim::wire
