// SPDX-License-Identifier: MIT
#include "svg.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "evolve/atomic_write.hpp"
#include "evolve/xml_escape.hpp"
#include "sim/robot_model.hpp"

namespace swarmpath::app {

using evolve::xml_escape;

namespace {

using sim::Vec2;

std::string hex(sim::Led c) {
  const sim::Rgb rgb = sim::rgb(c);
  std::ostringstream o;
  o << '#' << std::hex << std::setfill('0') << std::setw(2) << int{rgb.r} << std::setw(2) << int{rgb.g}
    << std::setw(2) << int{rgb.b};
  return o.str();
}

struct Frame {
  sim::Aabb arena;
  double k;    // px per metre
  double top;  // px above the arena for the title

  double x(double wx) const { return (wx - arena.lo.x) * k; }

  double y(double wy) const { return top + (arena.hi.y - wy) * k; }
};

// the occupancy layer: cells by density on a log scale, and a legend line
void write_occupancy(std::ostream& out, const Frame& f, const sim::Occupancy& occ, double& max_density) {
  max_density = 0.0;
  for (int iy = 0; iy < occ.cells_y(); ++iy) {
    for (int ix = 0; ix < occ.cells_x(); ++ix) max_density = std::max(max_density, occ.density(ix, iy));
  }
  if (max_density <= 0.0) return;
  out << "<g stroke=\"none\">\n";
  for (int iy = 0; iy < occ.cells_y(); ++iy) {
    for (int ix = 0; ix < occ.cells_x(); ++ix) {
      if (occ.count(ix, iy) == 0) continue;
      const sim::Aabb b = occ.cell_bounds(ix, iy);
      const double hi_x = std::min(b.hi.x, f.arena.hi.x);
      const double hi_y = std::min(b.hi.y, f.arena.hi.y);
      out << "<rect x=\"" << f.x(b.lo.x) << "\" y=\"" << f.y(hi_y) << "\" width=\"" << (hi_x - b.lo.x) * f.k
          << "\" height=\"" << (hi_y - b.lo.y) * f.k << "\" fill=\""
          << heat_color(heat_level(occ.density(ix, iy), max_density)) << "\"/>";
    }
    out << "\n";
  }
  out << "</g>\n";
}

}  // namespace

std::string heat_color(double t) {
  // YlOrRd: pale yellow, orange, dark red
  constexpr double kStops[3][3] = {{255, 255, 178}, {253, 141, 60}, {128, 0, 38}};
  t = std::clamp(t, 0.0, 1.0);
  const int k = t < 0.5 ? 0 : 1;
  const double u = t < 0.5 ? 2.0 * t : 2.0 * t - 1.0;
  std::ostringstream o;
  o << '#' << std::hex << std::setfill('0');
  for (int c = 0; c < 3; ++c) {
    const double v = kStops[k][c] + u * (kStops[k + 1][c] - kStops[k][c]);
    o << std::setw(2) << static_cast<int>(std::lround(v));
  }
  return o.str();
}

double heat_level(double density, double max_density) {
  if (!(density > 0.0) || !(max_density > 0.0)) return 0.0;
  return std::clamp(1.0 + 0.5 * std::log10(density / max_density), 0.0, 1.0);
}

void write_svg(std::ostream& out, const Picture& pic) {
  const sim::Scenario& s = *pic.scenario;
  const double header = 22.0 + 16.0 * static_cast<double>(pic.caption.size());
  const Frame f{s.arena_bounds(), pic.px_per_m, header};
  const double width = s.arena_size.x * f.k;
  const double legend_lines = static_cast<double>(pic.lines.size()) + (pic.occupancy != nullptr ? 1.0 : 0.0);
  const double height = header + s.arena_size.y * f.k + 8.0 + 16.0 * legend_lines;
  out << std::fixed << std::setprecision(2);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  // title and caption
  out << "<text x=\"6\" y=\"17\" font-size=\"15\" font-weight=\"bold\">" << xml_escape(s.name) << " ("
      << sim::to_string(s.env_class) << ")</text>\n";
  for (std::size_t i = 0; i < pic.caption.size(); ++i) {
    out << "<text x=\"6\" y=\"" << 17.0 + 16.0 * static_cast<double>(i + 1) << "\" font-size=\"12\">"
        << xml_escape(pic.caption[i]) << "</text>\n";
  }
  // arena floor and a 1 m grid
  out << "<rect x=\"0\" y=\"" << f.top << "\" width=\"" << width << "\" height=\"" << s.arena_size.y * f.k
      << "\" fill=\"#f7f7f2\" stroke=\"#999\"/>\n<g stroke=\"#e4e4dc\" stroke-width=\"1\">\n";
  for (double gx = std::ceil(f.arena.lo.x); gx <= f.arena.hi.x; gx += 1.0) {
    out << "<line x1=\"" << f.x(gx) << "\" y1=\"" << f.y(f.arena.lo.y) << "\" x2=\"" << f.x(gx) << "\" y2=\""
        << f.y(f.arena.hi.y) << "\"/>\n";
  }
  for (double gy = std::ceil(f.arena.lo.y); gy <= f.arena.hi.y; gy += 1.0) {
    out << "<line x1=\"" << f.x(f.arena.lo.x) << "\" y1=\"" << f.y(gy) << "\" x2=\"" << f.x(f.arena.hi.x)
        << "\" y2=\"" << f.y(gy) << "\"/>\n";
  }
  out << "</g>\n";
  double max_density = 0.0;
  if (pic.occupancy != nullptr) write_occupancy(out, f, *pic.occupancy, max_density);
  // deployment region
  const sim::Aabb dep = s.deployment.bounds();
  out << "<rect x=\"" << f.x(dep.lo.x) << "\" y=\"" << f.y(dep.hi.y) << "\" width=\""
      << s.deployment.size.x * f.k << "\" height=\"" << s.deployment.size.y * f.k
      << "\" fill=\"none\" stroke=\"#7a9cc6\" stroke-dasharray=\"6,4\"/>\n";
  // obstacles and walls
  out << "<g fill=\"#555\" stroke=\"#333\">\n";
  for (const sim::Shape& sh : sim::obstacle_shapes(s)) {
    if (sh.kind == sim::ShapeKind::kCircle) {
      out << "<circle cx=\"" << f.x(sh.center.x) << "\" cy=\"" << f.y(sh.center.y) << "\" r=\""
          << sh.radius * f.k << "\"/>\n";
      continue;
    }
    out << "<polygon points=\"";
    const Vec2 corners[4] = {
        {-sh.half.x, -sh.half.y}, {sh.half.x, -sh.half.y}, {sh.half.x, sh.half.y}, {-sh.half.x, sh.half.y}};
    for (const Vec2& c : corners) {
      const Vec2 w = sh.center + sim::rotate(c, sh.c, sh.s);
      out << f.x(w.x) << ',' << f.y(w.y) << ' ';
    }
    out << "\"/>\n";
  }
  out << "</g>\n";
  // trails
  if (!pic.trails.empty()) {
    out << "<g fill=\"none\" stroke=\"#b9b9b9\" stroke-width=\"0.8\">\n";
    for (const auto& t : pic.trails) {
      if (t.size() < 2) continue;
      out << "<polyline points=\"";
      for (const Vec2& p : t) out << f.x(p.x) << ',' << f.y(p.y) << ' ';
      out << "\"/>\n";
    }
    out << "</g>\n";
  }
  // nest (blue) with its reach circle, goal (yellow)
  out << "<circle cx=\"" << f.x(s.nest.x) << "\" cy=\"" << f.y(s.nest.y) << "\" r=\"" << 1.0 * f.k
      << "\" fill=\"none\" stroke=\"#0000ff\" stroke-opacity=\"0.35\" stroke-dasharray=\"3,3\"/>\n";
  out << "<circle cx=\"" << f.x(s.nest.x) << "\" cy=\"" << f.y(s.nest.y) << "\" r=\"" << 0.15 * f.k
      << "\" fill=\"#0000ff\" stroke=\"black\"/>\n";
  out << "<circle cx=\"" << f.x(s.goal.x) << "\" cy=\"" << f.y(s.goal.y) << "\" r=\"" << 0.15 * f.k
      << "\" fill=\"#ffff00\" stroke=\"black\"/>\n";
  // paths
  for (const Polyline& line : pic.lines) {
    if (line.points.size() < 2) continue;
    out << "<polyline fill=\"none\" stroke=\"" << line.color << "\" stroke-width=\"" << line.width_px
        << "\" stroke-linejoin=\"round\" points=\"";
    for (const Vec2& p : line.points) out << f.x(p.x) << ',' << f.y(p.y) << ' ';
    out << "\"/>\n";
    if (line.dots) {
      for (const Vec2& p : line.points) {
        out << "<circle cx=\"" << f.x(p.x) << "\" cy=\"" << f.y(p.y) << "\" r=\"" << 1.5 * line.width_px
            << "\" fill=\"" << line.color << "\"/>\n";
      }
    }
  }
  // robots: body filled with the LED colour, a tick for the heading
  if (pic.world != nullptr) {
    const double r = sim::kRobotRadius * f.k;
    out << "<g stroke-width=\"1\">\n";
    for (std::size_t i = 0; i < pic.world->poses.size(); ++i) {
      const sim::Pose& p = pic.world->poses[i];
      const sim::Led led = pic.world->leds[i];
      const std::string fill = led == sim::Led::kBlack ? "#2b2b2b" : hex(led);
      out << "<circle cx=\"" << f.x(p.p.x) << "\" cy=\"" << f.y(p.p.y) << "\" r=\"" << r << "\" fill=\""
          << fill << "\" stroke=\"black\"/>";
      const Vec2 tip = p.p + sim::kRobotRadius * Vec2{p.c, p.s};
      out << "<line x1=\"" << f.x(p.p.x) << "\" y1=\"" << f.y(p.p.y) << "\" x2=\"" << f.x(tip.x) << "\" y2=\""
          << f.y(tip.y) << "\" stroke=\"black\"/>\n";
      if (sim::has_failed(*pic.world, static_cast<int>(i))) {  // a failed robot: a red cross over it
        const double d = 1.3 * r;
        out << "<path d=\"M" << f.x(p.p.x) - d << "," << f.y(p.p.y) - d << "l" << 2 * d << "," << 2 * d << "M"
            << f.x(p.p.x) - d << "," << f.y(p.p.y) + d << "l" << 2 * d << "," << -2 * d
            << "\" stroke=\"#e00000\" stroke-width=\"2\"/>\n";
      }
    }
    out << "</g>\n";
  }
  // legend of the paths
  double ly = f.top + s.arena_size.y * f.k + 18.0;
  for (const Polyline& line : pic.lines) {
    if (line.label.empty()) continue;
    out << "<line x1=\"8\" y1=\"" << ly - 4 << "\" x2=\"36\" y2=\"" << ly - 4 << "\" stroke=\"" << line.color
        << "\" stroke-width=\"3\"/><text x=\"42\" y=\"" << ly << "\" font-size=\"12\">"
        << xml_escape(line.label) << "</text>\n";
    ly += 16.0;
  }
  if (pic.occupancy != nullptr) {
    const sim::Occupancy& occ = *pic.occupancy;
    for (int i = 0; i < 5; ++i) {
      out << "<rect x=\"" << 8 + 6 * i << "\" y=\"" << ly - 10 << "\" width=\"6\" height=\"10\" fill=\""
          << heat_color(0.25 * i) << "\"/>";
    }
    std::ostringstream what;
    what << std::setprecision(3) << "occupancy of "
         << (occ.only() ? std::string(sim::name(*occ.only())) : "all") << " robots over " << occ.ticks()
         << " ticks, " << occ.cell_m() * 100.0 << " cm cells, log scale: darkest " << max_density
         << " robots/m², palest 1/100 of it or less";
    out << "<text x=\"42\" y=\"" << ly << "\" font-size=\"12\">" << xml_escape(what.str()) << "</text>\n";
  }
  out << "</svg>\n";
}

void write_svg_file(const std::string& path, const Picture& pic) {
  evolve::write_file_atomic(path, [&](std::ostream& out) { write_svg(out, pic); });
}

}  // namespace swarmpath::app
