#pragma once
// Child processes for the integration tests: started with fork + exec, stdout and stderr to
// files, waited for with a timeout, stopped by their own pid only; their command lines and
// log paths.

#include <sys/types.h>

#include <string>
#include <vector>

namespace towsim::testing {

class Process {
 public:
  // starts argv[0] with argv; stdout and stderr go to `log_prefix`.out / .err; `env` entries
  // ("NAME=value") are set in the child on top of the test's environment
  Process(std::vector<std::string> argv, const std::string& log_prefix,
          std::vector<std::string> env = {});
  ~Process();  // kills the child (SIGKILL) if it still runs
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;

  pid_t pid() const { return pid_; }
  // sends `signal` to the child
  void Signal(int signal);
  // waits up to `timeout` [s]; true if it exited (exit_code() valid)
  bool Wait(double timeout);
  bool running();
  // the exit status: the code, or 128 + signal if a signal ended it
  int exit_code() const { return exit_code_; }
  std::string out() const;
  std::string err() const;
  std::string command_line() const;

 private:
  std::vector<std::string> argv_;
  std::string out_path_, err_path_;
  pid_t pid_ = -1;
  bool exited_ = false;
  int exit_code_ = -1;
};

std::string ReadFile(const std::string& path);

// a log path prefix for a child of the running GoogleTest test, unique to that test:
// TempDir()/towsim_<suite>_<test>_<what> (Process adds .out / .err); the file itself and its
// .out / .err are removed at the end of a passing test, kept after a failing one
// (testing/test_logs.h)
std::string LogPrefix(const std::string& what);

// the command line `program --scene S --mode M --domain N` followed by `extra`, for sim_node
// in a DDS mode (README.md, "Command line")
std::vector<std::string> SimNodeArgs(const std::string& program, const std::string& scene,
                                     const std::string& mode, int domain,
                                     const std::vector<std::string>& extra = {});

}  // namespace towsim::testing
