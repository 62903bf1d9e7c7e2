// SPDX-License-Identifier: MIT
#include "ablation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "evolve/xml_escape.hpp"

namespace swarmpath::app {

std::string_view to_string(Arm a) {
  switch (a) {
    case Arm::kDefault:
      return "default";
    case Arm::kLiteral:
      return "literal";
  }
  return "?";
}

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::kHelps:
      return "helps";
    case Verdict::kHurts:
      return "hurts";
    case Verdict::kMixed:
      return "mixed";
    case Verdict::kNotMeasurable:
      return "not measurable";
  }
  return "?";
}

Effect paired_effect(std::span<const RunOutcome> with, std::span<const RunOutcome> without) {
  if (with.size() != without.size()) throw std::invalid_argument("paired_effect: the runs do not pair up");
  Effect e;
  e.pairs = static_cast<int>(with.size());
  std::vector<double> success, ticks, path, rr;
  int with_ok = 0, without_ok = 0;
  for (std::size_t i = 0; i < with.size(); ++i) {
    const RunOutcome& a = with[i];
    const RunOutcome& b = without[i];
    with_ok += a.success ? 1 : 0;
    without_ok += b.success ? 1 : 0;
    success.push_back((a.success ? 1.0 : 0.0) - (b.success ? 1.0 : 0.0));
    if (a.success && b.success) {
      ticks.push_back(a.ticks - b.ticks);
      if (std::isfinite(a.path_ratio) && std::isfinite(b.path_ratio))
        path.push_back(a.path_ratio - b.path_ratio);
    }
    if (std::isfinite(a.rr_pct) && std::isfinite(b.rr_pct)) rr.push_back(a.rr_pct - b.rr_pct);
  }
  if (e.pairs > 0) {
    e.success_with = static_cast<double>(with_ok) / e.pairs;
    e.success_without = static_cast<double>(without_ok) / e.pairs;
  }
  e.success = evolve::mean_interval(success);
  e.ticks = evolve::mean_interval(ticks);
  e.path_ratio = evolve::mean_interval(path);
  e.rr_pct = evolve::mean_interval(rr);
  e.verdict = verdict_of(e);
  return e;
}

namespace {

// the interval lies wholly above (+1) or below (-1) zero; 0: it includes zero (or is undefined)
int side(const evolve::Interval& i) {
  if (i.n < 2 || !std::isfinite(i.half_width)) return 0;
  if (i.lower() > 0.0) return 1;
  if (i.upper() < 0.0) return -1;
  return 0;
}

}  // namespace

Verdict verdict_of(const Effect& e) {
  // (the sign that is good: more success and resource reduction, fewer ticks, a shorter path)
  const int signs[] = {side(e.success), -side(e.ticks), -side(e.path_ratio), side(e.rr_pct)};
  bool good = false, bad = false;
  for (const int s : signs) {
    good = good || s > 0;
    bad = bad || s < 0;
  }
  if (good && bad) return Verdict::kMixed;
  if (good) return Verdict::kHelps;
  if (bad) return Verdict::kHurts;
  return Verdict::kNotMeasurable;
}

namespace {

std::string num(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream o;
  o << std::fixed << std::setprecision(digits) << v;
  return o.str();
}

// "+3.1 [-1.0, 7.2]", bold when the interval excludes zero; `scale` converts to the printed unit
std::string interval_text(const evolve::Interval& i, double scale, int digits) {
  if (i.n == 0) return "-";
  std::ostringstream o;
  const double m = scale * i.mean;
  o << (m >= 0 ? "+" : "") << num(m, digits);
  if (i.n >= 2 && std::isfinite(i.half_width)) {
    o << " [" << num(scale * i.lower(), digits) << ", " << num(scale * i.upper(), digits) << "]";
  }
  const std::string text = o.str();
  return side(i) != 0 ? "**" + text + "**" : text;
}

std::string_view mode_name(sim::Mode m) { return m == sim::Mode::kTaskAllocation ? "ta" : "pf"; }

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string join(const std::vector<int>& v) {
  std::string s;
  for (const int x : v) s += (s.empty() ? "" : ", ") + std::to_string(x);
  return s;
}

nlohmann::ordered_json interval_json(const evolve::Interval& i) {
  nlohmann::ordered_json j;
  j["n"] = i.n;
  if (i.n > 0) j["mean"] = i.mean;
  if (i.n >= 2 && std::isfinite(i.half_width)) {
    j["lower"] = i.lower();
    j["upper"] = i.upper();
  }
  return j;
}

}  // namespace

void write_ablation_markdown(std::ostream& out, const AblationGrid& grid,
                             const std::vector<AblationRow>& rows) {
  out << "Grid: " << join(grid.scenarios) << "; robots " << join(grid.robots) << "; seeds " << grid.seed_base
      << "-" << grid.seed_base + static_cast<std::uint64_t>(grid.seeds) - 1 << "; T_max " << grid.max_ticks
      << " ticks. Each row pairs the runs of one (arena, robots, seed) case with and without the addition "
         "(common random numbers); an effect is with it minus without it, its 95 % Student-t interval in "
         "brackets, **bold** where the interval excludes zero. Time and path / A* are over the pairs where "
         "both runs formed the path (their number in parentheses); resource reduction over the "
         "task-allocation "
         "pairs.\n";
  for (const Arm arm : {Arm::kDefault, Arm::kLiteral}) {
    bool any = false;
    for (const AblationRow& r : rows) any = any || r.arm == arm;
    if (!any) continue;
    out << "\n### "
        << (arm == Arm::kDefault
                ? "The default controller (" + grid.default_params + "), each addition off in turn"
                : "The paper-literal controller (" + grid.literal_params +
                      "), each addition on in turn (with the additions it needs)")
        << "\n\n";
    out << "| addition | SPEC rule | mode | pairs | success with / without | success (points) | time (ticks) "
           "| "
           "path / A* | resource reduction (points) | verdict |\n";
    out << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const AblationRow& r : rows) {
      if (r.arm != arm) continue;
      const Effect& e = r.effect;
      out << "| `" << r.addition << "`: " << r.title << " | " << r.rule << " | " << mode_name(r.mode) << " | "
          << e.pairs << " | " << num(100.0 * e.success_with, 0) << " / " << num(100.0 * e.success_without, 0)
          << " % | " << interval_text(e.success, 100.0, 1) << " | " << interval_text(e.ticks, 1.0, 0) << " ("
          << e.ticks.n << ") | " << interval_text(e.path_ratio, 1.0, 3) << " | "
          << (r.mode == sim::Mode::kTaskAllocation ? interval_text(e.rr_pct, 1.0, 1) : std::string("-"))
          << " | " << to_string(e.verdict) << " |\n";
    }
  }
}

nlohmann::ordered_json ablation_json(const AblationGrid& grid, const std::vector<AblationRow>& rows) {
  nlohmann::ordered_json j;
  j["grid"] = {{"scenarios", grid.scenarios},
               {"robots", grid.robots},
               {"seeds", grid.seeds},
               {"seed_base", grid.seed_base},
               {"max_ticks", grid.max_ticks},
               {"default_params", grid.default_params},
               {"literal_params", grid.literal_params}};
  j["effect"] = "with the addition minus without it, over paired runs; 95 % Student-t intervals";
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const AblationRow& r : rows) {
    const Effect& e = r.effect;
    list.push_back({{"arm", to_string(r.arm)},
                    {"addition", r.addition},
                    {"title", r.title},
                    {"rule", r.rule},
                    {"mode", mode_name(r.mode)},
                    {"pairs", e.pairs},
                    {"success_with", e.success_with},
                    {"success_without", e.success_without},
                    {"success", interval_json(e.success)},
                    {"ticks_to_form", interval_json(e.ticks)},
                    {"path_ratio", interval_json(e.path_ratio)},
                    {"resource_reduction_pct", interval_json(e.rr_pct)},
                    {"verdict", to_string(e.verdict)}});
  }
  j["rows"] = std::move(list);
  return j;
}

namespace {

// one panel of the forest plot: a column of rows, each a point and its interval for pf and ta
struct Panel {
  std::string title;
  Arm arm;
  bool ticks;  // else success (points)
};

}  // namespace

void write_ablation_svg(std::ostream& out, const AblationGrid& grid, const std::vector<AblationRow>& rows) {
  // the additions in the rows' order
  std::vector<std::string> names;
  std::map<std::string, std::string> titles;
  for (const AblationRow& r : rows) {
    if (std::find(names.begin(), names.end(), r.addition) == names.end()) names.push_back(r.addition);
    titles[r.addition] = r.title;
  }
  const std::vector<Panel> panels = {{"default, each off: success (points)", Arm::kDefault, false},
                                     {"default, each off: time (ticks, both formed)", Arm::kDefault, true},
                                     {"paper-literal, each on: success (points)", Arm::kLiteral, false}};
  constexpr double kLabelW = 220, kPanelW = 260, kGap = 20, kRowH = 18, kTop = 70, kBottom = 40;
  const double width = kLabelW + static_cast<double>(panels.size()) * (kPanelW + kGap);
  const double height = kTop + kRowH * static_cast<double>(names.size()) + kBottom;
  const auto value = [](const Effect& e, bool ticks) -> const evolve::Interval& {
    return ticks ? e.ticks : e.success;
  };
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"10\" y=\"18\" font-size=\"14\">Ablation of the additions beyond SPEC: with the addition "
         "minus "
         "without it, 95 % intervals</text>\n";
  out << "<text x=\"10\" y=\"34\">" << evolve::xml_escape(join(grid.scenarios)) << "; robots "
      << join(grid.robots) << "; " << grid.seeds << " seeds; circles pf, squares ta; filled: the interval "
      << "excludes 0</text>\n";
  for (std::size_t k = 0; k < names.size(); ++k) {
    const double y = kTop + kRowH * (static_cast<double>(k) + 0.5);
    out << "<text x=\"" << kLabelW - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">"
        << evolve::xml_escape(names[k]) << "</text>\n";
    if (k % 2 == 0) {
      out << "<rect x=\"" << kLabelW << "\" y=\"" << y - kRowH / 2 << "\" width=\"" << width - kLabelW
          << "\" height=\"" << kRowH << "\" fill=\"#f4f4f4\"/>\n";
    }
  }
  for (std::size_t pi = 0; pi < panels.size(); ++pi) {
    const Panel& panel = panels[pi];
    const double x0 = kLabelW + static_cast<double>(pi) * (kPanelW + kGap) + kGap / 2;
    // the scale: symmetric about zero, to the widest interval end of the panel
    double reach = panel.ticks ? 100.0 : 5.0;
    for (const AblationRow& r : rows) {
      if (r.arm != panel.arm) continue;
      const evolve::Interval& i = value(r.effect, panel.ticks);
      const double scale = panel.ticks ? 1.0 : 100.0;
      if (i.n == 0) continue;
      reach = std::max(reach, std::fabs(scale * i.mean));
      if (i.n >= 2 && std::isfinite(i.half_width))
        reach = std::max({reach, std::fabs(scale * i.lower()), std::fabs(scale * i.upper())});
    }
    reach *= 1.05;
    const auto px = [&](double v) { return x0 + kPanelW / 2 + v / reach * (kPanelW / 2); };
    out << "<text x=\"" << x0 + kPanelW / 2 << "\" y=\"" << kTop - 22 << "\" text-anchor=\"middle\">"
        << evolve::xml_escape(panel.title) << "</text>\n";
    out << "<line x1=\"" << px(0) << "\" y1=\"" << kTop - 8 << "\" x2=\"" << px(0) << "\" y2=\""
        << height - kBottom << "\" stroke=\"#888\"/>\n";
    for (const double v : {-reach / 1.05, reach / 1.05}) {
      out << "<text x=\"" << px(v) << "\" y=\"" << height - kBottom + 14 << "\" text-anchor=\"middle\">"
          << num(v, panel.ticks ? 0 : 0) << "</text>\n";
    }
    for (const AblationRow& r : rows) {
      if (r.arm != panel.arm) continue;
      const auto k = static_cast<double>(std::find(names.begin(), names.end(), r.addition) - names.begin());
      const bool ta = r.mode == sim::Mode::kTaskAllocation;
      const double y = kTop + kRowH * (k + 0.5) + (ta ? 4.0 : -4.0);
      const evolve::Interval& i = value(r.effect, panel.ticks);
      if (i.n == 0) continue;
      const double scale = panel.ticks ? 1.0 : 100.0;
      const std::string colour = ta ? "#d95f02" : "#1b9e77";
      if (i.n >= 2 && std::isfinite(i.half_width)) {
        out << "<line x1=\"" << px(scale * i.lower()) << "\" y1=\"" << y << "\" x2=\""
            << px(scale * i.upper()) << "\" y2=\"" << y << "\" stroke=\"" << colour << "\"/>\n";
      }
      const std::string fill = side(i) != 0 ? colour : "white";
      if (ta) {
        out << "<rect x=\"" << px(scale * i.mean) - 3 << "\" y=\"" << y - 3
            << "\" width=\"6\" height=\"6\" fill=\"" << fill << "\" stroke=\"" << colour << "\"/>\n";
      } else {
        out << "<circle cx=\"" << px(scale * i.mean) << "\" cy=\"" << y << "\" r=\"3\" fill=\"" << fill
            << "\" stroke=\"" << colour << "\"/>\n";
      }
    }
  }
  out << "</svg>\n";
}

}  // namespace swarmpath::app
