#include "scene/overrides.h"

#include <algorithm>

#include "scene/config_error.h"

namespace towsim::scene::internal {
namespace {

constexpr const char* kSet = "--set";

std::vector<std::string> SplitPath(const std::string& path) {
  std::vector<std::string> parts;
  size_t begin = 0;
  while (true) {
    const size_t dot = path.find('.', begin);
    parts.push_back(path.substr(begin, dot == std::string::npos ? std::string::npos : dot - begin));
    if (dot == std::string::npos) return parts;
    begin = dot + 1;
  }
}

// the value under the plain-name key `key` of map `map`; an undefined node if absent
YAML::Node FindChild(const YAML::Node& map, const std::string& key) {
  for (auto it = map.begin(); it != map.end(); ++it) {
    if (it->first.IsScalar() && it->first.Scalar() == key) return it->second;
  }
  return YAML::Node(YAML::NodeType::Undefined);
}

// map[key] = value, in place when the key exists (keeps the key order of the file)
void Assign(YAML::Node map, const std::string& key, const YAML::Node& value) {
  YAML::Node slot = FindChild(map, key);
  if (slot.IsDefined()) {
    slot = value;
  } else {
    map[key] = value;
  }
}

// comma-separated names of a map of named entries (bodies, cables), for error messages
std::string BodyList(const YAML::Node& bodies) {
  std::string list;
  if (!bodies.IsMap()) return "none";
  for (auto it = bodies.begin(); it != bodies.end(); ++it) {
    list += (list.empty() ? "" : ", ") + FormatNode(it->first);
  }
  return list.empty() ? "none" : list;
}

}  // namespace

void ApplyOverrides(const std::vector<std::string>& overrides, YAML::Node root, Source* scene) {
  for (const std::string& override_text : overrides) {
    // key.path=value
    const size_t equals = override_text.find('=');
    if (equals == std::string::npos) {
      throw ConfigError(override_text, "<missing>", kSet,
                        "must be key.path=value, e.g. cable.elements=40");
    }
    const std::string key = Trim(override_text.substr(0, equals));
    const std::string text = Trim(override_text.substr(equals + 1));
    const std::vector<std::string> parts = SplitPath(key);
    if (std::any_of(parts.begin(), parts.end(), [](const auto& p) { return p.empty(); })) {
      throw ConfigError(key, text, kSet,
                        "key path must be names joined by dots, e.g. cable.length");
    }

    // the value is YAML: 40, static, [0.5, 0, 0], {fixed: [0, 0, 10]}
    YAML::Node value;
    try {
      value = YAML::Load(text);
    } catch (const YAML::Exception& e) {
      throw ConfigError(key, text, kSet, "value is not valid YAML: " + e.msg);
    }

    // walk the schema and the tree together, creating missing maps
    YAML::Node node = root;
    MapKind kind = MapKind::kScene;
    std::string path;
    for (size_t i = 0; i < parts.size(); ++i) {
      const std::string& part = parts[i];
      const bool last = i + 1 == parts.size();
      const std::string parent = path.empty() ? "the scene" : path;
      path = JoinPath(path, part);
      // the key must be one the schema allows here
      if (kind == MapKind::kBodies) {
        if (!IsValidName(part)) {
          throw ConfigError(key, text, kSet, "body name " + part + " " + kNameRule);
        }
        // keys of a body need the body; a whole new body may be given as a map
        if (!last && !FindChild(node, part).IsDefined()) {
          throw ConfigError(
              key, text, kSet,
              "no body named " + part + " in the scene (bodies: " + BodyList(node) + ")");
        }
      } else if (kind == MapKind::kCables) {
        // cables.<name>.elements=40: the keys of a cable need the cable; a whole new cable may
        // be given as a map (cables.<name>={...})
        if (!IsValidName(part)) {
          throw ConfigError(key, text, kSet, "cable name " + part + " " + kNameRule);
        }
        if (!last && !FindChild(node, part).IsDefined()) {
          throw ConfigError(
              key, text, kSet,
              "no cable named " + part + " in the scene (cables: " + BodyList(node) + ")");
        }
      } else if (kind == MapKind::kLineTypes) {
        // a line type's keys may start a new type (its missing keys are then reported)
        if (!IsValidName(part)) {
          throw ConfigError(key, text, kSet, "line type name " + part + " " + kNameRule);
        }
      } else {
        const std::vector<std::string>& allowed = AllowedKeys(kind);
        if (std::find(allowed.begin(), allowed.end(), part) == allowed.end()) {
          throw ConfigError(key, text, kSet, parent + ": " + UnknownKeyRule(part, allowed));
        }
      }
      if (last) {
        Assign(node, part, value);
        scene->set_paths.insert(path);
        break;
      }
      // only maps of named keys can be walked into
      const std::optional<MapKind> child_kind = ChildMap(kind, part);
      if (!child_kind) {
        throw ConfigError(key, text, kSet,
                          path + " holds a value, not keys; set it whole: " + path + "=...");
      }
      YAML::Node child = FindChild(node, part);
      if (!child.IsDefined() || child.IsNull()) {
        Assign(node, part, YAML::Node(YAML::NodeType::Map));
        child.reset(FindChild(node, part));  // rebind (operator= would write the tree)
        scene->set_paths.insert(path);
      } else if (!child.IsMap()) {
        // the file holds a non-map value here: report it where the file has it
        const Field in_file(child, child.Mark(), path, std::make_shared<Source>(*scene));
        throw ConfigError(path, in_file.text(), in_file.location(),
                          "must be a map of keys to --set " + key);
      }
      node.reset(child);  // rebind the handle; operator= would overwrite the tree
      kind = *child_kind;
    }
  }
}

}  // namespace towsim::scene::internal
