#include "app/dds_uri.h"

#include <cstdio>
#include <cstdlib>

namespace towsim::app {

std::string DdsUriFromEnvironment(const char* program) {
  const char* uri = std::getenv("CYCLONEDDS_URI");
  if (uri == nullptr || *uri == '\0') {
    std::fprintf(stderr,
                 "%s: warning: CYCLONEDDS_URI is not set: Cyclone DDS uses its defaults; the "
                 "project's loopback configuration is config/cyclonedds.xml\n",
                 program);
    return "";
  }
  return uri;
}

}  // namespace towsim::app
