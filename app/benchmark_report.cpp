// SPDX-License-Identifier: MIT
#include "benchmark_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

#include "common.hpp"
#include "evolve/svg_plot.hpp"
#include "evolve/xml_escape.hpp"

namespace swarmpath::app {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const std::string kAll = "all families";
const std::string kPaper = "paper arenas";

// sums over runs, then means
struct Sums {
  int runs = 0, ok = 0, allocated = 0;
  double ticks = 0, censored = 0, ratio = 0, rr = 0;
  int ratios = 0;

  void add(const GridRun& r, double astar) {
    const sim::Metrics& m = r.m;
    ++runs;
    censored += static_cast<double>(m.success ? m.ticks_to_form : m.ticks);
    if (m.allocated >= 0 && !std::isnan(m.resource_reduction_pct)) {
      ++allocated;
      rr += m.resource_reduction_pct;
    }
    if (!m.success) return;
    ++ok;
    ticks += static_cast<double>(m.ticks_to_form);
    if (std::isfinite(m.path_length_tu) && astar > 0) {
      ratio += m.path_length_tu / astar;
      ++ratios;
    }
  }

  ModeFigures figures() const {
    ModeFigures f;
    f.runs = runs;
    f.successes = ok;
    f.success_rate = runs > 0 ? static_cast<double>(ok) / runs : 0.0;
    f.ticks = ok > 0 ? ticks / ok : kNaN;
    f.ticks_censored = runs > 0 ? censored / runs : kNaN;
    f.path_ratio = ratios > 0 ? ratio / ratios : kNaN;
    f.resource_reduction = allocated > 0 ? rr / allocated : kNaN;
    return f;
  }
};

// the row names in order: the groups, all families, the paper arenas (when any)
std::vector<std::string> row_names(const std::vector<std::string>& groups,
                                   const std::vector<std::string>& group_of) {
  std::vector<std::string> rows;
  for (const std::string& g : groups) {
    if (g != "paper") rows.push_back(g);
  }
  rows.push_back(kAll);
  if (std::find(group_of.begin(), group_of.end(), "paper") != group_of.end()) rows.push_back(kPaper);
  return rows;
}

bool in_row(const std::string& row, const std::string& group) {
  if (row == kAll) return group != "paper";
  if (row == kPaper) return group == "paper";
  return row == group;
}

std::string cell(double v, int digits) { return std::isnan(v) ? "-" : fixed(v, digits); }

std::string pct(double v) { return fixed(100.0 * v, 0) + " %"; }

std::string signed_text(double v, int digits) {
  if (std::isnan(v)) return "-";
  return (v > 0 ? "+" : "") + fixed(v, digits);
}

nlohmann::ordered_json or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json figures_json(const ModeFigures& f) {
  return {{"runs", f.runs},
          {"successes", f.successes},
          {"success_rate", f.success_rate},
          {"ticks_to_form", or_null(f.ticks)},
          {"ticks_censored", or_null(f.ticks_censored)},
          {"path_ratio_to_astar", or_null(f.path_ratio)},
          {"resource_reduction_pct", or_null(f.resource_reduction)}};
}

nlohmann::ordered_json paired_json(const PairedFigures& p) {
  return {{"both_formed", p.both},
          {"ticks_params", or_null(p.ticks_a)},
          {"ticks_against", or_null(p.ticks_b)},
          {"only_params", p.only_a},
          {"only_against", p.only_b}};
}

}  // namespace

std::vector<BenchmarkRow> benchmark_rows(const std::vector<std::string>& groups,
                                         const std::vector<std::string>& group_of,
                                         const std::vector<double>& astar8_tu,
                                         const std::vector<GridRun>& runs) {
  std::vector<BenchmarkRow> rows;
  for (const std::string& name : row_names(groups, group_of)) {
    Sums pf, ta;
    std::vector<bool> arena(group_of.size(), false);
    for (const GridRun& r : runs) {
      if (!in_row(name, group_of[r.c.scenario])) continue;
      arena[r.c.scenario] = true;
      (r.c.mode == sim::Mode::kTaskAllocation ? ta : pf).add(r, astar8_tu[r.c.scenario]);
    }
    rows.push_back(
        {name, static_cast<int>(std::count(arena.begin(), arena.end(), true)), pf.figures(), ta.figures()});
  }
  return rows;
}

std::vector<BenchmarkDifference> benchmark_differences(const std::vector<std::string>& groups,
                                                       const std::vector<std::string>& group_of,
                                                       const std::vector<GridRun>& runs_a,
                                                       const std::vector<GridRun>& runs_b) {
  std::vector<BenchmarkDifference> out;
  for (const std::string& name : row_names(groups, group_of)) {
    BenchmarkDifference d;
    d.group = name;
    double sum_a[2] = {0, 0}, sum_b[2] = {0, 0};
    for (std::size_t i = 0; i < runs_a.size(); ++i) {
      const GridRun& a = runs_a[i];
      const GridRun& b = runs_b[i];
      if (!in_row(name, group_of[a.c.scenario])) continue;
      const int k = a.c.mode == sim::Mode::kTaskAllocation ? 1 : 0;
      PairedFigures& p = k == 1 ? d.ta : d.pf;
      if (a.m.success && b.m.success) {
        ++p.both;
        sum_a[k] += static_cast<double>(a.m.ticks_to_form);
        sum_b[k] += static_cast<double>(b.m.ticks_to_form);
      } else if (a.m.success) {
        ++p.only_a;
      } else if (b.m.success) {
        ++p.only_b;
      }
    }
    for (int k = 0; k < 2; ++k) {
      PairedFigures& p = k == 1 ? d.ta : d.pf;
      p.ticks_a = p.both > 0 ? sum_a[k] / p.both : kNaN;
      p.ticks_b = p.both > 0 ? sum_b[k] / p.both : kNaN;
    }
    out.push_back(d);
  }
  return out;
}

Verdict benchmark_verdict(const BenchmarkRow& all_a, const BenchmarkRow& all_b,
                          const BenchmarkDifference& all, bool pf, bool ta) {
  Verdict v{true, ""};
  const auto judge = [&](const char* name, const ModeFigures& a, const ModeFigures& b,
                         const PairedFigures& p) {
    const bool more = a.success_rate > b.success_rate;
    const bool not_slower = !(p.ticks_a > p.ticks_b);
    v.wins = v.wins && more && not_slower;
    v.text += std::string(v.text.empty() ? "" : "; ") + name + ": success " + pct(a.success_rate) + " vs " +
              pct(b.success_rate) + (more ? " (higher)" : " (not higher)") +
              ", mean ticks to form over the " + std::to_string(p.both) + " runs both formed " +
              cell(p.ticks_a, 0) + " vs " + cell(p.ticks_b, 0) + (not_slower ? " (no higher)" : " (higher)");
  };
  if (pf) judge("without TA", all_a.pf, all_b.pf, all.pf);
  if (ta) judge("with TA", all_a.ta, all_b.ta, all.ta);
  return v;
}

void write_benchmark_markdown(std::ostream& out, const std::vector<BenchmarkRow>& rows, bool pf, bool ta) {
  out << "| arenas | n |";
  if (pf) out << " success without TA | time without TA | (failures at T_max) | path / A* without TA |";
  if (ta)
    out << " success with TA | time with TA | (failures at T_max) | path / A* with TA | resource reduction "
           "(%) |";
  out << "\n|---|---|" << (pf ? "---|---|---|---|" : "") << (ta ? "---|---|---|---|---|" : "") << "\n";
  for (const BenchmarkRow& r : rows) {
    out << "| " << (r.group == kAll ? "**" + r.group + "**" : r.group) << " | " << r.arenas << " |";
    if (pf) {
      out << " " << pct(r.pf.success_rate) << " | " << cell(r.pf.ticks, 0) << " | "
          << cell(r.pf.ticks_censored, 0) << " | " << cell(r.pf.path_ratio, 3) << " |";
    }
    if (ta) {
      out << " " << pct(r.ta.success_rate) << " | " << cell(r.ta.ticks, 0) << " | "
          << cell(r.ta.ticks_censored, 0) << " | " << cell(r.ta.path_ratio, 3) << " | "
          << cell(r.ta.resource_reduction, 1) << " |";
    }
    out << "\n";
  }
  out << "\nTimes in ticks (0.1 s) to form the path and path / A* are means over the runs that formed it; "
         "\"failures at T_max\" counts every run, a failure as its T_max. Resource reduction: SPEC §4.3, "
         "over "
         "the runs that allocated.\n";
}

void write_difference_markdown(std::ostream& out, const std::vector<BenchmarkRow>& a,
                               const std::vector<BenchmarkRow>& b, const std::vector<BenchmarkDifference>& d,
                               bool pf, bool ta) {
  out << "| arenas |";
  if (pf) out << " success without TA, A - B | time without TA, A / B (runs both formed) |";
  if (ta) out << " success with TA, A - B | time with TA, A / B (runs both formed) |";
  out << "\n|---|" << (pf ? "---|---|" : "") << (ta ? "---|---|" : "") << "\n";
  const auto time = [](const PairedFigures& p) {
    return cell(p.ticks_a, 0) + " / " + cell(p.ticks_b, 0) + " (" + std::to_string(p.both) + " runs)";
  };
  for (std::size_t i = 0; i < d.size(); ++i) {
    out << "| " << (d[i].group == kAll ? "**" + d[i].group + "**" : d[i].group) << " |";
    if (pf)
      out << " " << signed_text(100.0 * (a[i].pf.success_rate - b[i].pf.success_rate), 0) << " pts | "
          << time(d[i].pf) << " |";
    if (ta)
      out << " " << signed_text(100.0 * (a[i].ta.success_rate - b[i].ta.success_rate), 0) << " pts | "
          << time(d[i].ta) << " |";
    out << "\n";
  }
}

nlohmann::ordered_json benchmark_rows_json(const std::vector<BenchmarkRow>& rows) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const BenchmarkRow& r : rows) {
    j.push_back(
        {{"arenas", r.group}, {"n", r.arenas}, {"pf", figures_json(r.pf)}, {"ta", figures_json(r.ta)}});
  }
  return j;
}

nlohmann::ordered_json benchmark_differences_json(const std::vector<BenchmarkDifference>& d) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const BenchmarkDifference& x : d) {
    j.push_back({{"arenas", x.group}, {"pf", paired_json(x.pf)}, {"ta", paired_json(x.ta)}});
  }
  return j;
}

void write_success_svg(std::ostream& out, const std::string& title, const std::string& subtitle,
                       const std::vector<std::string>& groups, const std::vector<BarSet>& bars) {
  const double group_w = 22.0 * static_cast<double>(std::max<std::size_t>(1, bars.size())) + 18.0;
  evolve::PlotArea a;
  a.left = 64.0, a.top = 48.0 + 16.0 * static_cast<double>(bars.size());
  a.width = group_w * static_cast<double>(groups.size()), a.height = 260.0;
  a.y = evolve::Axis{0.0, 100.0, 20.0};
  a.x = evolve::Axis{0.0, static_cast<double>(groups.size()), 1.0};
  const double width = std::max(560.0, a.left + a.width + 20.0), height = a.top + a.height + 90.0;
  evolve::write_svg_open(out, width, height, title, subtitle);
  out << "<g stroke=\"#e4e4dc\" font-size=\"11\" text-anchor=\"end\">\n";
  for (double v = 0.0; v <= 100.0; v += 20.0) {
    out << "<line x1=\"" << a.left << "\" y1=\"" << a.py(v) << "\" x2=\"" << a.left + a.width << "\" y2=\""
        << a.py(v) << "\"/><text stroke=\"none\" x=\"" << a.left - 6 << "\" y=\"" << a.py(v) + 4 << "\">"
        << static_cast<int>(v) << " %</text>\n";
  }
  out << "</g>\n";
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const double x0 = a.left + group_w * static_cast<double>(g) + 9.0;
    for (std::size_t b = 0; b < bars.size(); ++b) {
      const double v = 100.0 * bars[b].values[g];
      out << "<rect x=\"" << x0 + 22.0 * static_cast<double>(b) << "\" y=\"" << a.py(v)
          << "\" width=\"18\" height=\"" << a.py(0.0) - a.py(v) << "\" fill=\"" << bars[b].color
          << "\"><title>" << evolve::xml_escape(bars[b].label) << ", " << evolve::xml_escape(groups[g])
          << ": " << fixed(v, 0) << " %</title></rect>\n";
    }
    const double cx = x0 + 0.5 * (group_w - 18.0), cy = a.top + a.height + 12.0;
    out << "<text x=\"" << cx << "\" y=\"" << cy
        << "\" font-size=\"11\" text-anchor=\"end\" transform=\"rotate(-35 " << cx << ' ' << cy << ")\">"
        << evolve::xml_escape(groups[g]) << "</text>\n";
  }
  out << "<rect x=\"" << a.left << "\" y=\"" << a.top << "\" width=\"" << a.width << "\" height=\""
      << a.height << "\" fill=\"none\" stroke=\"#999\"/>\n";
  for (std::size_t b = 0; b < bars.size(); ++b) {
    const double ly = 52.0 + 16.0 * static_cast<double>(b);
    out << "<rect x=\"" << a.left << "\" y=\"" << ly - 10 << "\" width=\"14\" height=\"10\" fill=\""
        << bars[b].color << "\"/><text x=\"" << a.left + 20 << "\" y=\"" << ly << "\" font-size=\"12\">"
        << evolve::xml_escape(bars[b].label) << "</text>\n";
  }
  out << "</svg>\n";
}

}  // namespace swarmpath::app
