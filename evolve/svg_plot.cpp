// SPDX-License-Identifier: MIT
#include "svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

#include "evolve/xml_escape.hpp"

namespace swarmpath::evolve {

double nice_step(double range) {
  if (!(range > 0.0) || !std::isfinite(range)) return 1.0;
  const double raw = range / 5.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * p >= raw) return m * p;
  }
  return 10.0 * p;
}

std::string short_text(double v) {
  std::ostringstream o;
  if (std::isfinite(v) && std::fabs(v) >= 1e4 && std::fabs(v) < 1e12 && v == std::round(v)) {
    o << std::fixed << std::setprecision(0) << v;  // 35000, not 3.5e+04
  } else {
    o << std::setprecision(4) << v;
  }
  return o.str();
}

Axis Axis::over(const std::vector<double>& values) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (lo > hi) lo = 0.0, hi = 1.0;
  if (hi - lo < 1e-9 * std::max(1.0, std::fabs(hi))) {
    const double pad = std::max(0.5, 0.05 * std::fabs(hi));
    lo -= pad, hi += pad;
  }
  Axis a;
  a.step = nice_step(hi - lo);
  a.lo = std::floor(lo / a.step) * a.step;
  a.hi = std::ceil(hi / a.step) * a.step;
  return a;
}

void write_svg_open(std::ostream& out, double width, double height, const std::string& title,
                    const std::string& subtitle) {
  out << std::fixed << std::setprecision(2);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"6\" y=\"20\" font-size=\"15\" font-weight=\"bold\">" << xml_escape(title) << "</text>\n";
  out << "<text x=\"6\" y=\"36\" font-size=\"12\">" << xml_escape(subtitle) << "</text>\n";
}

void write_frame(std::ostream& out, const PlotArea& a, const std::string& x_title,
                 const std::string& y_title) {
  const double eps = 0.5;
  out << "<g stroke=\"#e4e4dc\" stroke-width=\"1\">\n";
  for (double v = a.y.lo; v <= a.y.hi + eps * a.y.step; v += a.y.step) {
    out << "<line x1=\"" << a.left << "\" y1=\"" << a.py(v) << "\" x2=\"" << a.left + a.width << "\" y2=\""
        << a.py(v) << "\"/>\n";
  }
  for (double v = a.x.lo; v <= a.x.hi + eps * a.x.step; v += a.x.step) {
    out << "<line x1=\"" << a.px(v) << "\" y1=\"" << a.top << "\" x2=\"" << a.px(v) << "\" y2=\""
        << a.top + a.height << "\"/>\n";
  }
  out << "</g>\n<g font-size=\"11\" text-anchor=\"end\">\n";
  for (double v = a.y.lo; v <= a.y.hi + eps * a.y.step; v += a.y.step) {
    out << "<text x=\"" << a.left - 6 << "\" y=\"" << a.py(v) + 4 << "\">" << short_text(v) << "</text>\n";
  }
  out << "</g>\n<g font-size=\"11\" text-anchor=\"middle\">\n";
  for (double v = a.x.lo; v <= a.x.hi + eps * a.x.step; v += a.x.step) {
    out << "<text x=\"" << a.px(v) << "\" y=\"" << a.top + a.height + 16 << "\">" << short_text(v)
        << "</text>\n";
  }
  out << "</g>\n";
  out << "<rect x=\"" << a.left << "\" y=\"" << a.top << "\" width=\"" << a.width << "\" height=\""
      << a.height << "\" fill=\"none\" stroke=\"#999\"/>\n";
  out << "<text x=\"" << a.left + a.width / 2 << "\" y=\"" << a.top + a.height + 34
      << "\" font-size=\"12\" text-anchor=\"middle\">" << xml_escape(x_title) << "</text>\n";
  const double ty = a.top + a.height / 2, tx = a.left - 52;
  out << "<text x=\"" << tx << "\" y=\"" << ty
      << "\" font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 " << tx << ' ' << ty << ")\">"
      << xml_escape(y_title) << "</text>\n";
}

void write_line_chart(std::ostream& out, const std::string& title, const std::string& subtitle,
                      const std::string& y_title, const std::vector<Series>& series) {
  const double width = 720.0, height = 420.0;
  std::size_t n = 0;
  std::vector<double> all;
  for (const Series& s : series) {
    n = std::max(n, s.values.size());
    all.insert(all.end(), s.values.begin(), s.values.end());
  }
  PlotArea a;
  a.left = 72.0, a.top = 44.0, a.width = width - 72.0 - 24.0, a.height = height - 44.0 - 52.0;
  a.y = Axis::over(all);
  const double gmax = n > 1 ? static_cast<double>(n - 1) : 1.0;
  a.x = Axis{0.0, gmax, std::max(1.0, nice_step(gmax))};
  write_svg_open(out, width, height, title, subtitle);
  write_frame(out, a, "generation", y_title);
  for (const Series& s : series) {
    if (s.values.empty()) continue;
    out << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"2\" points=\"";
    for (std::size_t i = 0; i < s.values.size(); ++i) {
      if (std::isfinite(s.values[i])) out << a.px(static_cast<double>(i)) << ',' << a.py(s.values[i]) << ' ';
    }
    out << "\"/>\n";
    for (std::size_t i = 0; i < s.values.size(); ++i) {
      if (!std::isfinite(s.values[i])) continue;  // a generation without this value
      out << "<circle cx=\"" << a.px(static_cast<double>(i)) << "\" cy=\"" << a.py(s.values[i])
          << "\" r=\"2.5\" fill=\"" << s.color << "\"/>\n";
    }
  }
  double ly = a.top + 16;
  for (const Series& s : series) {
    const double lx = a.left + a.width - 150;
    out << "<line x1=\"" << lx << "\" y1=\"" << ly - 4 << "\" x2=\"" << lx + 26 << "\" y2=\"" << ly - 4
        << "\" stroke=\"" << s.color << "\" stroke-width=\"3\"/><text x=\"" << lx + 32 << "\" y=\"" << ly
        << "\" font-size=\"12\">" << xml_escape(s.label) << "</text>\n";
    ly += 16;
  }
  out << "</svg>\n";
}

}  // namespace swarmpath::evolve
