#include "common/config_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <yaml-cpp/yaml.h>

#include "installed/installed_data.h"

namespace towsim::controllers {
namespace {

std::string Join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string BaseName(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string Shown(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

ConfigError At(const std::string& key, const YAML::Node& value, const std::string& file,
               const std::string& rule) {
  return ConfigError(key + " = " + Shown(value) + " (" + file + ":" +
                     std::to_string(value.Mark().line + 1) + "): " + rule);
}

void CheckKeys(const YAML::Node& map, const std::vector<std::string>& allowed,
               const std::string& prefix, const std::string& file) {
  for (const auto& kv : map) {
    const std::string key = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw ConfigError(prefix + key + " = " + Shown(kv.second) + " (" + file + ":" +
                        std::to_string(kv.first.Mark().line + 1) +
                        "): unknown key (allowed: " + Join(allowed) + ")");
    }
  }
}

double ToNumber(const YAML::Node& n, const std::string& key, const std::string& file) {
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() && *end == '\0' && std::isfinite(v)) return v;
  }
  throw At(key, n, file, "must be a finite number");
}

}  // namespace

struct ConfigFile::Impl {
  YAML::Node root;
};

ConfigFile::ConfigFile(const std::string& name, const std::vector<std::string>& allowed,
                       const char* installed_folder)
    : path_(installed_folder ? installed::ResolveInstalled(name, installed_folder) : name),
      name_(BaseName(path_)),
      impl_(new Impl) {
  const std::string& path = path_;
  try {
    impl_->root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    delete impl_;
    throw ConfigError(path + ": cannot read the file");
  } catch (const YAML::Exception& e) {
    delete impl_;
    throw ConfigError(path + ":" + std::to_string(e.mark.line + 1) + ": YAML: " + e.msg);
  }
  if (!impl_->root.IsMap()) {
    delete impl_;
    throw ConfigError(path + ": must be a map of keys (allowed: " + Join(allowed) + ")");
  }
  try {
    CheckKeys(impl_->root, allowed, "", name_);
  } catch (...) {
    delete impl_;
    throw;
  }
}

ConfigFile::~ConfigFile() { delete impl_; }

bool ConfigFile::Has(const std::string& key) const { return bool(impl_->root[key]); }

double ConfigFile::Number(const std::string& key) const {
  return ToNumber(impl_->root[key], key, name_);
}

std::string ConfigFile::String(const std::string& key) const {
  const YAML::Node n = impl_->root[key];
  if (!n.IsScalar()) throw At(key, n, name_, "must be a string");
  return n.Scalar();
}

bool ConfigFile::Bool(const std::string& key) const {
  const YAML::Node n = impl_->root[key];
  if (n.IsScalar()) {
    if (n.Scalar() == "true") return true;
    if (n.Scalar() == "false") return false;
  }
  throw At(key, n, name_, "must be true or false");
}

std::vector<double> ConfigFile::Numbers(const std::string& key, size_t size) const {
  const YAML::Node n = impl_->root[key];
  if (!n.IsSequence() || (size > 0 && n.size() != size)) {
    throw At(key, n, name_,
             size > 0 ? "must be a list of " + std::to_string(size) + " numbers"
                      : "must be a list of numbers");
  }
  std::vector<double> v;
  for (size_t i = 0; i < n.size(); ++i) {
    v.push_back(ToNumber(n[i], key + "[" + std::to_string(i) + "]", name_));
  }
  return v;
}

ConfigError ConfigFile::Error(const std::string& key, const std::string& rule) const {
  return At(key, impl_->root[key], name_, rule);
}

struct ConfigFile::Entry::Impl {
  YAML::Node node;
  std::string path;
};

ConfigFile::Entry::Entry(const ConfigFile& file, const YAML::Node& node, const std::string& path)
    : file_(file), impl_(new Impl{node, path}) {}
ConfigFile::Entry::~Entry() { delete impl_; }

bool ConfigFile::Entry::Has(const std::string& key) const { return bool(impl_->node[key]); }

double ConfigFile::Entry::Number(const std::string& key) const {
  return ToNumber(impl_->node[key], impl_->path + "." + key, file_.name_);
}

ConfigError ConfigFile::Entry::Error(const std::string& key, const std::string& rule) const {
  return At(impl_->path + "." + key, impl_->node[key], file_.name_, rule);
}

void ConfigFile::List(const std::string& key, const std::vector<std::string>& allowed,
                      const std::function<void(size_t, const Entry&)>& each) const {
  const YAML::Node n = impl_->root[key];
  if (!n.IsSequence()) throw At(key, n, name_, "must be a list of maps");
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string path = key + "[" + std::to_string(i) + "]";
    if (!n[i].IsMap()) throw At(path, n[i], name_, "must be a map");
    CheckKeys(n[i], allowed, path + ".", name_);
    each(i, Entry(*this, n[i], path));
  }
}

}  // namespace towsim::controllers
