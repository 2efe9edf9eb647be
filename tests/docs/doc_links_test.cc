// The documentation's links: every relative link of README.md and docs/*.md resolves to a file
// and every #anchor to a heading of the page it names, every page of docs/ can be reached
// from README.md, and no link or path in code leads outside the repository (the pages cite
// only what a clone holds). The anchors are checked against GitHub's rendering rules
// (github-slugger, as github.com shows README.md and docs/): the examples below are the anchors
// GitHub gives those headings.

#include "markdown_links.h"

#include <cstdio>
#include <filesystem>
#include <queue>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "app/common/text_file.h"
#include "temp_dir.h"

namespace towsim::docs {
namespace {

namespace fs = std::filesystem;

void Write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  app::WriteTextFileAtomically(file.string(), text);
}

TEST(DocLinks, HeadingAnchorsAreGithubs) {
  EXPECT_EQ(HeadingAnchor("Output files (`--csv DIR`)"), "output-files---csv-dir");
  EXPECT_EQ(HeadingAnchor("DDS lockstep and realtime pacing: `tests/integration/bench_dds.sh`"),
            "dds-lockstep-and-realtime-pacing-testsintegrationbench_ddssh");
  EXPECT_EQ(HeadingAnchor("8. Tests"), "8-tests");
  EXPECT_EQ(HeadingAnchor("The paper's cases"), "the-papers-cases");
  EXPECT_EQ(HeadingAnchor("Controllers: manoeuvres \xE2\x80\x94 measured"),  // an em dash
            "controllers-manoeuvres--measured");
  EXPECT_EQ(HeadingAnchor("See [the page](other.md) **now**"), "see-the-page-now");
}

TEST(DocLinks, RepeatedHeadingsAreNumberedAndCodeIsNoHeading) {
  const std::set<std::string> anchors = HeadingAnchors(
      "# Title\n## Verified\ntext\n## Verified\n```sh\n# a shell comment\n```\n### Verified #\n");
  EXPECT_EQ(anchors, (std::set<std::string>{"title", "verified", "verified-1", "verified-2"}));
}

TEST(DocLinks, RelativeLinksSkipUrlsAndCode) {
  const std::vector<Link> links = RelativeLinks(
      "[a](a.md) and [web](https://example.org/x.md) ![fig](figures/f.png)\n"
      "`[not](code.md)` [`code text`](b.md#part)\n"
      "```\n[in](fence.md)\n```\n[self](#top)\n");
  ASSERT_EQ(links.size(), 4u);
  EXPECT_EQ(links[0].target, "a.md");
  EXPECT_EQ(links[0].line, 1);
  EXPECT_EQ(links[1].target, "figures/f.png");
  EXPECT_EQ(links[2].target, "b.md#part");
  EXPECT_EQ(links[2].line, 2);
  EXPECT_EQ(links[3].target, "#top");
  EXPECT_EQ(links[3].line, 6);
}

TEST(DocLinks, BrokenLinksAreFoundAndNamed) {
  test::TempDir dir;
  Write(dir.path() / "docs/b.md", "# B\n## Present part\n");
  Write(dir.path() / "docs/figures/f.png", "png");
  Write(dir.path() / "README.md",
        "# Top\n"
        "[ok](docs/b.md) [ok](docs/b.md#present-part) [ok](#top) ![ok](docs/figures/f.png)\n"
        "[bad](docs/b.md#absent)\n"
        "[bad](docs/missing.md)\n"
        "[bad](docs/figures/f.png#x) [bad](#nowhere)\n");
  const std::vector<std::string> broken = BrokenLinks(dir.path() / "README.md");
  ASSERT_EQ(broken.size(), 4u);
  const std::string readme = (dir.path() / "README.md").string();
  EXPECT_EQ(broken[0].rfind(readme + ":3: docs/b.md#absent: no heading with the anchor #absent",
                            0), 0u) << broken[0];
  EXPECT_EQ(broken[1].rfind(readme + ":4: docs/missing.md: no such file", 0), 0u) << broken[1];
  EXPECT_EQ(broken[2], readme + ":5: docs/figures/f.png#x: an #anchor needs a Markdown page");
  EXPECT_EQ(broken[3].rfind(readme + ":5: #nowhere: no heading", 0), 0u) << broken[3];
}

TEST(DocLinks, CodePathsAreSingleWordsWithASlash) {
  const std::vector<CodePath> paths = CodePaths(
      "`docs/topics.md` and `sim_node --csv DIR` and `name`\n"
      "`file://$PWD/config/cyclonedds.xml` ``../shared/x.md``\n"
      "```\n`../in/fence.md`\n```\n`/clock`\n");
  ASSERT_EQ(paths.size(), 3u);
  EXPECT_EQ(paths[0].path, "docs/topics.md");
  EXPECT_EQ(paths[0].line, 1);
  EXPECT_EQ(paths[1].path, "../shared/x.md");
  EXPECT_EQ(paths[1].line, 2);
  EXPECT_EQ(paths[2].path, "/clock");
  EXPECT_EQ(paths[2].line, 6);
}

TEST(DocLinks, PathsOutsideTheRepositoryAreFoundAndNamed) {
  test::TempDir dir;
  const fs::path root = dir.path() / "repo";
  // the outside file exists on this machine: a clone elsewhere would not have it
  Write(dir.path() / "shared/x.md", "# X\n");
  Write(root / "docs/b.md", "# B\n");
  Write(root / "docs/a.md",
        "# A\n"
        "[ok](b.md) [ok](../README.md#top) [ok](#a) [web](https://example.org/x.md)\n"
        "`docs/b.md` `config/scenes/x.yaml` `/clock` `/usr/bin/python3` `/tmp/run/bodies.csv`\n"
        "[bad](../../shared/x.md) and `../shared/x.md`\n"
        "`/home/me/notes.md`\n");
  Write(root / "README.md", "# Top\n(design: [bad](../shared/x.md#x))\n");

  const std::vector<std::string> readme = OutsideRepository(root / "README.md", root);
  ASSERT_EQ(readme.size(), 1u);
  EXPECT_EQ(readme[0], (root / "README.md").string() + ":2: ../shared/x.md#x: outside the " +
                           "repository (" + (dir.path() / "shared/x.md").string() + ")");

  const std::vector<std::string> page = OutsideRepository(root / "docs/a.md", root);
  const std::string a = (root / "docs/a.md").string();
  ASSERT_EQ(page.size(), 3u);
  EXPECT_EQ(page[0], a + ":4: ../../shared/x.md: outside the repository (" +
                         (dir.path() / "shared/x.md").string() + ")");
  EXPECT_EQ(page[1], a + ":4: `../shared/x.md`: outside the repository (" +
                         (dir.path() / "shared/x.md").string() + ")");
  EXPECT_EQ(page[2], a + ":5: `/home/me/notes.md`: outside the repository (/home/me/notes.md)");
  // the link checker alone passes the outside link: its file exists
  EXPECT_TRUE(BrokenLinks(root / "README.md").empty());
}

// The pages of the repository: README.md and every docs/*.md.
std::vector<fs::path> Pages() {
  const fs::path root = TOWSIM_SOURCE_DIR;
  std::vector<fs::path> pages = {root / "README.md"};
  for (const auto& entry : fs::directory_iterator(root / "docs")) {
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  }
  return pages;
}

TEST(DocLinks, EveryLinkOfTheReadmeAndDocsResolves) {
  // a checker that found no links would pass anything: README.md's table of pages alone has
  // 22, and the pages link each other (111 when this test was written)
  constexpr std::size_t kFewestLinks = 60;
  std::size_t links = 0;
  for (const fs::path& page : Pages()) {
    links += RelativeLinks(app::ReadTextFile(page.string())).size();
    for (const std::string& b : BrokenLinks(page)) ADD_FAILURE() << b;
  }
  EXPECT_GE(links, kFewestLinks);
  std::printf("[doc_links] %zu pages, %zu relative links checked\n", Pages().size(), links);
}

TEST(DocLinks, NoPageCitesAPathOutsideTheRepository) {
  // a checker that found no paths would pass anything: the pages write many repository paths
  // in code (559 when this test was written)
  constexpr std::size_t kFewestCodePaths = 300;
  std::size_t paths = 0;
  for (const fs::path& page : Pages()) {
    paths += CodePaths(app::ReadTextFile(page.string())).size();
    for (const std::string& o : OutsideRepository(page, TOWSIM_SOURCE_DIR)) ADD_FAILURE() << o;
  }
  EXPECT_GE(paths, kFewestCodePaths);
  std::printf("[doc_links] %zu paths in code checked\n", paths);
}

TEST(DocLinks, EveryDocsPageCanBeReachedFromTheReadme) {
  const fs::path root = TOWSIM_SOURCE_DIR;
  std::set<fs::path> reached;
  std::queue<fs::path> todo;
  todo.push(fs::weakly_canonical(root / "README.md"));
  while (!todo.empty()) {
    const fs::path page = todo.front();
    todo.pop();
    if (!reached.insert(page).second) continue;
    for (const Link& link : RelativeLinks(app::ReadTextFile(page.string()))) {
      const std::string path = link.target.substr(0, link.target.find('#'));
      if (path.empty()) continue;
      const fs::path target = fs::weakly_canonical(page.parent_path() / path);
      if (target.extension() == ".md" && fs::exists(target)) todo.push(target);
    }
  }
  for (const fs::path& page : Pages()) {
    EXPECT_EQ(reached.count(fs::weakly_canonical(page)), 1u)
        << page << ": no chain of links from README.md leads here";
  }
}

}  // namespace
}  // namespace towsim::docs
