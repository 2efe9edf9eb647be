#include "markdown_links.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <utility>

#include "app/common/text_file.h"

namespace towsim::docs {
namespace {

// A fence opens or closes a fenced code block: ``` or ~~~ after at most 3 spaces.
bool IsFence(const std::string& line) {
  const std::size_t i = line.find_first_not_of(' ');
  return i != std::string::npos && i <= 3 &&
         (line.compare(i, 3, "```") == 0 || line.compare(i, 3, "~~~") == 0);
}

// The lines of `markdown` outside fenced code blocks, with their 1-based numbers.
std::vector<std::pair<int, std::string>> ProseLines(const std::string& markdown) {
  std::vector<std::pair<int, std::string>> lines;
  std::istringstream in(markdown);
  std::string line;
  bool fenced = false;
  for (int n = 1; std::getline(in, line); ++n) {
    if (IsFence(line)) {
      fenced = !fenced;
      continue;
    }
    if (!fenced) lines.emplace_back(n, line);
  }
  return lines;
}

// One code span of a line: [begin, end) including its backticks, and its text.
struct CodeSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::string text;
};

// The code spans of `line`: a run of backticks up to the next run of the same length (an
// unmatched run is literal backticks).
std::vector<CodeSpan> CodeSpans(const std::string& line) {
  std::vector<CodeSpan> spans;
  std::size_t i = line.find('`');
  while (i != std::string::npos) {
    std::size_t run = line.find_first_not_of('`', i);
    if (run == std::string::npos) run = line.size();
    const std::string ticks = line.substr(i, run - i);
    const std::size_t close = line.find(ticks, run);
    if (close == std::string::npos) {
      i = line.find('`', run);
      continue;
    }
    spans.push_back({i, close + ticks.size(), line.substr(run, close - run)});
    i = line.find('`', close + ticks.size());
  }
  return spans;
}

// `line` with each code span replaced by its text (keep_text: a heading's anchor keeps the
// code's text) or by a plain word (a link inside code is not a link).
std::string WithoutCodeSpans(const std::string& line, bool keep_text) {
  std::string out;
  std::size_t i = 0;
  for (const CodeSpan& span : CodeSpans(line)) {
    out += line.substr(i, span.begin - i);
    out += keep_text ? span.text : "code";
    i = span.end;
  }
  return out + line.substr(i);
}

const std::regex& LinkPattern() {
  static const std::regex pattern(R"(!?\[([^\]]*)\]\(([^()\s]*)\))");
  return pattern;
}

bool IsAbsoluteUrl(const std::string& target) {
  static const std::regex scheme(R"(^[A-Za-z][A-Za-z0-9+.-]*:)");
  return std::regex_search(target, scheme);
}

// `path` lies in `root` or below it (both absolute; compared as written, after removing "."
// and ".." lexically).
bool IsInside(const std::filesystem::path& path, const std::filesystem::path& root) {
  const std::filesystem::path relative =
      path.lexically_normal().lexically_relative(root.lexically_normal());
  return !relative.empty() && *relative.begin() != "..";
}

// An absolute path in code names a file outside the machine's own folders: a last name with an
// extension ("notes.md"), a first folder other than the system's.
bool IsForeignAbsoluteFile(const std::filesystem::path& path) {
  static const std::set<std::string> kSystemFolders = {"usr", "etc",  "opt", "tmp",
                                                       "dev", "proc", "sys", "var"};
  if (!path.is_absolute() || !path.has_extension() || path.filename().string()[0] == '.') {
    return false;
  }
  const auto first = std::next(path.begin());  // the component after "/"
  return first == path.end() || kSystemFolders.count(first->string()) == 0;
}

}  // namespace

std::string HeadingAnchor(const std::string& heading_text) {
  // links keep their text, code spans theirs; emphasis markers go
  const std::string text =
      std::regex_replace(WithoutCodeSpans(heading_text, true), LinkPattern(), "$1");
  std::string anchor;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '_' || c == '-') {
      anchor += static_cast<char>(std::tolower(u));
    } else if (c == ' ') {
      anchor += '-';
    }  // anything else (punctuation, non-ASCII such as an em dash) is dropped
  }
  return anchor;
}

std::set<std::string> HeadingAnchors(const std::string& markdown) {
  static const std::regex heading(R"(^ {0,3}#{1,6}[ \t]+(.*?)[ \t]*#*[ \t]*$)");
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  for (const auto& [n, line] : ProseLines(markdown)) {
    std::smatch m;
    if (!std::regex_match(line, m, heading)) continue;
    const std::string base = HeadingAnchor(m[1].str());
    const int k = seen[base]++;
    anchors.insert(k == 0 ? base : base + "-" + std::to_string(k));
  }
  return anchors;
}

std::vector<Link> RelativeLinks(const std::string& markdown) {
  std::vector<Link> links;
  for (const auto& [n, line] : ProseLines(markdown)) {
    const std::string prose = WithoutCodeSpans(line, false);
    for (auto it = std::sregex_iterator(prose.begin(), prose.end(), LinkPattern());
         it != std::sregex_iterator(); ++it) {
      const std::string target = (*it)[2].str();
      if (target.empty() || IsAbsoluteUrl(target)) continue;
      links.push_back({n, target});
    }
  }
  return links;
}

std::vector<CodePath> CodePaths(const std::string& markdown) {
  static const std::regex path_word(R"(^[^\s]*/[^\s]*$)");
  std::vector<CodePath> paths;
  for (const auto& [n, line] : ProseLines(markdown)) {
    for (const CodeSpan& span : CodeSpans(line)) {
      if (!std::regex_match(span.text, path_word) || span.text.find("://") != std::string::npos) {
        continue;
      }
      paths.push_back({n, span.text});
    }
  }
  return paths;
}

std::vector<std::string> BrokenLinks(const std::filesystem::path& file) {
  std::vector<std::string> broken;
  for (const Link& link : RelativeLinks(app::ReadTextFile(file.string()))) {
    const std::size_t hash = link.target.find('#');
    const std::string path = link.target.substr(0, hash);
    const std::string anchor = hash == std::string::npos ? "" : link.target.substr(hash + 1);
    const std::filesystem::path resolved = path.empty() ? file : file.parent_path() / path;
    const std::string where = file.string() + ":" + std::to_string(link.line) + ": " +
                              link.target + ": ";
    if (!std::filesystem::exists(resolved)) {
      broken.push_back(where + "no such file " + resolved.lexically_normal().string());
      continue;
    }
    if (anchor.empty()) continue;
    if (resolved.extension() != ".md") {
      broken.push_back(where + "an #anchor needs a Markdown page");
    } else if (HeadingAnchors(app::ReadTextFile(resolved.string())).count(anchor) == 0) {
      broken.push_back(where + "no heading with the anchor #" + anchor + " in " +
                       resolved.lexically_normal().string());
    }
  }
  return broken;
}

std::vector<std::string> OutsideRepository(const std::filesystem::path& file,
                                           const std::filesystem::path& root) {
  const std::string markdown = app::ReadTextFile(file.string());
  std::vector<std::pair<int, std::string>> found;  // line, "<cited>: outside ... (<where>)"
  const auto outside = [](const std::string& cited, const std::filesystem::path& where) {
    return cited + ": outside the repository (" + where.lexically_normal().string() + ")";
  };
  for (const Link& link : RelativeLinks(markdown)) {
    const std::string path = link.target.substr(0, link.target.find('#'));
    if (path.empty()) continue;
    const std::filesystem::path resolved = file.parent_path() / path;
    if (!IsInside(resolved, root)) found.emplace_back(link.line, outside(link.target, resolved));
  }
  for (const CodePath& code : CodePaths(markdown)) {
    const std::filesystem::path path = code.path;
    const bool leaves =
        path.is_absolute() ? IsForeignAbsoluteFile(path) : !IsInside(root / path, root);
    if (leaves) {
      found.emplace_back(code.line,
                         outside("`" + code.path + "`", path.is_absolute() ? path : root / path));
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> lines;
  for (const auto& [n, what] : found) {
    lines.push_back(file.string() + ":" + std::to_string(n) + ": " + what);
  }
  return lines;
}

}  // namespace towsim::docs
