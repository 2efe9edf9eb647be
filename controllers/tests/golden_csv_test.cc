// testing/golden_csv.h: equal files pass; a value beyond abs + rel |golden| fails naming the
// row, the column and both numbers; header, row count and key columns must match exactly;
// TOWSIM_UPDATE_GOLDEN=1 rewrites the golden file; a missing golden file says how to make it.

#include "testing/golden_csv.h"

#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include "temp_dir.h"
#include "testing/process.h"

namespace towsim::testing {
namespace {

constexpr char kHeader[] = "t,body,x,yaw\n";

std::string Write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p.string();
}

class GoldenCsvTest : public ::testing::Test {
 protected:
  void SetUp() override { unsetenv("TOWSIM_UPDATE_GOLDEN"); }
  void TearDown() override { unsetenv("TOWSIM_UPDATE_GOLDEN"); }
  test::TempDir tmp_;
};

TEST_F(GoldenCsvTest, WithinToleranceOrNot) {
  const std::string golden =
      Write(tmp_.path() / "golden.csv", std::string(kHeader) + "0,a,100,0.5\n0.1,a,200,0.25\n");
  const std::string same =
      Write(tmp_.path() / "same.csv", std::string(kHeader) + "0,a,100,0.5\n0.1,a,200,0.25\n");
  EXPECT_TRUE(MatchesGoldenCsv(same, golden, {0.0, 0.0}));
  // 200 -> 200.0015: |error| 1.5e-3 within 1e-3 + 1e-5 * 200 = 3e-3, not within 1e-3 + 0
  const std::string near =
      Write(tmp_.path() / "near.csv", std::string(kHeader) + "0,a,100,0.5\n0.1,a,200.0015,0.25\n");
  EXPECT_TRUE(MatchesGoldenCsv(near, golden, {1e-3, 1e-5}));
  const ::testing::AssertionResult r = MatchesGoldenCsv(near, golden, {1e-3, 0.0});
  ASSERT_FALSE(r);
  EXPECT_NE(std::string(r.message()).find("1 values beyond"), std::string::npos) << r.message();
  EXPECT_NE(std::string(r.message()).find("row 2 (0.1,a): x = 200.0015, golden 200"),
            std::string::npos)
      << r.message();
  EXPECT_NE(std::string(r.message()).find("TOWSIM_UPDATE_GOLDEN=1"), std::string::npos);
}

TEST_F(GoldenCsvTest, HeaderRowsAndKeysMustMatch) {
  const std::string golden = Write(tmp_.path() / "golden.csv", std::string(kHeader) + "0,a,1,2\n");
  const std::string header = Write(tmp_.path() / "h.csv", "t,body,x,pitch\n0,a,1,2\n");
  EXPECT_NE(std::string(MatchesGoldenCsv(header, golden, {1, 1}).message()).find("header"),
            std::string::npos);
  const std::string rows =
      Write(tmp_.path() / "r.csv", std::string(kHeader) + "0,a,1,2\n0,b,1,2\n");
  EXPECT_NE(std::string(MatchesGoldenCsv(rows, golden, {1, 1}).message()).find("has 2 rows"),
            std::string::npos);
  const std::string key = Write(tmp_.path() / "k.csv", std::string(kHeader) + "0,b,1,2\n");
  EXPECT_NE(std::string(MatchesGoldenCsv(key, golden, {1, 1}).message()).find("body b vs golden a"),
            std::string::npos);
}

TEST_F(GoldenCsvTest, UpdateRewritesAndMissingSaysHow) {
  const std::string actual = Write(tmp_.path() / "a.csv", std::string(kHeader) + "0,a,1,2\n");
  const std::string golden = (tmp_.path() / "sub" / "golden.csv").string();
  const ::testing::AssertionResult missing = MatchesGoldenCsv(actual, golden, {0, 0});
  ASSERT_FALSE(missing);
  EXPECT_NE(std::string(missing.message())
                .find("does not exist: run the test with "
                      "TOWSIM_UPDATE_GOLDEN=1"),
            std::string::npos)
      << missing.message();
  setenv("TOWSIM_UPDATE_GOLDEN", "1", 1);
  EXPECT_TRUE(MatchesGoldenCsv(actual, golden, {0, 0}));
  EXPECT_EQ(ReadFile(golden), ReadFile(actual));
  unsetenv("TOWSIM_UPDATE_GOLDEN");
  EXPECT_TRUE(MatchesGoldenCsv(actual, golden, {0, 0}));
}

}  // namespace
}  // namespace towsim::testing
