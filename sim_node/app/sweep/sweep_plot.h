#pragma once
// The sweep's plot DIR/results.svg (SVG 1.1, no dependencies): one panel per result, the result
// of every ok case against the first parameter; numbers on a linear axis, other values (names,
// vectors) as evenly spaced categories in first-seen order. With more parameters, one curve per
// combination of the others (the family: a colour each, joined in x order, named in a legend
// "b = 2, c = x"). A case whose result did not settle (settled:) is a hollow circle. Failed
// cases are left out and counted in the panel title. Plots in PNG and SVG with a heat map:
// scripts/plot_sweep.py.

#include <optional>
#include <string>
#include <vector>

#include "app/sweep/sweep_case.h"
#include "app/sweep/sweep_file.h"

namespace towsim::app {

// the SVG text
std::string SweepPlotSvg(const SweepSpec& spec, const std::vector<std::optional<SweepRow>>& rows);

}  // namespace towsim::app
