#include "app/common/tool_flags.h"

namespace towsim::app {

bool ToolFlags::Next() {
  if (++i_ >= argc_) return false;
  arg_ = argv_[i_];
  raw_ = arg_;
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

std::vector<std::string> TopicList(const std::vector<std::string>& values) {
  std::vector<std::string> out;
  for (const std::string& t : values) out.push_back(t[0] == '/' ? t : "/" + t);
  return out;
}

std::string ReadTopics(ToolFlags& flags, std::vector<std::string>* topics) {
  for (const std::string& t : TopicList(flags.List())) topics->push_back(t);
  return topics->empty() ? "--topics needs at least one topic" : "";
}

}  // namespace towsim::app
