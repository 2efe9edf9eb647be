// app/common/dds_tool_options: the options towsim_record, towsim_replay and towsim_foxglove
// share: the domain range, the namespace rule, --security and --quiet.

#include "app/common/dds_tool_options.h"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/common/tool_command_line.h"
#include "app/common/tool_flags.h"
#include "tool_argv.h"

namespace towsim::app {
namespace {

using test::Argv;

TEST(DdsToolOptionsTest, DomainIsAnIntegerFrom0To232) {
  uint32_t d = 99;
  EXPECT_EQ(ParseDomain("0", &d), "");
  EXPECT_EQ(d, 0u);
  EXPECT_EQ(ParseDomain("232", &d), "");
  EXPECT_EQ(d, 232u);
  for (const char* bad : {"233", "-1", "", "5x", "1.5"}) {
    EXPECT_EQ(ParseDomain(bad, &d),
              std::string("--domain ") + bad + ": must be an integer from 0 to 232");
  }
  EXPECT_EQ(d, 232u);  // unchanged by a bad value
}

// the options every DDS tool shares: read into the tool's fields; other arguments left alone
TEST(DdsToolOptionsTest, SharedDdsOptionsAreReadIntoTheToolsFields) {
  std::vector<std::string> args = {
      "tool",        "--domain=9", "--namespace", "/sys_a",   "--security",
      "keys/ctl",    "--quiet",    "file.mcap",   "--domain", "300",
      "--namespace", "no slash",   "--security",  ""};
  std::vector<char*> argv = Argv(args);
  ToolFlags f(static_cast<int>(argv.size()), argv.data());
  uint32_t domain = 0;
  std::string ns, security;
  bool quiet = false, has_domain = false;
  const DdsToolFields fields{&domain, &ns, &security, &quiet, &has_domain};
  std::string error;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(f.Next());
    EXPECT_TRUE(ReadDdsToolOption(f, fields, &error)) << f.arg();
    EXPECT_EQ(error, "") << f.arg();
  }
  EXPECT_EQ(domain, 9u);
  EXPECT_TRUE(has_domain);
  EXPECT_EQ(ns, "/sys_a");
  EXPECT_EQ(security, "keys/ctl");
  EXPECT_TRUE(quiet);
  ASSERT_TRUE(f.Next());
  EXPECT_FALSE(ReadDdsToolOption(f, fields, &error));  // a positional argument
  EXPECT_EQ(error, "");
  ASSERT_TRUE(f.Next());
  EXPECT_TRUE(ReadDdsToolOption(f, fields, &error));
  EXPECT_EQ(error, ParseDomain("300", &domain));  // the domain's own rule
  EXPECT_NE(error, "");
  error.clear();
  ASSERT_TRUE(f.Next());
  EXPECT_TRUE(ReadDdsToolOption(f, fields, &error));
  EXPECT_EQ(error.rfind("--namespace no slash: ", 0), 0u) << error;
  error.clear();
  ASSERT_TRUE(f.Next());
  EXPECT_TRUE(ReadDdsToolOption(f, fields, &error));
  EXPECT_EQ(error, "--security needs DIR/NAME");
  EXPECT_FALSE(f.Next());
}

// the same options on a tool's command line, read before the tool's own
TEST(DdsToolOptionsTest, ToolCommandLineReadsThem) {
  std::vector<std::string> args = {"tool", "--domain", "5", "--namespace=/n", "--quiet"};
  std::vector<char*> argv = Argv(args);
  uint32_t domain = 0;
  std::string ns, security;
  bool quiet = false, has_domain = false, help = true;
  ToolCommandLine line("tool", "usage: tool\n");
  line.Shared(DdsToolOptions({&domain, &ns, &security, &quiet, &has_domain}));
  EXPECT_EQ(line.Parse(static_cast<int>(argv.size()), argv.data(), &help), "");
  EXPECT_FALSE(help);
  EXPECT_EQ(domain, 5u);
  EXPECT_TRUE(has_domain);
  EXPECT_EQ(ns, "/n");
  EXPECT_TRUE(quiet);
  EXPECT_EQ(security, "");
  std::vector<std::string> bad = {"tool", "--domain=233"};
  argv = Argv(bad);
  EXPECT_EQ(line.Parse(static_cast<int>(argv.size()), argv.data(), &help),
            "--domain 233: must be an integer from 0 to 232");
}

}  // namespace
}  // namespace towsim::app
