#include "app/sweep/sweep_controllers.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

namespace towsim::app {
namespace {

namespace fs = std::filesystem;

// calls `on_text` for the literal pieces and `on_name` for each placeholder of `text`
void Scan(const std::string& text, const std::function<void(const std::string&)>& on_text,
          const std::function<void(const std::string&)>& on_name) {
  size_t at = 0;
  for (;;) {
    const size_t open = text.find("${", at);
    if (open == std::string::npos) {
      on_text(text.substr(at));
      return;
    }
    const size_t close = text.find('}', open + 2);
    if (close == std::string::npos) {
      throw std::invalid_argument("\"${\" without its \"}\" in " + text);
    }
    const std::string name = text.substr(open + 2, close - open - 2);
    if (name.empty()) throw std::invalid_argument("an empty placeholder ${} in " + text);
    on_text(text.substr(at, open - at));
    on_name(name);
    at = close + 1;
  }
}

// a parameter's value (YAML flow style, as --set takes it) as a controller's argument: a
// scalar's text without YAML's quotes ("\"20=3\"" -> 20=3), anything else as it is ([1, 2])
std::string ArgumentText(const std::string& flow) {
  try {
    const YAML::Node node = YAML::Load(flow);
    if (node.IsScalar()) return node.Scalar();
  } catch (const YAML::Exception&) {
  }
  return flow;
}

bool Executable(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0;
}

}  // namespace

std::vector<std::string> PlaceholderNames(const std::string& text) {
  std::vector<std::string> names;
  Scan(
      text, [](const std::string&) {}, [&](const std::string& n) { names.push_back(n); });
  return names;
}

std::string ExpandPlaceholders(
    const std::string& text,
    const std::function<std::optional<std::string>(const std::string& name)>& lookup) {
  std::string out;
  Scan(
      text, [&](const std::string& piece) { out += piece; },
      [&](const std::string& name) {
        const std::optional<std::string> value = lookup(name);
        out += value ? *value : "${" + name + "}";
      });
  return out;
}

std::vector<CaseController> CaseControllers(const SweepSpec& spec, const SweepCase& c,
                                            const std::string& case_dir,
                                            const std::vector<std::string>& programs) {
  const std::string dir = fs::absolute(case_dir).lexically_normal().string();
  auto lookup = [&](const std::string& name) -> std::optional<std::string> {
    if (name == "case") return c.name;
    if (name == "case_dir") return dir;
    for (const auto& [path, value] : c.values) {
      if (path == name) return ArgumentText(value);
    }
    return std::nullopt;  // ${domain}: when the case starts
  };
  std::vector<CaseController> out;
  for (size_t i = 0; i < spec.controllers.size(); ++i) {
    CaseController k;
    k.name = spec.controllers[i].name;
    k.program = programs.at(i);
    for (const std::string& a : spec.controllers[i].args) {
      k.args.push_back(ExpandPlaceholders(a, lookup));
    }
    out.push_back(std::move(k));
  }
  return out;
}

std::vector<std::string> WithDomain(const std::vector<std::string>& args, int domain) {
  std::vector<std::string> out;
  for (const std::string& a : args) {
    out.push_back(ExpandPlaceholders(a, [domain](const std::string& name) {
      return name == "domain" ? std::optional<std::string>(std::to_string(domain)) : std::nullopt;
    }));
  }
  return out;
}

std::string ResolveProgram(const std::string& program, const std::string& sweep_dir,
                           const std::string& self_dir, std::string* why) {
  if (program.find('/') != std::string::npos) {
    fs::path p(program);
    if (p.is_relative()) p = fs::path(sweep_dir) / p;
    p = fs::absolute(p).lexically_normal();
    if (Executable(p)) return p.string();
    *why = "no executable file " + p.string() + " (a path is relative to the sweep file)";
    return {};
  }
  std::vector<fs::path> tried;
  if (!self_dir.empty()) tried.push_back(fs::path(self_dir) / program);
  if (const char* path = std::getenv("PATH")) {
    const std::string dirs = path;
    size_t begin = 0;
    while (begin <= dirs.size()) {
      const size_t end = std::min(dirs.find(':', begin), dirs.size());
      if (end > begin) tried.push_back(fs::path(dirs.substr(begin, end - begin)) / program);
      begin = end + 1;
    }
  }
  for (const fs::path& p : tried) {
    if (Executable(p)) return fs::absolute(p).lexically_normal().string();
  }
  *why = "not found beside towsim_sweep (" + self_dir +
         ") nor on the PATH (a build tree: PATH=build/controllers:$PATH, or give its path)";
  return {};
}

}  // namespace towsim::app
