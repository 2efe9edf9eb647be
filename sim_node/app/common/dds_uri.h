#pragma once
// The Cyclone DDS configuration of the DDS programs (sim_node, towsim_record, towsim_replay):
// what $CYCLONEDDS_URI holds. Without it Cyclone DDS uses its defaults (every interface,
// multicast), so the programs say so and point to the project's loopback configuration.

#include <string>

namespace towsim::app {

// $CYCLONEDDS_URI; if it is unset or empty, "" (Cyclone's defaults) and a warning on stderr
// that starts with `program`: "towsim_record: warning: CYCLONEDDS_URI is not set: ..."
std::string DdsUriFromEnvironment(const char* program);

}  // namespace towsim::app
