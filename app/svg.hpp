// SPDX-License-Identifier: MIT
// SVG pictures of an arena and a run: obstacles, nest and goal, robots coloured by LED,
// the A* path in red, optional trails.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "sim/occupancy.hpp"
#include "sim/scenario.hpp"
#include "sim/world.hpp"

namespace swarmpath::app {

struct Polyline {
  std::vector<sim::Vec2> points;
  std::string color;  ///< SVG colour
  double width_px = 2.0;
  std::string label;  ///< legend text; empty = no legend entry
  bool dots = false;  ///< mark the vertices
};

struct Picture {
  const sim::Scenario* scenario = nullptr;
  const sim::World* world = nullptr;           ///< robots to draw (optional)
  std::vector<Polyline> lines;                 ///< drawn in order, over the arena
  std::vector<std::vector<sim::Vec2>> trails;  ///< per-robot trails (thin, grey)
  std::vector<std::string> caption;            ///< lines of text under the title
  const sim::Occupancy* occupancy = nullptr;   ///< drawn on the floor as a heat map (optional)
  double px_per_m = 50.0;
};

void write_svg(std::ostream& out, const Picture& pic);

/// Colour of an occupancy cell: `t` in [0, 1] from pale yellow (0) through orange to dark red (1).
std::string heat_color(double t);

/// Where a density falls on the picture's log scale: 0 at max / 100 or below, 1 at max.
double heat_level(double density, double max_density);

/// Writes to `path` with evolve::write_file_atomic (throws evolve::WriteError naming it).
void write_svg_file(const std::string& path, const Picture& pic);

}  // namespace swarmpath::app
