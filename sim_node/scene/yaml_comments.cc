#include "scene/yaml_comments.h"

#include <cstddef>
#include <string_view>

namespace towsim::scene::internal {
namespace {

bool OpensToken(std::string_view line, size_t i) {
  if (i == 0) return true;
  const char p = line[i - 1];
  return p == ' ' || p == '[' || p == '{' || p == ',' || p == ':';
}

}  // namespace

std::string StripYamlComments(const std::string& text) {
  for (const char c : text) {
    if (c == '\t' || c == '\r' || c == '\0') return text;
  }
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) return text;
  enum class Quote { kNone, kDouble, kSingle };
  Quote quote = Quote::kNone;
  long block_indent = -1;  // >= 0: inside a block scalar opened on a line so indented
  long flow_depth = 0;     // open [ and { (outside quoted scalars)
  std::string out;
  out.reserve(text.size());
  size_t pos = 0;
  while (pos < text.size()) {
    size_t eol = text.find('\n', pos);
    const bool has_newline = eol != std::string::npos;
    if (!has_newline) eol = text.size();
    const std::string_view line(text.data() + pos, eol - pos);
    pos = has_newline ? eol + 1 : eol;
    const size_t first = line.find_first_not_of(' ');
    const bool blank = first == std::string_view::npos;
    const long indent = blank ? static_cast<long>(line.size()) : static_cast<long>(first);
    if (block_indent >= 0) {
      if (blank || indent > block_indent) {
        // block scalar content, as written; one that yaml-cpp might read as a quoted scalar
        // or a flow collection instead (the scan's block may reach further than the true one)
        // is not followed
        for (size_t i = 0; i < line.size(); ++i) {
          const char c = line[i];
          if (c == '"' || c == '[' || c == ']' || c == '{' || c == '}') return text;
          if (c == '\'' && OpensToken(line, i)) return text;
          if ((c == '|' || c == '>') && (i == 0 || line[i - 1] == ' ')) return text;
        }
        out += line;
        if (has_newline) out += '\n';
        continue;
      }
      block_indent = -1;  // the first line after the block
    }
    size_t comment = line.size();  // where a comment starts
    bool block_opens = false;
    bool indicator_seen = false;  // a ':', '- ' or '? ' before this point of the line
    for (size_t i = blank ? line.size() : first; i < line.size(); ++i) {
      const char c = line[i];
      if (quote == Quote::kDouble) {
        if (c == '\\') {
          ++i;  // the escaped character
        } else if (c == '"') {
          quote = Quote::kNone;
        }
        continue;
      }
      if (quote == Quote::kSingle) {
        if (c == '\'') {
          if (i + 1 < line.size() && line[i + 1] == '\'') {
            ++i;  // '' is a quote inside the scalar
          } else {
            quote = Quote::kNone;
          }
        }
        continue;
      }
      if (c == '[' || c == '{') ++flow_depth;
      if ((c == ']' || c == '}') && --flow_depth < 0) return text;  // closes nothing
      const bool after_space = i == 0 || line[i - 1] == ' ';
      if (c == '#' && after_space) {
        comment = i;
        break;
      }
      if ((c == '"' || c == '\'') && OpensToken(line, i)) {
        quote = c == '"' ? Quote::kDouble : Quote::kSingle;
        continue;
      }
      if ((c == '|' || c == '>') && after_space) {
        // its parent's indentation is this line's only after an indicator on it; none in a
        // flow collection
        if (!indicator_seen || flow_depth > 0) return text;
        block_opens = true;
      }
      if (c == ':' || ((c == '-' || c == '?') && after_space &&
                       (i + 1 == line.size() || line[i + 1] == ' '))) {
        indicator_seen = true;
      }
    }
    if (comment < line.size()) {
      // the comment's text goes, its '#' stays: a comment ends a plain scalar, so a more
      // indented line below must not become its continuation
      if (comment == first) {
        out.append(line.data(), comment + 1);  // a comment line: its indentation and '#'
      } else {
        size_t end = comment;
        while (end > 0 && line[end - 1] == ' ') --end;
        out.append(line.data(), end);
        out += " #";  // the separating space and the '#', one column each
      }
    } else {
      // the blanks at the end of the line
      size_t end = line.size();
      while (end > 0 && line[end - 1] == ' ') --end;
      out.append(line.data(), end);
    }
    if (has_newline) out += '\n';
    if (quote != Quote::kNone) return text;  // a quoted scalar across lines
    if (block_opens) block_indent = indent;
  }
  return out;
}

}  // namespace towsim::scene::internal
