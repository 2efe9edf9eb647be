// dds_sim_node: sim_node with the DDS modes, for the integration tests until the sim_node
// executable calls RunDdsNode itself (then the tests run sim_node and this file goes). It
// takes the final command line of sim_node:
//
//   dds_sim_node --scene FILE [--mode realtime|fast|lockstep] [--duration S] [--rate R]
//                [--set key.path=value ...] [--domain N] [--namespace NS]
//
// --domain and --namespace are taken here; the rest goes through app/command_line.

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/dds_node.h"
#include "app/stop_signal.h"
#include "scene/scene_loader.h"

namespace {

bool ParseDomain(const std::string& text, uint32_t* domain) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const unsigned long d = std::strtoul(text.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || text[0] == '-' || d > 0xffffffffUL) return false;
  *domain = static_cast<uint32_t>(d);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using towsim::app::DdsNodeOptions;
  DdsNodeOptions dds;
  std::vector<const char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    std::string name = arg, value;
    bool has_value = false;
    if (const auto eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
      has_value = true;
    }
    if (name != "--domain" && name != "--namespace") {
      rest.push_back(argv[i]);
      continue;
    }
    if (!has_value) {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "sim_node: error: option %s needs a value\n", name.c_str());
        return 2;
      }
      value = argv[++i];
    }
    if (name == "--domain") {
      if (!ParseDomain(value, &dds.domain)) {
        std::fprintf(stderr, "sim_node: error: --domain %s: must be an integer >= 0\n",
                     value.c_str());
        return 2;
      }
    } else {
      dds.ns = value;
    }
  }
  const towsim::app::ParseResult parsed =
      towsim::app::ParseCommandLine(static_cast<int>(rest.size()), rest.data());
  if (!parsed.ok()) {
    std::fprintf(stderr, "sim_node: error: %s\n", parsed.error.c_str());
    return 2;
  }
  const towsim::app::Options& options = parsed.options;
  towsim::core::Model model;
  try {
    model = towsim::scene::LoadScene(options.scene, options.overrides);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sim_node: error: %s\n", e.what());
    return 2;
  }
  if (model.name.empty()) model.name = std::filesystem::path(options.scene).stem().string();
  dds.mode = options.mode;
  dds.duration = options.duration.value_or(model.time.duration);
  dds.rate = options.rate.value_or(1.0);
  towsim::app::InstallStopHandlers();
  try {
    return towsim::app::RunDdsNode(model, dds);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sim_node: error: %s\n", e.what());
    return 1;
  }
}
