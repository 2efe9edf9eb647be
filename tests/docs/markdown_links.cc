#include "markdown_links.h"

#include <cctype>
#include <map>
#include <regex>
#include <sstream>

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

// `line` with each code span replaced by its text (keep_text: a heading's anchor keeps the
// code's text) or by a plain word (a link inside code is not a link).
std::string WithoutCodeSpans(const std::string& line, bool keep_text) {
  std::string out;
  std::size_t i = 0;
  while (i < line.size()) {
    if (line[i] != '`') {
      out += line[i++];
      continue;
    }
    std::size_t run = line.find_first_not_of('`', i);
    if (run == std::string::npos) run = line.size();
    const std::string ticks = line.substr(i, run - i);
    const std::size_t close = line.find(ticks, run);
    if (close == std::string::npos) {  // an unmatched backtick is a literal backtick
      out += ticks;
      i = run;
      continue;
    }
    out += keep_text ? line.substr(run, close - run) : "code";
    i = close + ticks.size();
  }
  return out;
}

const std::regex& LinkPattern() {
  static const std::regex pattern(R"(!?\[([^\]]*)\]\(([^()\s]*)\))");
  return pattern;
}

bool IsAbsoluteUrl(const std::string& target) {
  static const std::regex scheme(R"(^[A-Za-z][A-Za-z0-9+.-]*:)");
  return std::regex_search(target, scheme);
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

}  // namespace towsim::docs
