// sim_node/app/tool_flags: the command lines of towsim_record, towsim_replay and
// towsim_foxglove: "--name value", "--name=value", lists and the domain range.

#include "app/common/tool_flags.h"

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace towsim::app {
namespace {

// argv of string literals (ToolFlags does not write to it)
std::vector<char*> Argv(std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  return argv;
}

TEST(ToolFlagsTest, ValuesAfterTheNameOrItsEqualsSign) {
  std::vector<std::string> args = {"tool",           "--domain",  "7",
                                   "--namespace=/a", "file.mcap", "--port"};
  std::vector<char*> argv = Argv(args);
  ToolFlags f(static_cast<int>(argv.size()), argv.data());
  std::string v;
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.arg(), "--domain");
  ASSERT_TRUE(f.Value(&v));
  EXPECT_EQ(v, "7");
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.arg(), "--namespace");
  ASSERT_TRUE(f.Value(&v));
  EXPECT_EQ(v, "/a");
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.arg(), "file.mcap");
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.arg(), "--port");
  EXPECT_FALSE(f.Value(&v));  // nothing follows
  EXPECT_FALSE(f.Next());
}

TEST(ToolFlagsTest, ListsRunToTheNextOptionAndSplitAtCommas) {
  std::vector<std::string> args = {"tool", "--topics", "/clock",
                                   "a,b,", "--quiet",  "--topics=/x,y"};
  std::vector<char*> argv = Argv(args);
  ToolFlags f(static_cast<int>(argv.size()), argv.data());
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(TopicList(f.List()), (std::vector<std::string>{"/clock", "/a", "/b"}));
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.arg(), "--quiet");
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(TopicList(f.List()), (std::vector<std::string>{"/x", "/y"}));
  EXPECT_FALSE(f.Next());
}

TEST(ToolFlagsTest, DomainIsAnIntegerFrom0To232) {
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
TEST(ToolFlagsTest, SharedDdsOptionsAreReadIntoTheToolsFields) {
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

}  // namespace
}  // namespace towsim::app
