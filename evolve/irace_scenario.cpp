// SPDX-License-Identifier: MIT
#include "irace_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "evolve/atomic_write.hpp"
#include "evolve/simulation_budget.hpp"
#include "sim/config_error.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::evolve {

namespace {

namespace fs = std::filesystem;

std::string num(double v) {
  std::ostringstream o;
  o.precision(12);
  o << v;
  return o.str();
}

bool whole(double v) { return std::isfinite(v) && v == std::floor(v); }

// single-quoted for sh
std::string sh_quote(const std::string& s) {
  std::string out = "'";
  for (const char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

std::string absolute(const std::string& path) { return fs::absolute(path).lexically_normal().string(); }

// decimal places irace keeps for real parameters: enough for the smallest positive bound
int irace_digits(const Genome& g) {
  int digits = 6;
  for (const Gene& gene : g.genes) {
    if (gene.binary()) continue;
    const double smallest = gene.lo > 0.0 ? gene.lo : (gene.step > 0.0 ? gene.step : 0.0);
    if (smallest > 0.0) digits = std::max(digits, static_cast<int>(std::ceil(-std::log10(smallest))) + 4);
  }
  return std::min(digits, 15);
}

void write_text(const fs::path& path, const std::string& text, bool executable = false) {
  write_file_atomic(path.string(), text);
  if (executable) {
    fs::permissions(path, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                    fs::perm_options::add);
  }
}

std::string configurations_txt(const Genome& g) {
  std::ostringstream o;
  o << "## The base params of the evolve config: irace's first configuration, as swarmpath's optimisers\n"
       "## start from it.\n";
  for (const Gene& gene : g.genes) o << gene.info->name << ' ';
  o << '\n';
  for (const Gene& gene : g.genes) {
    const double v = sim::get_value(g.base, *gene.info);
    if (gene.info->type == sim::ParamType::kBool) {
      o << (v != 0.0 ? "true" : "false");
    } else if (gene.info->type == sim::ParamType::kChoice) {
      o << gene.info->choices[v != 0.0 ? 1 : 0];
    } else {
      o << num(v);
    }
    o << ' ';
  }
  o << '\n';
  return o.str();
}

std::string target_runner(const EvolveConfig& c, const IraceScenarioOptions& o) {
  std::ostringstream s;
  s << "#!/bin/sh\n"
       "# irace's target runner for the evolve config "
    << c.name
    << ": one simulation of one configuration on one\n"
       "# instance. irace calls it as\n"
       "#   target-runner <configuration id> <instance id> <seed> <scenario file> --robots <N> "
       "--<name>=<value>...\n"
       "# and reads the run's cost from its output: the config's [fitness] of that run (minimised). The\n"
       "# simulation seed is irace's seed, so every configuration meets the same seeds on an instance.\n"
       "# Written by `swarmpath irace`.\n"
       "shift 2\n"
       "seed=$1\n"
       "shift\n"
       "exec "
    << sh_quote(o.swarmpath) << " irace run --config " << sh_quote(absolute(c.file))
    << " --seed \"$seed\" \"$@\"\n";
  return s.str();
}

std::string scenario_txt(const EvolveConfig& c, const IraceManifest& m, int digits) {
  std::ostringstream s;
  s << "## irace scenario for the swarmpath evolve config " << m.config << "\n"
    << "## (hash " << m.config_hash
    << "), written by `swarmpath irace`. Run it with ./run-irace (irace, then\n"
    << "## elites.csv), then `swarmpath irace import <this folder> --out best.toml`.\n"
    << "## Relative paths are relative to this file's folder.\n"
    << "parameterFile = \"./parameters.txt\"\n"
    << "configurationsFile = \"./configurations.txt\"\n"
    << "trainInstancesDir = \"\"\n"
    << "trainInstancesFile = \"./instances.txt\"\n"
    << "targetRunner = \"./target-runner\"\n"
    << "execDir = \"./\"\n"
    << "logFile = \"./irace.Rdata\"\n"
    << "## the simulations the config's own run spends to choose its best (swarmpath irace --help)\n"
    << "maxExperiments = " << m.max_experiments << "\n"
    << "parallel = " << m.parallel << "\n"
    << "seed = " << m.seed << "\n"
    << "## simulations are noisy: a configuration runs again on every new (instance, seed)\n"
    << "deterministic = 0\n"
    << "digits = " << digits << "\n";
  if (c.evaluation.fixed_seeds)
    s << "## fixed_seeds in the config: irace still draws a new seed per instance\n";
  return s.str();
}

const char* const kRunIrace =
    "#!/bin/sh\n"
    "# Runs irace on this scenario (more irace options may follow, e.g. --parallel 4), then writes\n"
    "# elites.csv (irace's final elites, best first) for `swarmpath irace import`. Written by `swarmpath "
    "irace`.\n"
    "set -e\n"
    "cd \"$(dirname \"$0\")\"\n"
    "Rscript --vanilla -e 'library(irace); irace.cmdline()' --scenario scenario.txt \"$@\"\n"
    "Rscript --vanilla export-elites.R .\n";

const char* const kExportElites =
    "# Writes elites.csv beside irace.Rdata: irace's final elite configurations, best first (rank 1 is\n"
    "# irace's best), each with its mean cost and the number of instance runs behind it. Written by\n"
    "# `swarmpath irace`; `swarmpath irace import` runs it when elites.csv is missing or older than "
    "irace.Rdata.\n"
    "args <- commandArgs(trailingOnly = TRUE)\n"
    "dir <- if (length(args) >= 1) args[[1]] else \".\"\n"
    "load(file.path(dir, \"irace.Rdata\"))\n"
    "if (!exists(\"iraceResults\")) stop(\"irace.Rdata holds no iraceResults\")\n"
    "elites <- as.character(iraceResults$allElites[[length(iraceResults$allElites)]])\n"
    "confs <- iraceResults$allConfigurations\n"
    "rows <- confs[match(elites, as.character(confs$.ID.)), , drop = FALSE]\n"
    "exps <- iraceResults$experiments[, elites, drop = FALSE]\n"
    "params <- iraceResults$parameters$names\n"
    "version <- if (is.null(iraceResults$irace.version)) \"unknown\" else iraceResults$irace.version\n"
    "out <- data.frame(rank = seq_along(elites), id = elites, rows[, params, drop = FALSE],\n"
    "                  mean_cost = colMeans(exps, na.rm = TRUE), runs = colSums(!is.na(exps)),\n"
    "                  experiments = iraceResults$state$experimentsUsedSoFar,\n"
    "                  irace_version = version, irace_seed = iraceResults$scenario$seed,\n"
    "                  check.names = FALSE)\n"
    "write.csv(out, file.path(dir, \"elites.csv\"), row.names = FALSE, quote = FALSE)\n";

}  // namespace

std::vector<std::string> irace_parameter_lines(const Genome& g) {
  std::vector<std::string> lines;
  for (const Gene& gene : g.genes) {
    const std::string name(gene.info->name);
    std::string type;
    std::string range;
    if (gene.info->type == sim::ParamType::kBool) {
      type = "c";
      range = "(false, true)";
    } else if (gene.info->type == sim::ParamType::kChoice) {
      type = "c";
      range = "(" + std::string(gene.info->choices[0]) + ", " + std::string(gene.info->choices[1]) + ")";
    } else {
      const bool integral = gene.integer || (gene.step > 0.0 && whole(gene.step) && whole(gene.lo));
      type = integral ? "i" : "r";
      if (gene.log) type += ",log";
      const double lo = integral ? std::ceil(gene.lo) : gene.lo;
      const double hi = integral ? std::floor(gene.hi) : gene.hi;
      range = "(" + num(lo) + ", " + num(hi) + ")";
    }
    std::string line = name;
    line.resize(std::max<std::size_t>(line.size() + 1, 20), ' ');
    std::string sw = "\"--" + name + "=\"";
    sw.resize(std::max<std::size_t>(sw.size() + 1, 22), ' ');
    line += sw + type;
    line.resize(std::max<std::size_t>(line.size() + 1, 48), ' ');
    line += range;
    if (gene.step > 0.0 && !gene.binary()) line += "  # rounded to lo + k * " + num(gene.step);
    lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> irace_instance_lines(const EvolveConfig& c) {
  std::vector<std::string> lines;
  for (const ScenarioRef& ref : c.evaluation.scenarios) {
    const std::string path = absolute(ref.path);
    if (path.find_first_of(" \t\n") != std::string::npos) {
      throw sim::ConfigError(c.file, 0, "evaluation.scenarios",
                             "\"" + path + "\" holds whitespace, which irace's instance lines cannot carry");
    }
    std::vector<int> robots = c.evaluation.robots;
    if (robots.empty()) robots.push_back(sim::load_scenario(ref.path).robots);
    for (const int n : robots) lines.push_back(path + " --robots " + std::to_string(n));
  }
  return lines;
}

IraceManifest write_irace_scenario(const EvolveConfig& c, const IraceScenarioOptions& o) {
  if (c.multi_objective()) {
    throw sim::ConfigError(
        c.file, 0, "optimizer.name",
        "irace minimises one cost: a multi-objective config (nsga2) cannot be written as an "
        "irace scenario; use a single-objective optimiser with [fitness] weights");
  }
  IraceManifest m;
  m.config = absolute(c.file);
  m.config_hash = config_hash(c);
  m.parallel = std::max(1, o.parallel);
  m.seed = o.seed.value_or(c.seed);
  if (o.max_experiments) {
    m.max_experiments = *o.max_experiments;
  } else {
    const std::optional<SimulationBudget> b = simulation_budget(c);
    if (!b) {
      throw sim::ConfigError(c.file, 0, "budget",
                             "a wall-time budget has no simulation count for irace's maxExperiments: give "
                             "[budget] generations or evaluations, or --max-experiments");
    }
    m.max_experiments = b->total;
  }
  if (m.max_experiments < 1) throw sim::ConfigError("--max-experiments", 0, "", "must be at least 1");
  m.instances = irace_instance_lines(c);

  const fs::path dir(o.out_dir);
  fs::create_directories(dir);
  std::ostringstream params;
  params << "## irace parameters: the [tune] table of " << m.config << "\n"
         << "## name              switch                type  range\n";
  for (const std::string& line : irace_parameter_lines(c.genome)) params << line << "\n";
  write_text(dir / "parameters.txt", params.str());
  std::ostringstream instances;
  instances << "## the training settings of " << m.config << ": scenario file and robot count\n";
  for (const std::string& line : m.instances) instances << line << "\n";
  write_text(dir / "instances.txt", instances.str());
  write_text(dir / "configurations.txt", configurations_txt(c.genome));
  write_text(dir / "target-runner", target_runner(c, o), true);
  write_text(dir / "scenario.txt", scenario_txt(c, m, irace_digits(c.genome)));
  write_text(dir / "run-irace", kRunIrace, true);
  write_text(dir / "export-elites.R", kExportElites);
  write_text(dir / "swarmpath-irace.json", manifest_json(m).dump(2) + "\n");
  return m;
}

nlohmann::ordered_json manifest_json(const IraceManifest& m) {
  nlohmann::ordered_json j;
  j["tool"] = "swarmpath irace";
  j["config"] = m.config;
  j["config_hash"] = m.config_hash;
  j["max_experiments"] = m.max_experiments;
  j["parallel"] = m.parallel;
  j["seed"] = m.seed;
  j["instances"] = m.instances;
  return j;
}

IraceManifest read_irace_manifest(const std::string& dir) {
  const std::string path = (fs::path(dir) / "swarmpath-irace.json").string();
  std::ifstream in(path);
  if (!in) {
    throw sim::ConfigError(
        path, 0, "", "not found: is " + dir + " a folder written by `swarmpath irace --config ... --out`?");
  }
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    IraceManifest m;
    m.config = j.at("config").get<std::string>();
    m.config_hash = j.at("config_hash").get<std::string>();
    m.max_experiments = j.at("max_experiments").get<std::int64_t>();
    m.parallel = j.at("parallel").get<int>();
    m.seed = j.at("seed").get<std::uint64_t>();
    m.instances = j.at("instances").get<std::vector<std::string>>();
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw sim::ConfigError(path, 0, "", std::string("malformed: ") + e.what());
  }
}

}  // namespace swarmpath::evolve
