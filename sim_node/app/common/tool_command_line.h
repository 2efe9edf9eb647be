#pragma once
// The command line of a tool (towsim_record, towsim_replay, towsim_export, towsim_foxglove,
// towsim_sweep): its options declared once, read the same way by every tool.
//
//   ToolCommandLine line("towsim_record", kUsage);
//   line.Flag("--overwrite", &o.overwrite)
//       .Value("--output", [&](const std::string& v) { o.output = v; return ""; })
//       .Check([&] { return o.output.empty() ? "missing --output FILE.mcap" : ""; });
//   if (const std::optional<int> exit = line.Read(argc, argv)) return *exit;
//   ... the tool's job
//
// Options are "--name value" or "--name=value" (app/common/tool_flags.h). --help or -h prints
// the usage on stdout and exits kExitOk; an unknown option, a missing or bad value, or a
// failed check prints "<program>: error: <what>", a blank line and the usage on stderr and
// exits kExitBadInput (app/common/exit_codes.h). The first error ends the reading; the checks
// run after the whole line, not with --help.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/common/tool_flags.h"

namespace towsim::app {

class ToolCommandLine {
 public:
  // reads an option's value: "" or the error
  using ValueReader = std::function<std::string(const std::string& value)>;
  // reads what follows an option itself (flags.Value, flags.List): "" or the error
  using OptionReader = std::function<std::string(ToolFlags& flags)>;
  // an argument no option took (flags.arg(), flags.raw()): "" if taken, else the error
  using OtherReader = std::function<std::string(const ToolFlags& flags)>;
  // options read by a shared reader (ReadDdsToolOption): true if it took flags.arg(), the
  // error in *error
  using SharedReader = std::function<bool(ToolFlags& flags, std::string* error)>;
  // after the whole line: "" or the error
  using Check = std::function<std::string()>;

  ToolCommandLine(std::string program, std::string usage)
      : program_(std::move(program)), usage_(std::move(usage)) {}

  // "--name": sets *on
  ToolCommandLine& Flag(const std::string& name, bool* on);
  // "--name": does `act`
  ToolCommandLine& Flag(const std::string& name, std::function<void()> act);
  // "--name V": read(V); without V the error `missing`, by default "<name> needs a value"
  ToolCommandLine& Value(const std::string& name, ValueReader read, std::string missing = "");
  // "--name V": *into = V; without V "<name> needs a value"
  ToolCommandLine& Value(const std::string& name, std::string* into);
  // "--name ...": read(flags) takes what follows
  ToolCommandLine& Option(const std::string& name, OptionReader read);
  // options read elsewhere, asked before the declared ones
  ToolCommandLine& Shared(SharedReader read);
  // every other argument (a file name); without it: "unknown option '<arg>'"
  ToolCommandLine& Others(OtherReader read);
  // a rule on the whole line (a required option), in the order declared
  ToolCommandLine& Require(Check check);

  // towsim_export's and towsim_sweep's reading, kept as they were: a flag given a value
  // ("--info=1") is not that flag but another argument
  ToolCommandLine& FlagsTakeNoValue();
  // towsim_export's, kept as it was: --help (also "--help=x") answers at once, the rest of the
  // line unread, and an error is followed by the usage without a blank line
  ToolCommandLine& HelpAtOnce();

  // reads the line: "" (then *help says whether --help was given) or the first error
  std::string Parse(int argc, char** argv, bool* help) const;
  // Parse, then answers --help (usage on stdout: kExitOk) and errors (on stderr with the
  // usage: kExitBadInput); std::nullopt when the tool is to run
  std::optional<int> Read(int argc, char** argv) const;

  // "<program>: error: <message>" on stderr (no usage: for errors after the line was read)
  int Fail(const std::string& message) const;
  const std::string& usage() const { return usage_; }

 private:
  struct Declared {
    std::string name;
    bool is_flag = false;
    OptionReader read;
  };

  std::string program_, usage_;
  std::vector<Declared> options_;
  std::vector<SharedReader> shared_;
  std::vector<Check> checks_;
  OtherReader others_;
  bool flags_take_no_value_ = false;
  bool help_at_once_ = false;
};

// "unknown option '<arg>'": the error of an argument no option takes
std::string UnknownOption(const ToolFlags& flags);

}  // namespace towsim::app
