// The text file reader of the scene loader (scene/yaml_reader.h, ReadTextFile): the exact bytes
// of the file, the size limit at its edge, and a buffer of the file's size rather than of the
// limit (docs/benchmarks.md, "Start-up": a buffer of the whole 16 MB limit, zeroed for every
// scene and model file, was most of sim_node's start-up).

#include "scene/yaml_reader.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "counting_new.h"
#include "temp_dir.h"

namespace towsim::scene::internal {
namespace {

namespace fs = std::filesystem;

std::string Write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

TEST(ReadTextFile, ReadsTheExactBytes) {
  test::TempDir dir;
  std::string text = "name: a\n";
  for (int i = 0; i < 300; ++i) {
    text += "# line " + std::to_string(i) + std::string("\0\r\n", 3);  // any byte is kept
  }
  const std::string path = Write(dir.path() / "a.yaml", text);
  std::string read, why;
  ASSERT_TRUE(ReadTextFile(path, &read, &why)) << why;
  EXPECT_EQ(read, text);
  const std::string empty = Write(dir.path() / "empty.yaml", "");
  ASSERT_TRUE(ReadTextFile(empty, &read, &why)) << why;
  EXPECT_EQ(read, "");
}

// a 3 kB file asks for buffers of about its own size: the largest request is the file stream's
// own buffer (BUFSIZ, 8 kB in glibc) or the text (3 kB + 1), not the 16 MB + 1 of the limit
TEST(ReadTextFile, BufferOfTheFileSizeNotTheLimit) {
  test::TempDir dir;
  const std::string text(3000, 'x');
  const std::string path = Write(dir.path() / "b.yaml", text);
  std::string read, why;
  g_largest_new = 0;
  g_counting = true;
  const bool ok = ReadTextFile(path, &read, &why);
  g_counting = false;
  ASSERT_TRUE(ok) << why;
  EXPECT_EQ(read.size(), text.size());
  constexpr std::size_t kMaxRequest = 64 * 1024;  // 8x the stream buffer, 1/256 of the limit
  EXPECT_LE(g_largest_new.load(), kMaxRequest);
}

// exactly the limit is read; one byte more is refused with the rule (sparse files: no disk)
TEST(ReadTextFile, LimitIsInclusive) {
  test::TempDir dir;
  const std::string at = Write(dir.path() / "at.yaml", "name: at\n");
  fs::resize_file(at, kMaxTextFileBytes);
  std::string read, why;
  ASSERT_TRUE(ReadTextFile(at, &read, &why)) << why;
  EXPECT_EQ(read.size(), kMaxTextFileBytes);
  const std::string over = Write(dir.path() / "over.yaml", "name: over\n");
  fs::resize_file(over, kMaxTextFileBytes + 1);
  EXPECT_FALSE(ReadTextFile(over, &read, &why));
  EXPECT_EQ(why, "16777217 bytes: larger than the limit of 16777216 bytes (16 MB)");
}

}  // namespace
}  // namespace towsim::scene::internal
