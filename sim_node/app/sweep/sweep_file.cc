#include "app/sweep/sweep_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>

#include <yaml-cpp/yaml.h>

#include "app/sweep/sweep_controllers.h"
#include "app/sweep/sweep_values.h"
#include "scene/config_error.h"
#include "scene/overrides.h"
#include "scene/scene_schema.h"
#include "scene/yaml_reader.h"

namespace towsim::app {
namespace {

// the scene reader's YAML fields, key-path errors and overrides (scene/yaml_reader.h)
using scene::ConfigError;
using scene::internal::ApplyOverrides;
using scene::internal::Field;
using scene::internal::FormatNode;
using scene::internal::IsValidName;
using scene::internal::JoinPath;
using scene::internal::kNameRule;
using scene::internal::LoadYamlMap;
using scene::internal::Range;
using scene::internal::ReadTextFile;
using scene::internal::Source;
using scene::internal::Trim;
using scene::internal::UnknownKeyRule;

constexpr const char* kValuesRule =
    "must be a list of values, a range {from, to, step} or {from, to, count}, or seeded draws "
    "{random: uniform|normal|integer, ..., count, seed}";
constexpr double kTwoTo53 = 9007199254740992.0;  // integers below it are exact in a double
// the columns of results.csv before the parameters (docs/sweeps.md)
const std::vector<std::string> kFixedColumns = {"case", "status", "exit_code", "message", "wall_s"};

// a YAML value as one line of flow style, complete ("[3, 0, 0]", "{fixed: [0, 0, 5]}")
std::string FlowText(const YAML::Node& node) {
  if (node.IsNull()) return "null";
  if (node.IsScalar()) return node.Tag() == "!" ? "\"" + node.Scalar() + "\"" : node.Scalar();
  YAML::Emitter out;
  out.SetMapFormat(YAML::Flow);
  out.SetSeqFormat(YAML::Flow);
  out << node;
  return out.c_str();
}

// the entries of a map whose keys the user names: plain, each once; `what` names them
std::vector<std::pair<std::string, Field>> NamedEntries(const Field& map, const char* what) {
  std::vector<std::pair<std::string, Field>> entries;
  if (!map.present() || map.node().IsNull()) return entries;
  if (!map.node().IsMap()) map.Fail(std::string("must be a map of ") + what);
  for (auto it = map.node().begin(); it != map.node().end(); ++it) {
    const YAML::Node key = it->first;
    const std::string name = key.IsScalar() ? key.Scalar() : FormatNode(key);
    Field entry(it->second, key.Mark(), JoinPath(map.path(), name), map.source());
    if (!key.IsScalar()) entry.Fail("keys must be plain names");
    for (const auto& [seen, first] : entries) {
      if (seen == name) entry.Fail("duplicate key (first given at " + first.location() + ")");
    }
    entries.emplace_back(name, std::move(entry));
  }
  return entries;
}

// a map of fixed keys: `allowed` only, each once
std::vector<std::pair<std::string, Field>> CheckedEntries(const Field& map,
                                                          const std::vector<std::string>& allowed) {
  std::vector<std::pair<std::string, Field>> entries = NamedEntries(map, "keys");
  for (const auto& [name, entry] : entries) {
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
      entry.Fail(UnknownKeyRule(name, allowed));
    }
  }
  return entries;
}

Field Get(const std::vector<std::pair<std::string, Field>>& entries, const std::string& key,
          const Field& parent) {
  for (const auto& [name, entry] : entries) {
    if (name == key) return entry;
  }
  return Field::Missing(JoinPath(parent.path(), key), parent);
}

bool IsIntegerText(const Field& f) {
  if (!f.node().IsScalar()) return false;
  std::string text = f.node().Scalar();
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) text.erase(0, 1);
  return !text.empty() && std::all_of(text.begin(), text.end(), ::isdigit);
}

std::vector<std::string> Formatted(const std::vector<double>& values, bool integers) {
  std::vector<std::string> texts;
  for (double v : values) {
    texts.push_back(integers ? std::to_string(static_cast<long long>(std::llround(v)))
                             : FormatSweepNumber(v));
  }
  return texts;
}

// {from, to, step} or {from, to, count}
std::vector<std::string> ReadRange(const Field& field) {
  const auto entries = CheckedEntries(field, {"from", "to", "step", "count"});
  const Field from = Get(entries, "from", field);
  const Field to = Get(entries, "to", field);
  const Field step = Get(entries, "step", field);
  const Field count = Get(entries, "count", field);
  const double a = from.Number();
  const double b = to.Number();
  if (step.present() == count.present()) {
    field.Fail("a range needs exactly one of step and count");
  }
  if (count.present()) {
    const int n = count.Integer(Range::Closed(1, 1e6));
    if (n == 1 && a != b) count.Fail("must be >= 2 when from != to");
    return Formatted(LinspaceValues(a, b, n), false);
  }
  const double s = step.Number();
  if (s == 0.0) step.Fail("must not be 0");
  if ((b - a) * s < 0.0) step.Fail("must point from `from` towards `to`");
  if ((b - a) / s > 1e6) step.Fail("gives more than 1e6 values");
  const bool integers = IsIntegerText(from) && IsIntegerText(to) && IsIntegerText(step);
  if (integers) {
    // an integer is exact in a double up to 2^53; beyond, neighbours merge and llround overflows
    for (const Field* f : {&from, &to, &step}) {
      if (std::fabs(f->Number()) >= kTwoTo53) {
        f->Fail(
            "an integer range must lie within -(2^53 - 1) .. 2^53 - 1 = 9007199254740991 "
            "(exact in a double)");
      }
    }
  }
  return Formatted(RangeValues(a, b, s), integers);
}

// {random: uniform|normal|integer, low/high or mean/stddev, count, seed}
std::vector<std::string> ReadDraws(const Field& field) {
  const auto entries =
      CheckedEntries(field, {"random", "low", "high", "mean", "stddev", "count", "seed"});
  const Field kind = Get(entries, "random", field);
  const size_t k = kind.Choice({"uniform", "normal", "integer"});
  const int count = Get(entries, "count", field).Integer(Range::Closed(1, 1e6));
  const Field seed_field = Get(entries, "seed", field);
  if (!seed_field.present()) seed_field.Fail("is required: every draw is seeded (reproducible)");
  const auto seed = static_cast<std::uint64_t>(seed_field.Integer(Range::Closed(0, 2147483647)));
  // only the keys of this kind
  const std::vector<std::string> own =
      k == 1 ? std::vector<std::string>{"mean", "stddev"} : std::vector<std::string>{"low", "high"};
  for (const auto& [name, entry] : entries) {
    if (name == "random" || name == "count" || name == "seed") continue;
    if (std::find(own.begin(), own.end(), name) == own.end()) {
      entry.Fail("not a key of random: " + kind.String() + " (it takes " + own[0] + ", " + own[1] +
                 ", count, seed)");
    }
  }
  if (k == 1) {
    const double mean = Get(entries, "mean", field).Number();
    const double stddev = Get(entries, "stddev", field).Number(Range::AtLeast(0.0));
    return Formatted(NormalDraws(mean, stddev, count, seed), false);
  }
  const Field low = Get(entries, "low", field);
  const Field high = Get(entries, "high", field);
  if (k == 2) {
    const int lo = low.Integer(Range::Closed(-2147483647.0, 2147483647.0));
    const int hi = high.Integer(Range::Closed(lo, 2147483647.0));
    std::vector<std::string> texts;
    for (long long v : IntegerDraws(lo, hi, count, seed)) texts.push_back(std::to_string(v));
    return texts;
  }
  const double lo = low.Number();
  const double hi = high.Number(Range::Above(lo));
  return Formatted(UniformDraws(lo, hi, count, seed), false);
}

SweepParameter ReadParameter(const std::string& path, const Field& field) {
  SweepParameter p;
  p.path = path;
  p.location = field.location();
  if (path.empty() || path.front() == '.' || path.back() == '.' ||
      path.find("..") != std::string::npos) {
    field.Fail("key path must be names joined by dots, e.g. cable.length");
  }
  const YAML::Node& node = field.node();
  if (node.IsSequence()) {
    if (node.size() == 0) field.Fail("must list at least one value");
    for (size_t i = 0; i < node.size(); ++i) p.values.push_back(FlowText(node[i]));
  } else if (node.IsMap()) {
    p.values = node["random"] ? ReadDraws(field) : ReadRange(field);
  } else {
    field.Fail(kValuesRule);
  }
  return p;
}

SweepResult ReadResult(const std::string& name, const Field& field) {
  if (!IsValidName(name)) field.Fail(std::string("result names ") + kNameRule);
  if (std::find(kFixedColumns.begin(), kFixedColumns.end(), name) != kFixedColumns.end()) {
    field.Fail("is a column of results.csv already; choose another name");
  }
  SweepResult r;
  r.name = name;
  r.location = field.location();
  if (!field.node().IsMap()) field.Fail("must be a map {signal: S, stat: final|max|...}");
  const auto entries = CheckedEntries(field, {"signal", "stat", "from", "to", "settled"});
  r.signal = Trim(Get(entries, "signal", field).String());
  if (r.signal.empty()) Get(entries, "signal", field).Fail("must name a signal");
  const Field stat = Get(entries, "stat", field);
  if (stat.present()) r.stat = SweepStats()[stat.Choice(SweepStats())];
  const Field from = Get(entries, "from", field);
  const Field to = Get(entries, "to", field);
  if (from.present()) r.from = from.Number(Range::AtLeast(0.0));
  if (to.present()) r.to = to.Number(Range::Above(r.from.value_or(0.0)));
  const Field settled = Get(entries, "settled", field);
  if (settled.present()) {
    if (!settled.node().IsMap()) {
      settled.Fail(
          "must be a map {window: W, tolerance: T}: the signal settled when its change "
          "(max - min) over the final W seconds is below T");
    }
    const auto keys = CheckedEntries(settled, {"window", "tolerance"});
    SweepSettled s;
    s.window = Get(keys, "window", settled).Number(Range::Above(0.0));
    s.tolerance = Get(keys, "tolerance", settled).Number(Range::Above(0.0));
    r.settled = s;
  }
  return r;
}

// `controllers`: a list of {program, args, name}
std::vector<SweepController> ReadControllers(const Field& list) {
  std::vector<SweepController> out;
  if (!list.node().IsSequence() || list.node().size() == 0) {
    list.Fail("must be a list of controllers, each {program: P, args: [...], name: N}");
  }
  for (const Field& item : list.Items()) {
    if (!item.node().IsMap()) item.Fail("must be a map {program: P, args: [...], name: N}");
    const auto keys = CheckedEntries(item, {"program", "args", "name"});
    SweepController k;
    k.location = item.location();
    const Field program = Get(keys, "program", item);
    if (!program.present()) program.Fail("is required: the controller's executable");
    k.program = Trim(program.String());
    if (k.program.empty()) program.Fail("must name an executable");
    const Field name = Get(keys, "name", item);
    k.name = name.present() ? name.String() : std::filesystem::path(k.program).filename().string();
    if (!IsValidName(k.name)) {
      (name.present() ? name : program)
          .Fail(std::string("a controller's name ") + kNameRule + " (give one with name:)");
    }
    if (k.name == "sim_node") {
      (name.present() ? name : program).Fail("sim_node's logs have this name; give another name:");
    }
    for (const SweepController& seen : out) {
      if (seen.name == k.name) {
        (name.present() ? name : program)
            .Fail("a second controller named " + k.name + " (first at " + seen.location +
                  "); give each its own name:");
      }
    }
    const Field args = Get(keys, "args", item);
    if (args.present() && !args.node().IsNull()) {
      if (!args.node().IsSequence()) args.Fail("must be a list of arguments");
      for (const Field& a : args.Items()) {
        if (!a.node().IsScalar()) a.Fail("an argument must be a scalar (quote it)");
        const std::string text = a.node().Scalar();
        if (text.find('\n') != std::string::npos) a.Fail("an argument must be one line");
        try {
          PlaceholderNames(text);
        } catch (const std::invalid_argument& e) {
          a.Fail(e.what());
        }
        k.args.push_back(text);
      }
    }
    out.push_back(std::move(k));
  }
  return out;
}

// the placeholders every controller argument names exist: parameters or built-ins
void CheckPlaceholders(const Field& list, const SweepSpec& spec) {
  const std::vector<Field> items = list.Items();
  for (size_t i = 0; i < spec.controllers.size(); ++i) {
    const auto keys = CheckedEntries(items[i], {"program", "args", "name"});
    const Field args = Get(keys, "args", items[i]);
    const std::vector<Field> arg_fields =
        args.present() && !args.node().IsNull() ? args.Items() : std::vector<Field>{};
    for (size_t j = 0; j < spec.controllers[i].args.size(); ++j) {
      for (const std::string& name : PlaceholderNames(spec.controllers[i].args[j])) {
        bool known = false;
        for (const std::string& b : BuiltinPlaceholders()) known = known || b == name;
        for (const SweepParameter& p : spec.parameters) known = known || p.path == name;
        if (!known) {
          std::string names;
          for (const SweepParameter& p : spec.parameters) names += p.path + ", ";
          arg_fields[j].Fail("${" + name +
                             "} names no parameter; the placeholders are the "
                             "parameters (" +
                             names + "...) and domain, case, case_dir");
        }
      }
    }
  }
}

// the key path must be one sim_node's --set accepts for this scene (same code: ApplyOverrides)
void CheckAgainstScene(const SweepSpec& spec, const std::string& scene_location,
                       const std::vector<Field>& fields) {
  std::string text;
  std::string why;
  if (!ReadTextFile(spec.scene, &text, &why)) {
    throw ConfigError("scene", spec.scene, scene_location,
                      "cannot read the scene file (" + why +
                          "; the path is relative to the "
                          "sweep file)");
  }
  YAML::Node root;
  try {
    root = LoadYamlMap(text, spec.scene, "a scene must be a map of keys");
  } catch (const ConfigError& e) {
    throw ConfigError("scene", spec.scene, scene_location, e.what());
  }
  for (size_t i = 0; i < spec.parameters.size(); ++i) {
    const SweepParameter& p = spec.parameters[i];
    if (p.controllers_only) continue;
    Source source;
    source.name = std::filesystem::path(spec.scene).filename().string();
    try {
      ApplyOverrides({p.path + "=" + p.values.front()}, root, &source);
    } catch (const ConfigError& e) {
      std::string rule = e.rule();
      if (!spec.controllers.empty() && p.path.find('.') == std::string::npos) {
        rule +=
            " (a parameter of the controllers only is named in their args as ${" + p.path + "})";
      }
      fields[i].Fail(rule);
    }
  }
}

}  // namespace

const std::vector<std::string>& SweepStats() {
  static const std::vector<std::string> kStats = {"final",   "initial", "min", "max",
                                                  "max_abs", "mean",    "rms", "std"};
  return kStats;
}

SweepSpec LoadSweepFile(const std::string& path) {
  std::string text;
  std::string why;
  if (!ReadTextFile(path, &text, &why)) {
    throw ConfigError("sweep", path, path, "cannot read the sweep file (" + why + ")");
  }
  const std::filesystem::path file(path);
  const std::string base_dir = file.has_parent_path() ? file.parent_path().string() : ".";
  return LoadSweepFromString(text, file.filename().string(), base_dir);
}

SweepSpec LoadSweepFromString(const std::string& yaml, const std::string& name_for_messages,
                              const std::string& base_dir) {
  auto source = std::make_shared<Source>();
  source->name = name_for_messages;
  const YAML::Node root = LoadYamlMap(
      yaml, name_for_messages,
      "a sweep file must be a map of keys (scene, duration, combine, parameters, results, "
      "controllers, domain, lockstep_timeout)");
  const Field top(root, root.Mark(), "", source);
  const auto entries = CheckedEntries(top, {"scene", "duration", "combine", "parameters", "results",
                                            "controllers", "domain", "lockstep_timeout"});

  SweepSpec spec;
  spec.name = name_for_messages;
  spec.base_dir = base_dir;
  const Field scene = Get(entries, "scene", top);
  const std::filesystem::path scene_path(scene.String());
  spec.scene = scene_path.is_absolute() ? scene_path.string()
                                        : (std::filesystem::path(base_dir) / scene_path).string();
  const Field duration = Get(entries, "duration", top);
  if (duration.present()) spec.duration = duration.Number(Range::AtLeast(0.0));
  const Field combine = Get(entries, "combine", top);
  if (combine.present()) {
    spec.combine =
        combine.Choice({"product", "zip"}) == 0 ? SweepCombine::kProduct : SweepCombine::kZip;
  }

  const Field parameters = Get(entries, "parameters", top);
  if (!parameters.present()) parameters.Fail("is required: a map of scene key paths to values");
  std::vector<Field> parameter_fields;
  for (const auto& [path, field] : NamedEntries(parameters, "scene key paths to values")) {
    spec.parameters.push_back(ReadParameter(path, field));
    parameter_fields.push_back(field);
  }
  if (spec.parameters.empty()) parameters.Fail("must name at least one parameter");
  if (spec.combine == SweepCombine::kZip) {
    const size_t n = spec.parameters.front().values.size();
    for (size_t i = 1; i < spec.parameters.size(); ++i) {
      if (spec.parameters[i].values.size() != n) {
        parameter_fields[i].Fail("has " + std::to_string(spec.parameters[i].values.size()) +
                                 " values, " + spec.parameters.front().path + " has " +
                                 std::to_string(n) + ": combine: zip needs lists of one length");
      }
    }
  }

  // the controllers, and what only they need
  const Field controllers = Get(entries, "controllers", top);
  const Field domain = Get(entries, "domain", top);
  const Field lockstep_timeout = Get(entries, "lockstep_timeout", top);
  if (controllers.present()) {
    spec.controllers = ReadControllers(controllers);
    if (!duration.present()) {
      controllers.Fail(
          "need duration: (a DDS node runs until stopped; a case runs `duration` "
          "seconds of simulated time)");
    }
  } else {
    for (const Field* f : {&domain, &lockstep_timeout}) {
      if (f->present()) {
        f->Fail("needs controllers: (cases without controllers run offline, without DDS)");
      }
    }
  }
  if (domain.present()) {
    spec.domain = domain.Integer(Range::Closed(0, kMaxSweepDomain));
    spec.domain_location = domain.location();
  }
  if (lockstep_timeout.present())
    spec.lockstep_timeout = lockstep_timeout.Number(Range::AtLeast(0));
  for (size_t i = 0; i < spec.parameters.size(); ++i) {
    SweepParameter& p = spec.parameters[i];
    for (const std::string& b : BuiltinPlaceholders()) {
      if (p.path == b && !spec.controllers.empty()) {
        parameter_fields[i].Fail("is a placeholder of its own (${" + b + "}); choose another name");
      }
    }
    if (p.path.find('.') != std::string::npos) continue;  // a scene key path
    for (const SweepController& k : spec.controllers) {
      for (const std::string& a : k.args) {
        for (const std::string& name : PlaceholderNames(a)) {
          p.controllers_only = p.controllers_only || name == p.path;
        }
      }
    }
  }
  if (controllers.present()) CheckPlaceholders(controllers, spec);
  // every controller is told the case's domain
  for (SweepController& k : spec.controllers) {
    bool named = false;
    for (const std::string& a : k.args) {
      for (const std::string& name : PlaceholderNames(a)) named = named || name == "domain";
    }
    if (!named) k.args.insert(k.args.end(), {"--domain", "${domain}"});
  }

  for (const auto& [name, field] : NamedEntries(Get(entries, "results", top), "result names")) {
    for (const SweepParameter& p : spec.parameters) {
      if (p.path == name) field.Fail("is the name of a parameter column; choose another name");
    }
    spec.results.push_back(ReadResult(name, field));
  }

  CheckAgainstScene(spec, scene.location(), parameter_fields);
  return spec;
}

}  // namespace towsim::app
