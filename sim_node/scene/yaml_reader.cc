#include "scene/yaml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "scene/config_error.h"

namespace towsim::scene::internal {
namespace {

constexpr const char* kMissing = "<missing>";
constexpr size_t kMaxValueChars = 80;  // longer values are shortened in messages

bool IsQuoted(const YAML::Node& node) { return node.Tag() == "!"; }

// a plain YAML scalar as a double (YAML 1.2 core schema); false if it is not a number
bool ParseDouble(std::string text, double* value) {
  if (text == ".inf" || text == ".Inf" || text == ".INF" || text == "+.inf" || text == "+.Inf" ||
      text == "+.INF") {
    *value = std::numeric_limits<double>::infinity();
    return true;
  }
  if (text == "-.inf" || text == "-.Inf" || text == "-.INF") {
    *value = -std::numeric_limits<double>::infinity();
    return true;
  }
  if (text == ".nan" || text == ".NaN" || text == ".NAN") {
    *value = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, *value);
  return ec == std::errc() && ptr == end;
}

// a plain YAML scalar as a decimal integer; false if it is not one
bool ParseInteger(std::string text, long long* value) {
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, *value);
  return ec == std::errc() && ptr == end;
}

}  // namespace

bool Source::FromSet(const std::string& path) const {
  for (const std::string& set : set_paths) {
    if (path.compare(0, set.size(), set) != 0) continue;
    // a key path at or below `set`: equal, or continued by ".key" or "[i]"
    if (path.size() == set.size() || path[set.size()] == '.' || path[set.size()] == '[') {
      return true;
    }
  }
  return false;
}

std::string Range::Violation(double x) const {
  if (lo_open ? !(x > lo) : !(x >= lo)) {
    return (lo_open ? "must be > " : "must be >= ") + FormatNumber(lo);
  }
  if (hi_open ? !(x < hi) : !(x <= hi)) {
    return (hi_open ? "must be < " : "must be <= ") + FormatNumber(hi);
  }
  return {};
}

std::string Trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  const size_t last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

bool ReadTextFile(const std::string& path, std::string* text, std::string* why) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    *why = "no such file";
    return false;
  }
  if (std::filesystem::is_directory(path, error)) {
    *why = "it is a directory";
    return false;
  }
  // a device (/dev/zero) never ends and a FIFO blocks until a writer comes: neither is read
  if (!std::filesystem::is_regular_file(path, error)) {
    *why = "not a regular file";
    return false;
  }
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error) {
    *why = "cannot read its size: " + error.message();
    return false;
  }
  if (bytes > kMaxTextFileBytes) {
    *why = std::to_string(bytes) + " bytes: larger than the limit of " +
           std::to_string(kMaxTextFileBytes) + " bytes (16 MB)";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *why = "cannot open it for reading";
    return false;
  }
  // the size found plus one byte, then more only if the file grew meanwhile, never past the
  // limit + 1 (a buffer of the whole limit would cost 16 MB of zeroed pages for every file:
  // docs/benchmarks.md, "Start-up")
  std::string buffer;
  size_t wanted = static_cast<size_t>(bytes) + 1;
  while (buffer.size() <= kMaxTextFileBytes) {
    const size_t old_size = buffer.size();
    buffer.resize(std::min<size_t>(old_size + wanted, kMaxTextFileBytes + 1));
    in.read(buffer.data() + old_size, static_cast<std::streamsize>(buffer.size() - old_size));
    buffer.resize(old_size + static_cast<size_t>(in.gcount()));
    if (!in) break;          // end of file (or a read error: the bytes read so far)
    wanted = buffer.size();  // grew while read: double the buffer
  }
  if (buffer.size() > kMaxTextFileBytes) {
    *why = "larger than the limit of " + std::to_string(kMaxTextFileBytes) + " bytes (16 MB)";
    return false;
  }
  *text = std::move(buffer);
  return true;
}

YAML::Node LoadOneDocument(const std::string& text, const std::string& name_for_messages,
                           const std::string& key, const std::string& value_if_invalid) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    const std::string line = e.mark.is_null() ? "" : ":" + std::to_string(e.mark.line + 1);
    throw ConfigError(key, value_if_invalid, name_for_messages + line, "not valid YAML: " + e.msg);
  }
  if (documents.size() > 1) {
    const YAML::Mark second = documents[1].Mark();
    const std::string line = second.is_null() ? "" : ":" + std::to_string(second.line + 1);
    throw ConfigError(key, "<" + std::to_string(documents.size()) + " YAML documents>",
                      name_for_messages + line,
                      "a file must hold one YAML document (the second starts here)");
  }
  return documents.empty() ? YAML::Node() : documents[0];
}

YAML::Node LoadYamlMap(const std::string& yaml, const std::string& name,
                       const std::string& not_a_map_rule) {
  const YAML::Node root = LoadOneDocument(yaml, name, name, "<not YAML>");
  if (!root.IsMap()) {
    throw ConfigError(name, root.IsNull() ? "<empty>" : FormatNode(root), name, not_a_map_rule);
  }
  return root;
}

std::string JoinPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string FormatNumber(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

std::string FormatVector(const core::Vec3& v) {
  return "[" + FormatNumber(v.x()) + ", " + FormatNumber(v.y()) + ", " + FormatNumber(v.z()) + "]";
}

std::string FormatNode(const YAML::Node& node) {
  if (!node.IsDefined()) return kMissing;
  if (node.IsNull()) return "null";
  // quoted strings keep their quotes, so "100" is seen to be a string
  if (node.IsScalar()) return IsQuoted(node) ? "\"" + node.Scalar() + "\"" : node.Scalar();
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  std::string text = out.c_str();
  if (text.size() > kMaxValueChars) text = text.substr(0, kMaxValueChars - 3) + "...";
  return text;
}

Field::Field(YAML::Node node, YAML::Mark mark, std::string path,
             std::shared_ptr<const Source> source)
    : node_(std::move(node)), mark_(mark), path_(std::move(path)), source_(std::move(source)) {}

Field& Field::operator=(const Field& other) {
  if (this == &other) return *this;
  node_.reset(other.node_);
  mark_ = other.mark_;
  path_ = other.path_;
  source_ = other.source_;
  present_ = other.present_;
  return *this;
}

Field Field::Missing(std::string path, const Field& parent) {
  Field field(YAML::Node(), parent.mark_, std::move(path), parent.source_);
  field.present_ = false;
  return field;
}

std::string Field::location() const {
  if (source_->FromSet(path_)) return "--set";
  if (mark_.is_null()) return source_->name;
  return source_->name + ":" + std::to_string(mark_.line + 1);
}

std::string Field::text() const { return present_ ? FormatNode(node_) : kMissing; }

void Field::Fail(const std::string& rule) const {
  throw ConfigError(path_, text(), location(), rule);
}

double Field::Number(const Range& range) const {
  // a number is a plain scalar that parses as a finite double
  if (!present_) Fail("is required");
  double value = 0.0;
  if (!node_.IsScalar() || IsQuoted(node_) || !ParseDouble(node_.Scalar(), &value)) {
    Fail(IsQuoted(node_) ? "must be a number, not a quoted string" : "must be a number");
  }
  if (!std::isfinite(value)) Fail("must be a finite number");
  const std::string violation = range.Violation(value);
  if (!violation.empty()) Fail(violation);
  return value;
}

int Field::Integer(const Range& range) const {
  // an integer is a plain scalar in decimal digits; the range keeps it within int
  if (!present_) Fail("is required");
  long long value = 0;
  if (!node_.IsScalar() || IsQuoted(node_) || !ParseInteger(node_.Scalar(), &value)) {
    Fail("must be an integer");
  }
  const std::string violation = range.Violation(static_cast<double>(value));
  if (!violation.empty()) Fail(violation);
  return static_cast<int>(value);
}

bool Field::Boolean() const {
  if (!present_) Fail("is required");
  bool value = false;
  if (!node_.IsScalar() || IsQuoted(node_) || !YAML::convert<bool>::decode(node_, value)) {
    Fail("must be true or false");
  }
  return value;
}

std::string Field::String() const {
  if (!present_) Fail("is required");
  if (!node_.IsScalar()) Fail("must be a string");
  return node_.Scalar();
}

core::Vec3 Field::Vector() const {
  // a vector is a list of exactly 3 finite numbers
  if (!present_) Fail("is required");
  if (!node_.IsSequence()) Fail("must be a list of 3 numbers [x, y, z]");
  if (node_.size() != 3) {
    Fail("must be a list of 3 numbers [x, y, z] (it has " + std::to_string(node_.size()) + ")");
  }
  const std::vector<Field> items = Items();
  return {items[0].Number(), items[1].Number(), items[2].Number()};
}

size_t Field::Choice(const std::vector<std::string>& choices) const {
  const std::string value = String();
  const auto it = std::find(choices.begin(), choices.end(), value);
  if (it == choices.end()) {
    std::string rule = "must be one of ";
    for (size_t i = 0; i < choices.size(); ++i) rule += (i ? ", " : "") + choices[i];
    Fail(rule);
  }
  return static_cast<size_t>(it - choices.begin());
}

std::vector<Field> Field::Items() const {
  std::vector<Field> items;
  if (!present_ || node_.IsNull()) return items;
  if (!node_.IsSequence()) Fail("must be a list");
  items.reserve(node_.size());
  for (size_t i = 0; i < node_.size(); ++i) {
    const YAML::Node item = node_[i];
    items.emplace_back(item, item.Mark(), path_ + "[" + std::to_string(i) + "]", source_);
  }
  return items;
}

MapReader::MapReader(const Field& field, MapKind kind) : field_(field) {
  if (!field.present() || field.node().IsNull()) return;
  if (!field.node().IsMap()) field.Fail("must be a map of keys");
  const std::vector<std::string>& allowed = AllowedKeys(kind);
  for (auto it = field.node().begin(); it != field.node().end(); ++it) {
    const YAML::Node key = it->first;  // a copy: it-> yields a temporary proxy
    const std::string name = key.IsScalar() ? key.Scalar() : FormatNode(key);
    Field entry(it->second, key.Mark(), JoinPath(field.path(), name), field.source());
    // keys are plain names
    if (!key.IsScalar()) entry.Fail("keys must be plain names");
    // only the keys of the schema; body names follow the naming rule
    if (const char* named = NamedEntries(kind)) {
      if (!IsValidName(name)) entry.Fail(std::string(named) + " " + kNameRule);
    } else if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      entry.Fail(UnknownKeyRule(name, allowed));
    }
    // each key once
    if (Has(name)) {
      entry.Fail("duplicate key (first given at " + Get(name).location() + ")");
    }
    entries_.emplace_back(name, std::move(entry));
  }
}

bool MapReader::Has(const std::string& key) const {
  return std::any_of(entries_.begin(), entries_.end(),
                     [&](const auto& entry) { return entry.first == key; });
}

Field MapReader::Get(const std::string& key) const {
  for (const auto& entry : entries_) {
    if (entry.first == key) return entry.second;
  }
  return Field::Missing(JoinPath(field_.path(), key), field_);
}

Field MapReader::Require(const std::string& key) const {
  Field value = Get(key);
  if (!value.present()) value.Fail("is required");
  return value;
}

double MapReader::Number(const std::string& key, const Range& range) const {
  return Require(key).Number(range);
}

int MapReader::Integer(const std::string& key, const Range& range) const {
  return Require(key).Integer(range);
}

core::Vec3 MapReader::Vector(const std::string& key) const { return Require(key).Vector(); }

double MapReader::Number(const std::string& key, const Range& range, double fallback) const {
  return Has(key) ? Get(key).Number(range) : fallback;
}

int MapReader::Integer(const std::string& key, const Range& range, int fallback) const {
  return Has(key) ? Get(key).Integer(range) : fallback;
}

core::Vec3 MapReader::Vector(const std::string& key, const core::Vec3& fallback) const {
  return Has(key) ? Get(key).Vector() : fallback;
}

}  // namespace towsim::scene::internal
