// SPDX-License-Identifier: MIT
// swarmpath table: a grid of scenario x robots x seed in parallel, written as the paper's table
// (the grid and its summary are table_run's, which the Python module's table() calls too).
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
#include "evolve/path_collision.hpp"
#include "experiment.hpp"
#include "fault_options.hpp"
#include "recording_file.hpp"
#include "sim/recorder.hpp"
#include "table_run.hpp"

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

int table_command(const TableOptions& o, const evolve::EvaluatorFactory& evaluators, std::ostream& out,
                  std::ostream& err) {
  TableRequest r;
  r.scenarios = o.scenarios;
  r.robots = o.robots;
  r.seeds = o.seeds;
  r.seed_base = o.seed_base;
  r.mode = o.mode;
  r.params = params_or_defaults(o.params);
  r.params_file = o.params;
  r.ticks = o.ticks;
  r.threads = o.threads;
  r.faults = o.faults;
  const TablePlan plan = plan_table(r);
  std::vector<evolve::NamedPath> inputs = {{"--params", o.params}};
  for (const std::string& f : plan.files) inputs.push_back({"--scenarios", f});
  evolve::check_output_paths(inputs, {{"--json", o.json}, {"--csv", o.csv}, {"--md", o.markdown}});
  note_benchmark_arenas(plan.scenarios, err);

  const std::unique_ptr<evolve::BatchEvaluator> evaluator = evaluators(plan.threads);
  const bool tty = stderr_is_terminal();
  const Stopwatch clock;
  err << "swarmpath table: " << plan.scenarios.size() << " scenarios x " << o.robots.size()
      << " robot counts x " << plan.modes.size() << " modes x " << o.seeds << " seeds = " << plan.grid.size()
      << " runs, mode " << o.mode << ", " << evaluator->describe() << "\n";
  const TableOutcome outcome = run_table(plan, *evaluator, grid_progress(err, tty));
  if (tty) err << "\n";
  err << "  done in " << fixed(clock.seconds(), 1) << " s: " << evaluator->summary() << "\n";
  if (!o.record_failures.empty())
    record_failures(plan.scenarios, outcome.runs, r.params, o, plan.threads, err);

  const int code = write_outputs({{o.json, [&](std::ostream& f) { f << outcome.json.dump(2) << "\n"; }},
                                  {o.csv, [&](std::ostream& f) { f << table_runs_csv(plan, outcome); }},
                                  {o.markdown, [&](std::ostream& f) { f << outcome.markdown; }}},
                                 err);
  out << outcome.markdown;
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
  return [o, evaluators](std::ostream& out, std::ostream& err) {
    return table_command(*o, evaluators, out, err);
  };
}

}  // namespace swarmpath::app
