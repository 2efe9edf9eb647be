// StripYamlComments (scene/yaml_comments.h) against yaml-cpp itself: the stripped text must
// parse to the same nodes at the same marks (line and column) as the original, or fail with
// the same message at the same mark. Zero tolerance: every scalar, tag, type and mark compared
// exactly. The texts: every YAML file the project ships, hand-written cases of each rule, and
// seeded random documents built from lines that mix comments, quotes and block scalars.

#include "scene/yaml_comments.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

namespace towsim::scene::internal {
namespace {

namespace fs = std::filesystem;

// every node of a and b: type, tag, scalar and mark; maps in order, keys included
void ExpectSameTree(const YAML::Node& a, const YAML::Node& b, const std::string& where) {
  ASSERT_EQ(a.Type(), b.Type()) << where;
  EXPECT_EQ(a.Tag(), b.Tag()) << where;
  EXPECT_EQ(a.Mark().line, b.Mark().line) << where;
  EXPECT_EQ(a.Mark().column, b.Mark().column) << where;
  if (a.IsScalar()) {
    EXPECT_EQ(a.Scalar(), b.Scalar()) << where;
  }
  if (a.IsSequence()) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (size_t i = 0; i < a.size(); ++i) {
      ExpectSameTree(a[i], b[i], where + "[" + std::to_string(i) + "]");
    }
  }
  if (a.IsMap()) {
    ASSERT_EQ(a.size(), b.size()) << where;
    auto ia = a.begin();
    auto ib = b.begin();
    for (; ia != a.end(); ++ia, ++ib) {
      ExpectSameTree(ia->first, ib->first, where + " key");
      ExpectSameTree(ia->second, ib->second, where + "." + ia->first.Scalar());
    }
  }
}

// the original and the stripped text: the same documents, or the same error
void ExpectSameParse(const std::string& text, const std::string& name) {
  const std::string stripped = StripYamlComments(text);
  ASSERT_LE(stripped.size(), text.size()) << name;
  EXPECT_EQ(std::count(stripped.begin(), stripped.end(), '\n'),
            std::count(text.begin(), text.end(), '\n'))
      << name;
  std::vector<YAML::Node> a, b;
  std::string error_a, error_b;
  try {
    a = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    error_a = e.what();
  }
  try {
    b = YAML::LoadAll(stripped);
  } catch (const YAML::Exception& e) {
    error_b = e.what();
  }
  ASSERT_EQ(error_a, error_b) << name << "\n--- original:\n" << text << "\n--- stripped:\n"
                              << stripped;
  ASSERT_EQ(a.size(), b.size()) << name;
  for (size_t i = 0; i < a.size(); ++i) {
    ExpectSameTree(a[i], b[i], name + " document " + std::to_string(i));
  }

}

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(StripYamlComments, EveryShippedFileParsesTheSame) {
  int files = 0;
  size_t before = 0, after = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(TOWSIM_SOURCE_DIR) / "config")) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string text = ReadAll(entry.path());
    ExpectSameParse(text, entry.path().string());
    before += text.size();
    after += StripYamlComments(text).size();
    ++files;
  }
  EXPECT_GE(files, 10);
  // the shipped files are commented: stripping must take a good part of them out (the scan
  // gave up on none of them)
  EXPECT_LT(static_cast<double>(after), 0.7 * static_cast<double>(before));
}

TEST(StripYamlComments, CommentsGoEverythingElseStays) {
  const std::string text =
      "a: 1   # a comment\n"
      "b: \"x # not a comment\"   # one\n"
      "c: 'it''s # not one' # one\n"
      "d: foo#bar\n"
      "# a whole line\n"
      "e: [1, 2,   # in a flow sequence\n"
      "    3]\n"
      "f: {g: 1, # in a flow map\n"
      "    h: \"2\"}\n"
      "i: &x 7 # anchor\n"
      "j: *x # alias\n"
      "k: # null\n"
      "l:\n"
      "  - 1 # item\n"
      "  # between items\n"
      "  - two words # item\n"
      "m: trailing blanks   \n";
  const std::string stripped = StripYamlComments(text);
  EXPECT_EQ(stripped,
            "a: 1 #\n"
            "b: \"x # not a comment\" #\n"
            "c: 'it''s # not one' #\n"
            "d: foo#bar\n"
            "#\n"
            "e: [1, 2, #\n"
            "    3]\n"
            "f: {g: 1, #\n"
            "    h: \"2\"}\n"
            "i: &x 7 #\n"
            "j: *x #\n"
            "k: #\n"
            "l:\n"
            "  - 1 #\n"
            "  #\n"
            "  - two words #\n"
            "m: trailing blanks\n");
  ExpectSameParse(text, "mixed");
}

TEST(StripYamlComments, BlockScalarsAreNotTouched) {
  const std::string block =
      "s: |\n"
      "  # content, not a comment\n"
      "   kept as written   \n"
      "\n"
      "  more # content\n"
      "t: >-\n"
      "  folded # content\n"
      "# after the block: a comment\n"
      "u:\n"
      "  - |\n"
      "    # content\n"
      "  - 3 # comment\n";
  const std::string stripped = StripYamlComments(block);
  EXPECT_NE(stripped.find("  # content, not a comment\n   kept as written   \n"), std::string::npos);
  EXPECT_NE(stripped.find("  more # content\n"), std::string::npos);
  EXPECT_NE(stripped.find("  folded # content\n#\nu:"), std::string::npos);
  EXPECT_NE(stripped.find("    # content\n  - 3 #\n"), std::string::npos);
  ExpectSameParse(block, "block scalars");

  ExpectSameParse("p: first\n  second # c\n  # a comment line\nz: 1\n", "multi-line plain");
  ExpectSameParse("a: x | y # c\nb:\n  # c\n  c: 1\n", "a bar inside a plain scalar");
}

TEST(StripYamlComments, WhatTheScanDoesNotFollowIsLeftAlone) {
  for (const std::string& text : std::vector<std::string>{
           std::string("k:\n  |\n  # content at the key's indentation + 2\n"),  // on its own line
           std::string("k:\n  !!str |\n  # content\n"),
           std::string("--- |\n# content of a root scalar\n"),
           std::string("|\n# content\n"),
           std::string("a: 1\t# a tab\n"),
           std::string("a: 1 # a comment\r\nb: 2\r\n"),
           std::string("\xEF\xBB\xBF" "a: 1 # c\n"),
           std::string("a: \"never closed # x\nb: 1 # c\n"),
           std::string("q: \"first # a\n  second # b\"  # c\n"),  // quotes across lines
           std::string("r: 'one # x\n  two' # y\n"),
           std::string("a: 1 # c\n]\nb: 2 # c\n"),                // a ] that closes nothing
           std::string("a: [1, # c\n  - | # c\n  # x\n  ]\n"),     // a block in a flow
       }) {
    EXPECT_EQ(StripYamlComments(text), text);
    ExpectSameParse(text, text);
  }
}

TEST(StripYamlComments, ErrorsKeepTheirMessageAndPlace) {
  // bad indentation after a comment, a tab-free unterminated flow map, a duplicate document
  for (const std::string& text : std::vector<std::string>{
           std::string("a: 1 # c\n b: 2 # c\n"),
           std::string("a: {b: 1, # c\n  c: 2\n"),
           std::string("a: [1, 2 # c\n"),
           std::string("a: 1 # c\n---\nb: 2 # c\n"),
           std::string("a: 1 # c\n  - 2 # c\n"),
       }) {
    ExpectSameParse(text, text);
  }
}

// seeded random documents: lines drawn from fragments that mix comments, quotes, flow
// collections and block scalars at random indentations, valid or not; each parses the same
// (or fails the same) before and after
TEST(StripYamlComments, RandomDocumentsParseTheSame) {
  const std::vector<std::string> fragments = {
      "key: value", "key: value # c", "key: 'q # x' # c", "key: \"q \\\" # x\" # c", "# comment",
      "key:", "- item # c", "- 'it''s' # c", "key: [1, 2] # c", "key: {a: 1} # c",
      "key: [1, # c", "  2]", "key: |", "key: >- # c", "  # block content?", "   text  ", "",
      "key: \"open # x", "close\" # c", "key: a#b", "key: a | b # c", "- key: | # c",
      "? complex # c", ": value # c", "key: &a x # c", "other: *a # c", "--- # c",
      "  continued   ", "a: b  ", "  - 1 #c", "x: 'a' 'b' # c", "- | # c", "  | # c", "? | # c",
      "key: !!str | # c", "[a, b # c", "}", "{a: 1, # c", "key: \"a\\\\\" # c", "key: '' # c", "...",
      "%YAML 1.2 # c", "- - x # c", "key: a # b # c", "key:   # c", "#", " #", "key: >", "  #"};
  std::mt19937_64 rng(20261201);
  std::uniform_int_distribution<size_t> pick(0, fragments.size() - 1);
  std::uniform_int_distribution<int> lines(1, 12), indent(0, 3);
  int changed = 0;
  for (int doc = 0; doc < 5000; ++doc) {
    std::string text;
    const int n = lines(rng);
    for (int k = 0; k < n; ++k) {
      const std::string& f = fragments[pick(rng)];
      text += std::string(2 * static_cast<size_t>(indent(rng)) * (k > 0), ' ') + f + "\n";
    }
    ExpectSameParse(text, "random document " + std::to_string(doc));
    if (HasFatalFailure()) return;
    if (StripYamlComments(text) != text) ++changed;
  }
  EXPECT_GT(changed, 1000);  // the scan did not simply give up
}

}  // namespace
}  // namespace towsim::scene::internal
