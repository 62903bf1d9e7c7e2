// SPDX-License-Identifier: MIT
// swarmpath robustness: success, time and path against the share of robots failing and the
// packet loss, with and without task allocation, from one command (docs/faults.md).
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "benchmark_config.hpp"
#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/path_collision.hpp"
#include "experiment.hpp"
#include "fault_options.hpp"
#include "robustness.hpp"
#include "robustness_output.hpp"
#include "sim/config_error.hpp"
#include "sim/controller.hpp"

namespace swarmpath::app {

namespace {

struct RobustnessOptions {
  std::vector<std::string> scenarios{"configs/scenarios/paper"};
  std::string benchmark;
  std::vector<int> robots{60, 100};
  int seeds = 10;
  std::uint64_t seed_base = 1;
  std::string mode = "both";
  std::string params;
  std::optional<std::int64_t> ticks;
  std::optional<int> threads;
  RobustnessGrid grid;
  FaultOptions faults;
  std::string json;
  std::string markdown;
  std::string svg;
};

void check_sweep(const char* option, const std::vector<double>& v) {
  if (v.empty()) throw sim::ConfigError(option, 0, "", "give at least one value");
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!(v[i] >= 0.0 && v[i] <= 1.0))
      throw sim::ConfigError(option, 0, "", "values must lie in [0, 1] (got " + fixed(v[i], 3) + ")");
    if (i > 0 && !(v[i] > v[i - 1]))
      throw sim::ConfigError(option, 0, "", "values must increase, e.g. 0,0.1,0.3");
  }
}

int run_robustness(const RobustnessOptions& o, const evolve::EvaluatorFactory& evaluators, std::ostream& out,
                   std::ostream& err) {
  if (o.seeds < 1 || o.seeds > 100000) throw sim::ConfigError("--seeds", 0, "", "must lie in [1, 100000]");
  if (o.robots.empty()) throw sim::ConfigError("--robots", 0, "", "give at least one robot count");
  check_sweep("--fail-fractions", o.grid.fail_fractions);
  check_sweep("--packet-loss", o.grid.packet_losses);
  const std::vector<sim::Mode> modes = path_modes(o.mode);
  const sim::Params p = params_or_defaults(o.params);
  const std::vector<std::string> files = scenario_files(o.scenarios);
  std::vector<evolve::NamedPath> inputs = {{"--params", o.params}};
  for (const std::string& f : files) inputs.push_back({"--scenarios", f});
  if (!o.benchmark.empty()) inputs.push_back({"--benchmark", o.benchmark});
  evolve::check_output_paths(inputs, {{"--json", o.json}, {"--md", o.markdown}, {"--svg", o.svg}});
  std::vector<sim::Scenario> base;
  std::vector<std::string> group_of;  // a scenario file's folder (paper), or the benchmark's name
  for (const std::string& f : files) {
    base.push_back(with_fault_options(scenario_with_overrides(f, {}, o.ticks), o.faults));
    group_of.push_back(std::filesystem::path(f).parent_path().filename().string());
  }
  check_seed_range("--seed-base", o.seed_base, o.seeds);
  const int threads = threads_or_all(o.threads);
  if (!o.benchmark.empty()) {
    // the benchmark's arenas, every family, beside the scenario files (its robots and seeds are the options')
    const BenchmarkConfig c = load_benchmark_config(o.benchmark);
    std::vector<const BenchmarkFamily*> families;
    for (const BenchmarkFamily& f : c.families) families.push_back(&f);
    err << "swarmpath robustness: drawing the arenas of " << c.name << " v" << c.version << " (" << c.file
        << ")\n";
    for (const sim::arenas::GeneratedArena& a : draw_benchmark_arenas(families, threads)) {
      const sim::Scenario s = sim::with_max_ticks(a.scenario, o.ticks.value_or(c.max_ticks), c.file);
      base.push_back(with_fault_options(s, o.faults));
      group_of.push_back(c.name);
    }
  }
  if (base.empty()) throw sim::ConfigError("--scenarios", 0, "", "no scenario to run");
  const std::vector<double> astar8 = astar8_lengths(base);
  const std::vector<Variant> variants = make_variants(base.size(), o.grid);
  const std::vector<sim::Scenario> cases = variant_scenarios(base, variants, o.grid);
  RobustnessGrid sweep = o.grid;
  sweep.pf_radio = sim::sensor_needs(sim::Mode::kPathFormation, p).rab;  // share_sighting
  const std::vector<GridCase> grid =
      robustness_cases(variants, o.robots, modes, o.seeds, o.seed_base, sweep.pf_radio);

  const std::unique_ptr<evolve::BatchEvaluator> evaluator = evaluators(threads);
  const bool tty = stderr_is_terminal();
  const Stopwatch clock;
  err << "swarmpath robustness: " << base.size() << " scenarios x " << o.robots.size() << " robot counts x "
      << o.grid.fail_fractions.size() << " failure fractions x " << o.grid.packet_losses.size()
      << (sweep.pf_radio ? " packet losses x " : " packet losses (task allocation only) x ") << o.seeds
      << " seeds = " << grid.size() << " runs, mode " << o.mode << ", " << evaluator->describe() << "\n";
  const std::vector<GridRun> runs = run_grid(cases, grid, p, *evaluator, grid_progress(err, tty));
  if (tty) err << "\n";
  err << "  done in " << fixed(clock.seconds(), 1) << " s: " << evaluator->summary() << "\n";

  const RobustnessReport report = summarise_robustness(base, astar8, variants, sweep, modes, runs, group_of);
  std::ostringstream md;
  const sim::FaultModel& f = base[0].faults;
  std::string robots;
  for (const int n : o.robots) robots += (robots.empty() ? "" : ",") + std::to_string(n);
  sim::FaultModel other = f;  // the sources the sweep does not set
  other.fail_fraction = 0;
  other.packet_loss = 0;
  md << "Robustness of " << (o.params.empty() ? std::string("the default params") : o.params) << ": "
     << base.size() << " scenarios, robots " << robots << ", " << o.seeds << " seeds from " << o.seed_base
     << "; the failing robots are drawn from "
     << (f.fail_target == sim::FailTarget::kAny ? "the whole swarm" : "the chain's links")
     << ", their failure times uniform over ticks " << f.fail_from << "-" << f.fail_until
     << "; other faults: " << faults_text(other) << "\n\n";
  write_robustness_markdown(md, report);
  const int code =
      write_outputs({{o.markdown, [&](std::ostream& file) { file << md.str(); }},
                     {o.json,
                      [&](std::ostream& file) {
                        nlohmann::ordered_json j = robustness_json(report, cases, runs, variants, astar8);
                        j["params"] = o.params.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.params);
                        j["robots"] = o.robots;
                        j["seeds"] = o.seeds;
                        j["seed_base"] = o.seed_base;
                        j["faults"] = faults_json(base[0].faults);
                        file << j.dump(2) << "\n";
                      }},
                     {o.svg,
                      [&](std::ostream& file) {
                        write_robustness_svg(
                            file, report,
                            std::to_string(base.size()) + " scenarios, " + std::to_string(o.robots.size()) +
                                " robot counts, " + std::to_string(o.seeds) + " seeds; " +
                                (o.params.empty() ? std::string("default params") : o.params));
                      }}},
                    err);
  out << md.str();
  return code;
}

}  // namespace

Runner add_robustness(CLI::App& app, const evolve::EvaluatorFactory& evaluators) {
  auto o = std::make_shared<RobustnessOptions>();
  app.add_option("--scenarios", o->scenarios, "Scenario files or directories of *.toml")
      ->capture_default_str();
  app.add_option("--benchmark", o->benchmark,
                 "Also run the arenas of this benchmark (e.g. configs/benchmarks/generalisation.toml, every "
                 "family) beside the scenarios, at --robots and --seeds; success is reported per group too");
  app.add_option("--robots", o->robots, "Robot counts, e.g. 60,100")->delimiter(',')->capture_default_str();
  app.add_option("--seeds", o->seeds, "Seeds per (scenario, robots, condition) case")->capture_default_str();
  add_seed_option(app, "--seed-base", o->seed_base, "The first seed; every condition runs the same seeds");
  app.add_option("--mode", o->mode, "pf, ta or both (each case with and without task allocation)")
      ->capture_default_str();
  app.add_option("--params", o->params, "Params file (default: the code's defaults)");
  app.add_option("--ticks", o->ticks, "Override every scenario's max_ticks");
  add_threads_option(app, o->threads);
  app.add_option("--fail-fractions", o->grid.fail_fractions,
                 "Shares of the robots that fail-stop during each run, increasing, e.g. 0,0.05,0.1,0.2")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--packet-loss", o->grid.packet_losses,
                 "Range-and-bearing packet losses, increasing, e.g. 0,0.1,0.3 (path formation without "
                 "share_sighting uses no radio: its runs stand for every loss)")
      ->delimiter(',')
      ->capture_default_str();
  add_fault_options(app, o->faults, /*sweep=*/true);
  app.add_option("--json", o->json, "Write every run and every cell as JSON");
  app.add_option("--md", o->markdown, "Write the markdown tables to this file too");
  app.add_option("--svg", o->svg, "Write success, time and path / A* against the failure fraction as SVG");
  return [o, evaluators](std::ostream& out, std::ostream& err) {
    return run_robustness(*o, evaluators, out, err);
  };
}

}  // namespace swarmpath::app
