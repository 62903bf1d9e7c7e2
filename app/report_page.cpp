// SPDX-License-Identifier: MIT
#include "report_page.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "common.hpp"
#include "evolve/pareto_objectives.hpp"
#include "evolve/svg_plot.hpp"
#include "evolve/trajectory_svg.hpp"
#include "recording_file.hpp"
#include "sim/config_error.hpp"
#include "web_assets.hpp"

namespace swarmpath::app {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string text_or_empty(const fs::path& p) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return {};
  return read_file_bytes(p.string());
}

Json json_file(const fs::path& p) {
  const std::string text = read_file_bytes(p.string());
  try {
    return Json::parse(text);
  } catch (const std::exception& e) {
    throw sim::ConfigError(p.string(), 0, "", std::string("not valid JSON: ") + e.what());
  }
}

// a JSON number, or NaN for null / missing
double number(const Json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return kNaN;
  return j[key].get<double>();
}

std::string num(double v, int digits) { return std::isfinite(v) ? fixed(v, digits) : std::string("–"); }

std::string esc(const std::string& s) { return html_escape(s); }

// an SVG file's markup without an XML declaration, to sit inline in the page
std::string inline_svg(const std::string& svg) {
  const std::size_t at = svg.find("<svg");
  return at == std::string::npos ? std::string() : svg.substr(at);
}

std::string interval_text(const MeanInterval& m, int digits) {
  if (m.n == 0) return "–";
  if (!std::isfinite(m.half_width)) return num(m.mean, digits) + " (n = 1)";
  return num(m.mean, digits) + " ± " + num(m.half_width, digits);
}

std::string success_text(int k, int n) {
  if (n == 0) return "–";
  const auto [lo, hi] = wilson_interval(k, n);
  return fixed(100.0 * k / n, 0) + " % <span class=\"rp-ci\">[" + fixed(100.0 * lo, 0) + ", " +
         fixed(100.0 * hi, 0) + "]</span>";
}

// one side's outcomes of a group of evaluate.json runs
struct Side {
  int runs = 0, successes = 0;
  std::vector<double> ticks, path, robots;

  void add(const Json& o) {
    ++runs;
    if (o.value("success", false)) {
      ++successes;
      if (std::isfinite(number(o, "ticks_to_form"))) ticks.push_back(number(o, "ticks_to_form"));
      if (std::isfinite(number(o, "path_ratio"))) path.push_back(number(o, "path_ratio"));
    }
    if (std::isfinite(number(o, "robots_used"))) robots.push_back(number(o, "robots_used"));
  }
};

struct Group {
  std::string scenario;
  int robots = 0;
  Side a, b;
  std::vector<double> d_ticks, d_path;  // paired, both succeeded

  void add(const Json& run) {
    const Json& pa = run.at("params");
    const Json& pb = run.at("against");
    a.add(pa);
    b.add(pb);
    if (pa.value("success", false) && pb.value("success", false)) {
      d_ticks.push_back(number(pa, "ticks_to_form") - number(pb, "ticks_to_form"));
      d_path.push_back(number(pa, "path_ratio") - number(pb, "path_ratio"));
    }
  }
};

void comparison_row(std::ostream& o, const std::string& name, const std::string& robots, const Group& g) {
  o << "<tr><td>" << name << "</td><td>" << robots << "</td><td>" << g.a.runs << "</td><td>"
    << success_text(g.a.successes, g.a.runs) << "</td><td>" << success_text(g.b.successes, g.b.runs)
    << "</td><td>" << interval_text(mean_interval(g.a.ticks), 0) << "</td><td>"
    << interval_text(mean_interval(g.b.ticks), 0) << "</td><td>" << interval_text(mean_interval(g.d_ticks), 0)
    << "</td><td>" << interval_text(mean_interval(g.a.path), 3) << "</td><td>"
    << interval_text(mean_interval(g.b.path), 3) << "</td><td>" << interval_text(mean_interval(g.d_path), 3)
    << "</td><td>" << interval_text(mean_interval(g.a.robots), 1) << "</td><td>"
    << interval_text(mean_interval(g.b.robots), 1) << "</td></tr>\n";
}

// the evaluate table: best against base on the same fresh seeds, per scenario and overall
void comparison_section(std::ostream& o, const ReportInputs& in) {
  o << "<section id=\"comparison\"><h2>The reported genome against the base, on fresh seeds</h2>\n";
  if (in.evaluate && in.evaluate->contains("runs") && !(*in.evaluate)["against"].is_null()) {
    const Json& e = *in.evaluate;
    o << "<p>From <code>evaluate.json</code>: A = <code>" << esc(e.value("params", std::string("?")))
      << "</code>, B = <code>" << esc(e.value("against", std::string("?"))) << "</code>, mode "
      << esc(e.value("mode", std::string("?"))) << ", " << e.value("seeds", 0) << " seeds from "
      << e.value("seed_base", 0)
      << " per scenario and robot count. Means with 95 % intervals (Student's t; success: Wilson); ticks and "
         "path / A* over the successful runs; Δ = A − B over the runs where both formed the path (paired on "
         "the seed).</p>\n";
    std::vector<Group> groups;
    Group all;
    for (const Json& run : e.at("runs")) {
      const std::string s = run.value("scenario", std::string("?"));
      const int n = run.value("robots", 0);
      if (groups.empty() || groups.back().scenario != s || groups.back().robots != n)
        groups.push_back({s, n, {}, {}, {}, {}});
      groups.back().add(run);
      all.add(run);
    }
    o << "<div class=\"rp-scroll\"><table "
         "class=\"rp-table\"><thead><tr><th>scenario</th><th>robots</th><th>runs</th>"
         "<th>success A</th><th>success B</th><th>ticks A</th><th>ticks B</th><th>Δ ticks</th><th>path/A* "
         "A</th>"
         "<th>path/A* B</th><th>Δ path/A*</th><th>robots A</th><th>robots B</th></tr></thead><tbody>\n";
    for (const Group& g : groups) comparison_row(o, esc(g.scenario), std::to_string(g.robots), g);
    comparison_row(o, "<b>overall</b>", "", all);
    o << "</tbody></table></div>\n</section>\n";
    return;
  }
  // no evaluate.json: the re-evaluation the run itself made (means, no intervals)
  const Json& best = in.run.contains("best") ? in.run["best"] : Json();
  const Json reev = best.is_object() ? best.value("reevaluated", Json()) : Json();
  const Json base = in.run.value("base_reevaluated", Json());
  o << "<p>This folder has no <code>evaluate.json</code>; below are the run's own re-evaluation means (the "
       "finalists and the base on the same fresh seeds). For the table with intervals run <code>swarmpath "
       "evaluate "
       "--params "
    << esc(in.dir) << "/best.toml --against BASE --json " << esc(in.dir)
    << "/evaluate.json</code> (as <code>make run</code> does) and write the report again.</p>\n";
  o << "<table class=\"rp-table\"><thead><tr><th></th><th>runs</th><th>fitness</th><th>success</th><th>mean "
       "ticks</th><th>path/A*</th><th>robots used</th></tr></thead><tbody>\n";
  for (const auto& [label, s] : {std::pair<std::string, Json>{"reported genome", reev}, {"base", base}}) {
    if (!s.is_object()) continue;
    o << "<tr><td>" << label << "</td><td>" << s.value("runs", 0) << "</td><td>"
      << num(number(s, "fitness"), 4) << "</td><td>" << num(100.0 * number(s, "success_rate"), 0)
      << " %</td><td>" << num(number(s, "mean_ticks"), 0) << "</td><td>"
      << num(number(s, "mean_path_ratio"), 3) << "</td><td>" << num(number(s, "mean_robots"), 1)
      << "</td></tr>\n";
  }
  o << "</tbody></table>\n</section>\n";
}

// each tuned parameter over the generations
void parameters_section(std::ostream& o, const ReportInputs& in) {
  o << "<section id=\"parameters\"><h2>Tuned parameters over the generations</h2>\n";
  const Json& tune = in.run.at("config").at("tune");
  const Json reported =
      in.pareto
          ? (in.run.contains("front") && !in.run["front"].empty() ? in.run["front"][0].value("tuned", Json())
                                                                  : Json())
          : (in.run.contains("best") && in.run["best"].is_object() ? in.run["best"].value("tuned", Json())
                                                                   : Json());
  const Json base =
      in.pareto ? in.run.value("base", Json()).value("tuned", Json()) : in.run.value("base_tuned", Json());
  const bool has_values = !in.state.history.empty() && !in.state.history.front().tuned_mean.empty();
  o << "<p>Orange: the best candidate of each generation; blue: the population's mean and its range (valid "
       "candidates); dashed: the base value; green ring: the value of the reported genome"
    << (in.pareto ? " (front point 0)" : "") << ".</p>\n";
  if (!has_values)
    o << "<p class=\"rp-note\">This run's checkpoint predates the per-generation values: only the base and "
         "reported values are drawn.</p>\n";
  o << "<div class=\"rp-grid\">\n";
  for (std::size_t k = 0; k < tune.size(); ++k) {
    const Json& g = tune[k];
    evolve::Trajectory t;
    t.name = g.value("name", std::string("?"));
    t.lo = g.value("binary", false) ? 0.0 : number(g, "lo");
    t.hi = g.value("binary", false) ? 1.0 : number(g, "hi");
    t.base = number(base, t.name.c_str());
    t.reported = number(reported, t.name.c_str());
    if (base.is_object() && base.contains(t.name) && base[t.name].is_boolean())
      t.base = base[t.name].get<bool>() ? 1 : 0;
    if (reported.is_object() && reported.contains(t.name) && reported[t.name].is_boolean())
      t.reported = reported[t.name].get<bool>() ? 1 : 0;
    for (const evolve::GenerationRecord& r : in.state.history) {
      const auto at = [&](const std::vector<double>& v) { return k < v.size() ? v[k] : kNaN; };
      if (!r.tuned_best.empty()) t.best.push_back(at(r.tuned_best));
      if (!r.tuned_mean.empty()) {
        t.mean.push_back(at(r.tuned_mean));
        t.min.push_back(at(r.tuned_min));
        t.max.push_back(at(r.tuned_max));
      }
    }
    std::ostringstream svg;
    evolve::write_trajectory_svg(svg, t);
    o << "<figure>" << svg.str() << "</figure>\n";
  }
  o << "</div>\n</section>\n";
}

void pareto_section(std::ostream& o, const ReportInputs& in) {
  if (!in.pareto) return;
  o << "<section id=\"pareto\"><h2>Pareto front</h2>\n";
  if (!in.pareto_svg.empty()) o << "<figure class=\"rp-wide\">" << inline_svg(in.pareto_svg) << "</figure>\n";
  const Json front = in.run.value("front", Json::array());
  std::vector<std::string> objectives;
  if (!front.empty()) {
    const Json first = front[0].value("reevaluated_objectives", Json::object());
    for (const auto& item : first.items()) objectives.push_back(item.key());
  }
  o << "<p>The front re-evaluated on fresh seeds: means with 95 % intervals.</p>\n<div "
       "class=\"rp-scroll\"><table "
       "class=\"rp-table\"><thead><tr><th>point</th><th>found</th><th>success</th>";
  for (const std::string& n : objectives) o << "<th>" << esc(n) << "</th>";
  o << "<th>note</th></tr></thead><tbody>\n";
  const auto row = [&](const std::string& label, const std::string& found, const Json& p,
                       const std::string& note) {
    o << "<tr><td>" << label << "</td><td>" << found << "</td><td>"
      << num(100.0 * number(p.value("reevaluated", Json()), "success_rate"), 0) << " %</td>";
    const Json iv = p.value("reevaluated_objectives", Json::object());
    for (const std::string& n : objectives) {
      const Json x = iv.value(n, Json());
      o << "<td>" << num(number(x, "mean"), 3) << " <span class=\"rp-ci\">[" << num(number(x, "ci95_low"), 3)
        << ", " << num(number(x, "ci95_high"), 3) << "]</span></td>";
    }
    o << "<td>" << note << "</td></tr>\n";
  };
  for (std::size_t i = 0; i < front.size(); ++i) {
    const Json& p = front[i];
    std::string note;
    if (!p.value("feasible_after_reevaluation", true)) note = "infeasible after re-evaluation";
    if (p.value("dominated_after_reevaluation", false)) note = "dominated after re-evaluation";
    if (p.value("dominates_base", false))
      note += std::string(note.empty() ? "" : "; ") + "dominates the base";
    row(std::to_string(i),
        "gen " + std::to_string(p.value("generation", 0)) + " #" + std::to_string(p.value("candidate", 0)), p,
        note);
  }
  if (in.run.contains("base")) row("base", "", in.run["base"], "");
  o << "</tbody></table></div>\n</section>\n";
}

void provenance_section(std::ostream& o, const ReportInputs& in) {
  const Json& r = in.run;
  o << "<section id=\"provenance\"><h2>Config and provenance</h2>\n<table class=\"rp-table rp-kv\"><tbody>\n";
  const auto kv = [&](const std::string& k, const std::string& v) {
    o << "<tr><td>" << esc(k) << "</td><td>" << esc(v) << "</td></tr>\n";
  };
  const Json versions = r.value("versions", Json::object());
  for (const auto& [k, v] : versions.items()) kv(k, v.is_string() ? v.get<std::string>() : v.dump());
  kv("config file", r.at("config").value("file", std::string("?")));
  kv("config hash", r.value("config_hash", std::string("?")));
  kv("master seed", r.contains("seeds") ? r["seeds"].value("master", Json()).dump() : "?");
  kv("threads", r.value("threads", Json()).dump());
  kv("wall time", num(number(r, "wall_seconds"), 1) + " s");
  kv("stop reason", r.value("stop_reason", std::string("?")));
  o << "</tbody></table>\n";
  o << "<details><summary>The reported genome (<code>" << esc(in.genome_file) << "</code>)</summary><pre>"
    << esc(in.genome_toml) << "</pre></details>\n";
  o << "<details><summary>The config, every value explicit (run.json)</summary><pre>"
    << esc(r.at("config").dump(2)) << "</pre></details>\n";
  if (r.contains("seeds"))
    o << "<details><summary>Every seed (run.json)</summary><pre>" << esc(r["seeds"].dump(1))
      << "</pre></details>\n";
  o << "</section>\n";
}

}  // namespace

std::string ReportInputs::name() const {
  return run.at("config").value("name", fs::path(dir).filename().string());
}

ReportInputs read_report_inputs(const std::string& dir) {
  ReportInputs in;
  in.dir = dir;
  const fs::path d(dir);
  std::error_code ec;
  if (!fs::is_directory(d, ec))
    throw sim::ConfigError(dir, 0, "",
                           "not a folder: give the output folder of an evolve run (results/evolve/NAME)");
  if (!fs::is_regular_file(d / "run.json", ec))
    throw sim::ConfigError((d / "run.json").string(), 0, "",
                           "missing: the evolve run has not finished (run.json is written at its end)");
  in.run = json_file(d / "run.json");
  if (!in.run.is_object() || !in.run.contains("config") || !in.run["config"].contains("tune"))
    throw sim::ConfigError((d / "run.json").string(), 0, "config",
                           "missing: not the run.json of swarmpath evolve");
  in.state = evolve::read_checkpoint((d / "checkpoint.json").string());
  in.pareto = in.run.contains("front");
  if (fs::is_regular_file(d / "evaluate.json", ec)) in.evaluate = json_file(d / "evaluate.json");
  in.genome_file = in.pareto ? "front/000.toml" : "best.toml";
  in.genome_toml = text_or_empty(d / in.genome_file);
  in.progress_svg = text_or_empty(d / (in.pareto ? "hypervolume.svg" : "fitness.svg"));
  in.pareto_svg = text_or_empty(d / "pareto.svg");
  return in;
}

MeanInterval mean_interval(const std::vector<double>& values) {
  MeanInterval m;
  double sum = 0.0;
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    sum += v;
    ++m.n;
  }
  if (m.n == 0) return m;
  m.mean = sum / m.n;
  if (m.n < 2) {
    m.half_width = std::numeric_limits<double>::infinity();
    return m;
  }
  double sq = 0.0;
  for (const double v : values) {
    if (std::isfinite(v)) sq += (v - m.mean) * (v - m.mean);
  }
  m.half_width =
      evolve::t_quantile_975(m.n - 1) * std::sqrt(sq / (m.n - 1)) / std::sqrt(static_cast<double>(m.n));
  return m;
}

std::pair<double, double> wilson_interval(int k, int n) {
  if (n <= 0) return {0.0, 1.0};
  constexpr double z = 1.959963984540054;
  const double p = static_cast<double>(k) / n, nn = n;
  const double denom = 1.0 + z * z / nn;
  const double centre = (p + z * z / (2.0 * nn)) / denom;
  const double half = z / denom * std::sqrt(p * (1.0 - p) / nn + z * z / (4.0 * nn * nn));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::string report_page(const ReportInputs& in, const std::vector<PageRecording>& replays,
                        const std::vector<std::string>& notes) {
  const Json& r = in.run;
  const Json& cfg = r.at("config");
  std::ostringstream o;
  o << "<main class=\"rp\">\n<header><h1>Tuning run <code>" << esc(in.name()) << "</code></h1>\n<p>"
    << esc(cfg.at("optimizer").value("name", std::string("?"))) << ", mode "
    << esc(cfg.value("mode", std::string("?"))) << ", " << r.value("generations", 0) << " generations, "
    << r.value("evaluations", 0) << " candidates, " << r.value("runs", 0) << " training runs; stopped by "
    << esc(r.value("stop_reason", std::string("?"))) << ". Tuned: ";
  const Json& tune = cfg.at("tune");
  for (std::size_t k = 0; k < tune.size(); ++k)
    o << (k ? ", " : "") << "<code>" << esc(tune[k].value("name", "")) << "</code>";
  o << ".";
  if (!in.pareto && r.contains("best") && r["best"].is_object()) {
    const Json reev = r["best"].value("reevaluated", Json());
    const Json base = r.value("base_reevaluated", Json());
    if (r["best"].value("base", false))
      o << " No finalist beat the base params on fresh seeds, so the reported genome is the base params: "
           "they "
           "score "
        << num(number(reev, "fitness"), 4) << " on fresh seeds (success "
        << num(100.0 * number(reev, "success_rate"), 0) << " %); lower is better.";
    else
      o << " The reported genome (generation " << r["best"].value("generation", 0) << ") scores "
        << num(number(reev, "fitness"), 4) << " on fresh seeds (success "
        << num(100.0 * number(reev, "success_rate"), 0) << " %) against the base's "
        << num(number(base, "fitness"), 4) << " (success " << num(100.0 * number(base, "success_rate"), 0)
        << " %); lower is better.";
  }
  o << "</p>\n<nav><a href=\"#progress\">progress</a> <a href=\"#parameters\">parameters</a> <a "
       "href=\"#comparison\">against the base</a>"
    << (in.pareto ? " <a href=\"#pareto\">Pareto front</a>" : "")
    << " <a href=\"#replays\">replays</a> <a href=\"#provenance\">config and "
       "provenance</a></nav>\n</header>\n";
  for (const std::string& n : notes) o << "<p class=\"rp-note\">" << esc(n) << "</p>\n";

  o << "<section id=\"progress\"><h2>"
    << (in.pareto ? "Hypervolume per generation" : "Fitness per generation") << "</h2>\n";
  if (!in.progress_svg.empty())
    o << "<figure class=\"rp-wide\">" << inline_svg(in.progress_svg) << "</figure>\n";
  else
    o << "<p class=\"rp-note\">No " << (in.pareto ? "hypervolume.svg" : "fitness.svg")
      << " in the folder.</p>\n";
  o << "</section>\n";
  parameters_section(o, in);
  comparison_section(o, in);
  pareto_section(o, in);
  o << "<section id=\"replays\"><h2>Replays of the reported genome</h2>\n";
  if (replays.empty()) {
    o << "<p class=\"rp-note\">No replays in this report.</p>\n";
  } else {
    o << "<p>One run per training arena, with the reported genome, on the first re-evaluation seed of each "
         "(pick "
         "one above the arena). Click a robot for its state and transitions; the keys are listed beside "
         "the arena.</p>\n<div class=\"rp-viewer\">"
      << viewer_html(replays) << "</div>\n";
  }
  o << "</section>\n";
  provenance_section(o, in);
  o << "</main>\n";
  return html_page("swarmpath report: " + in.name(), o.str(), web::report_css());
}

}  // namespace swarmpath::app
