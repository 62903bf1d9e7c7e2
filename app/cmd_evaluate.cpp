// SPDX-License-Identifier: MIT
// swarmpath evaluate: the experiment table of one params file (success rate, ticks to form,
// path / A*, robots used; per scenario and robot count, and overall), or of two side by side on the same
// seeds with their differences and a paired comparison.
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/params_export.hpp"
#include "evolve/path_collision.hpp"
#include "experiment.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "table_output.hpp"

namespace swarmpath::app {

namespace {

struct EvaluateOptions {
  std::string params;
  std::string against;
  std::vector<std::string> scenarios{"configs/scenarios/paper"};
  std::vector<int> robots;
  int seeds = 5;
  std::uint64_t seed_base = 1;
  std::string mode = "pf";
  std::optional<std::int64_t> ticks;
  std::optional<int> threads;
  std::string json;
};

// one run as the table counts it
struct Outcome {
  bool success = false;
  double ticks = std::numeric_limits<double>::quiet_NaN();       // ticks to form (successes)
  double path_ratio = std::numeric_limits<double>::quiet_NaN();  // path / A* (successes)
  double robots = std::numeric_limits<double>::quiet_NaN();      // allocated (ta) or chain robots (pf)
};

Outcome outcome(const sim::Metrics& m, double astar, sim::Mode mode) {
  Outcome o;
  o.success = m.success;
  if (!m.success) return o;
  o.ticks = static_cast<double>(m.ticks_to_form);
  if (std::isfinite(m.path_length_tu) && astar > 0) o.path_ratio = m.path_length_tu / astar;
  o.robots = static_cast<double>(mode == sim::Mode::kTaskAllocation ? m.allocated : m.path_robots);
  return o;
}

// means over the successful runs of a group
struct Summary {
  int runs = 0;
  int ok = 0;
  double ticks = 0, path = 0, robots = 0;
  int paths = 0;

  void add(const Outcome& o) {
    ++runs;
    if (!o.success) return;
    ++ok;
    ticks += o.ticks;
    robots += o.robots;
    if (std::isfinite(o.path_ratio)) {
      path += o.path_ratio;
      ++paths;
    }
  }

  double success_rate() const { return runs > 0 ? static_cast<double>(ok) / runs : 0.0; }

  double mean_ticks() const { return ok > 0 ? ticks / ok : std::nan(""); }

  double mean_path() const { return paths > 0 ? path / paths : std::nan(""); }

  double mean_robots() const { return ok > 0 ? robots / ok : std::nan(""); }
};

nlohmann::ordered_json or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json summary_json(const Summary& s) {
  return {{"runs", s.runs},
          {"success_rate", s.success_rate()},
          {"mean_ticks_to_form", or_null(s.mean_ticks())},
          {"mean_path_ratio", or_null(s.mean_path())},
          {"mean_robots_used", or_null(s.mean_robots())}};
}

nlohmann::ordered_json outcome_json(const Outcome& o) {
  return {{"success", o.success},
          {"ticks_to_form", or_null(o.ticks)},
          {"path_ratio", or_null(o.path_ratio)},
          {"robots_used", or_null(o.robots)}};
}

std::string cell(double v, int digits) { return std::isnan(v) ? "-" : fixed(v, digits); }

std::string diff(double a, double b, int digits) {
  if (std::isnan(a) || std::isnan(b)) return "-";
  const double d = a - b;
  return (d > 0 ? "+" : "") + fixed(d, digits);
}

std::string pct(double v) { return fixed(100.0 * v, 0) + " %"; }

// paired comparison over the runs both parameter sets share (same scenario, robots, seed)
struct Paired {
  int both = 0, first_faster = 0, second_faster = 0, equal = 0, only_first = 0, only_second = 0, neither = 0;
};

int run_evaluate(const EvaluateOptions& o, const evolve::EvaluatorFactory& evaluators, std::ostream& out,
                 std::ostream& err) {
  if (o.seeds < 1 || o.seeds > 100000) throw sim::ConfigError("--seeds", 0, "", "must lie in [1, 100000]");
  const sim::Mode mode = mode_from_option(o.mode);
  if (mode == sim::Mode::kDiffusion) throw sim::ConfigError("--mode", 0, "", "must be pf or ta");
  const int threads = threads_or_all(o.threads);
  check_seed_range("--seed-base", o.seed_base, o.seeds);
  check_distinct_robots("--robots", o.robots);
  const bool two = !o.against.empty();
  std::vector<evolve::NamedPath> inputs = {{"--params", o.params}, {"--against", o.against}};
  const std::vector<std::string> files = scenario_files(o.scenarios);
  for (const std::string& f : files) inputs.push_back({"--scenarios", f});
  evolve::check_output_paths(inputs, {{"--json", o.json}});
  const sim::Params pa = sim::load_params(o.params);
  const sim::Params pb = two ? sim::load_params(o.against) : sim::Params{};

  // the grid: every scenario x robot count (its own count by default) x seed
  std::vector<sim::Scenario> scenarios;
  for (const std::string& f : files) scenarios.push_back(scenario_with_overrides(f, {}, o.ticks));
  check_distinct_scenarios("--scenarios", files, scenarios);
  std::vector<GridCase> grid;
  for (std::size_t s = 0; s < scenarios.size(); ++s) {
    const std::vector<int> robots = o.robots.empty() ? std::vector<int>{scenarios[s].robots} : o.robots;
    for (const int n : robots) {
      for (int k = 0; k < o.seeds; ++k)
        grid.push_back({s, n, mode, o.seed_base + static_cast<std::uint64_t>(k)});
    }
  }
  note_benchmark_arenas(scenarios, err);
  const std::vector<double> astar = astar8_lengths(scenarios);

  const std::unique_ptr<evolve::BatchEvaluator> evaluator = evaluators(threads);
  const bool tty = stderr_is_terminal();
  const Stopwatch clock;
  const GridProgress progress = [&](std::size_t done, std::size_t total) {
    if (tty)
      err << "\r  " << done << " / " << total << " runs, " << fixed(clock.seconds(), 0) << " s   "
          << std::flush;
  };
  err << "swarmpath evaluate: " << scenarios.size() << " scenarios, " << grid.size()
      << " runs per params file" << (two ? " (x 2, same seeds)" : "") << ", mode " << o.mode << ", "
      << evaluator->describe() << "\n";
  // both params sets in one batch, on the same seeds
  std::vector<std::vector<GridRun>> both =
      run_grid(scenarios, grid, two ? std::vector<sim::Params>{pa, pb} : std::vector<sim::Params>{pa},
               *evaluator, progress);
  const std::vector<GridRun> ra = std::move(both[0]);
  const std::vector<GridRun> rb = two ? std::move(both[1]) : std::vector<GridRun>{};
  if (tty) err << "\n";
  err << "  done in " << fixed(clock.seconds(), 1) << " s: " << evaluator->summary() << "\n";

  // per (scenario, robots) group and overall, both sets; the paired comparison
  struct Group {
    std::size_t scenario;
    int robots;
    Summary a, b;
  };

  std::vector<Group> groups;
  Summary ta, tb;
  Paired paired;
  nlohmann::ordered_json runs = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const std::size_t s = grid[i].scenario;
    if (groups.empty() || groups.back().scenario != s || groups.back().robots != grid[i].robots) {
      groups.push_back({s, grid[i].robots, {}, {}});
    }
    Group& grp = groups.back();
    const Outcome a = outcome(ra[i].m, astar[s], mode);
    grp.a.add(a);
    ta.add(a);
    nlohmann::ordered_json jr = {
        {"scenario", scenarios[s].name}, {"robots", grid[i].robots}, {"seed", grid[i].seed}};
    jr["params"] = outcome_json(a);
    if (two) {
      const Outcome b = outcome(rb[i].m, astar[s], mode);
      grp.b.add(b);
      tb.add(b);
      jr["against"] = outcome_json(b);
      if (a.success && b.success) {
        ++paired.both;
        if (a.ticks < b.ticks) ++paired.first_faster;
        if (a.ticks > b.ticks) ++paired.second_faster;
        if (a.ticks == b.ticks) ++paired.equal;
      } else if (a.success) {
        ++paired.only_first;
      } else if (b.success) {
        ++paired.only_second;
      } else {
        ++paired.neither;
      }
    }
    runs.push_back(jr);
  }

  out << "evaluate " << o.params << (two ? " against " + o.against : "") << ": mode " << o.mode << ", "
      << o.seeds << " seeds from " << o.seed_base
      << " per scenario and robot count; means over successful runs\n";
  out << "controllers: " << o.params << " runs the " << evolve::controller_text(pa);
  if (two) out << "; " << o.against << " the " << evolve::controller_text(pb);
  out << "\n\n";
  if (!two) {
    out << "| scenario | robots | A* [TU] | runs | success | ticks to form | path/A* | robots used |\n"
           "|---|---|---|---|---|---|---|---|\n";
    const auto row = [&](const std::string& name, const std::string& n, const std::string& a8,
                         const Summary& s) {
      out << "| " << name << " | " << n << " | " << a8 << " | " << s.runs << " | " << pct(s.success_rate())
          << " | " << cell(s.mean_ticks(), 0) << " | " << cell(s.mean_path(), 3) << " | "
          << cell(s.mean_robots(), 1) << " |\n";
    };
    for (const Group& g : groups) {
      row(markdown_text(scenarios[g.scenario].name), std::to_string(g.robots), cell(astar[g.scenario], 1),
          g.a);
    }
    row("**overall**", "", "", ta);
  } else {
    out << "A = " << o.params << ", B = " << o.against << "; differences are A - B\n\n";
    out << "| scenario | robots | runs | success A | success B | ticks A | ticks B | diff | path/A* A | "
           "path/A* B | "
           "diff "
           "| robots A | robots B | diff |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    const auto row = [&](const std::string& name, const std::string& n, const Summary& a, const Summary& b) {
      out << "| " << name << " | " << n << " | " << a.runs << " | " << pct(a.success_rate()) << " | "
          << pct(b.success_rate()) << " | " << cell(a.mean_ticks(), 0) << " | " << cell(b.mean_ticks(), 0)
          << " | " << diff(a.mean_ticks(), b.mean_ticks(), 0) << " | " << cell(a.mean_path(), 3) << " | "
          << cell(b.mean_path(), 3) << " | " << diff(a.mean_path(), b.mean_path(), 3) << " | "
          << cell(a.mean_robots(), 1) << " | " << cell(b.mean_robots(), 1) << " | "
          << diff(a.mean_robots(), b.mean_robots(), 1) << " |\n";
    };
    for (const Group& g : groups)
      row(markdown_text(scenarios[g.scenario].name), std::to_string(g.robots), g.a, g.b);
    row("**overall**", "", ta, tb);
    out << "\npaired (same scenario, robots and seed): both formed the path in " << paired.both << " of "
        << grid.size() << " cases; A faster in " << paired.first_faster << ", B faster in "
        << paired.second_faster << ", equal in " << paired.equal << "; only A formed it in "
        << paired.only_first << ", only B in " << paired.only_second << ", neither in " << paired.neither
        << "\n";
  }

  if (!o.json.empty()) {
    nlohmann::ordered_json j;
    j["params"] = o.params;
    j["controller"] = evolve::controller_json(pa);
    j["against"] = two ? nlohmann::ordered_json(o.against) : nlohmann::ordered_json(nullptr);
    j["against_controller"] = two ? evolve::controller_json(pb) : nlohmann::ordered_json(nullptr);
    j["mode"] = o.mode;
    j["seeds"] = o.seeds;
    j["seed_base"] = o.seed_base;
    nlohmann::ordered_json per = nlohmann::ordered_json::array();
    for (const Group& g : groups) {
      nlohmann::ordered_json e = {{"scenario", scenarios[g.scenario].name},
                                  {"robots", g.robots},
                                  {"astar_tu", or_null(astar[g.scenario])}};
      e["params"] = summary_json(g.a);
      if (two) e["against"] = summary_json(g.b);
      per.push_back(e);
    }
    j["cases"] = per;
    j["overall"] = {{"params", summary_json(ta)}};
    if (two) {
      j["overall"]["against"] = summary_json(tb);
      j["paired"] = {{"both_succeeded", paired.both},
                     {"params_faster", paired.first_faster},
                     {"against_faster", paired.second_faster},
                     {"equal", paired.equal},
                     {"only_params", paired.only_first},
                     {"only_against", paired.only_second},
                     {"neither", paired.neither}};
    }
    j["runs"] = runs;
    evolve::write_file_atomic(o.json, j.dump(2) + "\n");
  }
  return kExitOk;
}

}  // namespace

Runner add_evaluate(CLI::App& app, const evolve::EvaluatorFactory& evaluators) {
  auto o = std::make_shared<EvaluateOptions>();
  app.add_option("--params", o->params, "Params file to evaluate")->required();
  app.add_option("--against", o->against,
                 "A second params file, run on the same seeds (e.g. genomes/default.toml)");
  app.add_option("--scenarios", o->scenarios, "Scenario files or directories of *.toml")
      ->capture_default_str();
  app.add_option("--robots", o->robots, "Robot counts, e.g. 60,100 (default: each scenario's own)")
      ->delimiter(',');
  app.add_option("--seeds", o->seeds, "Seeds per (scenario, robots)")->capture_default_str();
  add_seed_option(app, "--seed-base", o->seed_base,
                  "The first seed; runs use seed-base ... seed-base+seeds-1");
  app.add_option("--mode", o->mode, "pf (path formation) or ta (task allocation, then path formation)")
      ->capture_default_str();
  app.add_option("--ticks", o->ticks, "Override every scenario's max_ticks");
  add_threads_option(app, o->threads);
  app.add_option("--json", o->json, "Write per-scenario, overall and per-run results as JSON");
  return [o, evaluators](std::ostream& out, std::ostream& err) {
    return run_evaluate(*o, evaluators, out, err);
  };
}

}  // namespace swarmpath::app
