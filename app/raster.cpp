// SPDX-License-Identifier: MIT
#include "raster.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace swarmpath::app {

namespace {

// 2 x 2 sample offsets inside a pixel
constexpr std::array<sim::Vec2, 4> kSamples{{{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}}};

// a 3 x 5 dot font: digits, '.', ':'; each row's three bits, top row first
std::array<std::uint8_t, 5> glyph(char ch) {
  switch (ch) {
    case '0':
      return {7, 5, 5, 5, 7};
    case '1':
      return {2, 6, 2, 2, 7};
    case '2':
      return {7, 1, 7, 4, 7};
    case '3':
      return {7, 1, 7, 1, 7};
    case '4':
      return {5, 5, 7, 1, 1};
    case '5':
      return {7, 4, 7, 1, 7};
    case '6':
      return {7, 4, 7, 5, 7};
    case '7':
      return {7, 1, 1, 1, 1};
    case '8':
      return {7, 5, 7, 5, 7};
    case '9':
      return {7, 5, 7, 1, 7};
    case '.':
      return {0, 0, 0, 0, 2};
    case ':':
      return {0, 2, 0, 2, 0};
    case '/':
      return {1, 1, 2, 4, 4};
    default:
      return {0, 0, 0, 0, 0};
  }
}

}  // namespace

Raster::Raster(int width, int height)
    : w_(width),
      h_(height),
      px_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 255) {}

sim::Rgb Raster::at(int x, int y) const {
  const std::size_t k =
      (static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(x)) * 3;
  return {px_[k], px_[k + 1], px_[k + 2]};
}

void Raster::clear(sim::Rgb c) {
  for (std::size_t k = 0; k < px_.size(); k += 3) {
    px_[k] = c.r;
    px_[k + 1] = c.g;
    px_[k + 2] = c.b;
  }
}

void Raster::blend(int x, int y, sim::Rgb c, double alpha) {
  if (x < 0 || y < 0 || x >= w_ || y >= h_ || alpha <= 0.0) return;
  const std::size_t k =
      (static_cast<std::size_t>(y) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(x)) * 3;
  const auto mix = [&](std::uint8_t& dst, std::uint8_t src) {
    dst = static_cast<std::uint8_t>(std::lround(dst + alpha * (src - dst)));
  };
  mix(px_[k], c.r);
  mix(px_[k + 1], c.g);
  mix(px_[k + 2], c.b);
}

void Raster::fill_convex(std::span<const sim::Vec2> corners, sim::Rgb c, double alpha) {
  if (corners.size() < 3) return;
  double x0 = corners[0].x, x1 = x0, y0 = corners[0].y, y1 = y0;
  double area = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const sim::Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    x0 = std::min(x0, a.x);
    x1 = std::max(x1, a.x);
    y0 = std::min(y0, a.y);
    y1 = std::max(y1, a.y);
    area += a.x * b.y - b.x * a.y;
  }
  const double sign = area >= 0.0 ? 1.0 : -1.0;
  const int ix0 = std::max(0, static_cast<int>(std::floor(x0))),
            ix1 = std::min(w_ - 1, static_cast<int>(std::ceil(x1)));
  const int iy0 = std::max(0, static_cast<int>(std::floor(y0))),
            iy1 = std::min(h_ - 1, static_cast<int>(std::ceil(y1)));
  for (int y = iy0; y <= iy1; ++y) {
    for (int x = ix0; x <= ix1; ++x) {
      int inside = 0;
      for (const sim::Vec2 s : kSamples) {
        const sim::Vec2 p{x + s.x, y + s.y};
        bool in = true;
        for (std::size_t i = 0; i < corners.size() && in; ++i) {
          const sim::Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
          in = sign * ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) >= 0.0;
        }
        inside += in ? 1 : 0;
      }
      if (inside > 0) blend(x, y, c, alpha * inside / 4.0);
    }
  }
}

void Raster::fill_circle(sim::Vec2 centre, double radius, sim::Rgb c, double alpha) {
  const int ix0 = std::max(0, static_cast<int>(std::floor(centre.x - radius)));
  const int ix1 = std::min(w_ - 1, static_cast<int>(std::ceil(centre.x + radius)));
  const int iy0 = std::max(0, static_cast<int>(std::floor(centre.y - radius)));
  const int iy1 = std::min(h_ - 1, static_cast<int>(std::ceil(centre.y + radius)));
  const double r2 = radius * radius;
  for (int y = iy0; y <= iy1; ++y) {
    for (int x = ix0; x <= ix1; ++x) {
      int inside = 0;
      for (const sim::Vec2 s : kSamples) {
        const double dx = x + s.x - centre.x, dy = y + s.y - centre.y;
        inside += dx * dx + dy * dy <= r2 ? 1 : 0;
      }
      if (inside > 0) blend(x, y, c, alpha * inside / 4.0);
    }
  }
}

void Raster::line(sim::Vec2 a, sim::Vec2 b, double width, sim::Rgb c, double alpha) {
  const sim::Vec2 d = b - a;
  const double len = std::hypot(d.x, d.y);
  if (len <= 0.0) return;
  const sim::Vec2 n{-d.y / len * width / 2, d.x / len * width / 2};
  const std::array<sim::Vec2, 4> quad{a + n, b + n, b - n, a - n};
  fill_convex(quad, c, alpha);
}

void Raster::text(sim::Vec2 at, std::string_view s, int scale, sim::Rgb c) {
  double x = at.x;
  for (const char ch : s) {
    const auto g = glyph(ch);
    for (int row = 0; row < 5; ++row) {
      for (int col = 0; col < 3; ++col) {
        if (((g[static_cast<std::size_t>(row)] >> (2 - col)) & 1) == 0) continue;
        for (int dy = 0; dy < scale; ++dy) {
          for (int dx = 0; dx < scale; ++dx)
            blend(static_cast<int>(x) + col * scale + dx, static_cast<int>(at.y) + row * scale + dy, c, 1.0);
        }
      }
    }
    x += 4 * scale;
  }
}

}  // namespace swarmpath::app
