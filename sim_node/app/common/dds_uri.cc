#include "app/common/dds_uri.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "installed/installed_data.h"

namespace towsim::app {

std::string DdsUriFromEnvironment(const char* program) {
  const char* uri = std::getenv("CYCLONEDDS_URI");
  if (uri == nullptr || *uri == '\0') {
    // an installed program names the installed file (installed/installed_data.h)
    const std::optional<std::filesystem::path> data = installed::InstalledDataDir();
    const std::string config =
        data ? (*data / "cyclonedds.xml").string() : std::string("config/cyclonedds.xml");
    std::fprintf(stderr,
                 "%s: warning: CYCLONEDDS_URI is not set: Cyclone DDS uses its defaults; the "
                 "project's loopback configuration is %s\n",
                 program, config.c_str());
    return "";
  }
  return uri;
}

}  // namespace towsim::app
