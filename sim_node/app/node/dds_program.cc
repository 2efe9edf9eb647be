#include "app/node/dds_program.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <system_error>

#include "app/common/exit_codes.h"
#include "installed/installed_data.h"

namespace towsim::app {

namespace fs = std::filesystem;

std::vector<fs::path> DdsProgramCandidates(const fs::path& exe) {
  std::vector<fs::path> candidates = {exe.parent_path() / kDdsProgramName};
  if (const std::optional<fs::path> prefix = installed::InstallPrefix(exe)) {
    const fs::path installed = *prefix / installed::kPrivateProgramDir / kDdsProgramName;
    if (installed != candidates.front()) candidates.push_back(installed);
  }
  return candidates;
}

int ExecDdsProgram(Mode mode, char** argv) {
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  if (ec) {
    std::fprintf(stderr,
                 "sim_node: error: --mode %s: cannot find this program (/proc/self/exe: %s)\n",
                 ModeName(mode), ec.message().c_str());
    return kExitError;
  }
  std::string looked;
  for (const fs::path& program : DdsProgramCandidates(exe)) {
    if (::access(program.c_str(), X_OK) == 0 && fs::is_regular_file(program, ec)) {
      ::execv(program.c_str(), argv);
      std::fprintf(stderr, "sim_node: error: --mode %s: cannot start %s: %s\n", ModeName(mode),
                   program.c_str(), std::strerror(errno));
      return kExitError;
    }
    looked += (looked.empty() ? "" : ", ") + program.string();
  }
  std::fprintf(
      stderr,
      "sim_node: error: --mode %s: the DDS modes run in %s, which is not installed (looked "
      "for %s); --mode offline needs no DDS\n",
      ModeName(mode), kDdsProgramName, looked.c_str());
  return kExitError;
}

}  // namespace towsim::app
