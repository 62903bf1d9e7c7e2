// SPDX-License-Identifier: MIT
// swarmpath irace: an evolve config as an irace tuning scenario (write), irace's best as a params
// file (import), and the one simulation irace's target runner asks for (run).
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <memory>
#include <ostream>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <omp.h>

#include "cli.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/irace_import.hpp"
#include "evolve/irace_scenario.hpp"
#include "evolve/objective.hpp"
#include "evolve/path_collision.hpp"
#include "evolve/simulation_budget.hpp"
#include "sim/config_error.hpp"

extern char** environ;

namespace swarmpath::app {

namespace {

namespace fs = std::filesystem;

struct IraceOptions {
  // write
  std::string config;
  std::string out;
  std::optional<std::int64_t> max_experiments;
  int threads = 0;
  std::optional<std::uint64_t> seed;
  // import
  std::string dir;
  std::string best = "best.toml";
  int rank = 1;
  // run
  std::string run_config;
  std::uint64_t run_seed = 1;
  std::string scenario;
  std::optional<int> robots;
  CLI::App* run = nullptr;
  CLI::App* import = nullptr;
};

// the running binary, for the target runner to call
std::string this_executable() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  if (ec)
    throw std::runtime_error("cannot find the swarmpath binary's path (/proc/self/exe): " + ec.message());
  return p.string();
}

int write_scenario(const IraceOptions& o, std::ostream& out) {
  if (o.config.empty()) throw sim::ConfigError("--config", 0, "", "required (the evolve config to tune)");
  if (o.out.empty()) throw sim::ConfigError("--out", 0, "", "required (the folder of the irace scenario)");
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  if (threads > 1024) throw sim::ConfigError("--threads", 0, "", "at most 1024");
  const evolve::EvolveConfig c = evolve::load_evolve_config(o.config);
  // the scenario's files never replace the config or the files it names
  std::vector<evolve::NamedPath> inputs = {{"--config", o.config}, {"params", c.params_file}};
  for (const evolve::ScenarioRef& ref : c.evaluation.scenarios)
    inputs.push_back({"evaluation.scenarios", ref.path});
  std::vector<evolve::NamedPath> outputs;
  fs::create_directories(o.out);
  for (const char* name : {"parameters.txt", "instances.txt", "configurations.txt", "target-runner",
                           "scenario.txt", "run-irace", "export-elites.R", "swarmpath-irace.json"}) {
    outputs.push_back({"--out", (fs::path(o.out) / name).string()});
  }
  evolve::check_output_paths(inputs, outputs);
  evolve::IraceScenarioOptions so;
  so.out_dir = o.out;
  so.swarmpath = this_executable();
  so.max_experiments = o.max_experiments;
  so.parallel = threads;
  so.seed = o.seed;
  const evolve::IraceManifest m = evolve::write_irace_scenario(c, so);
  out << "irace scenario for " << c.name << " in " << o.out << ": " << c.genome.genes.size()
      << " parameters, " << m.instances.size() << " instances, maxExperiments " << m.max_experiments;
  if (!o.max_experiments) {
    if (const auto b = evolve::simulation_budget(c)) {
      out << " (" << b->candidates << " candidates x " << b->cases_per_candidate << " runs + "
          << b->reevaluation << " re-evaluation runs, as the config's own run)";
    }
  }
  out << ", parallel " << m.parallel << ", seed " << m.seed << "\n";
  out << "  run irace:   " << (fs::path(o.out) / "run-irace").string() << "   (irace, then elites.csv)\n";
  out << "  then:        swarmpath irace import " << o.out << " --out best.toml\n";
  return kExitOk;
}

// runs a program (no shell) and waits; its exit status, or -1 when it could not start
int run_program(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// elites.csv, written from irace.Rdata first when it is missing or older
std::string elites_csv(const std::string& dir, std::ostream& err) {
  const fs::path csv = fs::path(dir) / "elites.csv";
  const fs::path rdata = fs::path(dir) / "irace.Rdata";
  std::error_code ec;
  const bool have_rdata = fs::exists(rdata, ec);
  const bool stale =
      !fs::exists(csv, ec) || (have_rdata && fs::last_write_time(csv, ec) < fs::last_write_time(rdata, ec));
  if (!stale) return csv.string();
  if (!have_rdata) {
    throw sim::ConfigError(rdata.string(), 0, "",
                           "not found: run irace first (" + (fs::path(dir) / "run-irace").string() + ")");
  }
  err << "reading irace's elites from " << rdata.string() << " (Rscript export-elites.R)\n";
  const int rc = run_program({"Rscript", "--vanilla", (fs::path(dir) / "export-elites.R").string(), dir});
  if (rc != 0) {
    throw std::runtime_error("Rscript export-elites.R failed (" +
                             (rc < 0 ? std::string("Rscript not found: install r-cran-irace")
                                     : "exit status " + std::to_string(rc)) +
                             ")");
  }
  return csv.string();
}

int import_best(const IraceOptions& o, std::ostream& out, std::ostream& err) {
  const evolve::IraceManifest m = evolve::read_irace_manifest(o.dir);
  const evolve::EvolveConfig c = evolve::load_evolve_config(m.config);
  if (evolve::config_hash(c) != m.config_hash) {
    throw sim::ConfigError(m.config, 0, "",
                           "changed since the irace scenario in " + o.dir + " was written (hash " +
                               m.config_hash + ", now " + evolve::config_hash(c) +
                               "): write the scenario again and rerun irace");
  }
  const std::string csv = elites_csv(o.dir, err);
  evolve::check_output_paths(
      {{"elites.csv", csv}, {"the evolve config", m.config}, {"its params", c.params_file}},
      {{"--out", o.best}});
  const std::vector<evolve::IraceElite> elites = evolve::read_irace_elites(csv);
  if (o.rank < 1 || o.rank > static_cast<int>(elites.size())) {
    throw sim::ConfigError(
        "--rank", 0, "",
        "irace kept " + std::to_string(elites.size()) + " elites: give 1-" + std::to_string(elites.size()));
  }
  const evolve::IraceElite& e = elites[static_cast<std::size_t>(o.rank - 1)];
  const evolve::Decoded d = evolve::irace_elite_candidate(c.genome, e, csv);
  if (!d.violation.empty())
    throw sim::ConfigError(csv, 0, "", "irace's configuration " + e.id + ": " + d.violation);
  evolve::write_file_atomic(o.best, evolve::irace_params_toml(c, m, e, d, o.dir));
  out << "irace's elite " << e.rank << " (configuration " << e.id << ", mean cost " << fixed(e.mean_cost, 4)
      << " over " << e.runs << " runs) -> " << o.best << "\n ";
  for (const auto& [name, value] : evolve::tuned_values(c.genome, d.params))
    out << ' ' << name << " = " << value;
  out << "\n";
  return kExitOk;
}

// "--name=value" of a tuned parameter, as irace's buildCommandLine writes it
std::vector<double> tuned_from_switches(const evolve::Genome& g, const std::vector<std::string>& switches) {
  std::vector<double> values(g.genes.size());
  for (std::size_t i = 0; i < g.genes.size(); ++i) values[i] = sim::get_value(g.base, *g.genes[i].info);
  for (const std::string& s : switches) {
    const auto eq = s.find('=');
    if (s.rfind("--", 0) != 0 || eq == std::string::npos) {
      throw sim::ConfigError("irace run", 0, s, "expected --<parameter>=<value>");
    }
    const std::string name = s.substr(2, eq - 2);
    const std::string text = s.substr(eq + 1);
    std::size_t i = 0;
    while (i < g.genes.size() && g.genes[i].info->name != name) ++i;
    if (i == g.genes.size())
      throw sim::ConfigError("irace run", 0, name, "not a parameter the evolve config tunes");
    const sim::ParamInfo& info = *g.genes[i].info;
    if (info.type == sim::ParamType::kBool) {
      if (text != "true" && text != "false")
        throw sim::ConfigError("irace run", 0, name, "expected true or false");
      values[i] = text == "true" ? 1.0 : 0.0;
    } else if (info.type == sim::ParamType::kChoice) {
      if (text != info.choices[0] && text != info.choices[1])
        throw sim::ConfigError("irace run", 0, name, "not one of the parameter's choices: " + text);
      values[i] = text == info.choices[1] ? 1.0 : 0.0;
    } else {
      std::size_t used = 0;
      try {
        values[i] = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != text.size() || text.empty())
        throw sim::ConfigError("irace run", 0, name, "not a number: " + text);
    }
  }
  return values;
}

int run_one(const IraceOptions& o, std::ostream& out) {
  const evolve::EvolveConfig c = evolve::load_evolve_config(o.run_config);
  // the training setting of this instance (its scenario file and robot count), alone: one A*
  std::error_code ec;
  const fs::path want = fs::weakly_canonical(o.scenario, ec);
  evolve::EvolveConfig one = c;
  one.reevaluate.held_out.clear();
  bool found = false;
  for (const evolve::ScenarioRef& ref : c.evaluation.scenarios) {
    if (found || fs::weakly_canonical(ref.path, ec) != want) continue;
    const int n = o.robots ? *o.robots : sim::load_scenario(ref.path).robots;
    const std::vector<int>& robots = c.evaluation.robots;
    if (!robots.empty() && std::find(robots.begin(), robots.end(), n) == robots.end()) continue;
    if (robots.empty() && o.robots && *o.robots != sim::load_scenario(ref.path).robots) continue;
    one.evaluation.scenarios = {ref};
    one.evaluation.robots = {n};
    found = true;
  }
  if (!found) {
    throw sim::ConfigError(o.scenario, 0, "",
                           "not a training scenario (with --robots " +
                               (o.robots ? std::to_string(*o.robots) : "-") + ") of " + c.file);
  }
  const evolve::SwarmObjective f(one);
  const evolve::Decoded d =
      evolve::decode_values(c.genome, tuned_from_switches(c.genome, o.run->remaining()));
  const evolve::EvalCase ec0{0, 0, o.run_seed};
  const evolve::RunScore s = d.violation.empty() ? f.evaluate(d.params, ec0) : f.penalty(ec0);
  out << std::setprecision(17) << s.fitness << "\n";
  return kExitOk;
}

}  // namespace

Runner add_irace(CLI::App& app) {
  auto o = std::make_shared<IraceOptions>();
  app.require_subcommand(0, 1);
  app.footer(
      "Write an irace scenario from an evolve config (irace --config C --out DIR), run it (DIR/run-irace), "
      "then "
      "turn irace's best into a params file (irace import DIR --out best.toml).");
  app.add_option("--config", o->config,
                 "Evolve config (TOML) whose [tune], [evaluation], [fitness] and budget irace gets");
  app.add_option("--out", o->out, "Folder of the irace scenario (created)");
  app.add_option(
      "--max-experiments", o->max_experiments,
      "irace's budget in simulations (default: what the config's own run spends to choose its best: "
      "its candidates x runs each, plus the finalists' and, with keep_base, the base params' "
      "re-evaluation)");
  app.add_option("--threads", o->threads, "irace's parallel: simulations at once (default: all cores)");
  app.add_option("--seed", o->seed, "irace's seed (default: the config's master seed)");

  o->import =
      app.add_subcommand("import", "Turn irace's best configuration into a params file with its provenance");
  o->import->add_option("dir", o->dir, "The irace scenario folder (after irace ran in it)")->required();
  o->import->add_option("--out", o->best, "The params file to write")->capture_default_str();
  o->import->add_option("--rank", o->rank, "Which of irace's final elites (1: irace's best)")
      ->capture_default_str();

  o->run = app.add_subcommand(
      "run", "One simulation of one configuration, its fitness printed (what the target runner calls)");
  o->run->add_option("--config", o->run_config, "The evolve config")->required();
  o->run->add_option("--seed", o->run_seed, "Simulation seed (irace's)")->required();
  o->run->add_option("scenario", o->scenario, "Scenario file of a training setting")->required();
  o->run->add_option("--robots", o->robots, "Robot count of the training setting");
  o->run->allow_extras();
  o->run->footer("Tuned parameters follow as --<name>=<value> (irace's switches).");

  return [o](std::ostream& out, std::ostream& err) {
    if (o->import->parsed()) return import_best(*o, out, err);
    if (o->run->parsed()) return run_one(*o, out);
    return write_scenario(*o, out);
  };
}

}  // namespace swarmpath::app
