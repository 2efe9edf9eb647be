#pragma once
// Minimal flag parsing for the controllers: --name value or --name=value. Every controller
// knows --help (Help()): it prints its usage on stdout and exits 0.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace towsim::controllers {

class Flags {
 public:
  // `known`: flag names taking a value; `switches`: flags without one (and --help); throws on
  // anything else
  Flags(int argc, char** argv, const std::vector<std::string>& known,
        const std::vector<std::string>& switches = {}) {
    for (int i = 1; i < argc; ++i) {
      std::string arg = argv[i], value;
      if (arg == "--help") {
        values_["help"] = "1";
        continue;
      }
      bool has_value = false;
      const auto eq = arg.find('=');
      if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
        value = arg.substr(eq + 1);
        arg = arg.substr(0, eq);
        has_value = true;
      }
      const std::string name = arg.rfind("--", 0) == 0 ? arg.substr(2) : "";
      if (Contains(switches, name) && !has_value) {
        values_[name] = "1";
      } else if (Contains(known, name)) {
        if (!has_value) {
          if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
          value = argv[++i];
        }
        values_[name] = value;
      } else {
        throw std::runtime_error("unknown option " + std::string(argv[i]));
      }
    }
  }
  bool Has(const std::string& name) const { return values_.count(name) > 0; }
  // --help was given: print the usage on stdout and exit 0, before reading anything else
  bool Help() const { return Has("help"); }
  std::string String(const std::string& name, const std::string& fallback) const {
    const auto it = values_.find(name);
    return it == values_.end() ? fallback : it->second;
  }
  // a finite number (nan and inf are refused: a controller would send them on)
  double Number(const std::string& name, double fallback) const {
    const auto it = values_.find(name);
    if (it == values_.end()) return fallback;
    char* end = nullptr;
    const double v = std::strtod(it->second.c_str(), &end);
    if (end == it->second.c_str() || *end != '\0') {
      throw std::runtime_error("--" + name + " " + it->second + ": not a number");
    }
    if (!std::isfinite(v)) {
      throw std::runtime_error("--" + name + " " + it->second + ": must be a finite number");
    }
    return v;
  }
  // a finite number with lo <= x <= hi (lo_open: lo < x); the rule is in the message
  double Number(const std::string& name, double fallback, double lo, double hi,
                bool lo_open = false) const {
    const double v = Number(name, fallback);
    if (!Has(name) || ((lo_open ? v > lo : v >= lo) && v <= hi)) return v;
    std::string rule = std::string("must be ") + (lo_open ? "> " : ">= ") + Format(lo);
    if (hi < std::numeric_limits<double>::max()) rule += " and <= " + Format(hi);
    throw std::runtime_error("--" + name + " " + String(name, "") + ": " + rule);
  }
  // a DDS domain id: an integer 0 to 232 (Cyclone's range; sim_node --domain checks the ports)
  uint32_t Domain(const std::string& name = "domain") const {
    const double v = Number(name, 0.0, 0.0, 232.0);
    if (v != static_cast<double>(static_cast<uint32_t>(v))) {
      throw std::runtime_error("--" + name + " " + String(name, "") + ": must be an integer");
    }
    return static_cast<uint32_t>(v);
  }

 private:
  static std::string Format(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
  }
  static bool Contains(const std::vector<std::string>& v, const std::string& s) {
    for (const auto& x : v) {
      if (x == s) return true;
    }
    return false;
  }
  std::map<std::string, std::string> values_;
};

}  // namespace towsim::controllers
