// SPDX-License-Identifier: MIT
// Plain-SVG building blocks for the evolve reports: axis ticks, a plot frame with a grid, and a
// line chart of per-generation series (fitness.svg, hypervolume.svg).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace swarmpath::evolve {

/// 1, 2 or 5 times a power of ten, about range / 5 (1 for an empty range).
double nice_step(double range);

/// Four significant digits (whole numbers from 10^4 on in full).
std::string short_text(double v);

/// A linear axis: the data range [lo, hi] widened to whole steps.
struct Axis {
  double lo = 0.0;
  double hi = 1.0;
  double step = 1.0;

  /// The axis over these values (NaN and inf ignored; a point or nothing is padded to a range).
  static Axis over(const std::vector<double>& values);
};

/// A rectangle of the picture and the axes it maps.
struct PlotArea {
  double left = 0.0, top = 0.0, width = 1.0, height = 1.0;
  Axis x, y;

  double px(double v) const { return left + width * (v - x.lo) / (x.hi - x.lo); }

  double py(double v) const { return top + height * (y.hi - v) / (y.hi - y.lo); }
};

/// The grid, the tick labels, the frame and the axis titles of an area.
void write_frame(std::ostream& out, const PlotArea& a, const std::string& x_title,
                 const std::string& y_title);

/// `<svg ...>` with a white background, a bold title and a subtitle line.
void write_svg_open(std::ostream& out, double width, double height, const std::string& title,
                    const std::string& subtitle);

/// One series of a line chart over the generations.
struct Series {
  std::string label;
  std::string color;
  std::vector<double> values;  ///< one per generation
};

/// A line chart of series over generations 0..n-1 with a legend (top right).
void write_line_chart(std::ostream& out, const std::string& title, const std::string& subtitle,
                      const std::string& y_title, const std::vector<Series>& series);

}  // namespace swarmpath::evolve
