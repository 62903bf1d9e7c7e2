// SPDX-License-Identifier: MIT
#include "trajectory_svg.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "evolve/svg_plot.hpp"
#include "evolve/xml_escape.hpp"

namespace swarmpath::evolve {

namespace {

void polyline(std::ostream& out, const PlotArea& a, const std::vector<double>& v, const char* colour,
              double width, const char* dash = nullptr) {
  out << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << width << "\"";
  if (dash != nullptr) out << " stroke-dasharray=\"" << dash << "\"";
  out << " points=\"";
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::isfinite(v[i])) out << a.px(static_cast<double>(i)) << ',' << a.py(v[i]) << ' ';
  }
  out << "\"/>\n";
}

}  // namespace

void write_trajectory_svg(std::ostream& out, const Trajectory& t) {
  const double width = 360.0, height = 230.0;
  const std::size_t n = std::max({t.best.size(), t.mean.size(), std::size_t{1}});
  PlotArea a;
  a.left = 64.0, a.top = 44.0, a.width = width - 64.0 - 14.0, a.height = height - 44.0 - 48.0;
  a.y = Axis::over({t.lo, t.hi});
  const double gmax = n > 1 ? static_cast<double>(n - 1) : 1.0;
  a.x = Axis{0.0, gmax, std::max(1.0, nice_step(gmax))};
  std::string subtitle = "range " + short_text(t.lo) + " to " + short_text(t.hi);
  if (std::isfinite(t.base)) subtitle += "; base " + short_text(t.base);
  if (std::isfinite(t.reported)) subtitle += "; reported " + short_text(t.reported);
  write_svg_open(out, width, height, t.name, subtitle);
  write_frame(out, a, "generation", "");
  // the population's band, then its mean, the base, the best of each generation, the reported value
  if (!t.min.empty() && t.min.size() == t.max.size()) {
    out << "<polygon fill=\"#7a9cc6\" fill-opacity=\"0.25\" stroke=\"none\" points=\"";
    for (std::size_t i = 0; i < t.max.size(); ++i)
      out << a.px(static_cast<double>(i)) << ',' << a.py(t.max[i]) << ' ';
    for (std::size_t i = t.min.size(); i-- > 0;)
      out << a.px(static_cast<double>(i)) << ',' << a.py(t.min[i]) << ' ';
    out << "\"/>\n";
  }
  polyline(out, a, t.mean, "#7a9cc6", 1.5);
  if (std::isfinite(t.base)) polyline(out, a, std::vector<double>(n, t.base), "#555", 1.2, "5,4");
  polyline(out, a, t.best, "#e07000", 2.0);
  for (std::size_t i = 0; i < t.best.size(); ++i) {
    if (!std::isfinite(t.best[i])) continue;
    out << "<circle cx=\"" << a.px(static_cast<double>(i)) << "\" cy=\"" << a.py(t.best[i])
        << "\" r=\"2.2\" fill=\"#e07000\"/>\n";
  }
  if (std::isfinite(t.reported)) {
    out << "<circle cx=\"" << a.px(gmax) << "\" cy=\"" << a.py(t.reported)
        << "\" r=\"5\" fill=\"none\" stroke=\"#00a651\" stroke-width=\"2.5\"><title>reported: "
        << xml_escape(short_text(t.reported)) << "</title></circle>\n";
  }
  out << "</svg>\n";
}

}  // namespace swarmpath::evolve
