#pragma once
// The relative links of a Markdown page and the anchors its headings define, as GitHub renders
// them (README.md "Documentation": every page links the others by relative path and #anchor).
// Used by doc_links_test to prove that every relative link of README.md and docs/*.md resolves
// to a file and every #anchor to a heading of the page it names, and that no link or path in
// code names something outside the repository (the pages cite only what a clone holds).

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace towsim::docs {

// One link of a page: `[text](target)` or `![alt](target)`, target = path and/or #anchor.
struct Link {
  int line = 0;        // 1-based line of the page
  std::string target;  // as written, e.g. "docs/topics.md#topics", "#exit-codes"
};

// One path a page writes in a code span: a single word with a '/' and no URL scheme, e.g.
// `config/scenes/case1_forward.yaml`, `../shared/x.md`, `/usr/bin/python3`, `/clock`.
struct CodePath {
  int line = 0;      // 1-based line of the page
  std::string path;  // the code span's text
};

// GitHub's anchor of a heading's text: inline markup removed (code spans keep their text,
// links keep theirs), lower case, every character but letters, digits, '_', '-' and ' '
// dropped, spaces turned into '-'. "Output files (`--csv DIR`)" -> "output-files---csv-dir".
std::string HeadingAnchor(const std::string& heading_text);

// The anchors the headings (ATX, `#` to `######`, outside fenced code) of `markdown` define;
// a repeated anchor gets -1, -2, ... appended, as GitHub does.
std::set<std::string> HeadingAnchors(const std::string& markdown);

// The links of `markdown` whose target is neither an absolute URL (scheme:...) nor empty;
// links inside fenced code blocks and code spans are not links.
std::vector<Link> RelativeLinks(const std::string& markdown);

// The paths written in the code spans of `markdown` (outside fenced code blocks).
std::vector<CodePath> CodePaths(const std::string& markdown);

// Every relative link of the page `file` that does not resolve: the path (relative to the
// page's folder) must exist, and an anchor must be a heading anchor of the page it names (a
// Markdown file). Each entry reads "<file>:<line>: <target>: <what is wrong>".
std::vector<std::string> BrokenLinks(const std::filesystem::path& file);

// Everything the page `file` cites that a clone of the repository at `root` does not hold:
// - a relative link that leaves `root` (resolved from the page's folder, as GitHub does), even
//   when the target exists on this machine;
// - a relative path in code that leaves `root` (read from `root`, as the pages write repository
//   paths: `docs/topics.md`; so `../shared/x.md` fails on every page);
// - an absolute path in code naming a file (its name has an extension) outside the machine's own
//   folders (/usr, /etc, /opt, /tmp, /dev, /proc, /sys, /var): `/home/me/notes.md`. Topic names
//   (`/clock`) and programs (`/usr/bin/python3`) pass.
// Each entry reads "<file>:<line>: <link or path>: outside the repository (<where it leads>)".
std::vector<std::string> OutsideRepository(const std::filesystem::path& file,
                                           const std::filesystem::path& root);

}  // namespace towsim::docs
