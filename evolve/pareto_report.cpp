// SPDX-License-Identifier: MIT
#include "pareto_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "evolve/params_export.hpp"
#include "evolve/report.hpp"
#include "evolve/svg_plot.hpp"
#include "evolve/xml_escape.hpp"

namespace swarmpath::evolve {

namespace {

std::string csv_number(double v) { return std::isfinite(v) ? exact(v) : std::string(); }

std::string base_name(const EvolveConfig& c) {
  return c.params_written.empty() ? "paper defaults"
                                  : std::filesystem::path(c.params_written).filename().string();
}

nlohmann::ordered_json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

// One {mean, ci95_low, ci95_high, n} object per objective, keyed by its name.
nlohmann::ordered_json intervals_json(const std::vector<ObjectiveKind>& objectives,
                                      const std::vector<Interval>& intervals) {
  nlohmann::ordered_json j;
  for (std::size_t k = 0; k < objectives.size(); ++k) {
    const Interval& i = intervals[k];
    j[std::string(objective_name(objectives[k]))] = {{"mean", number_or_null(i.mean)},
                                                     {"ci95_low", number_or_null(i.lower())},
                                                     {"ci95_high", number_or_null(i.upper())},
                                                     {"n", i.n}};
  }
  return j;
}

nlohmann::ordered_json point_json(const EvolveConfig& c, const FrontPoint& p, bool base) {
  nlohmann::ordered_json j;
  if (!base) {
    j["generation"] = p.elite.generation;
    j["candidate"] = p.elite.candidate;
    j["generation_stats"] = stats_json(p.elite.stats);
    nlohmann::ordered_json gen;
    for (std::size_t k = 0; k < c.multi.objectives.size(); ++k) {
      gen[std::string(objective_name(c.multi.objectives[k]))] = p.objectives[k];
    }
    j["generation_objectives"] = gen;
  }
  j["reevaluated_objectives"] = intervals_json(c.multi.objectives, p.intervals);
  j["reevaluated"] = stats_json(p.reevaluated);
  j["held_out"] = p.held_out.runs > 0 ? stats_json(p.held_out) : nlohmann::ordered_json(nullptr);
  j["feasible_after_reevaluation"] = p.reevaluated_violation <= 0.0;
  if (!base) {
    j["dominated_after_reevaluation"] = p.dominated_after_reevaluation;
    j["dominates_base"] = p.dominates_base;
    j["minus_base_paired"] = intervals_json(c.multi.objectives, p.versus_base);
  }
  nlohmann::ordered_json tuned;
  for (const Gene& g : c.genome.genes) tuned[std::string(g.info->name)] = param_value_json(p.params, *g.info);
  j["tuned"] = tuned;
  if (!base) j["x"] = p.elite.x;
  return j;
}

}  // namespace

std::string objective_title(ObjectiveKind k) {
  switch (k) {
    case ObjectiveKind::kPathRatio:
      return "path / A*";
    case ObjectiveKind::kTicks:
      return "ticks to form";
    case ObjectiveKind::kRobotsFraction:
      return "robots used / N";
  }
  return "?";
}

std::string objective_text(ObjectiveKind k, double v) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(k == ObjectiveKind::kTicks ? 0 : 3) << v;
  return o.str();
}

std::string interval_text(ObjectiveKind k, const Interval& i) {
  if (!std::isfinite(i.half_width)) return objective_text(k, i.mean);
  return objective_text(k, i.mean) + " +- " + objective_text(k, i.half_width);
}

void write_pareto_log_csv(std::ostream& out, const std::vector<GenerationRecord>& history,
                          const std::vector<ObjectiveKind>& kinds) {
  out << "generation,hypervolume,front_size,feasible,best_success_rate";
  for (const ObjectiveKind k : kinds) out << ",min_" << objective_name(k);
  out << ",evaluations,seconds\n";
  for (const GenerationRecord& r : history) {
    out << r.generation << ',' << exact(r.hypervolume) << ',' << r.front_size << ',' << r.feasible << ','
        << exact(r.best_success_rate);
    for (std::size_t k = 0; k < kinds.size(); ++k) {
      out << ',' << (k < r.front_min.size() ? exact(r.front_min[k]) : std::string());
    }
    out << ',' << r.evaluations << ',' << exact(r.seconds) << '\n';
  }
}

void write_hypervolume_svg(std::ostream& out, const std::string& title,
                           const std::vector<GenerationRecord>& history) {
  Series hv{"hypervolume", "#00a651", {}};
  for (const GenerationRecord& r : history) hv.values.push_back(r.hypervolume);
  write_line_chart(out, title, "hypervolume of the feasible front per generation (higher is better)",
                   "hypervolume", {hv});
}

std::string front_file_name(std::size_t i) {
  std::ostringstream o;
  o << std::setw(3) << std::setfill('0') << i << ".toml";
  return o.str();
}

void write_pareto_csv(std::ostream& out, const EvolveConfig& c, const ParetoResult& r) {
  const std::vector<ObjectiveKind>& kinds = c.multi.objectives;
  out << "point,generation,candidate";
  for (const Gene& g : c.genome.genes) out << ',' << g.info->name;
  for (const ObjectiveKind k : kinds) out << ",gen_" << objective_name(k);
  out << ",gen_success_rate";
  for (const ObjectiveKind k : kinds) {
    const std::string_view n = objective_name(k);
    out << ',' << n << "_mean," << n << "_ci95_low," << n << "_ci95_high," << n << "_n";
  }
  out << ",success_rate,runs,feasible,dominated_after_reevaluation,dominates_base";
  for (const ObjectiveKind k : kinds) {
    const std::string_view n = objective_name(k);
    out << ',' << n << "_vs_base_mean," << n << "_vs_base_ci95_low," << n << "_vs_base_ci95_high," << n
        << "_vs_base_n";
  }
  out << ",params_file\n";
  const auto row = [&](const FrontPoint& p, const std::string& label, bool base) {
    out << label << ',' << (base ? "" : std::to_string(p.elite.generation)) << ','
        << (base ? "" : std::to_string(p.elite.candidate));
    for (const Gene& g : c.genome.genes) out << ',' << sim::format_value(p.params, *g.info);
    for (std::size_t k = 0; k < kinds.size(); ++k) out << ',' << (base ? "" : csv_number(p.objectives[k]));
    out << ',' << (base ? "" : exact(p.elite.stats.success_rate));
    for (const Interval& i : p.intervals) {
      out << ',' << csv_number(i.mean) << ',' << csv_number(i.lower()) << ',' << csv_number(i.upper()) << ','
          << i.n;
    }
    const auto flag = [&](bool v) { return base ? "" : v ? "1" : "0"; };
    out << ',' << exact(p.reevaluated.success_rate) << ',' << p.reevaluated.runs << ','
        << (p.reevaluated_violation <= 0.0 ? 1 : 0) << ',' << flag(p.dominated_after_reevaluation) << ','
        << flag(p.dominates_base) << ',';
    for (std::size_t k = 0; k < kinds.size(); ++k) {
      if (base) {
        out << ",,,,";
        continue;
      }
      const Interval& d = p.versus_base[k];
      out << csv_number(d.mean) << ',' << csv_number(d.lower()) << ',' << csv_number(d.upper()) << ',' << d.n
          << ',';
    }
    out << (base ? (c.params_written.empty() ? "" : c.params_written) : "front/" + label + ".toml") << '\n';
  };
  for (std::size_t i = 0; i < r.front.size(); ++i) {
    std::string name = front_file_name(i);
    name.resize(name.size() - 5);  // without ".toml"
    row(r.front[i], name, false);
  }
  row(r.base, "base", true);
}

std::string front_point_toml(const EvolveConfig& c, const ParetoResult& r, std::size_t i) {
  const FrontPoint& p = r.front.at(i);
  const BuildInfo b = build_info();
  std::ostringstream h;
  h << "# swarmpath evolve: point " << i << " of the final Pareto front of run \"" << c.name << "\" (config "
    << c.file << ", hash " << config_hash(c) << ", swarmpath " << b.version << ", git " << b.git_commit
    << ").\n";
  h << "# Found in generation " << p.elite.generation << " (candidate " << p.elite.candidate << "). On "
    << p.reevaluated.runs << " fresh runs: success rate " << short_text(p.reevaluated.success_rate);
  for (std::size_t k = 0; k < c.multi.objectives.size(); ++k) {
    h << ", " << objective_name(c.multi.objectives[k]) << ' '
      << interval_text(c.multi.objectives[k], p.intervals[k]);
  }
  h << " (mean +- 95 % CI).\n# Minus the base params, paired on the same runs:";
  for (std::size_t k = 0; k < c.multi.objectives.size(); ++k) {
    h << (k ? ", " : " ") << objective_name(c.multi.objectives[k]) << ' '
      << interval_text(c.multi.objectives[k], p.versus_base[k]);
  }
  h << ".\n# " << (p.dominated_after_reevaluation ? "Dominated" : "Not dominated")
    << " by another front point after re-evaluation; "
    << (p.dominates_base ? "dominates" : "does not dominate") << " the base params (" << base_name(c)
    << ") on the same fresh seeds.\n";
  h << "# Mode " << sim::to_string(c.mode) << "; tuned:";
  for (const Gene& g : c.genome.genes) h << ' ' << g.info->name;
  h << "; the others as in " << (c.params_written.empty() ? "the paper's defaults" : c.params_written)
    << ".\n\n";
  std::ostringstream out;
  sim::write_params_toml(out, p.params, h.str());
  return out.str();
}

void write_pareto_svg(std::ostream& out, const EvolveConfig& c, const ParetoResult& r) {
  const std::vector<ObjectiveKind>& kinds = c.multi.objectives;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < kinds.size(); ++a) {
    for (std::size_t b = a + 1; b < kinds.size(); ++b) pairs.emplace_back(a, b);
  }
  const double panel_w = 340.0, panel_h = 300.0, gap = 90.0, left = 78.0, top = 60.0;
  // at least wide enough for the subtitle and the legend when there is a single panel (2 objectives)
  const double width =
      std::max(720.0, left + static_cast<double>(pairs.size()) * (panel_w + gap) - gap + 30.0);
  const double height = top + panel_h + 150.0;
  std::ostringstream sub;
  sub << r.front.size() << " front points on " << r.base.reevaluated.runs
      << " fresh runs each (mean, 95 % CI); "
      << "mode " << sim::to_string(c.mode) << ", min success " << short_text(c.multi.min_success)
      << "; all objectives minimised";
  write_svg_open(out, width, height, c.name + ": Pareto front", sub.str());

  // every value a panel shows, per objective
  const auto finite_or = [](double v, double fallback) { return std::isfinite(v) ? v : fallback; };
  std::vector<Axis> axes;
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    std::vector<double> v;
    const auto add = [&](const FrontPoint& p) {
      v.push_back(p.intervals[k].mean);
      v.push_back(finite_or(p.intervals[k].lower(), p.intervals[k].mean));
      v.push_back(finite_or(p.intervals[k].upper(), p.intervals[k].mean));
    };
    for (const FrontPoint& p : r.front) {
      add(p);
      v.push_back(p.objectives[k]);
    }
    add(r.base);
    axes.push_back(Axis::over(v));
  }
  const std::string base = base_name(c);
  for (std::size_t q = 0; q < pairs.size(); ++q) {
    const auto [kx, ky] = pairs[q];
    PlotArea a;
    a.left = left + static_cast<double>(q) * (panel_w + gap), a.top = top, a.width = panel_w,
    a.height = panel_h;
    a.x = axes[kx], a.y = axes[ky];
    write_frame(out, a, objective_title(kinds[kx]), objective_title(kinds[ky]));
    const auto whiskers = [&](const FrontPoint& p, const char* color) {
      const Interval& ix = p.intervals[kx];
      const Interval& iy = p.intervals[ky];
      const double x = a.px(ix.mean), y = a.py(iy.mean);
      out << "<g stroke=\"" << color << "\" stroke-width=\"1.2\">";
      if (std::isfinite(ix.half_width)) {
        out << "<line x1=\"" << a.px(ix.lower()) << "\" y1=\"" << y << "\" x2=\"" << a.px(ix.upper())
            << "\" y2=\"" << y << "\"/>";
      }
      if (std::isfinite(iy.half_width)) {
        out << "<line x1=\"" << x << "\" y1=\"" << a.py(iy.lower()) << "\" x2=\"" << x << "\" y2=\""
            << a.py(iy.upper()) << "\"/>";
      }
      out << "</g>\n";
    };
    for (std::size_t i = 0; i < r.front.size(); ++i) {
      const FrontPoint& p = r.front[i];
      const double gx = a.px(p.objectives[kx]), gy = a.py(p.objectives[ky]);
      const double x = a.px(p.intervals[kx].mean), y = a.py(p.intervals[ky].mean);
      out << "<line x1=\"" << gx << "\" y1=\"" << gy << "\" x2=\"" << x << "\" y2=\"" << y
          << "\" stroke=\"#bbbbbb\" stroke-dasharray=\"3,2\"/><circle cx=\"" << gx << "\" cy=\"" << gy
          << "\" r=\"2.5\" fill=\"#bbbbbb\"/>\n";
      whiskers(p, "#9db7d8");
      const bool kept = !p.dominated_after_reevaluation && p.reevaluated_violation <= 0.0;
      out << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"4.5\" fill=\"" << (kept ? "#1f5fa8" : "white")
          << "\" stroke=\"" << (p.dominates_base ? "#00a651" : "#1f5fa8") << "\" stroke-width=\""
          << (p.dominates_base ? 2.5 : 1.5) << "\"><title>point " << i << "</title></circle>\n";
      out << "<text x=\"" << x + 6 << "\" y=\"" << y - 5 << "\" font-size=\"9\" fill=\"#555\">" << i
          << "</text>\n";
    }
    whiskers(r.base, "#e08080");
    const double bx = a.px(r.base.intervals[kx].mean), by = a.py(r.base.intervals[ky].mean);
    out << "<path d=\"M " << bx << ' ' << by - 7 << " L " << bx + 7 << ' ' << by << " L " << bx << ' '
        << by + 7 << " L " << bx - 7 << ' ' << by << " Z\" fill=\"#d62020\"><title>" << xml_escape(base)
        << "</title></path>\n";
    out << "<text x=\"" << bx + 9 << "\" y=\"" << by + 4 << "\" font-size=\"10\" fill=\"#d62020\">"
        << xml_escape(base) << "</text>\n";
  }
  // legend, one entry per row
  double ly = top + panel_h + 62.0;
  const double lx = left + 6.0;
  out << "<g font-size=\"12\">\n";
  const auto entry = [&](const std::string& mark, const std::string& text) {
    out << mark << "<text x=\"" << lx + 12 << "\" y=\"" << ly << "\">" << xml_escape(text) << "</text>\n";
    ly += 17.0;
  };
  const auto circle = [&](double radius, const char* fill, const char* stroke, double stroke_width) {
    std::ostringstream m;
    m << std::fixed << std::setprecision(2) << "<circle cx=\"" << lx << "\" cy=\"" << ly - 4 << "\" r=\""
      << radius << "\" fill=\"" << fill << "\" stroke=\"" << stroke << "\" stroke-width=\"" << stroke_width
      << "\"/>";
    return m.str();
  };
  entry(circle(4.5, "#1f5fa8", "#1f5fa8", 1.5),
        "front point on fresh seeds (lines: 95 % confidence intervals)");
  entry(circle(4.5, "white", "#1f5fa8", 1.5),
        "dominated by another front point, or infeasible, after re-evaluation");
  entry(circle(4.5, "#1f5fa8", "#00a651", 2.5), "dominates " + base + " on the same fresh seeds");
  entry(circle(2.5, "#bbbbbb", "none", 0.0),
        "its value during evolution (dashed line: where fresh seeds moved it)");
  {
    std::ostringstream m;
    m << std::fixed << std::setprecision(2) << "<path d=\"M " << lx << ' ' << ly - 11 << " L " << lx + 7
      << ' ' << ly - 4 << " L " << lx << ' ' << ly + 3 << " L " << lx - 7 << ' ' << ly - 4
      << " Z\" fill=\"#d62020\"/>";
    entry(m.str(), "base params (" + base + ") on the same fresh seeds");
  }
  out << "</g>\n</svg>\n";
}

nlohmann::ordered_json pareto_run_json(const EvolveConfig& c, const ParetoResult& r, int threads) {
  nlohmann::ordered_json j = run_json_common(c, r.state, r.settings, r.cases, r.reevaluation_cases, r.seconds,
                                             r.stop_reason, threads);
  j["hypervolume"] = r.hypervolume;
  j["reevaluated_hypervolume"] = r.reevaluated_hypervolume;
  nlohmann::ordered_json front = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.front.size(); ++i) {
    nlohmann::ordered_json p = point_json(c, r.front[i], false);
    p["params_file"] = "front/" + front_file_name(i);
    front.push_back(p);
  }
  j["front"] = front;
  j["base"] = point_json(c, r.base, true);
  std::size_t dominating = 0;
  for (const FrontPoint& p : r.front) dominating += p.dominates_base ? 1 : 0;
  j["points_dominating_base"] = dominating;
  return j;
}

}  // namespace swarmpath::evolve
