// SPDX-License-Identifier: MIT
// swarmpath verify: does each shipped tuned genome still beat the default? Each runs with the
// default on fresh cases of the evolve config that tuned it (seeds and arenas no run drew) and is
// judged as that run judged; genomes/tuned.toml lists them (make verify-genomes).
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
#include "evolve/genome_manifest.hpp"
#include "evolve/objective.hpp"
#include "evolve/path_collision.hpp"
#include "evolve/verify.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::app {

namespace {

struct VerifyOptions {
  std::string manifest = "genomes/tuned.toml";
  std::string genome;
  std::string config;
  std::string against;
  int seeds = 4;
  int arenas = 4;
  std::uint64_t salt = 0;
  std::optional<int> threads;
  std::string json;
};

int run_verify(const VerifyOptions& o, const evolve::EvaluatorFactory& evaluators, std::ostream& out,
               std::ostream& err) {
  if (o.seeds < 1 || o.seeds > 10000) throw sim::ConfigError("--seeds", 0, "", "must lie in [1, 10000]");
  if (o.arenas < 1 || o.arenas > 10000) throw sim::ConfigError("--arenas", 0, "", "must lie in [1, 10000]");
  if (o.genome.empty() != o.config.empty()) {
    throw sim::ConfigError(o.genome.empty() ? "--config" : "--genome", 0, "",
                           "give --genome and --config together");
  }
  evolve::check_output_paths(
      {{"--manifest", o.manifest}, {"--genome", o.genome}, {"--config", o.config}, {"--against", o.against}},
      {{"--json", o.json}});
  const int threads = threads_or_all(o.threads);
  const std::unique_ptr<evolve::BatchEvaluator> evaluator = evaluators(threads);
  evolve::GenomeManifest m;
  if (o.genome.empty()) {
    m = evolve::load_genome_manifest(o.manifest);
  } else {
    if (o.against.empty()) throw sim::ConfigError("--against", 0, "", "name the default genome to beat");
    m.genomes.push_back({o.genome, o.config, "", std::nullopt});
  }
  if (!o.against.empty()) m.against = o.against;
  const sim::Params against = sim::load_params(m.against);
  const bool tty = stderr_is_terminal();
  const Stopwatch clock;
  int still = 0;
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  out << "| genome | config | runs | fitness / objectives | verdict |\n|---|---|---|---|---|\n";
  for (const evolve::ShippedGenome& g : m.genomes) {
    const evolve::EvolveConfig c = evolve::load_evolve_config(g.config);
    std::string notes;
    if (!g.run.empty()) {
      if (const std::string mismatch = evolve::genome_mismatch(g); !mismatch.empty())
        notes += " " + mismatch + ".";
      const std::string then = evolve::recorded_config_hash(g), now = evolve::config_hash(c);
      if (then != now) {
        notes += " The config or its inputs (base params, scenario files) changed since the run (hash " +
                 then + " then, " + now + " now).";
      }
    }
    err << "swarmpath verify: " << g.params << " against " << m.against << " on fresh cases of " << g.config
        << "\n";
    const evolve::SwarmObjective f(c);
    const evolve::VerifyResult r =
        evolve::verify_genome(c, f, sim::load_params(g.params), against, o.seeds, o.arenas, o.salt,
                              *evaluator, [&](std::size_t done, std::size_t total) {
                                if (tty)
                                  err << "\r  " << done << " / " << total << " runs, "
                                      << fixed(clock.seconds(), 0) << " s   " << std::flush;
                              });
    if (tty) err << "\n";
    still += r.wins ? 1 : 0;
    out << "| " << g.params << " | " << g.config << " | " << r.genome.runs << " | "
        << (c.multi_objective()
                ? "objectives"
                : "fitness " + fixed(r.genome.fitness, 4) + " vs " + fixed(r.against.fitness, 4))
        << " | **" << (r.wins ? "wins" : "does not win") << "**: " << r.verdict << "." << notes << " |\n";
    results.push_back({{"genome", g.params},
                       {"config", g.config},
                       {"against", m.against},
                       {"runs", r.genome.runs},
                       {"wins", r.wins},
                       {"verdict", r.verdict},
                       {"notes", notes},
                       {"genome_success_rate", r.genome.success_rate},
                       {"against_success_rate", r.against.success_rate},
                       {"genome_fitness", r.genome.fitness},
                       {"against_fitness", r.against.fitness}});
  }
  out << "\n"
      << still << " of " << m.genomes.size() << " shipped genomes still beat " << m.against << " (" << o.seeds
      << " fresh seeds per scenario and robot count, " << o.arenas << " fresh arenas per family entry; "
      << fixed(clock.seconds(), 0) << " s)\n";
  if (!o.json.empty()) evolve::write_file_atomic(o.json, results.dump(2) + "\n");
  return kExitOk;
}

}  // namespace

Runner add_verify(CLI::App& app, const evolve::EvaluatorFactory& evaluators) {
  auto o = std::make_shared<VerifyOptions>();
  app.add_option("--manifest", o->manifest, "The shipped tuned genomes and their configs and runs")
      ->capture_default_str();
  app.add_option("--genome", o->genome, "Verify this params file instead (with --config and --against)");
  app.add_option("--config", o->config, "The evolve config that tuned --genome");
  app.add_option("--against", o->against, "The default genome to beat (default: the manifest's)");
  app.add_option("--seeds", o->seeds, "Fresh seeds per scenario and robot count")->capture_default_str();
  app.add_option("--arenas", o->arenas, "Fresh arenas per family entry")->capture_default_str();
  app.add_option("--salt", o->salt, "Another set of fresh seeds and arenas (0: the usual one)")
      ->capture_default_str();
  add_threads_option(app, o->threads);
  app.add_option("--json", o->json, "Write each genome's verdict as JSON");
  return
      [o, evaluators](std::ostream& out, std::ostream& err) { return run_verify(*o, evaluators, out, err); };
}

}  // namespace swarmpath::app
