#pragma once
// The error an output file throws when its bytes cannot be written (disk full, quota, I/O
// error): the file was opened but the data did not reach it. sim_node and the tools exit 1
// on it (docs/command_line.md "Exit codes"), whereas a path that cannot be opened is bad
// input (exit 2).

#include <stdexcept>
#include <string>

namespace towsim::io {

class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace towsim::io
