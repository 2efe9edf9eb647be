// sim_node: the towsim simulation node (docs/contract.md §4-5). Parses the command line, loads the
// scene and runs it offline (no DDS) in this process; a DDS mode (realtime, fast, lockstep)
// runs in the DDS program sim_node_dds, which this process becomes (app/node/node_main.h), so an
// offline run loads no DDS library.

#include "app/node/node_main.h"

int main(int argc, char** argv) { return towsim::app::NodeMain(argc, argv, nullptr); }
