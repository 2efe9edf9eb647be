#pragma once
// Typed, located reads from a yaml-cpp tree. Every failed read throws ConfigError with the key
// path, the value as written, where it was written (file:line, or --set) and the rule.
// Private to the scene layer: the core and the app never see yaml-cpp.

#include <cstdint>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/constants.h"
#include "core/model.h"
#include "scene/scene_schema.h"

namespace towsim::scene::internal {

// One YAML document being read: the scene file or a vehicle model file.
struct Source {
  std::string name;                 // file name used in messages
  std::set<std::string> set_paths;  // key paths whose value (subtree) came from --set

  // true if `path` or a key above it was given by --set
  bool FromSet(const std::string& path) const;
};

// An interval a number must lie in; open or closed at each end.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Range Any() { return {}; }
  static Range Above(double lo) { return {lo, Range{}.hi, true, false}; }        // x > lo
  static Range AtLeast(double lo) { return {lo, Range{}.hi, false, false}; }     // x >= lo
  static Range AtMost(double hi) { return {Range{}.lo, hi, false, false}; }      // x <= hi
  static Range Closed(double lo, double hi) { return {lo, hi, false, false}; }   // lo <= x <= hi
  static Range LeftOpen(double lo, double hi) { return {lo, hi, true, false}; }  // lo < x <= hi
  static Range Open(double lo, double hi) { return {lo, hi, true, true}; }       // lo < x < hi

  // the broken rule ("must be >= 1"), or empty when x lies in the range
  std::string Violation(double x) const;
};

inline constexpr double kDegToRad = core::kPi / 180.0;  // values given in _deg
inline constexpr double kRadToDeg = 180.0 / core::kPi;

// `text` without leading and trailing blanks (spaces, tabs)
std::string Trim(const std::string& text);

// The largest scene or model file read [bytes] (docs/scene_format.md): a YAML tree takes
// hundreds of bytes per node, so a bigger file would cost gigabytes before any rule is checked.
inline constexpr std::uintmax_t kMaxTextFileBytes = 16u << 20;

// Reads the regular file at `path` (at most kMaxTextFileBytes) into `text`; false with the
// reason in `why` when it cannot (missing, a directory, a device or FIFO, too large).
bool ReadTextFile(const std::string& path, std::string* text, std::string* why);

// Parses `text` as exactly one YAML document (an empty text reads as null). A syntax error
// (value `value_if_invalid`) or a second document throws ConfigError(key, value,
// name_for_messages:line, rule).
YAML::Node LoadOneDocument(const std::string& text, const std::string& name_for_messages,
                           const std::string& key, const std::string& value_if_invalid);

// `yaml` parsed as one YAML document (LoadOneDocument) that must be a map of keys (a scene,
// a sweep file).
// Throws ConfigError: "<name> = <not YAML> (<name>:<line>): not valid YAML: ..." or, for a
// document that is not a map, the value and `not_a_map_rule`.
YAML::Node LoadYamlMap(const std::string& yaml, const std::string& name,
                       const std::string& not_a_map_rule);

// "a.b" from "a" and "b"; "b" when the parent is the root ("").
std::string JoinPath(const std::string& parent, const std::string& key);
// a number for messages: %g
std::string FormatNumber(double x);
// a vector for messages: [x, y, z]
std::string FormatVector(const core::Vec3& v);
// a YAML value for messages: scalars as written, collections in flow style (shortened)
std::string FormatNode(const YAML::Node& node);

// A value at a key path, present or not, with where it came from.
class Field {
 public:
  Field(YAML::Node node, YAML::Mark mark, std::string path, std::shared_ptr<const Source> source);
  // an absent key: value <missing>, location that of `parent`
  static Field Missing(std::string path, const Field& parent);
  // YAML::Node::operator= writes through to the tree; a Field rebinds instead
  Field(const Field& other) = default;
  Field& operator=(const Field& other);

  bool present() const { return present_; }
  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  const std::shared_ptr<const Source>& source() const { return source_; }
  std::string location() const;  // "file:line", "file", or "--set"
  std::string text() const;      // the value as written, or <missing>

  // throws ConfigError(path, text, location, rule)
  [[noreturn]] void Fail(const std::string& rule) const;

  // typed reads: each throws, naming the expected type, when the value does not fit
  double Number(const Range& range = Range::Any()) const;  // a finite number in range
  int Integer(const Range& range) const;                   // an integer in range
  bool Boolean() const;                                    // true or false
  std::string String() const;                              // any scalar, as text
  core::Vec3 Vector() const;                               // [x, y, z], finite numbers
  // one of `choices`; returns its index
  size_t Choice(const std::vector<std::string>& choices) const;
  // a list (null reads as empty); entries have paths "path[i]"
  std::vector<Field> Items() const;

 private:
  YAML::Node node_;
  YAML::Mark mark_;  // of the key for map entries, of the entry for list items
  std::string path_;
  std::shared_ptr<const Source> source_;
  bool present_ = true;
};

// A map whose keys have been checked: allowed for its kind, plain names, no duplicates.
// An absent field or a null value reads as an empty map.
class MapReader {
 public:
  MapReader(const Field& field, MapKind kind);

  const Field& field() const { return field_; }
  const std::vector<std::pair<std::string, Field>>& entries() const { return entries_; }
  bool Has(const std::string& key) const;
  Field Get(const std::string& key) const;      // Field::Missing when absent
  Field Require(const std::string& key) const;  // throws "is required" when absent

  // required values
  double Number(const std::string& key, const Range& range) const;
  int Integer(const std::string& key, const Range& range) const;
  core::Vec3 Vector(const std::string& key) const;
  // optional values: `fallback` when the key is absent
  double Number(const std::string& key, const Range& range, double fallback) const;
  int Integer(const std::string& key, const Range& range, int fallback) const;
  core::Vec3 Vector(const std::string& key, const core::Vec3& fallback) const;

 private:
  Field field_;
  std::vector<std::pair<std::string, Field>> entries_;  // document order
};

}  // namespace towsim::scene::internal
