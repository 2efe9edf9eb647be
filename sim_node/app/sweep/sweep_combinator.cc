#include "app/sweep/sweep_combinator.h"

#include <algorithm>
#include <stdexcept>

namespace towsim::app {

std::vector<std::string> SweepCase::Overrides() const {
  std::vector<std::string> sets;
  for (const auto& [path, value] : values) sets.push_back(path + "=" + value);
  return sets;
}

std::string CaseName(int index, int count) {
  const size_t width = std::max<size_t>(4, std::to_string(std::max(0, count - 1)).size());
  std::string digits = std::to_string(index);
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  return "case_" + digits;
}

std::vector<SweepCase> CombineParameters(const std::vector<SweepParameter>& parameters,
                                         SweepCombine combine, long max_cases) {
  // the number of cases
  long count = parameters.empty() ? 0 : 1;
  if (combine == SweepCombine::kZip) {
    count = parameters.empty() ? 0 : static_cast<long>(parameters.front().values.size());
  } else {
    for (const SweepParameter& p : parameters) {
      count *= static_cast<long>(p.values.size());
      if (count > max_cases) {
        throw std::invalid_argument("the product of the parameters' values has more than " +
                                    std::to_string(max_cases) + " cases");
      }
    }
  }
  std::vector<SweepCase> cases(static_cast<size_t>(count));
  for (long i = 0; i < count; ++i) {
    SweepCase& c = cases[static_cast<size_t>(i)];
    c.index = static_cast<int>(i);
    c.name = CaseName(c.index, static_cast<int>(count));
    // product: i in mixed radix, the last parameter the fastest digit
    std::vector<size_t> pick(parameters.size(), static_cast<size_t>(i));
    if (combine == SweepCombine::kProduct) {
      long rest = i;
      for (size_t k = parameters.size(); k-- > 0;) {
        const long n = static_cast<long>(parameters[k].values.size());
        pick[k] = static_cast<size_t>(rest % n);
        rest /= n;
      }
    }
    for (size_t k = 0; k < parameters.size(); ++k) {
      c.values.emplace_back(parameters[k].path, parameters[k].values[pick[k]]);
    }
  }
  return cases;
}

}  // namespace towsim::app
