#pragma once
// The one error the scene layer throws. Its message says where and why:
//   cable.elements = 0 (catenary.yaml:14): must be >= 1
// <location> is "<file>:<line>" (file basename, 1-based line), "<file>" when no line applies,
// or "--set" for a value given on the command line.

#include <stdexcept>
#include <string>

namespace towsim::scene {

class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string key, std::string value, std::string location, std::string rule);

  const std::string& key() const { return key_; }            // dotted key path, cable.start.fixed
  const std::string& value() const { return value_; }        // offending value, or <missing>
  const std::string& location() const { return location_; }  // file:line, or --set
  const std::string& rule() const { return rule_; }          // the rule that was broken

 private:
  std::string key_;
  std::string value_;
  std::string location_;
  std::string rule_;
};

}  // namespace towsim::scene
