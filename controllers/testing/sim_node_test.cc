#include "testing/sim_node_test.h"

#include <signal.h>

#include <cstdio>
#include <utility>

namespace towsim::testing {

SimNode& SimNodeTest::StartNode(SimNodeOptions options) {
  nodes_.push_back(std::make_unique<SimNode>(std::move(options)));
  return *nodes_.back();
}

Process& SimNodeTest::StartController(const SimNode& node, std::vector<std::string> argv,
                                      const std::string& name) {
  controllers_.push_back(
      std::make_unique<Process>(std::move(argv), node.log_dir() + "/" + name,
                                std::vector<std::string>{"CYCLONEDDS_URI=" + node.dds_uri()}));
  return *controllers_.back();
}

void SimNodeTest::TearDown() {
  // controllers first (they end with the node's run; a hung one is stopped)
  for (auto& c : controllers_) {
    if (c->running()) {
      c->Signal(SIGTERM);
      c->Wait(5.0);
    }
  }
  if (HasFailure()) {
    for (const auto& n : nodes_) {
      std::printf("[towsim] sim_node log (%s):\n%s\n", n->log_dir().c_str(), n->log().c_str());
    }
    for (const auto& c : controllers_) {
      std::printf("[towsim] controller log:\n--- %s (exit %d, stdout) ---\n%s--- stderr ---\n%s\n",
                  c->command_line().c_str(), c->exit_code(), c->out().c_str(), c->err().c_str());
    }
  }
  controllers_.clear();
  nodes_.clear();
}

}  // namespace towsim::testing
