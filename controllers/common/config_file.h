#pragma once
// YAML configuration files of the controllers (config/maneuvers/*.yaml,
// config/autopilot/*.yaml): a flat map of keys, each known to the reader. Errors name the key,
// the value, file:line and the rule, as the scene loader does:
//   rudder_dg = 10 (zigzag.yaml:4): unknown key (allowed: maneuver, body, ...)
// The controllers exit 2 on a ConfigError. `--config NAME` finds an installed file by bare
// name, as sim_node --scene does (installed/installed_data.h):
//   maneuver_runner --config zigzag_10_10  ->  P/share/towsim/maneuvers/zigzag_10_10.yaml

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace YAML {
class Node;
}

namespace towsim::controllers {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// a loaded map file: every top-level key must be in `allowed`
class ConfigFile {
 public:
  // throws ConfigError (unreadable file, YAML syntax, not a map, unknown key). With
  // `installed_folder` (installed::kManeuvers, kAutopilot), a bare name that is no file here
  // is looked up in P/share/towsim/<installed_folder> (installed::ResolveInstalled).
  ConfigFile(const std::string& path, const std::vector<std::string>& allowed,
             const char* installed_folder = nullptr);
  ~ConfigFile();
  ConfigFile(const ConfigFile&) = delete;
  ConfigFile& operator=(const ConfigFile&) = delete;

  bool Has(const std::string& key) const;
  // the value as a number / string / bool; throws ConfigError naming key, value, file:line
  double Number(const std::string& key) const;
  std::string String(const std::string& key) const;
  bool Bool(const std::string& key) const;
  // a list of numbers (e.g. [x, y]); `size` > 0 requires that many
  std::vector<double> Numbers(const std::string& key, size_t size = 0) const;
  // a list of maps, each read by `each(index, entry)`; entries' keys checked against `allowed`
  class Entry;
  void List(const std::string& key, const std::vector<std::string>& allowed,
            const std::function<void(size_t, const Entry&)>& each) const;
  // "key = value (file:line): rule" for the key's value
  ConfigError Error(const std::string& key, const std::string& rule) const;

  class Entry {
   public:
    Entry(const ConfigFile& file, const YAML::Node& node, const std::string& path);
    ~Entry();
    bool Has(const std::string& key) const;
    double Number(const std::string& key) const;
    ConfigError Error(const std::string& key, const std::string& rule) const;

   private:
    const ConfigFile& file_;
    struct Impl;
    Impl* impl_;
  };

 private:
  friend class Entry;
  std::string path_, name_;
  struct Impl;
  Impl* impl_;
};

}  // namespace towsim::controllers
