// app/common/tool_command_line: a tool's options declared once; --help, unknown options,
// missing values and failed checks answered with the texts and exit codes the tools gave
// before they shared it (docs/command_line.md "Exit codes").

#include "app/common/tool_command_line.h"

#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/common/exit_codes.h"
#include "tool_argv.h"

namespace towsim::app {
namespace {

constexpr char kUsage[] = "usage: tool --output FILE [--overwrite] [--count N] [FILE]\n";

// a tool like towsim_record: a required --output, a flag, a checked number, a shared option
struct Options {
  std::string output, input;
  bool overwrite = false, shared = false;
  int count = 0;
};

ToolCommandLine Line(Options* o) {
  ToolCommandLine line("tool", kUsage);
  line.Shared([o](ToolFlags& flags, std::string* error) {
        if (flags.arg() != "--shared") return false;
        std::string v;
        if (!flags.Value(&v) || v != "yes") *error = "--shared: must be yes";
        o->shared = error->empty();
        return true;
      })
      .Flag("--overwrite", &o->overwrite)
      .Value("--output", &o->output)
      .Value("--count",
             [o](const std::string& v) -> std::string {
               if (v != "1" && v != "2") return "--count " + v + ": must be 1 or 2";
               o->count = v[0] - '0';
               return "";
             })
      .Require([o]() -> std::string { return o->output.empty() ? "missing --output FILE" : ""; })
      .Require([o]() -> std::string {
        return o->count == 2 && !o->overwrite ? "--count 2 needs --overwrite" : "";
      });
  return line;
}

// the line's answer: the exit code (nullopt: run) and what it printed
struct Answer {
  std::optional<int> exit;
  std::string out, err;
};

Answer Answered(const ToolCommandLine& line, std::vector<std::string> args) {
  args.insert(args.begin(), "tool");
  std::vector<char*> argv = test::Argv(args);
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  Answer a;
  a.exit = line.Read(static_cast<int>(argv.size()), argv.data());
  a.out = testing::internal::GetCapturedStdout();
  a.err = testing::internal::GetCapturedStderr();
  return a;
}

TEST(ToolCommandLineTest, ExitCodesAreTheDocumentedOnes) {
  EXPECT_EQ(kExitOk, 0);
  EXPECT_EQ(kExitError, 1);
  EXPECT_EQ(kExitBadInput, 2);
  EXPECT_EQ(kExitSolver, 3);
  EXPECT_EQ(kExitIncomplete, 4);
}

TEST(ToolCommandLineTest, ReadsEveryKindOfOption) {
  Options o;
  const Answer a =
      Answered(Line(&o), {"--output=run.mcap", "--overwrite", "--count", "2", "--shared", "yes"});
  EXPECT_EQ(a.exit, std::nullopt);  // the tool runs
  EXPECT_EQ(a.out, "");
  EXPECT_EQ(a.err, "");
  EXPECT_EQ(o.output, "run.mcap");
  EXPECT_TRUE(o.overwrite);
  EXPECT_EQ(o.count, 2);
  EXPECT_TRUE(o.shared);
}

TEST(ToolCommandLineTest, HelpPrintsTheUsageAndExitsZeroWithoutTheChecks) {
  for (const char* help : {"--help", "-h"}) {
    Options o;
    const Answer a = Answered(Line(&o), {help});  // --output missing: not checked
    EXPECT_EQ(a.exit, kExitOk) << help;
    EXPECT_EQ(a.out, kUsage) << help;
    EXPECT_EQ(a.err, "") << help;
  }
}

TEST(ToolCommandLineTest, ErrorsPrintTheProgramTheErrorABlankLineAndTheUsage) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--output", "f", "--bogus"}, "unknown option '--bogus'"},
      {{"--output", "f", "--bogus=3"}, "unknown option '--bogus'"},
      {{"--output", "f", "extra.mcap"}, "unknown option 'extra.mcap'"},
      {{"--output"}, "--output needs a value"},
      {{"--output", "f", "--count", "7"}, "--count 7: must be 1 or 2"},
      {{"--shared", "no"}, "--shared: must be yes"},
      {{"--overwrite"}, "missing --output FILE"},
      {{"--count", "2"}, "missing --output FILE"},  // the checks in their order
      {{"--output", "f", "--count", "2"}, "--count 2 needs --overwrite"},
      {{"--help", "--bogus"}, "unknown option '--bogus'"},  // an error wins over --help
  };
  for (const auto& [args, error] : cases) {
    Options o;
    const Answer a = Answered(Line(&o), args);
    EXPECT_EQ(a.exit, kExitBadInput) << error;
    EXPECT_EQ(a.out, "") << error;
    EXPECT_EQ(a.err, "tool: error: " + error + "\n\n" + kUsage);
  }
}

TEST(ToolCommandLineTest, FlagsKeepAValueGivenAfterTheEqualsSignByDefault) {
  Options o;
  const Answer a = Answered(Line(&o), {"--overwrite=no", "--output", "f"});
  EXPECT_EQ(a.exit, std::nullopt);
  EXPECT_TRUE(o.overwrite);  // as towsim_record read "--overwrite=..." before
}

// towsim_sweep's reading: other arguments are its file (raw text in the errors), a flag with
// a value is another argument
TEST(ToolCommandLineTest, OthersTakePositionalsAndFlagsTakeNoValueWhenAsked) {
  std::string file;
  bool slurm = false;
  ToolCommandLine line("towsim_sweep", "usage: towsim_sweep FILE\n");
  line.FlagsTakeNoValue()
      .Flag("--slurm", &slurm)
      .Others([&file](const ToolFlags& flags) -> std::string {
        if (flags.raw().rfind("-", 0) == 0) return "unknown option " + flags.raw();
        if (!file.empty()) return "one sweep file only (" + file + ", then " + flags.raw() + ")";
        file = flags.raw();
        return "";
      });
  Answer a = Answered(line, {"sweep.yaml", "--slurm"});
  EXPECT_EQ(a.exit, std::nullopt);
  EXPECT_EQ(file, "sweep.yaml");
  EXPECT_TRUE(slurm);
  file.clear();
  a = Answered(line, {"sweep.yaml", "--slurm=1"});
  EXPECT_EQ(a.exit, kExitBadInput);
  EXPECT_EQ(a.err, "towsim_sweep: error: unknown option --slurm=1\n\nusage: towsim_sweep FILE\n");
  file.clear();
  a = Answered(line, {"a.yaml", "b.yaml"});
  EXPECT_EQ(a.err,
            "towsim_sweep: error: one sweep file only (a.yaml, then b.yaml)\n\n"
            "usage: towsim_sweep FILE\n");
}

// towsim_export's reading: --help answers at once; the usage follows an error without a
// blank line
TEST(ToolCommandLineTest, HelpAtOnceAnswersBeforeTheRestOfTheLine) {
  bool info = false;
  ToolCommandLine line("towsim_export", "usage: towsim_export FILE.mcap\n");
  line.HelpAtOnce().Flag("--info", &info).Require([] { return std::string("no recording given"); });
  Answer a = Answered(line, {"--help", "--bogus"});
  EXPECT_EQ(a.exit, kExitOk);
  EXPECT_EQ(a.out, "usage: towsim_export FILE.mcap\n");
  a = Answered(line, {"--info"});
  EXPECT_EQ(a.exit, kExitBadInput);
  EXPECT_EQ(a.err, "towsim_export: error: no recording given\nusage: towsim_export FILE.mcap\n");
}

TEST(ToolCommandLineTest, FailPrintsTheErrorWithoutTheUsage) {
  const ToolCommandLine line("tool", kUsage);
  testing::internal::CaptureStderr();
  EXPECT_EQ(line.Fail("DDS setup failed: no ports"), kExitBadInput);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "tool: error: DDS setup failed: no ports\n");
}

}  // namespace
}  // namespace towsim::app
