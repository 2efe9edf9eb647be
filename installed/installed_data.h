#pragma once
// Where an installed towsim keeps its configuration, one lookup for every program (sim_node,
// the tools and the controllers; docs/testing_controllers.md, "The installed package"):
// `cmake --install build --prefix P` and the Debian package put the programs in P/bin and the
// configuration in P/share/towsim:
//   P/share/towsim/scenes/*.yaml, vehicles/*.yaml, maneuvers/*.yaml, autopilot/*.yaml,
//   P/share/towsim/cyclonedds.xml (the loopback configuration for CYCLONEDDS_URI)
// A program finds its own prefix from its executable (/proc/self/exe), so a package
// installed anywhere (apt, a CI's temporary prefix) finds its files. The programs that only
// other programs run (sim_node's DDS program) live in P/libexec/towsim.
// The standard library only: sim_node/ and controllers/ both link it (towsim::installed).

#include <filesystem>
#include <optional>
#include <string>

namespace towsim::installed {

// the directory of the programs that only other programs run, under the prefix P (cmake/
// install.cmake installs them there)
inline constexpr const char* kPrivateProgramDir = "libexec/towsim";

// the folders of P/share/towsim that a program's option names a file of by bare name
inline constexpr const char* kScenes = "scenes";        // sim_node --scene
inline constexpr const char* kManeuvers = "maneuvers";  // maneuver_runner --config
inline constexpr const char* kAutopilot = "autopilot";  // autopilot --config

// the prefix P of an installed program `exe`: P/bin/<program> or P/libexec/towsim/<program>;
// nothing for any other place (a build tree)
std::optional<std::filesystem::path> InstallPrefix(const std::filesystem::path& exe);

// P/share/towsim when the running program is installed under P (InstallPrefix) and that
// directory exists; nothing when the program runs from a build tree
std::optional<std::filesystem::path> InstalledDataDir();

// the file that an option names: `name` itself if it exists; otherwise, for a bare name
// without a directory ("case1_forward" or "case1_forward.yaml"), the installed file
// <data>/<folder>/NAME[.yaml] if there is one (data: `data_dir`, folder: kScenes, ...);
// otherwise `name` unchanged (the reader then reports the missing file by the name given)
std::string ResolveInstalled(const std::string& name, const char* folder,
                             const std::optional<std::filesystem::path>& data_dir);

// ResolveInstalled in the running program's InstalledDataDir()
std::string ResolveInstalled(const std::string& name, const char* folder);

}  // namespace towsim::installed
