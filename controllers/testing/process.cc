#include "testing/process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>
#include <utility>

#include <gtest/gtest.h>

#include "testing/test_logs.h"

namespace towsim::testing {

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string LogPrefix(const std::string& what) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string prefix =
      ::testing::TempDir() + "/towsim_" + info->test_suite_name() + "_" + info->name() + "_" + what;
  // the file itself (a test's results.yaml) or a Process's .out / .err
  for (const char* suffix : {"", ".out", ".err"}) RemoveAfterPassingTest(prefix + suffix);
  return prefix;
}

std::vector<std::string> SimNodeArgs(const std::string& program, const std::string& scene,
                                     const std::string& mode, int domain,
                                     const std::vector<std::string>& extra) {
  std::vector<std::string> argv = {
      program, "--scene", scene, "--mode", mode, "--domain", std::to_string(domain)};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return argv;
}

Process::Process(std::vector<std::string> argv, const std::string& log_prefix,
                 std::vector<std::string> env)
    : argv_(std::move(argv)), out_path_(log_prefix + ".out"), err_path_(log_prefix + ".err") {
  // emptied before the child runs: a wait for a line must never find one of an earlier run
  for (const std::string& path : {out_path_, err_path_}) {
    const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) close(fd);
  }
  pid_ = fork();
  if (pid_ == 0) {
    const int out = open(out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(err_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out >= 0) dup2(out, STDOUT_FILENO);
    if (err >= 0) dup2(err, STDERR_FILENO);
    for (const std::string& e : env) {
      const auto eq = e.find('=');
      setenv(e.substr(0, eq).c_str(), e.substr(eq + 1).c_str(), 1);
    }
    std::vector<char*> args;
    for (std::string& a : argv_) args.push_back(a.data());
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
}

Process::~Process() {
  if (pid_ > 0 && !exited_) {
    kill(pid_, SIGKILL);
    Wait(5.0);
  }
}

void Process::Signal(int signal) {
  if (pid_ > 0 && !exited_) kill(pid_, signal);
}

bool Process::Wait(double timeout) {
  if (exited_) return true;
  if (pid_ <= 0) return false;
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    int status = 0;
    const pid_t r = waitpid(pid_, &status, WNOHANG);
    if (r == pid_) {
      exited_ = true;
      exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      return true;
    }
    if (std::chrono::steady_clock::now() - start > std::chrono::duration<double>(timeout)) {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

bool Process::running() { return !Wait(0.0); }

std::string Process::out() const { return ReadFile(out_path_); }
std::string Process::err() const { return ReadFile(err_path_); }

std::string Process::command_line() const {
  std::string s;
  for (const std::string& a : argv_) s += (s.empty() ? "" : " ") + a;
  return s;
}

}  // namespace towsim::testing
