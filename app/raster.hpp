// SPDX-License-Identifier: MIT
// A small RGB canvas for video frames: filled convex polygons, circles, thick lines and digits,
// each pixel sampled 2 x 2 times for smooth edges. Coordinates in pixels, y down.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "sim/led.hpp"
#include "sim/vec2.hpp"

namespace swarmpath::app {

class Raster {
 public:
  Raster(int width, int height);

  int width() const { return w_; }

  int height() const { return h_; }

  /// Rows top to bottom, three bytes a pixel.
  const std::vector<std::uint8_t>& rgb() const { return px_; }

  sim::Rgb at(int x, int y) const;

  void clear(sim::Rgb c);

  /// A convex polygon (either winding), blended with `alpha` in [0, 1].
  void fill_convex(std::span<const sim::Vec2> corners, sim::Rgb c, double alpha = 1.0);

  void fill_circle(sim::Vec2 centre, double radius, sim::Rgb c, double alpha = 1.0);

  void line(sim::Vec2 a, sim::Vec2 b, double width, sim::Rgb c, double alpha = 1.0);

  /// Digits, '.', ':' and ' ' (other characters are blank), `scale` pixels a font dot, from the
  /// top-left corner `at`.
  void text(sim::Vec2 at, std::string_view s, int scale, sim::Rgb c);

 private:
  void blend(int x, int y, sim::Rgb c, double alpha);

  int w_, h_;
  std::vector<std::uint8_t> px_;
};

}  // namespace swarmpath::app
