#pragma once
// The options every DDS tool (towsim_record, towsim_replay, towsim_foxglove) shares: the
// domain, the namespace, DDS Security and --quiet, read from a tool's command line
// (app/common/tool_flags.h).

#include <cstdint>
#include <string>

#include "app/common/tool_command_line.h"
#include "app/common/tool_flags.h"

namespace towsim::app {

// "--domain N": N an integer from 0 to 232 (Cyclone's range). Returns "" or the error text.
std::string ParseDomain(const std::string& text, uint32_t* domain);

// The options every DDS tool shares, read into the tool's own fields: --domain N (sets
// *has_domain when given), --namespace NS (checked with wire::CheckNamespace), --security
// DIR/NAME (not empty), --quiet.
struct DdsToolFields {
  uint32_t* domain;
  std::string* ns;
  std::string* security;
  bool* quiet;
  bool* has_domain = nullptr;
};
// true when flags.arg() is one of them: its value is read into `f`, or *error is set when the
// value is missing or bad; false (nothing read) for any other argument
bool ReadDdsToolOption(ToolFlags& flags, const DdsToolFields& f, std::string* error);
// the same, for a tool's command line: line.Shared(DdsToolOptions({&o.domain, ...}))
ToolCommandLine::SharedReader DdsToolOptions(const DdsToolFields& f);

}  // namespace towsim::app
