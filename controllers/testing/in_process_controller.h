#pragma once
// A controller under test run in the test's own process through the client library
// (common/client.h): a LockstepClient on its own thread, started after the node is up. The
// law runs on that thread; read what it recorded after Join().

#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "common/client.h"

namespace towsim::testing {

class SimNode;

class InProcessController {
 public:
  // connects to `node` (its domain and namespace) as `body`'s controller and runs `law` until
  // the end of the node's run; `options.domain` and `options.ns` are taken from the node
  InProcessController(const SimNode& node, controllers::ClientOptions options,
                      controllers::LockstepClient::Law law);
  // joins; a controller still running (a test that ended early) is stopped first
  ~InProcessController();
  InProcessController(const InProcessController&) = delete;
  InProcessController& operator=(const InProcessController&) = delete;

  // waits for the end of the run; the client's exit code (0: the node's run ended, 1: timeout
  // or DDS error, 2: the client could not start, error() says why)
  int Join();
  const std::string& error() const { return error_; }
  uint64_t steps_answered() const { return steps_; }

 private:
  std::atomic<bool> stop_{false};
  std::thread thread_;
  int code_ = -1;
  uint64_t steps_ = 0;
  std::string error_;
};

}  // namespace towsim::testing
