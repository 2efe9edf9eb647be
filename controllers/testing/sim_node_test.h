#pragma once
// The GoogleTest fixture for controller tests (docs/testing_controllers.md):
//
//   class MyControllerTest : public towsim::testing::SimNodeTest {};
//   TEST_F(MyControllerTest, ReachesTheHeading) {
//     SimNodeOptions o;
//     o.scene = "case1_forward";
//     o.duration = 60.0;
//     SimNode& node = StartNode(o);
//     StartController({"/path/to/my_controller", "--domain", std::to_string(node.domain())});
//     NodeResult end = node.Wait();
//     ...
//   }
//
// It owns the nodes and controller processes a test starts, stops them at the end of the test
// (whatever happens), and, if the test failed, prints each one's command line and log.

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testing/process.h"
#include "testing/sim_node.h"

namespace towsim::testing {

class SimNodeTest : public ::testing::Test {
 protected:
  // starts sim_node (see SimNode); throws std::runtime_error with the node's log if it does
  // not come up
  SimNode& StartNode(SimNodeOptions options);
  // starts a controller process with the node's CYCLONEDDS_URI in its environment; its stdout
  // and stderr go to <node log dir>/<name>.out / .err
  Process& StartController(const SimNode& node, std::vector<std::string> argv,
                           const std::string& name = "controller");

  void TearDown() override;

 private:
  std::vector<std::unique_ptr<SimNode>> nodes_;
  std::vector<std::unique_ptr<Process>> controllers_;
};

}  // namespace towsim::testing
