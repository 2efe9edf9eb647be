#include "app/installed_data.h"

#include <system_error>

namespace towsim::app {

namespace fs = std::filesystem;

std::optional<fs::path> InstalledDataDir() {
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  // P/bin/<program> -> P/share/towsim
  const fs::path data = exe.parent_path().parent_path() / "share" / "towsim";
  if (exe.parent_path().filename() != "bin" || !fs::is_directory(data, ec)) return std::nullopt;
  return data;
}

std::string ResolveScene(const std::string& scene, const std::optional<fs::path>& data_dir) {
  std::error_code ec;
  if (fs::exists(scene, ec) || !data_dir) return scene;
  const fs::path name(scene);
  if (name.has_parent_path()) return scene;
  for (const fs::path& candidate :
       {*data_dir / "scenes" / name, *data_dir / "scenes" / (scene + ".yaml")}) {
    if (fs::is_regular_file(candidate, ec)) return candidate.string();
  }
  return scene;
}

}  // namespace towsim::app
