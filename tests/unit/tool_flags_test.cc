// app/common/tool_flags: the arguments of a tool's command line: "--name value",
// "--name=value", the argument as given, and lists.

#include "app/common/tool_flags.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tool_argv.h"

namespace towsim::app {
namespace {

using test::Argv;

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

// the argument as given, and whether its value came after '='
TEST(ToolFlagsTest, RawArgumentAndInlineValue) {
  std::vector<std::string> args = {"tool", "--slurm=1", "--out", "d", "file.yaml"};
  std::vector<char*> argv = Argv(args);
  ToolFlags f(static_cast<int>(argv.size()), argv.data());
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.arg(), "--slurm");
  EXPECT_EQ(f.raw(), "--slurm=1");
  EXPECT_TRUE(f.has_inline_value());
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.raw(), "--out");
  EXPECT_FALSE(f.has_inline_value());
  std::string v;
  ASSERT_TRUE(f.Value(&v));
  EXPECT_EQ(v, "d");
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.arg(), "file.yaml");
  EXPECT_EQ(f.raw(), "file.yaml");
  EXPECT_FALSE(f.has_inline_value());
  EXPECT_FALSE(f.Next());
}

// "--topics T ...": appended as ROS names; none is an error
TEST(ToolFlagsTest, ReadTopicsAppendsAndRefusesAnEmptyList) {
  std::vector<std::string> args = {"tool", "--topics", "a,/b", "--topics", "--quiet"};
  std::vector<char*> argv = Argv(args);
  ToolFlags f(static_cast<int>(argv.size()), argv.data());
  std::vector<std::string> topics;
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(ReadTopics(f, &topics), "");
  EXPECT_EQ(topics, (std::vector<std::string>{"/a", "/b"}));
  ASSERT_TRUE(f.Next());
  std::vector<std::string> none;
  EXPECT_EQ(ReadTopics(f, &none), "--topics needs at least one topic");
  EXPECT_TRUE(none.empty());
  ASSERT_TRUE(f.Next());
  EXPECT_EQ(f.arg(), "--quiet");  // the list stopped at the next option
}

}  // namespace
}  // namespace towsim::app
