#include "app/common/tool_flags.h"

#include <cstdlib>

#include "wire/topic_names.h"

namespace towsim::app {

bool ToolFlags::Next() {
  if (++i_ >= argc_) return false;
  arg_ = argv_[i_];
  has_inline_ = false;
  inline_value_.clear();
  if (const auto eq = arg_.find('='); arg_.rfind("--", 0) == 0 && eq != std::string::npos) {
    inline_value_ = arg_.substr(eq + 1);
    arg_ = arg_.substr(0, eq);
    has_inline_ = true;
  }
  return true;
}

bool ToolFlags::Value(std::string* value) {
  if (has_inline_) {
    *value = inline_value_;
    return true;
  }
  if (i_ + 1 >= argc_) return false;
  *value = argv_[++i_];
  return true;
}

std::vector<std::string> ToolFlags::List() {
  std::vector<std::string> values;
  if (has_inline_) values.push_back(inline_value_);
  while (!has_inline_ && i_ + 1 < argc_ && std::string(argv_[i_ + 1]).rfind("--", 0) != 0) {
    values.push_back(argv_[++i_]);
  }
  std::vector<std::string> out;
  for (const std::string& v : values) {
    size_t start = 0;
    while (start <= v.size()) {
      const size_t comma = v.find(',', start);
      const std::string one = v.substr(start, comma == std::string::npos ? comma : comma - start);
      if (!one.empty()) out.push_back(one);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

std::string ParseDomain(const std::string& text, uint32_t* domain) {
  char* end = nullptr;
  const long d = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || d < 0 || d > 232) {
    return "--domain " + text + ": must be an integer from 0 to 232";
  }
  *domain = static_cast<uint32_t>(d);
  return "";
}

std::vector<std::string> TopicList(const std::vector<std::string>& values) {
  std::vector<std::string> out;
  for (const std::string& t : values) out.push_back(t[0] == '/' ? t : "/" + t);
  return out;
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

}  // namespace towsim::app
