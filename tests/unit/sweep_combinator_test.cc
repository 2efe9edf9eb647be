// app/sweep/sweep_combinator: the cases of a sweep, product (first parameter slowest) or zip.

#include "app/sweep/sweep_combinator.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace towsim::app {
namespace {

TEST(SweepCombinator, ProductIsNestedLoopsInFileOrder) {
  const std::vector<SweepParameter> p = {{"a", {"1", "2"}, ""}, {"b", {"x", "y", "z"}, ""}};
  const std::vector<SweepCase> cases = CombineParameters(p, SweepCombine::kProduct);
  ASSERT_EQ(cases.size(), 6u);
  const std::vector<std::pair<std::string, std::string>> expected[] = {
      {{"a", "1"}, {"b", "x"}}, {{"a", "1"}, {"b", "y"}}, {{"a", "1"}, {"b", "z"}},
      {{"a", "2"}, {"b", "x"}}, {{"a", "2"}, {"b", "y"}}, {{"a", "2"}, {"b", "z"}}};
  for (size_t i = 0; i < cases.size(); ++i) {
    EXPECT_EQ(cases[i].index, static_cast<int>(i));
    EXPECT_EQ(cases[i].values, expected[i]);
  }
  EXPECT_EQ(cases[4].name, "case_0004");
  EXPECT_EQ(cases[4].Overrides(), (std::vector<std::string>{"a=2", "b=y"}));
}

TEST(SweepCombinator, ZipTakesTheIthValuesTogether) {
  const std::vector<SweepParameter> p = {{"a", {"1", "2", "3"}, ""},
                                         {"b", {"[0, 0, 1]", "[0, 0, 2]", "[0, 0, 3]"}, ""}};
  const std::vector<SweepCase> cases = CombineParameters(p, SweepCombine::kZip);
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_EQ(cases[2].Overrides(), (std::vector<std::string>{"a=3", "b=[0, 0, 3]"}));
}

TEST(SweepCombinator, CaseNamesHaveAtLeastFourDigitsAndSortInOrder) {
  EXPECT_EQ(CaseName(7, 8), "case_0007");
  EXPECT_EQ(CaseName(7, 10001), "case_00007");
  EXPECT_EQ(CaseName(10000, 10001), "case_10000");
  // a product too large to run is refused before anything is allocated
  const std::vector<SweepParameter> big(7,
                                        SweepParameter{"a", std::vector<std::string>(10, "1"), ""});
  EXPECT_THROW(CombineParameters(big, SweepCombine::kProduct), std::invalid_argument);
}

}  // namespace
}  // namespace towsim::app
