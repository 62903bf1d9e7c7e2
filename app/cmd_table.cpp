// SPDX-License-Identifier: MIT
// swarmpath table: a grid of scenario x robots x seed in parallel, written as the paper's table.
#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/params_export.hpp"
#include "evolve/path_collision.hpp"
#include "experiment.hpp"
#include "fault_options.hpp"
#include "recording_file.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "table_output.hpp"
#include "table_report.hpp"

namespace swarmpath::app {

namespace {

struct TableOptions {
  std::vector<std::string> scenarios{"configs/scenarios/paper"};
  std::vector<int> robots{60, 70, 80, 90, 100};
  int seeds = 10;
  std::uint64_t seed_base = 1;
  std::string mode = "pf";
  std::string params;
  std::optional<std::int64_t> ticks;
  std::optional<int> threads;
  std::string json;
  std::string csv;
  std::string markdown;
  std::string record_failures;
  std::int64_t record_every = 0;
  FaultOptions faults;
};

// the failed runs of the grid again, recorded (the same runs: their state hashes are checked), one
// file each in `dir`: <scenario>-n<robots>-<mode>-s<seed>.swrec
void record_failures(const std::vector<sim::Scenario>& scenarios, const std::vector<GridRun>& runs,
                     const sim::Params& p, const TableOptions& o, int threads, std::ostream& err) {
  std::vector<std::size_t> failed;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!runs[i].m.success) failed.push_back(i);
  }
  std::filesystem::create_directories(o.record_failures);
  err << "  recording the " << failed.size() << " failed runs into " << o.record_failures << "\n";
  std::vector<std::string> errors(failed.size());
  const auto n = static_cast<std::int64_t>(failed.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t k = 0; k < n; ++k) {
    const GridRun& g = runs[failed[static_cast<std::size_t>(k)]];
    try {
      const sim::Scenario s = sim::with_robots(scenarios[g.c.scenario], g.c.robots);
      sim::Metrics m;
      sim::Recording r = sim::record_run(p, s, g.c.mode, g.c.seed, record_every(s, o.record_every), &m);
      if (m.state_hash != g.m.state_hash) throw std::logic_error("the recorded run differs from the table's");
      complete_recording(r, s);
      const std::string name = s.name + "-n" + std::to_string(g.c.robots) + "-" +
                               std::string(sim::to_string(g.c.mode)) + "-s" + std::to_string(g.c.seed) +
                               ".swrec";
      write_recording_file((std::filesystem::path(o.record_failures) / name).string(), r);
    } catch (const std::exception& e) {
      errors[static_cast<std::size_t>(k)] = e.what();
    }
  }
  for (const std::string& e : errors) {
    if (!e.empty()) throw std::runtime_error("recording a failed run: " + e);
  }
}

int run_table(const TableOptions& o, const evolve::EvaluatorFactory& evaluators, std::ostream& out,
              std::ostream& err) {
  if (o.seeds < 1 || o.seeds > 100000) throw sim::ConfigError("--seeds", 0, "", "must lie in [1, 100000]");
  if (o.robots.empty()) throw sim::ConfigError("--robots", 0, "", "give at least one robot count");
  check_distinct_robots("--robots", o.robots);
  check_seed_range("--seed-base", o.seed_base, o.seeds);
  const std::vector<sim::Mode> modes = path_modes(o.mode);
  const bool both = modes.size() == 2;
  const std::vector<std::string> files = scenario_files(o.scenarios);
  std::vector<evolve::NamedPath> inputs = {{"--params", o.params}};
  for (const std::string& f : files) inputs.push_back({"--scenarios", f});
  evolve::check_output_paths(inputs, {{"--json", o.json}, {"--csv", o.csv}, {"--md", o.markdown}});
  const sim::Params p = params_or_defaults(o.params);
  std::vector<sim::Scenario> scenarios;
  for (const std::string& f : files)
    scenarios.push_back(with_fault_options(scenario_with_overrides(f, {}, o.ticks), o.faults));
  note_benchmark_arenas(scenarios, err);
  check_distinct_scenarios("--scenarios", files, scenarios);
  const int threads = threads_or_all(o.threads);
  const std::vector<double> astar8 = astar8_lengths(scenarios);  // the A* baseline of each scenario, once

  const std::unique_ptr<evolve::BatchEvaluator> evaluator = evaluators(threads);
  const std::vector<GridCase> grid = make_grid(scenarios.size(), o.robots, modes, o.seeds, o.seed_base);
  const bool tty = stderr_is_terminal();
  const Stopwatch clock;
  const GridProgress progress = grid_progress(err, tty);
  err << "swarmpath table: " << scenarios.size() << " scenarios x " << o.robots.size() << " robot counts x "
      << modes.size() << " modes x " << o.seeds << " seeds = " << grid.size() << " runs, mode " << o.mode
      << ", " << evaluator->describe() << "\n";
  const std::vector<GridRun> runs = run_grid(scenarios, grid, p, *evaluator, progress);
  if (tty) err << "\n";
  err << "  done in " << fixed(clock.seconds(), 1) << " s: " << evaluator->summary() << "\n";
  if (!o.record_failures.empty()) record_failures(scenarios, runs, p, o, threads, err);

  std::ostringstream md;
  md << "Controller: the " << evolve::controller_text(p) << (o.params.empty() ? "" : ", " + o.params)
     << "; the paper's figures in parentheses.\n\n";
  nlohmann::ordered_json json;
  if (both) {
    const Comparison c = compare(
        summarise(scenarios, astar8, runs_of(runs, sim::Mode::kPathFormation), sim::Mode::kPathFormation),
        summarise(scenarios, astar8, runs_of(runs, sim::Mode::kTaskAllocation), sim::Mode::kTaskAllocation));
    write_markdown(md, c);
    if (!o.json.empty()) json = comparison_json(scenarios, astar8, runs, c);
  } else {
    const TableReport report = summarise(scenarios, astar8, runs, modes[0]);
    write_markdown(md, report);
    if (!o.json.empty()) json = table_json(scenarios, astar8, runs, report);
  }
  if (!o.json.empty()) {
    json["params"] = o.params;
    json["controller"] = evolve::controller_json(p);
  }
  // every output that can be written is (a full disk loses one file, not the others)
  int code = kExitOk;
  const auto save = [&](const std::string& path, const std::function<void(std::ostream&)>& write) {
    if (path.empty()) return;
    try {
      evolve::write_file_atomic(path, write);
    } catch (const evolve::WriteError& e) {
      err << "error: " << e.what() << "\n";
      code = kExitFailure;
    }
  };
  save(o.json, [&](std::ostream& f) { f << json.dump(2) << "\n"; });
  save(o.csv, [&](std::ostream& f) { write_runs_csv(f, scenarios, astar8, runs); });
  save(o.markdown, [&](std::ostream& f) { f << md.str(); });
  out << md.str();
  return code;
}

}  // namespace

Runner add_table(CLI::App& app, const evolve::EvaluatorFactory& evaluators) {
  auto o = std::make_shared<TableOptions>();
  app.add_option("--scenarios", o->scenarios, "Scenario files or directories of *.toml")
      ->capture_default_str();
  app.add_option("--robots", o->robots, "Robot counts, e.g. 60,70,80,90,100")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--seeds", o->seeds, "Seeds per (scenario, robots) case")->capture_default_str();
  add_seed_option(app, "--seed-base", o->seed_base,
                  "The first seed; a case uses seed-base ... seed-base+seeds-1");
  app.add_option("--mode", o->mode,
                 "pf (path formation), ta (task allocation, then path formation) or both (each case with and "
                 "without task allocation on the same seeds: the paper's whole table)")
      ->capture_default_str();
  app.add_option("--params", o->params, "Params file (default: the paper's defaults)");
  app.add_option("--ticks", o->ticks, "Override every scenario's max_ticks");
  add_threads_option(app, o->threads);
  app.add_option("--json", o->json, "Write runs, cases, environments and summary as JSON");
  app.add_option("--csv", o->csv, "Write one CSV line per run");
  app.add_option("--md", o->markdown, "Write the markdown table to this file too");
  app.add_option(
      "--record-failures", o->record_failures,
      "Record every run that did not form its path into this folder (.swrec, one per run; play them "
      "with 'swarmpath view')");
  app.add_option("--record-every", o->record_every,
                 "Ticks between recorded frames (default: one second of simulated time, 10 ticks)");
  add_fault_options(app, o->faults);
  return
      [o, evaluators](std::ostream& out, std::ostream& err) { return run_table(*o, evaluators, out, err); };
}

}  // namespace swarmpath::app
