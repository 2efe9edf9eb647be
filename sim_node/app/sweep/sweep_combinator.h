#pragma once
// The cases of a sweep: its parameters' value lists combined (docs/sweeps.md "Combining").
//   product: every combination, the first parameter varying slowest (nested loops in file
//            order): parameters a: [1, 2], b: [x, y] give (1, x), (1, y), (2, x), (2, y)
//   zip:     the i-th values together; the lists have one length (the sweep file checks it)
// Case i is named case_<i> with at least 4 digits (case_0000, ...), the name of its folder.

#include <string>
#include <utility>
#include <vector>

#include "app/sweep/sweep_file.h"

namespace towsim::app {

struct SweepCase {
  int index = 0;
  std::string name;  // case_0007
  // (key path, value) per parameter, in file order; value in YAML flow style
  std::vector<std::pair<std::string, std::string>> values;

  // the --set arguments of sim_node: "path=value"
  std::vector<std::string> Overrides() const;
};

// Throws std::invalid_argument if the product has more than `max_cases` cases.
std::vector<SweepCase> CombineParameters(const std::vector<SweepParameter>& parameters,
                                         SweepCombine combine, long max_cases = 1000000);

// case_0007: `index` with max(4, digits of count - 1) digits
std::string CaseName(int index, int count);

}  // namespace towsim::app
