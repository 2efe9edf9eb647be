#pragma once
// The arguments of a tool's command line (app/common/tool_command_line.h reads them for every
// tool): options as "--name value" or "--name=value", positional arguments as they are.
//
//   ToolFlags flags(argc, argv);
//   while (flags.Next()) {
//     if (flags.arg() == "--output") {
//       if (!flags.Value(&o->output)) return "--output needs a value";
//     } ...
//   }

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
  // the argument as given ("--name=value")
  const std::string& raw() const { return raw_; }
  // true if the argument carries its value after '='
  bool has_inline_value() const { return has_inline_; }
  // the option's value: after '=', else the next argument (consumed); false if there is none
  bool Value(std::string* value);
  // the values up to the next "--" option (or the one after '='), each split at commas, empty
  // pieces dropped
  std::vector<std::string> List();

 private:
  int argc_;
  char** argv_;
  int i_ = 0;
  std::string arg_, raw_, inline_value_;
  bool has_inline_ = false;
};

// "--topics T ...": ROS topic names, "/" prepended where missing
std::vector<std::string> TopicList(const std::vector<std::string>& values);
// "--topics T ..." read from `flags` (List) and appended to *topics: "" or, when there are
// none, "--topics needs at least one topic"
std::string ReadTopics(ToolFlags& flags, std::vector<std::string>* topics);

}  // namespace towsim::app
