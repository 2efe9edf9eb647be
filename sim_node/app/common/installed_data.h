#pragma once
// Where an installed towsim keeps its configuration (docs/testing_controllers.md, "The
// installed package"): `cmake --install build --prefix P` and the Debian package put the
// programs in P/bin and the configuration in P/share/towsim:
//   P/share/towsim/scenes/*.yaml, vehicles/*.yaml, maneuvers/*.yaml, autopilot/*.yaml,
//   P/share/towsim/cyclonedds.xml (the loopback configuration for CYCLONEDDS_URI)
// A program finds its own prefix from its executable (/proc/self/exe), so a package
// installed anywhere (apt, a CI's temporary prefix) finds its scenes. The programs that only
// other programs run (sim_node's DDS program, app/node/dds_program.h) live in P/libexec/towsim.

#include <filesystem>
#include <optional>
#include <string>

namespace towsim::app {

// the directory of the programs that only other programs run, under the prefix P (cmake/
// install.cmake installs them there)
inline constexpr const char* kPrivateProgramDir = "libexec/towsim";

// the prefix P of an installed program `exe`: P/bin/<program> or P/libexec/towsim/<program>;
// nothing for any other place (a build tree)
std::optional<std::filesystem::path> InstallPrefix(const std::filesystem::path& exe);

// P/share/towsim when the running program is installed under P (InstallPrefix) and that
// directory exists; nothing when the program runs from a build tree
std::optional<std::filesystem::path> InstalledDataDir();

// the scene file that `--scene` names: `scene` itself if it exists; otherwise, for a bare name
// without a directory ("case1_forward" or "case1_forward.yaml"), the installed scene
// <data>/scenes/NAME[.yaml] if there is one (data: `data_dir`); otherwise `scene` unchanged
// (the scene loader then reports the missing file by the name given)
std::string ResolveScene(const std::string& scene,
                         const std::optional<std::filesystem::path>& data_dir);

}  // namespace towsim::app
