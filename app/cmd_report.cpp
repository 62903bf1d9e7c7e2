// SPDX-License-Identifier: MIT
// swarmpath report: a tuning run as one self-contained web page, with replays of the reported
// genome on each training arena.
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <ostream>

#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/objective.hpp"
#include "evolve/path_collision.hpp"
#include "recording_file.hpp"
#include "report_page.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::app {

namespace fs = std::filesystem;

namespace {

struct ReportOptions {
  std::string dir;
  std::string out;
  std::string config;
  bool no_replays = false;
  std::int64_t record_every = 0;
  std::optional<int> threads;
};

// the reported genome on the first re-evaluation seed of each training arena (its first robot count)
std::vector<PageRecording> replays(const ReportOptions& o, const ReportInputs& in,
                                   std::vector<std::string>& notes, std::ostream& err) {
  const std::string config_file =
      !o.config.empty() ? o.config : in.run.at("config").value("file", std::string());
  std::error_code ec;
  if (config_file.empty() || !fs::is_regular_file(config_file, ec)) {
    notes.push_back("No replays: the evolve config " +
                    (config_file.empty() ? std::string("(unnamed)") : config_file) +
                    " is not here (run from the folder evolve ran in, or give --config).");
    return {};
  }
  const evolve::EvolveConfig c = evolve::load_evolve_config(config_file);
  if (evolve::config_hash(c) != in.run.value("config_hash", std::string())) {
    notes.push_back("No replays: " + config_file + " has changed since the run (config hash " +
                    evolve::config_hash(c) + ", the run's " + in.run.value("config_hash", std::string("?")) +
                    ").");
    return {};
  }
  const fs::path genome = fs::path(in.dir) / in.genome_file;
  if (!fs::is_regular_file(genome, ec)) {
    notes.push_back("No replays: " + genome.string() + " is missing.");
    return {};
  }
  const sim::Params p = sim::load_params(genome.string());
  const evolve::SwarmObjective objective(c);
  const std::vector<evolve::EvalSetting>& settings = objective.settings();
  const std::vector<evolve::EvalCase> cases = evolve::reevaluation_cases(settings, 1, c.seed);
  std::vector<std::size_t> chosen;  // one case per training arena
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const evolve::EvalSetting& s = settings[cases[i].setting];
    bool seen = s.held_out;
    for (const std::size_t j : chosen) seen = seen || settings[cases[j].setting].scenario == s.scenario;
    if (!seen) chosen.push_back(i);
  }
  err << "swarmpath report: recording " << chosen.size() << " replays of " << genome.string() << "\n";
  std::vector<PageRecording> out(chosen.size());
  const int threads = threads_or_all(o.threads);
  const auto n = static_cast<std::int64_t>(chosen.size());
  std::vector<std::string> errors(chosen.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const evolve::EvalCase& e = cases[chosen[k]];
    const sim::Scenario& s = objective.scenario(e.setting);
    try {
      sim::Metrics m;
      sim::Recording r = sim::record_run(p, s, c.mode, e.seed, record_every(s, o.record_every), &m);
      complete_recording(r, s);
      out[k] = {s.name + ", " + std::to_string(r.robots) + " robots, seed " + std::to_string(e.seed) + ": " +
                    (m.success ? "path at tick " + std::to_string(m.ticks_to_form) : std::string("no path")),
                sim::encode_recording(r)};
    } catch (const std::exception& ex) {
      errors[k] = ex.what();
    }
  }
  for (const std::string& e : errors) {
    if (!e.empty()) throw std::runtime_error("a replay failed: " + e);
  }
  return out;
}

int run_report(const ReportOptions& o, std::ostream& out, std::ostream& err) {
  const ReportInputs in = read_report_inputs(o.dir);
  const std::string path = !o.out.empty() ? o.out : (fs::path(o.dir) / "report.html").string();
  const fs::path d(o.dir);
  evolve::check_output_paths({{"run.json", (d / "run.json").string()},
                              {"checkpoint.json", (d / "checkpoint.json").string()},
                              {"evaluate.json", (d / "evaluate.json").string()},
                              {"--config", o.config}},
                             {{"--out", path}});

  std::vector<std::string> notes;
  const std::vector<PageRecording> runs =
      o.no_replays ? std::vector<PageRecording>{} : replays(o, in, notes, err);
  const std::string page = report_page(in, runs, notes);
  evolve::write_file_atomic(path, page);
  for (const std::string& n : notes) err << "note: " << n << "\n";
  out << "wrote " << path << " (" << fixed(static_cast<double>(page.size()) / 1e6, 2) << " MB, "
      << runs.size() << " replays): open it in a browser\n";
  return kExitOk;
}

}  // namespace

Runner add_report(CLI::App& app) {
  auto o = std::make_shared<ReportOptions>();
  app.add_option("dir", o->dir, "The output folder of an evolve run, e.g. results/evolve/default")
      ->required();
  app.add_option("--out", o->out, "The page to write (default: DIR/report.html)");
  app.add_option("--config", o->config,
                 "The run's evolve config, for the replays (default: the file run.json names, from here)");
  app.add_flag("--no-replays", o->no_replays, "Leave out the replays (no simulation)");
  app.add_option("--record-every", o->record_every,
                 "Ticks between the replays' frames (default: one second of simulated time, 10 ticks)");
  add_threads_option(app, o->threads);
  return [o](std::ostream& out, std::ostream& err) { return run_report(*o, out, err); };
}

}  // namespace swarmpath::app
