#include "installed/installed_data.h"

#include <iterator>
#include <system_error>

namespace towsim::installed {

namespace fs = std::filesystem;

std::optional<fs::path> InstallPrefix(const fs::path& exe) {
  const fs::path dir = exe.parent_path();
  if (dir.filename() == "bin") return dir.parent_path();
  // P/libexec/towsim/<program>: the directory's last components are kPrivateProgramDir
  const fs::path private_dir(kPrivateProgramDir);
  fs::path prefix = dir;
  for (auto part = std::distance(private_dir.begin(), private_dir.end()); part > 0; --part) {
    prefix = prefix.parent_path();
  }
  if (!prefix.empty() && prefix / private_dir == dir) return prefix;
  return std::nullopt;
}

std::optional<fs::path> InstalledDataDir() {
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  // P/bin/<program> or P/libexec/towsim/<program> -> P/share/towsim
  const std::optional<fs::path> prefix = InstallPrefix(exe);
  if (!prefix) return std::nullopt;
  const fs::path data = *prefix / "share" / "towsim";
  if (!fs::is_directory(data, ec)) return std::nullopt;
  return data;
}

std::string ResolveInstalled(const std::string& name, const char* folder,
                             const std::optional<fs::path>& data_dir) {
  std::error_code ec;
  if (name.empty() || fs::exists(name, ec) || !data_dir) return name;
  const fs::path bare(name);
  if (bare.has_parent_path()) return name;
  for (const fs::path& candidate :
       {*data_dir / folder / bare, *data_dir / folder / (name + ".yaml")}) {
    if (fs::is_regular_file(candidate, ec)) return candidate.string();
  }
  return name;
}

std::string ResolveInstalled(const std::string& name, const char* folder) {
  return ResolveInstalled(name, folder, InstalledDataDir());
}

}  // namespace towsim::installed
