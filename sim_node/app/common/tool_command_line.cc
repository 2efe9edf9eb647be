#include "app/common/tool_command_line.h"

#include <cstdio>
#include <utility>

#include "app/common/exit_codes.h"

namespace towsim::app {

ToolCommandLine& ToolCommandLine::Flag(const std::string& name, bool* on) {
  return Flag(name, [on] { *on = true; });
}

ToolCommandLine& ToolCommandLine::Flag(const std::string& name, std::function<void()> act) {
  options_.push_back({name, true, [act = std::move(act)](ToolFlags&) {
                        act();
                        return std::string();
                      }});
  return *this;
}

ToolCommandLine& ToolCommandLine::Value(const std::string& name, ValueReader read,
                                        std::string missing) {
  if (missing.empty()) missing = name + " needs a value";
  options_.push_back(
      {name, false, [read = std::move(read), missing = std::move(missing)](ToolFlags& flags) {
         std::string v;
         if (!flags.Value(&v)) return missing;
         return read(v);
       }});
  return *this;
}

ToolCommandLine& ToolCommandLine::Value(const std::string& name, std::string* into) {
  return Value(name, [into](const std::string& v) {
    *into = v;
    return std::string();
  });
}

ToolCommandLine& ToolCommandLine::Option(const std::string& name, OptionReader read) {
  options_.push_back({name, false, std::move(read)});
  return *this;
}

ToolCommandLine& ToolCommandLine::Shared(SharedReader read) {
  shared_.push_back(std::move(read));
  return *this;
}

ToolCommandLine& ToolCommandLine::Others(OtherReader read) {
  others_ = std::move(read);
  return *this;
}

ToolCommandLine& ToolCommandLine::Require(Check check) {
  checks_.push_back(std::move(check));
  return *this;
}

ToolCommandLine& ToolCommandLine::FlagsTakeNoValue() {
  flags_take_no_value_ = true;
  return *this;
}

ToolCommandLine& ToolCommandLine::HelpAtOnce() {
  help_at_once_ = true;
  return *this;
}

std::string ToolCommandLine::Parse(int argc, char** argv, bool* help) const {
  *help = false;
  ToolFlags flags(argc, argv);
  while (flags.Next()) {
    const std::string& arg = flags.arg();
    const bool flag_with_value = flags_take_no_value_ && flags.has_inline_value();
    // towsim_export took "--help=x" for --help, towsim_sweep did not
    if ((arg == "--help" || arg == "-h") && (help_at_once_ || !flag_with_value)) {
      *help = true;
      if (help_at_once_) return "";
      continue;
    }
    bool taken = false;
    for (const SharedReader& read : shared_) {
      if (std::string e; read(flags, &e)) {
        if (!e.empty()) return e;
        taken = true;
        break;
      }
    }
    if (taken) continue;
    const Declared* option = nullptr;
    for (const Declared& d : options_) {
      if (d.name == arg && !(d.is_flag && flag_with_value)) option = &d;
    }
    const std::string e = option != nullptr ? option->read(flags)
                          : others_         ? others_(flags)
                                            : UnknownOption(flags);
    if (!e.empty()) return e;
  }
  if (*help) return "";
  for (const Check& check : checks_) {
    if (const std::string e = check(); !e.empty()) return e;
  }
  return "";
}

std::optional<int> ToolCommandLine::Read(int argc, char** argv) const {
  bool help = false;
  if (const std::string e = Parse(argc, argv, &help); !e.empty()) {
    std::fprintf(stderr, "%s: error: %s\n%s%s", program_.c_str(), e.c_str(),
                 help_at_once_ ? "" : "\n", usage_.c_str());
    return kExitBadInput;
  }
  if (help) {
    std::fputs(usage_.c_str(), stdout);
    return kExitOk;
  }
  return std::nullopt;
}

int ToolCommandLine::Fail(const std::string& message) const {
  std::fprintf(stderr, "%s: error: %s\n", program_.c_str(), message.c_str());
  return kExitBadInput;
}

std::string UnknownOption(const ToolFlags& flags) { return "unknown option '" + flags.arg() + "'"; }

}  // namespace towsim::app
