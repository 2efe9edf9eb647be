#include "app/sweep/sweep_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace towsim::app {
namespace {

constexpr double kWidth = 640.0, kPanelHeight = 240.0;  // [px]
constexpr double kLeft = 80.0, kRight = 20.0, kTop = 30.0, kBottom = 40.0;
constexpr double kLegendWidth = 220.0;  // [px] right of the panels, with a family
// the family's colours (matplotlib's tab10), in turn
const char* const kColors[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                               "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

std::string Fmt(const char* format, double x) {
  char text[48];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

bool ParseNumber(const std::string& text, double* x) {
  if (text.empty()) return false;
  char* end = nullptr;
  *x = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(*x);
}

// [lo, hi] widened when empty, with 5% margins
std::pair<double, double> Span(double lo, double hi) {
  if (!(hi > lo)) {
    const double pad = std::max(1e-12, std::abs(lo) * 0.05 + (lo == 0.0 ? 1.0 : 0.0));
    return {lo - pad, hi + pad};
  }
  const double pad = 0.05 * (hi - lo);
  return {lo - pad, hi + pad};
}

}  // namespace

std::string SweepPlotSvg(const SweepSpec& spec, const std::vector<std::optional<SweepRow>>& rows) {
  const size_t panels = std::max<size_t>(1, spec.results.size());
  const double height = kPanelHeight * static_cast<double>(panels);
  // the family of a row: the values of every parameter but the first ("b = 2, c = x")
  std::vector<std::string> families;
  auto family_of = [&](const SweepRow& row) {
    std::string key;
    for (size_t p = 1; p < row.parameters.size() && p < spec.parameters.size(); ++p) {
      key += (key.empty() ? "" : ", ") + spec.parameters[p].path + " = " + row.parameters[p];
    }
    return key;
  };
  for (const auto& row : rows) {
    if (!row) continue;
    const std::string key = family_of(*row);
    if (std::find(families.begin(), families.end(), key) == families.end()) {
      families.push_back(key);
    }
  }
  const bool legend = families.size() > 1;
  const double width = kWidth + (legend ? kLegendWidth : 0.0);
  auto color_of = [&](const SweepRow& row) {
    const size_t k = static_cast<size_t>(
        std::find(families.begin(), families.end(), family_of(row)) - families.begin());
    return std::string(kColors[k % (sizeof kColors / sizeof kColors[0])]);
  };
  std::string svg =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
      "width=\"" +
      Fmt("%.0f", width) + "\" height=\"" + Fmt("%.0f", height) +
      "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const std::string x_name = spec.parameters.empty() ? "" : spec.parameters.front().path;

  // x positions: numbers if every value is one, else categories
  bool numeric = true;
  std::vector<std::string> categories;
  for (const auto& row : rows) {
    if (!row) continue;
    double x = 0.0;
    if (!ParseNumber(row->parameters.front(), &x)) numeric = false;
    if (std::find(categories.begin(), categories.end(), row->parameters.front()) ==
        categories.end()) {
      categories.push_back(row->parameters.front());
    }
  }
  auto x_of = [&](const SweepRow& row) {
    double x = 0.0;
    if (numeric && ParseNumber(row.parameters.front(), &x)) return x;
    return static_cast<double>(
        std::find(categories.begin(), categories.end(), row.parameters.front()) -
        categories.begin());
  };

  if (spec.results.empty()) {
    svg += "<text x=\"20\" y=\"40\">no results requested in " + Escape(spec.name) + "</text>\n";
  }
  for (size_t i = 0; i < spec.results.size(); ++i) {
    const double top = kPanelHeight * static_cast<double>(i);
    const double x0 = kLeft, x1 = kWidth - kRight, y0 = top + kTop,
                 y1 = top + kPanelHeight - kBottom;
    struct Point {
      double x, y;
      const SweepRow* row;
    };
    std::vector<Point> points;
    int failed = 0;
    for (const auto& row : rows) {
      if (!row) continue;
      if (!row->ok) {
        ++failed;
        continue;
      }
      if (std::isfinite(row->results[i])) points.push_back({x_of(*row), row->results[i], &*row});
    }
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (const Point& p : points) {
      xlo = std::min(xlo, p.x), xhi = std::max(xhi, p.x), ylo = std::min(ylo, p.y),
      yhi = std::max(yhi, p.y);
    }
    if (points.empty()) xlo = xhi = ylo = yhi = 0.0;
    const auto [xa, xb] = Span(xlo, xhi);
    const auto [ya, yb] = Span(ylo, yhi);
    auto px = [&](double x) { return x0 + (x - xa) / (xb - xa) * (x1 - x0); };
    auto py = [&](double y) { return y1 - (y - ya) / (yb - ya) * (y1 - y0); };

    const SweepResult& r = spec.results[i];
    std::string title = r.name + " (" + r.signal + (r.stat.empty() ? "" : ", " + r.stat) + ")";
    if (failed > 0) title += ", " + std::to_string(failed) + " failed case(s) not shown";
    svg += "<text x=\"" + Fmt("%.1f", x0) + "\" y=\"" + Fmt("%.1f", top + 18) +
           "\" font-size=\"13\">" + Escape(title) + "</text>\n";
    svg += "<rect x=\"" + Fmt("%.1f", x0) + "\" y=\"" + Fmt("%.1f", y0) + "\" width=\"" +
           Fmt("%.1f", x1 - x0) + "\" height=\"" + Fmt("%.1f", y1 - y0) +
           "\" fill=\"none\" stroke=\"black\"/>\n";
    // y ticks: 5, evenly spaced
    for (int k = 0; k <= 4; ++k) {
      const double y = ya + (yb - ya) * k / 4.0;
      svg += "<text x=\"" + Fmt("%.1f", x0 - 4) + "\" y=\"" + Fmt("%.1f", py(y) + 4) +
             "\" text-anchor=\"end\">" + Fmt("%.4g", y) + "</text>\n";
      svg += "<line x1=\"" + Fmt("%.1f", x0) + "\" x2=\"" + Fmt("%.1f", x1) + "\" y1=\"" +
             Fmt("%.1f", py(y)) + "\" y2=\"" + Fmt("%.1f", py(y)) + "\" stroke=\"#ddd\"/>\n";
    }
    // x ticks: 5 numbers, or the categories
    if (numeric) {
      for (int k = 0; k <= 4; ++k) {
        const double x = xa + (xb - xa) * k / 4.0;
        svg += "<text x=\"" + Fmt("%.1f", px(x)) + "\" y=\"" + Fmt("%.1f", y1 + 14) +
               "\" text-anchor=\"middle\">" + Fmt("%.4g", x) + "</text>\n";
      }
    } else {
      for (size_t k = 0; k < categories.size(); ++k) {
        svg += "<text x=\"" + Fmt("%.1f", px(static_cast<double>(k))) + "\" y=\"" +
               Fmt("%.1f", y1 + 14) + "\" text-anchor=\"middle\">" + Escape(categories[k]) +
               "</text>\n";
      }
    }
    svg += "<text x=\"" + Fmt("%.1f", 0.5 * (x0 + x1)) + "\" y=\"" + Fmt("%.1f", y1 + 30) +
           "\" text-anchor=\"middle\">" + Escape(x_name) + "</text>\n";
    // each family's curve in x order, then its points (hollow: not settled)
    for (const std::string& family : families) {
      std::vector<Point> curve;
      for (const Point& p : points) {
        if (family_of(*p.row) == family) curve.push_back(p);
      }
      std::stable_sort(curve.begin(), curve.end(),
                       [](const Point& a, const Point& b) { return a.x < b.x; });
      if (curve.size() > 1) {
        std::string line;
        for (const Point& p : curve)
          line += Fmt("%.1f", px(p.x)) + "," + Fmt("%.1f", py(p.y)) + " ";
        svg += "<polyline points=\"" + line + "\" fill=\"none\" stroke=\"" +
               color_of(*curve.front().row) + "\" stroke-width=\"1.5\"/>\n";
      }
    }
    bool hollow_any = false;
    for (const Point& p : points) {
      const bool hollow =
          i < p.row->settled.size() && p.row->settled[i].asked && !p.row->settled[i].settled;
      hollow_any = hollow_any || hollow;
      const std::string color = color_of(*p.row);
      svg += "<circle cx=\"" + Fmt("%.1f", px(p.x)) + "\" cy=\"" + Fmt("%.1f", py(p.y)) +
             "\" r=\"3.5\" fill=\"" + (hollow ? "white" : color) + "\" stroke=\"" + color +
             "\"/>\n";
    }
    if (hollow_any) {
      svg += "<text x=\"" + Fmt("%.1f", x1) + "\" y=\"" + Fmt("%.1f", top + 18) +
             "\" text-anchor=\"end\">hollow: not settled</text>\n";
    }
  }
  if (legend) {
    const double lx = kWidth + 10.0;
    svg += "<text x=\"" + Fmt("%.1f", lx) + "\" y=\"" + Fmt("%.1f", kTop + 8) +
           "\" font-size=\"12\">curves:</text>\n";
    for (size_t k = 0; k < families.size(); ++k) {
      const double y = kTop + 26.0 + 16.0 * static_cast<double>(k);
      svg += "<line x1=\"" + Fmt("%.1f", lx) + "\" x2=\"" + Fmt("%.1f", lx + 18) + "\" y1=\"" +
             Fmt("%.1f", y - 4) + "\" y2=\"" + Fmt("%.1f", y - 4) + "\" stroke=\"" +
             kColors[k % (sizeof kColors / sizeof kColors[0])] + "\" stroke-width=\"2\"/>\n";
      svg += "<text x=\"" + Fmt("%.1f", lx + 24) + "\" y=\"" + Fmt("%.1f", y) + "\">" +
             Escape(families[k]) + "</text>\n";
    }
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace towsim::app
