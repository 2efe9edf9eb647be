#include "scene/bathymetry_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "scene/yaml_reader.h"

namespace towsim::scene::internal {
namespace {

// a line of the file: its 1-based number and its blank-separated words (comment removed)
struct Line {
  int number = 0;
  std::vector<std::string> words;
};

std::vector<Line> Lines(const std::string& text) {
  std::vector<Line> lines;
  std::istringstream in(text);
  std::string raw;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    const size_t hash = raw.find('#');
    if (hash != std::string::npos) raw.resize(hash);
    std::istringstream words(raw);
    Line line;
    line.number = number;
    for (std::string w; words >> w;) line.words.push_back(w);
    if (!line.words.empty()) lines.push_back(std::move(line));
  }
  return lines;
}

// a finite number that is the whole word
bool ParseNumber(const std::string& word, double* x) {
  errno = 0;
  char* end = nullptr;
  *x = std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0' && errno != ERANGE && std::isfinite(*x);
}

bool ParseCount(const std::string& word, int* n) {
  double x = 0.0;
  if (!ParseNumber(word, &x) || x != std::floor(x) || x < 2.0 || x > 1e6) return false;
  *n = static_cast<int>(x);
  return true;
}

}  // namespace

bool ParseBathymetry(const std::string& text, const std::string& name, BathymetryGrid* grid,
                     std::string* why) {
  const auto fail = [&](int line, const std::string& rule) {
    *why = name + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + rule;
    return false;
  };
  const std::vector<Line> lines = Lines(text);
  if (lines.size() < 3) {
    return fail(0,
                "must hold a line 'nx ny', the x coordinates and the y coordinates, then "
                "one line 'x y depth' per grid node");
  }
  // nx ny
  int nx = 0, ny = 0;
  if (lines[0].words.size() != 2 || !ParseCount(lines[0].words[0], &nx) ||
      !ParseCount(lines[0].words[1], &ny)) {
    return fail(lines[0].number, "must be 'nx ny', two integers >= 2 (the grid's size)");
  }
  // the tick lines: n finite numbers, strictly increasing
  const auto ticks = [&](const Line& line, int n, const char* axis, std::vector<double>* out) {
    if (static_cast<int>(line.words.size()) != n) {
      return fail(line.number, "must hold the " + std::to_string(n) + " " + axis +
                                   " coordinates of the grid (it has " +
                                   std::to_string(line.words.size()) + ")");
    }
    out->resize(n);
    for (int i = 0; i < n; ++i) {
      if (!ParseNumber(line.words[i], &(*out)[i])) {
        return fail(line.number,
                    std::string(axis) + " coordinate " + line.words[i] + " is not a finite number");
      }
      if (i > 0 && (*out)[i] <= (*out)[i - 1]) {
        return fail(line.number, std::string(axis) + " coordinates must increase strictly (" +
                                     line.words[i] + " after " + line.words[i - 1] + ")");
      }
    }
    return true;
  };
  if (!ticks(lines[1], nx, "x", &grid->x) || !ticks(lines[2], ny, "y", &grid->y)) return false;

  // x y depth, each node once
  grid->depth.assign(static_cast<size_t>(nx) * ny, std::nan(""));
  std::vector<int> given_at(grid->depth.size(), 0);
  for (size_t l = 3; l < lines.size(); ++l) {
    const Line& line = lines[l];
    double v[3];
    if (line.words.size() != 3 || !ParseNumber(line.words[0], &v[0]) ||
        !ParseNumber(line.words[1], &v[1]) || !ParseNumber(line.words[2], &v[2])) {
      return fail(line.number, "must be 'x y depth', three finite numbers");
    }
    const auto ix = std::find(grid->x.begin(), grid->x.end(), v[0]);
    const auto iy = std::find(grid->y.begin(), grid->y.end(), v[1]);
    if (ix == grid->x.end() || iy == grid->y.end()) {
      return fail(line.number, "(" + line.words[0] + ", " + line.words[1] +
                                   ") is not a node of the grid (its x and y must be among the "
                                   "coordinates of lines " +
                                   std::to_string(lines[1].number) + " and " +
                                   std::to_string(lines[2].number) + ")");
    }
    if (v[2] <= 0.0) {
      return fail(line.number, "depth " + line.words[2] +
                                   " must be > 0 (positive down, below the mean surface)");
    }
    const size_t k =
        static_cast<size_t>(iy - grid->y.begin()) * nx + static_cast<size_t>(ix - grid->x.begin());
    if (given_at[k] != 0) {
      return fail(line.number, "node (" + line.words[0] + ", " + line.words[1] +
                                   ") given twice (first at line " + std::to_string(given_at[k]) +
                                   ")");
    }
    given_at[k] = line.number;
    grid->depth[k] = v[2];
  }
  for (size_t k = 0; k < given_at.size(); ++k) {
    if (given_at[k] == 0) {
      return fail(0, "node (" + FormatNumber(grid->x[k % nx]) + ", " +
                         FormatNumber(grid->y[k / nx]) + ") has no depth line (" +
                         std::to_string(given_at.size()) + " nodes needed)");
    }
  }
  return true;
}

}  // namespace towsim::scene::internal
