#include "app/common/dds_tool_options.h"

#include <cstdlib>

#include "wire/topic_names.h"

namespace towsim::app {

std::string ParseDomain(const std::string& text, uint32_t* domain) {
  char* end = nullptr;
  const long d = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || d < 0 || d > 232) {
    return "--domain " + text + ": must be an integer from 0 to 232";
  }
  *domain = static_cast<uint32_t>(d);
  return "";
}

bool ReadDdsToolOption(ToolFlags& flags, const DdsToolFields& f, std::string* error) {
  const std::string& arg = flags.arg();
  std::string v;
  if (arg == "--quiet") {
    *f.quiet = true;
  } else if (arg == "--security") {
    if (!flags.Value(&v) || v.empty()) {
      *error = "--security needs DIR/NAME";
    } else {
      *f.security = v;
    }
  } else if (arg == "--domain") {
    if (!flags.Value(&v)) {
      *error = "--domain needs a value";
    } else {
      *error = ParseDomain(v, f.domain);
      if (error->empty() && f.has_domain != nullptr) *f.has_domain = true;
    }
  } else if (arg == "--namespace") {
    if (!flags.Value(f.ns)) {
      *error = "--namespace needs a value";
    } else if (const std::string e = wire::CheckNamespace(*f.ns); !e.empty()) {
      *error = "--namespace " + *f.ns + ": " + e;
    }
  } else {
    return false;
  }
  return true;
}

ToolCommandLine::SharedReader DdsToolOptions(const DdsToolFields& f) {
  return [f](ToolFlags& flags, std::string* error) { return ReadDdsToolOption(flags, f, error); };
}

}  // namespace towsim::app
