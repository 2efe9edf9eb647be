#include "testing/test_logs.h"

#include <cstdio>
#include <filesystem>
#include <mutex>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

namespace towsim::testing {
namespace {

// one gtest listener, appended on first use, that ends each test by removing or keeping its
// registered paths
class TestLogs : public ::testing::EmptyTestEventListener {
 public:
  static TestLogs& Get() {
    static TestLogs* const logs = [] {
      auto* l = new TestLogs;  // owned by gtest's listener list
      ::testing::UnitTest::GetInstance()->listeners().Append(l);
      return l;
    }();
    return *logs;
  }

  void Add(const std::string& path) {
    std::lock_guard<std::mutex> lock(mutex_);
    paths_.push_back(path);
  }

  void OnTestEnd(const ::testing::TestInfo& info) override {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const std::string& path : paths_) {
      std::error_code ec;
      if (!std::filesystem::exists(path, ec)) continue;
      if (info.result()->Failed()) {
        std::printf("[towsim] the logs of the failed test are kept in %s\n", path.c_str());
      } else {
        std::filesystem::remove_all(path, ec);
      }
    }
    paths_.clear();
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> paths_;
};

}  // namespace

void RemoveAfterPassingTest(const std::string& path) {
  if (::testing::UnitTest::GetInstance()->current_test_info() == nullptr) return;
  TestLogs::Get().Add(path);
}

}  // namespace towsim::testing
