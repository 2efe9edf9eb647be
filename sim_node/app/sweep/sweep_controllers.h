#pragma once
// The controllers of a sweep (docs/sweeps.md "Controllers"): their arguments with the
// placeholders ${NAME} substituted, and their programs found.
//
// Placeholders: ${<parameter key path>} the case's value of that parameter (a scalar's text
// without YAML's quotes: "20=3" gives 20=3; a list or map in flow style, as in results.csv),
// ${case} the case's name (case_0003), ${case_dir} its folder (absolute),
// ${domain} the DDS domain id the case runs on (known only when it starts). A controller whose
// arguments do not name ${domain} gets `--domain ${domain}` appended (every towsim controller
// takes --domain). No escape: every "${" opens a placeholder.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/sweep/sweep_combinator.h"
#include "app/sweep/sweep_file.h"

namespace towsim::app {

// the built-in placeholders, besides the parameters
inline const std::vector<std::string>& BuiltinPlaceholders() {
  static const std::vector<std::string> kNames = {"domain", "case", "case_dir"};
  return kNames;
}

// the names of the placeholders in `text`, in order; throws std::invalid_argument for a "${"
// without its "}" or with an empty name
std::vector<std::string> PlaceholderNames(const std::string& text);

// `text` with each ${NAME} replaced by lookup(NAME); a name lookup does not know (nullopt) is
// left as it is. Throws std::invalid_argument as PlaceholderNames.
std::string ExpandPlaceholders(
    const std::string& text,
    const std::function<std::optional<std::string>(const std::string& name)>& lookup);

// one controller of one case: the program found and its arguments, every placeholder but
// ${domain} substituted
struct CaseController {
  std::string name;
  std::string program;            // absolute path
  std::vector<std::string> args;  // may still hold ${domain}
};

// the controllers of case `c` (folder `case_dir`); `programs[i]` is controller i's program as
// ResolveProgram found it
std::vector<CaseController> CaseControllers(const SweepSpec& spec, const SweepCase& c,
                                            const std::string& case_dir,
                                            const std::vector<std::string>& programs);

// `args` with ${domain} replaced by `domain`
std::vector<std::string> WithDomain(const std::vector<std::string>& args, int domain);

// The program of a controller: a name with a '/' is a path relative to `sweep_dir` (or
// absolute); a bare name is looked for beside towsim_sweep (`self_dir`: an installed bin/
// holds every program), then on the PATH. Returns the absolute path of an executable file,
// or "" and the reason in `why`.
std::string ResolveProgram(const std::string& program, const std::string& sweep_dir,
                           const std::string& self_dir, std::string* why);

}  // namespace towsim::app
