#pragma once
// The command lines of the DDS tools (towsim_record, towsim_replay, towsim_foxglove): options
// as "--name value" or "--name=value", positional arguments as they are.
//
//   ToolFlags flags(argc, argv);
//   while (flags.Next()) {
//     if (flags.arg() == "--domain") {
//       std::string v;
//       if (!flags.Value(&v)) return "--domain needs a value";
//       if (const std::string e = ParseDomain(v, &o->domain); !e.empty()) return e;
//     } ...
//   }

#include <cstdint>
#include <string>
#include <vector>

namespace towsim::app {

class ToolFlags {
 public:
  ToolFlags(int argc, char** argv) : argc_(argc), argv_(argv) {}

  // advances to the next argument; false past the last
  bool Next();
  // the argument: "--name" without its "=value", or a positional argument
  const std::string& arg() const { return arg_; }
  // the option's value: after '=', else the next argument (consumed); false if there is none
  bool Value(std::string* value);
  // the values up to the next "--" option (or the one after '='), each split at commas, empty
  // pieces dropped
  std::vector<std::string> List();

 private:
  int argc_;
  char** argv_;
  int i_ = 0;
  std::string arg_, inline_value_;
  bool has_inline_ = false;
};

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

// "--topics T ...": ROS topic names, "/" prepended where missing
std::vector<std::string> TopicList(const std::vector<std::string>& values);

}  // namespace towsim::app
