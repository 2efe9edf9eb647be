#include "dds/topic_names.h"

#include <cctype>
#include <utility>

namespace towsim::dds {
namespace {

bool IsNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool IsNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// [A-Za-z_][A-Za-z0-9_]*
bool IsName(const std::string& s, size_t begin, size_t end) {
  if (begin >= end || !IsNameStart(s[begin])) return false;
  for (size_t i = begin + 1; i < end; ++i) {
    if (!IsNameChar(s[i])) return false;
  }
  return true;
}

}  // namespace

std::string CheckNamespace(const std::string& ns) {
  if (ns.empty() || ns[0] != '/') return "must start with '/' (e.g. /towsim)";
  if (ns == "/") return "";
  if (ns.back() == '/') return "must not end with '/'";
  size_t begin = 1;
  while (begin <= ns.size()) {
    size_t end = ns.find('/', begin);
    if (end == std::string::npos) end = ns.size();
    if (!IsName(ns, begin, end)) {
      return "segment '" + ns.substr(begin, end - begin) + "' must match [A-Za-z_][A-Za-z0-9_]*";
    }
    begin = end + 1;
  }
  return "";
}

std::string CheckBodyName(const std::string& name) {
  if (!IsName(name, 0, name.size())) return "must match [A-Za-z_][A-Za-z0-9_]*";
  return "";
}

TopicNames::TopicNames(std::string ns) : ns_(std::move(ns)) {
  prefix_ = ns_ == "/" ? std::string("rt/") : "rt" + ns_ + "/";
}

}  // namespace towsim::dds
