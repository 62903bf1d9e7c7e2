// SPDX-License-Identifier: MIT
// swarmpath benchmark: runs a benchmark of generated arenas (configs/benchmarks/*.toml) and the
// paper arenas beside it with one params file, or two on the same runs, and reports per family
// and overall: success with and without task allocation, time to form, path / A*, resource
// reduction (markdown, JSON, SVG). For measuring a chosen genome, never for choosing one.
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "benchmark_config.hpp"
#include "benchmark_report.hpp"
#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/path_collision.hpp"
#include "experiment.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "table_output.hpp"
#include "table_report.hpp"

namespace swarmpath::app {

namespace {

struct BenchmarkOptions {
  std::string config = "configs/benchmarks/generalisation.toml";
  std::string params;
  std::string against;
  std::string mode = "both";
  std::vector<std::string> families;  // only these (default: all)
  bool no_paper = false;
  std::optional<int> threads;
  std::uint64_t seed_base = 0;  // a screen's: simulation seeds from here instead (seed_base_given)
  bool seed_base_given = false;
  std::string json, markdown, svg;
};

int run_benchmark(const BenchmarkOptions& o, const evolve::EvaluatorFactory& evaluators, std::ostream& out,
                  std::ostream& err) {
  BenchmarkConfig c = load_benchmark_config(o.config);
  if (o.seed_base_given) {
    if (!c.screen)
      throw sim::ConfigError("--seed-base", 0, "",
                             "a benchmark's simulation seeds are part of its version; only a screen "
                             "(purpose = \"screen\") takes other seeds");
    check_seed_range("--seed-base", o.seed_base, c.seeds);
    c.seed_base = o.seed_base;
  }
  const std::vector<sim::Mode> modes = path_modes(o.mode);
  const bool both = modes.size() == 2;
  const bool pf = both || modes[0] == sim::Mode::kPathFormation;
  const bool ta = both || modes[0] == sim::Mode::kTaskAllocation;
  const int threads = threads_or_all(o.threads);
  const bool two = !o.against.empty();
  evolve::check_output_paths({{"--params", o.params}, {"--against", o.against}, {"--config", o.config}},
                             {{"--json", o.json}, {"--md", o.markdown}, {"--svg", o.svg}});
  const sim::Params pa = params_or_defaults(o.params);
  const sim::Params pb = two ? sim::load_params(o.against) : sim::Params{};

  // the families asked for, then their arenas and the paper arenas, as one scenario list
  std::vector<const BenchmarkFamily*> chosen;
  std::vector<std::string> groups;
  std::vector<std::string> label_of;  // each arena's row, in the order they are drawn
  for (const BenchmarkFamily& f : c.families) {
    const std::string& name = f.label;
    if (!o.families.empty() && std::find(o.families.begin(), o.families.end(), name) == o.families.end())
      continue;
    chosen.push_back(&f);
    label_of.insert(label_of.end(), f.seeds.size(), name);
    if (std::find(groups.begin(), groups.end(), name) == groups.end()) groups.push_back(name);
  }
  for (const std::string& f : o.families) {
    if (std::find(groups.begin(), groups.end(), f) == groups.end()) {
      throw sim::ConfigError("--families", 0, "", "\"" + f + "\" is not a family of " + c.file);
    }
  }
  const Stopwatch clock;
  err << "swarmpath benchmark: " << c.name << " v" << c.version << " (" << c.file << "): drawing arenas\n";
  const std::vector<sim::arenas::GeneratedArena> arenas = draw_benchmark_arenas(chosen, threads);
  std::vector<sim::Scenario> scenarios;
  std::vector<std::string> group_of;
  std::vector<double> astar8;
  nlohmann::ordered_json arena_list = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < arenas.size(); ++k) {
    const sim::arenas::GeneratedArena& a = arenas[k];
    scenarios.push_back(sim::with_max_ticks(a.scenario, c.max_ticks, c.file));
    group_of.push_back(label_of[k]);
    astar8.push_back(sim::to_tu(a.astar8_m));
    arena_list.push_back({{"name", a.scenario.name},
                          {"family", a.scenario.origin->family},
                          {"row", label_of[k]},
                          {"seed", a.scenario.origin->seed},
                          {"class", std::string(sim::to_string(a.scenario.env_class))},
                          {"astar8_tu", sim::to_tu(a.astar8_m)}});
  }
  if (!o.no_paper) {
    for (const std::string& f : c.paper) {
      scenarios.push_back(scenario_with_overrides(f, {}, c.max_ticks));
      group_of.push_back("paper");
      const sim::AStarResult a = sim::astar(scenarios.back());
      astar8.push_back(a.found ? sim::to_tu(a.length_m) : std::nan(""));
    }
  }

  const std::vector<GridCase> grid = make_grid(scenarios.size(), c.robots, modes, c.seeds, c.seed_base);
  const bool tty = stderr_is_terminal();
  err << "  " << arenas.size() << " arenas of " << groups.size() << " families"
      << (o.no_paper ? "" : " and " + std::to_string(scenarios.size() - arenas.size()) + " paper arenas")
      << " x " << c.robots.size() << " robot counts x " << modes.size() << " modes x " << c.seeds
      << " seeds = " << grid.size() << " runs" << (two ? " per params file (x 2, the same runs)" : "")
      << "\n";
  const std::unique_ptr<evolve::BatchEvaluator> evaluator = evaluators(threads);
  const std::vector<std::vector<GridRun>> runs =
      run_grid(scenarios, grid, two ? std::vector<sim::Params>{pa, pb} : std::vector<sim::Params>{pa},
               *evaluator, grid_progress(err, tty));
  const std::vector<GridRun>& ra = runs[0];
  const std::vector<GridRun> rb = two ? runs[1] : std::vector<GridRun>{};
  if (tty) err << "\n";
  err << "  done in " << fixed(clock.seconds(), 1) << " s: " << evaluator->summary() << "\n";

  const std::string name_a = o.params.empty() ? "the defaults" : o.params;
  const std::vector<BenchmarkRow> rows_a = benchmark_rows(groups, group_of, astar8, ra);
  std::ostringstream md;
  md << "## " << c.name << " benchmark v" << c.version << ": " << name_a << "\n\n"
     << arenas.size() << " arenas of " << groups.size() << " families (seeds in " << c.file << ")"
     << (o.no_paper ? "" : " and the paper arenas") << ", robots " <<
      [&] {
        std::string s;
        for (const int n : c.robots) s += (s.empty() ? "" : ", ") + std::to_string(n);
        return s;
      }()
     << ", " << c.seeds << " seed" << (c.seeds > 1 ? "s" : "") << " from " << c.seed_base << ", T_max "
     << c.max_ticks << (both ? "; the same runs with and without TA" : "") << ".\n\n";
  write_benchmark_markdown(md, rows_a, pf, ta);
  nlohmann::ordered_json j;
  j["benchmark"] = {{"name", c.name},           {"version", c.version},
                    {"file", c.file},           {"generator_version", sim::arenas::kGeneratorVersion},
                    {"robots", c.robots},       {"seeds", c.seeds},
                    {"seed_base", c.seed_base}, {"max_ticks", c.max_ticks},
                    {"mode", o.mode},           {"arenas", arena_list}};
  j["params"] = {{"file", name_a}, {"rows", benchmark_rows_json(rows_a)}};
  std::vector<BarSet> bars;
  const auto success = [](const std::vector<BenchmarkRow>& rows, bool with_ta) {
    std::vector<double> v;
    for (const BenchmarkRow& r : rows) v.push_back(with_ta ? r.ta.success_rate : r.pf.success_rate);
    return v;
  };
  if (pf) bars.push_back({"A without TA", "#7a9cc6", success(rows_a, false)});
  if (ta) bars.push_back({"A with TA", "#1f4e8c", success(rows_a, true)});
  if (two) {
    const std::vector<BenchmarkRow> rows_b = benchmark_rows(groups, group_of, astar8, rb);
    const std::vector<BenchmarkDifference> d = benchmark_differences(groups, group_of, ra, rb);
    const auto all = [](const auto& v) {
      return *std::find_if(v.begin(), v.end(), [](const auto& r) { return r.group == "all families"; });
    };
    const Verdict verdict = benchmark_verdict(all(rows_a), all(rows_b), all(d), pf, ta);
    md << "\n## " << o.against << " on the same runs\n\n";
    write_benchmark_markdown(md, rows_b, pf, ta);
    md << "\n## A = " << name_a << " against B = " << o.against << "\n\n";
    write_difference_markdown(md, rows_a, rows_b, d, pf, ta);
    md << "\n**" << (verdict.wins ? "A beats B" : "A does not beat B") << "** on the benchmark's families ("
       << verdict.text << ").\n";
    j["against"] = {{"file", o.against}, {"rows", benchmark_rows_json(rows_b)}};
    j["differences"] = benchmark_differences_json(d);
    j["verdict"] = {{"params_beats_against", verdict.wins}, {"text", verdict.text}};
    if (pf) bars.push_back({"B without TA", "#f4b183", success(rows_b, false)});
    if (ta) bars.push_back({"B with TA", "#c55a11", success(rows_b, true)});
  }
  // the paper arenas' own table beside, from the table machinery
  if (!o.no_paper && !c.paper.empty()) {
    std::vector<sim::Scenario> paper(scenarios.begin() + static_cast<std::ptrdiff_t>(arenas.size()),
                                     scenarios.end());
    std::vector<double> paper_astar(astar8.begin() + static_cast<std::ptrdiff_t>(arenas.size()),
                                    astar8.end());
    std::vector<GridRun> paper_runs;
    for (const GridRun& r : ra) {
      if (r.c.scenario < arenas.size()) continue;
      GridRun p = r;
      p.c.scenario -= arenas.size();
      paper_runs.push_back(p);
    }
    md << "\n## The paper arenas with " << name_a << "\n\n";
    if (both) {
      write_markdown(md,
                     compare(summarise(paper, paper_astar, runs_of(paper_runs, sim::Mode::kPathFormation),
                                       sim::Mode::kPathFormation),
                             summarise(paper, paper_astar, runs_of(paper_runs, sim::Mode::kTaskAllocation),
                                       sim::Mode::kTaskAllocation)));
    } else {
      write_markdown(md, summarise(paper, paper_astar, paper_runs, modes[0]));
    }
  }
  std::vector<std::string> labels;
  for (const BenchmarkRow& r : rows_a) labels.push_back(r.group);
  const auto write_json = [&](std::ostream& f) {
    // every run, with the table machinery's fields
    j["table"] =
        both ? comparison_json(scenarios, astar8, ra,
                               compare(summarise(scenarios, astar8, runs_of(ra, sim::Mode::kPathFormation),
                                                 sim::Mode::kPathFormation),
                                       summarise(scenarios, astar8, runs_of(ra, sim::Mode::kTaskAllocation),
                                                 sim::Mode::kTaskAllocation)))
             : table_json(scenarios, astar8, ra, summarise(scenarios, astar8, ra, modes[0]));
    f << j.dump(2) << "\n";
  };
  const int code = write_outputs(
      {{o.svg,
        [&](std::ostream& f) {
          write_success_svg(f, c.name + " benchmark v" + std::to_string(c.version),
                            "success rate per family; A = " + name_a + (two ? ", B = " + o.against : ""),
                            labels, bars);
        }},
       {o.json, write_json},
       {o.markdown, [&](std::ostream& f) { f << md.str(); }}},
      err);
  out << md.str();
  return code;
}

}  // namespace

Runner add_benchmark(CLI::App& app, const evolve::EvaluatorFactory& evaluators) {
  auto o = std::make_shared<BenchmarkOptions>();
  app.add_option("--config", o->config, "Benchmark file")->capture_default_str();
  app.add_option("--params", o->params, "Params file to measure (default: the code's defaults)");
  app.add_option("--against", o->against,
                 "A second params file, on the same runs (e.g. genomes/default.toml)");
  app.add_option("--mode", o->mode, "pf, ta or both (each run with and without task allocation)")
      ->capture_default_str();
  app.add_option("--families", o->families, "Only these families, e.g. wall-gap,rooms")->delimiter(',');
  app.add_flag("--no-paper", o->no_paper, "Leave out the paper arenas");
  add_threads_option(app, o->threads);
  CLI::Option* seed_base = add_seed_option(
      app, "--seed-base", o->seed_base,
      "A screen's simulation seeds from this one instead of its seed_base (a rule's fresh seeds)");
  app.add_option("--json", o->json, "Write the rows, the arenas and every run as JSON");
  app.add_option("--md", o->markdown, "Write the markdown report to this file too");
  app.add_option("--svg", o->svg, "Draw the success rates per family");
  return [o, evaluators, seed_base](std::ostream& out, std::ostream& err) {
    o->seed_base_given = seed_base->count() > 0;
    return run_benchmark(*o, evaluators, out, err);
  };
}

}  // namespace swarmpath::app
