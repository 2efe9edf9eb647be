#include "testing/in_process_controller.h"

#include <exception>
#include <utility>

#include "testing/sim_node.h"

namespace towsim::testing {

InProcessController::InProcessController(const SimNode& node, controllers::ClientOptions options,
                                         controllers::LockstepClient::Law law) {
  options.domain = static_cast<uint32_t>(node.domain());
  options.ns = node.ns();
  options.stop = &stop_;
  thread_ = std::thread([this, options, law = std::move(law)] {
    try {
      controllers::LockstepClient client(options);
      code_ = client.Run(law);
      steps_ = client.steps_answered();
    } catch (const std::exception& e) {
      error_ = e.what();
      code_ = 2;
    }
  });
}

InProcessController::~InProcessController() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

int InProcessController::Join() {
  if (thread_.joinable()) thread_.join();
  return code_;
}

}  // namespace towsim::testing
