// SPDX-License-Identifier: MIT
#include "robustness_output.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "common.hpp"
#include "evolve/svg_plot.hpp"
#include "evolve/xml_escape.hpp"
#include "fault_options.hpp"
#include "sim/hash.hpp"

namespace swarmpath::app {

namespace {

std::string cell(double v, int digits) { return std::isnan(v) ? "-" : fixed(v, digits); }

nlohmann::json number_or_null(double v) {
  return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v);
}

std::string pct(double fraction) { return fixed(100.0 * fraction, 0) + " %"; }

std::string mode_name(sim::Mode m) { return std::string(sim::to_string(m)); }

bool ta(sim::Mode m) { return m == sim::Mode::kTaskAllocation; }

std::optional<std::size_t> index_of(const std::vector<double>& v, double x) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::fabs(v[i] - x) < 1e-12) return i;
  }
  return std::nullopt;
}

// the rows of a mode: one per packet loss with task allocation; one (any loss) without
std::vector<std::size_t> loss_rows(const RobustnessReport& r, sim::Mode m) {
  if (!uses_radio(m, r.grid)) return {0};
  std::vector<std::size_t> rows(r.grid.packet_losses.size());
  for (std::size_t l = 0; l < rows.size(); ++l) rows[l] = l;
  return rows;
}

std::string loss_label(const RobustnessReport& r, sim::Mode m, std::size_t l) {
  return uses_radio(m, r.grid) ? pct(r.grid.packet_losses[l]) : std::string("any (no radio)");
}

template <typename F>
void measure_table(std::ostream& out, const RobustnessReport& r, const std::string& title, F value) {
  out << "### " << title << "\n\n| mode | packet loss |";
  for (const double f : r.grid.fail_fractions) out << " " << pct(f) << " failing |";
  out << "\n|---|---|";
  for (std::size_t i = 0; i < r.grid.fail_fractions.size(); ++i) out << "---|";
  out << "\n";
  for (const sim::Mode m : r.modes) {
    for (const std::size_t l : loss_rows(r, m)) {
      out << "| " << mode_name(m) << " | " << loss_label(r, m, l) << " |";
      for (std::size_t f = 0; f < r.grid.fail_fractions.size(); ++f)
        out << " " << value(r.at(m, f, l)) << " |";
      out << "\n";
    }
  }
  out << "\n";
}

}  // namespace

std::optional<double> success_drop_at_10pct(const RobustnessReport& r, sim::Mode mode,
                                            const std::string& group) {
  const auto f0 = index_of(r.grid.fail_fractions, 0.0);
  const auto f10 = index_of(r.grid.fail_fractions, 0.1);
  const auto l0 = index_of(r.grid.packet_losses, 0.0);
  if (!f0 || !f10 || !l0 || std::find(r.modes.begin(), r.modes.end(), mode) == r.modes.end())
    return std::nullopt;
  if (!group.empty())
    return r.at(group, mode, *f0, *l0).success_pct - r.at(group, mode, *f10, *l0).success_pct;
  return r.at(mode, *f0, *l0).success_pct - r.at(mode, *f10, *l0).success_pct;
}

void write_robustness_markdown(std::ostream& out, const RobustnessReport& r) {
  measure_table(out, r, "Success (% of runs)", [](const RobustnessCell& c) {
    return cell(c.success_pct, 1) + " (" + std::to_string(c.runs) + ")";
  });
  measure_table(out, r, "Time to form the path (mean T_form of the successful runs, ticks)",
                [](const RobustnessCell& c) { return cell(c.ticks_to_form, 0); });
  measure_table(out, r, "Path / A* (mean of the successful runs)",
                [](const RobustnessCell& c) { return cell(c.ratio_to_astar, 3); });
  measure_table(
      out, r, "Robots failed per run before it ended (mean; holding a chain link)",
      [](const RobustnessCell& c) { return cell(c.failures, 1) + " (" + cell(c.chain_failures, 1) + ")"; });
  // success per group of arenas (the paper's, the benchmark's), when there are several
  if (!r.groups.empty() && !r.per_group.empty()) {
    out << "### Success per arena group (% of runs)\n\n| arenas | mode | packet loss |";
    for (const double f : r.grid.fail_fractions) out << " " << pct(f) << " failing |";
    out << "\n|---|---|---|";
    for (std::size_t i = 0; i < r.grid.fail_fractions.size(); ++i) out << "---|";
    out << "\n";
    for (const std::string& g : r.groups) {
      for (const sim::Mode m : r.modes) {
        for (const std::size_t l : loss_rows(r, m)) {
          out << "| " << g << " | " << mode_name(m) << " | " << loss_label(r, m, l) << " |";
          for (std::size_t f = 0; f < r.grid.fail_fractions.size(); ++f) {
            const RobustnessCell& c = r.at(g, m, f, l);
            out << " " << cell(c.success_pct, 1) << " (" << c.runs << ") |";
          }
          out << "\n";
        }
      }
    }
    out << "\n";
  }
  // success per scenario, one table per packet loss
  for (std::size_t l = 0; l < r.grid.packet_losses.size(); ++l) {
    std::vector<sim::Mode> shown;
    for (const sim::Mode m : r.modes) {
      if (l == 0 || uses_radio(m, r.grid)) shown.push_back(m);
    }
    if (shown.empty()) continue;
    out << "### Success per scenario (%), packet loss " << pct(r.grid.packet_losses[l])
        << (l == 0 || r.grid.pf_radio ? "" : " (task allocation only: path formation uses no radio)")
        << "\n\n| scenario |";
    for (const sim::Mode m : shown) {
      for (const double f : r.grid.fail_fractions) out << " " << mode_name(m) << " " << pct(f) << " |";
    }
    out << "\n|---|";
    for (std::size_t i = 0; i < shown.size() * r.grid.fail_fractions.size(); ++i) out << "---|";
    out << "\n";
    for (const std::string& s : r.scenarios) {
      out << "| " << s << " |";
      for (const sim::Mode m : shown) {
        for (std::size_t f = 0; f < r.grid.fail_fractions.size(); ++f) {
          for (const RobustnessCell& c : r.per_scenario) {
            if (c.scenario == s && c.mode == m && c.fail == f && c.loss == l)
              out << " " << cell(c.success_pct, 0) << " |";
          }
        }
      }
      out << "\n";
    }
    out << "\n";
  }
  std::vector<std::string> over{""};  // every scenario, then each group
  if (!r.per_group.empty()) over.insert(over.end(), r.groups.begin(), r.groups.end());
  for (const std::string& g : over) {
    for (const sim::Mode m : r.modes) {
      if (const auto drop = success_drop_at_10pct(r, m, g)) {
        out << "- " << (g.empty() ? "" : g + ", ") << (ta(m) ? "with" : "without")
            << " task allocation, 10 % of the robots failing: success "
            << (*drop >= 0 ? "drops by " : "rises by ") << fixed(std::fabs(*drop), 1)
            << " points (target: at most 10): " << (*drop <= 10.0 ? "met" : "missed") << "\n";
      }
    }
  }
}

nlohmann::ordered_json robustness_json(const RobustnessReport& r, const std::vector<sim::Scenario>& variants,
                                       const std::vector<GridRun>& runs,
                                       const std::vector<Variant>& variant_of,
                                       const std::vector<double>& astar8_tu) {
  const auto cell_json = [&](const RobustnessCell& c) {
    nlohmann::ordered_json o;
    if (!c.scenario.empty()) o["scenario"] = c.scenario;
    o["mode"] = mode_name(c.mode);
    o["fail_fraction"] = r.grid.fail_fractions[c.fail];
    o["packet_loss"] =
        uses_radio(c.mode, r.grid) ? nlohmann::json(r.grid.packet_losses[c.loss]) : nlohmann::json("any");
    o["runs"] = c.runs;
    o["successes"] = c.successes;
    o["success_pct"] = number_or_null(c.success_pct);
    o["ticks_to_form"] = number_or_null(c.ticks_to_form);
    o["ratio_to_astar"] = number_or_null(c.ratio_to_astar);
    o["failures"] = number_or_null(c.failures);
    o["chain_failures"] = number_or_null(c.chain_failures);
    if (ta(c.mode)) o["allocated"] = number_or_null(c.allocated);
    return o;
  };
  nlohmann::ordered_json j;
  j["fail_fractions"] = r.grid.fail_fractions;
  j["packet_losses"] = r.grid.packet_losses;
  j["path_formation_uses_radio"] = r.grid.pf_radio;
  nlohmann::ordered_json modes = nlohmann::ordered_json::array();
  for (const sim::Mode m : r.modes) modes.push_back(mode_name(m));
  j["modes"] = modes;
  j["scenarios"] = r.scenarios;
  j["note"] =
      "path formation never listens to the range-and-bearing medium: its runs at the first packet loss stand "
      "for every packet loss";
  nlohmann::ordered_json cells = nlohmann::ordered_json::array();
  for (std::size_t m = 0; m < r.modes.size(); ++m) {
    for (const RobustnessCell& c : r.overall) {
      if (c.mode == r.modes[m] && (uses_radio(c.mode, r.grid) || c.loss == 0)) cells.push_back(cell_json(c));
    }
  }
  j["cells"] = cells;
  nlohmann::ordered_json per = nlohmann::ordered_json::array();
  for (const RobustnessCell& c : r.per_scenario) {
    if (uses_radio(c.mode, r.grid) || c.loss == 0) per.push_back(cell_json(c));
  }
  j["scenario_cells"] = per;
  if (!r.per_group.empty()) {
    j["groups"] = r.groups;
    nlohmann::ordered_json groups = nlohmann::ordered_json::array();
    for (const RobustnessCell& c : r.per_group) {
      if (uses_radio(c.mode, r.grid) || c.loss == 0) groups.push_back(cell_json(c));
    }
    j["group_cells"] = groups;
  }
  nlohmann::ordered_json target;
  for (const sim::Mode m : r.modes) {
    if (const auto drop = success_drop_at_10pct(r, m))
      target[mode_name(m)] = {{"success_drop_points", *drop}, {"met", *drop <= 10.0}};
  }
  j["target_drop_at_10pct_failing"] = target;
  nlohmann::ordered_json rs = nlohmann::ordered_json::array();
  for (const GridRun& run : runs) {
    const Variant& v = variant_of[run.c.scenario];
    const sim::Scenario& s = variants[run.c.scenario];
    const sim::Metrics& m = run.m;
    nlohmann::ordered_json o;
    o["scenario"] = s.name;
    o["robots"] = run.c.robots;
    o["seed"] = run.c.seed;
    o["mode"] = mode_name(run.c.mode);
    o["fail_fraction"] = r.grid.fail_fractions[v.fail];
    o["packet_loss"] =
        uses_radio(run.c.mode, r.grid) ? nlohmann::json(r.grid.packet_losses[v.loss]) : nlohmann::json("any");
    o["success"] = m.success;
    o["ticks"] = m.ticks;
    o["ticks_to_form"] = m.ticks_to_form < 0 ? nlohmann::json(nullptr) : nlohmann::json(m.ticks_to_form);
    o["path_length_tu"] = number_or_null(m.success ? m.path_length_tu : std::nan(""));
    o["astar8_tu"] = astar8_tu[v.scenario];
    o["failures"] = m.failures;
    o["chain_failures"] = m.chain_failures;
    if (ta(run.c.mode)) o["allocated"] = m.allocated;
    o["state_hash"] = sim::to_hex(m.state_hash);
    rs.push_back(o);
  }
  j["runs"] = rs;
  return j;
}

void write_robustness_svg(std::ostream& out, const RobustnessReport& r, const std::string& subtitle) {
  // three panels side by side: success, T_form, path / A* against the failure fraction (%)
  const double panel_w = 330.0, panel_h = 260.0, left = 72.0, gap = 86.0, top = 56.0;
  const double width = left + 3 * panel_w + 2 * gap + 24.0;
  const std::size_t rows = [&] {
    std::size_t n = 0;
    for (const sim::Mode m : r.modes) n += loss_rows(r, m).size();
    return n;
  }();
  const double height = top + panel_h + 56.0 + 18.0 * static_cast<double>(rows) + 10.0;
  evolve::write_svg_open(out, width, height, "Robustness: success, time and path against robots failing",
                         subtitle);
  std::vector<double> xs;
  for (const double f : r.grid.fail_fractions) xs.push_back(100.0 * f);
  // one line per (mode, packet loss): path formation black; task allocation blue, orange, red, ...
  static const char* kLossColours[] = {"#1f4fff", "#ff8c00", "#d62728", "#9b30d0", "#2ca02c"};
  const auto colour = [&](sim::Mode m, std::size_t l) {
    if (ta(m)) return std::string(kLossColours[l % 5]);
    static const char* kGreys[] = {"#222222", "#666666", "#999999", "#bbbbbb", "#dddddd"};
    return std::string(kGreys[l % 5]);
  };

  struct Measure {
    const char* title;
    double (*get)(const RobustnessCell&);
  };

  const Measure measures[] = {
      {"success (% of runs)", [](const RobustnessCell& c) { return c.success_pct; }},
      {"mean T_form of successes (ticks)", [](const RobustnessCell& c) { return c.ticks_to_form; }},
      {"mean path / A* of successes", [](const RobustnessCell& c) { return c.ratio_to_astar; }},
  };
  for (std::size_t k = 0; k < 3; ++k) {
    evolve::PlotArea a;
    a.left = left + static_cast<double>(k) * (panel_w + gap);
    a.top = top;
    a.width = panel_w;
    a.height = panel_h;
    a.x = evolve::Axis::over(xs);
    std::vector<double> ys;
    for (const RobustnessCell& c : r.overall) ys.push_back(measures[k].get(c));
    if (k == 0) ys.insert(ys.end(), {0.0, 100.0});
    a.y = evolve::Axis::over(ys);
    evolve::write_frame(out, a, "robots failing (%)", measures[k].title);
    for (const sim::Mode m : r.modes) {
      for (const std::size_t l : loss_rows(r, m)) {
        out << "<polyline fill=\"none\" stroke=\"" << colour(m, l) << "\" stroke-width=\"2\""
            << (ta(m) ? "" : " stroke-dasharray=\"6 3\"") << " points=\"";
        for (std::size_t f = 0; f < xs.size(); ++f) {
          const double y = measures[k].get(r.at(m, f, l));
          if (!std::isnan(y)) out << a.px(xs[f]) << ',' << a.py(y) << ' ';
        }
        out << "\"/>\n";
        for (std::size_t f = 0; f < xs.size(); ++f) {
          const double y = measures[k].get(r.at(m, f, l));
          if (!std::isnan(y))
            out << "<circle cx=\"" << a.px(xs[f]) << "\" cy=\"" << a.py(y) << "\" r=\"3\" fill=\""
                << colour(m, l) << "\"/>\n";
        }
      }
    }
  }
  double ly = top + panel_h + 56.0;
  for (const sim::Mode m : r.modes) {
    for (const std::size_t l : loss_rows(r, m)) {
      const std::string label = std::string(ta(m) ? "with task allocation" : "without task allocation") +
                                (uses_radio(m, r.grid) ? ", packet loss " + pct(r.grid.packet_losses[l])
                                                       : ", any packet loss (no radio)");
      out << "<line x1=\"" << left << "\" y1=\"" << ly - 4 << "\" x2=\"" << left + 30 << "\" y2=\"" << ly - 4
          << "\" stroke=\"" << colour(m, l) << "\" stroke-width=\"3\""
          << (ta(m) ? "" : " stroke-dasharray=\"6 3\"") << "/><text x=\"" << left + 38 << "\" y=\"" << ly
          << "\" font-size=\"12\">" << evolve::xml_escape(label) << "</text>\n";
      ly += 18.0;
    }
  }
  out << "</svg>\n";
}

}  // namespace swarmpath::app
