#pragma once
// The bathymetry grid file named by environment.seabed.grid (docs/environment.md). Plain text,
// the layout of MoorDyn v2's 3D seafloor file:
//   nx ny                      two integers >= 2
//   x_0 x_1 ... x_{nx-1}       the grid's x coordinates [m], strictly increasing
//   y_0 y_1 ... y_{ny-1}       its y coordinates [m], strictly increasing
//   x y depth                  one line per grid node (nx ny lines, any order), the node's x and
//                              y exactly as in the tick lines, depth > 0 [m] positive down
// Text after '#' is a comment; blank lines are skipped. Every node must be given exactly once.
// (MoorDyn reads the third column as the seabed z; towsim as the depth below the mean surface,
// positive. A file with negative values is rejected, so a sign slip cannot pass unseen.)

#include <string>
#include <vector>

namespace towsim::scene::internal {

struct BathymetryGrid {
  std::vector<double> x;      // nx
  std::vector<double> y;      // ny
  std::vector<double> depth;  // depth[j * nx + i] = d(x_i, y_j)
};

// Parses `text` (the file's content); false with the reason in `why`, which starts with
// "<name>:<line>: " (or "<name>: " when no one line is at fault).
bool ParseBathymetry(const std::string& text, const std::string& name, BathymetryGrid* grid,
                     std::string* why);

}  // namespace towsim::scene::internal
