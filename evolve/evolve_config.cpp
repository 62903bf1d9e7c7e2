// SPDX-License-Identifier: MIT
#include "evolve_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "evolve/optim/multi_objective.hpp"
#include "evolve/params_export.hpp"
#include "evolve/path_collision.hpp"
#include "sim/config_error.hpp"
#include "sim/hash.hpp"
#include "sim/scenario.hpp"
#include "sim/scenario_identity.hpp"
#include "sim/toml_reader.hpp"

namespace swarmpath::evolve {

namespace {

using sim::TableReader;

std::string fmt(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

std::uint64_t file_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  sim::Fnv1a h;
  h.add_bytes(s.data(), s.size());
  return h.value();
}

ScenarioRef scenario_ref(const TableReader& t, std::string_view key, const std::string& written,
                         const std::string& base_dir) {
  const std::optional<std::string> path = resolve_path(written, base_dir);
  if (!path) {
    t.fail(key, "scenario file \"" + written + "\" not found (looked in " +
                    (base_dir.empty() ? "." : base_dir) + " and the working directory)");
  }
  return {written, *path, file_hash(*path)};
}

// each file once (a file listed twice would count twice in every candidate's mean)
std::vector<ScenarioRef> scenario_list(const TableReader& t, std::string_view key,
                                       const std::string& base_dir) {
  std::vector<ScenarioRef> out;
  for (const std::string& w : t.strings(key)) {
    ScenarioRef ref = scenario_ref(t, key, w, base_dir);
    for (const ScenarioRef& o : out) {
      if (same_file(o.path, ref.path))
        t.fail(key, "\"" + o.written + "\" and \"" + w + "\" are one file, listed twice");
    }
    out.push_back(std::move(ref));
  }
  return out;
}

// two entries of one list that load to the same experiment, or to one name, are refused too
void check_distinct(const TableReader& t, std::string_view key, const std::vector<ScenarioRef>& refs,
                    const std::vector<sim::Scenario>& loaded) {
  for (std::size_t i = 0; i < loaded.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      const std::string both = "\"" + refs[k].written + "\" and \"" + refs[i].written + "\"";
      if (sim::experiment_fingerprint(loaded[k]) == sim::experiment_fingerprint(loaded[i])) {
        t.fail(key,
               both + " are the same scenario (the same arena, robots and settings): it would count twice");
      }
      if (loaded[k].name == loaded[i].name) {
        t.fail(key, both + " are two scenarios named \"" + loaded[i].name + "\"; give one another name");
      }
    }
  }
}

int int_in(const TableReader& t, std::string_view key, std::int64_t fallback, std::int64_t lo,
           std::int64_t hi) {
  const std::int64_t v = t.integer_or(key, fallback);
  if (v < lo || v > hi) {
    t.fail(key, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " +
                    std::to_string(v) + ")");
  }
  return static_cast<int>(v);
}

double number_in(const TableReader& t, std::string_view key, double fallback, double lo, double hi) {
  const double v = t.number_or(key, fallback);
  if (v < lo || v > hi) t.fail(key, "must lie in [" + fmt(lo) + ", " + fmt(hi) + "] (got " + fmt(v) + ")");
  return v;
}

Gene read_gene(const TableReader& tune, const std::string& key) {
  const sim::ParamInfo* info = sim::find_param(key);
  if (info == nullptr) {
    tune.fail(key, "unknown parameter (the names are those of SPEC §7, as in genomes/default.toml)");
  }
  Gene g = default_gene(*info);
  const std::optional<TableReader> t = tune.table(key);
  if (g.binary()) {
    if (!t->keys().empty()) {
      t->fail(t->keys().front(), "a bool or choice parameter takes no settings (write " + key + " = {})");
    }
    return g;
  }
  const std::string range = "[" + fmt(info->lo) + ", " + fmt(info->hi) + "]";
  g.lo = t->number_or("lo", info->lo);
  g.hi = t->number_or("hi", info->hi);
  if (g.lo < info->lo || g.lo > info->hi) {
    t->fail("lo",
            "lies outside " + key + "'s range " + range + " (SPEC §7 row " + std::to_string(info->row) + ")");
  }
  if (g.hi < info->lo || g.hi > info->hi) {
    t->fail("hi",
            "lies outside " + key + "'s range " + range + " (SPEC §7 row " + std::to_string(info->row) + ")");
  }
  if (g.lo >= g.hi)
    t->fail(t->has("lo") ? "lo" : "hi", "lo (" + fmt(g.lo) + ") must be < hi (" + fmt(g.hi) + ")");
  g.log = t->boolean_or("log", false);
  if (g.log && g.lo <= 0.0) t->fail("log", "a log scale needs lo > 0 (lo = " + fmt(g.lo) + ")");
  const bool integer_type = info->type == sim::ParamType::kInteger;
  const bool integer = t->boolean_or("integer", integer_type);
  if (integer_type && !integer) t->fail("integer", key + " is an integer parameter");
  g.integer = integer;
  g.step = t->number_or("step", 0.0);
  if (g.step < 0.0 || g.step > g.hi - g.lo) {
    t->fail("step", "must lie in [0, hi - lo] = [0, " + fmt(g.hi - g.lo) + "] (0: continuous)");
  }
  if (g.integer) {
    if (g.step != std::floor(g.step)) t->fail("step", "an integer parameter needs a whole step");
    if (std::ceil(g.lo) > std::floor(g.hi)) t->fail("hi", "no whole number lies in [lo, hi]");
  }
  t->finish();
  return g;
}

void read_tune(EvolveConfig& c, const TableReader& root) {
  const TableReader tune = root.required_table("tune");
  for (const std::string& key : tune.keys()) c.genome.genes.push_back(read_gene(tune, key));
  tune.finish();
  if (c.genome.genes.empty()) root.fail("tune", "name at least one parameter to tune, e.g. v_max = {}");
  // genes in SPEC §7 row order (the descriptor table's order), whatever order the file uses
  const auto table = sim::param_table();
  const auto rank = [&](const Gene& g) { return g.info - table.data(); };
  std::sort(c.genome.genes.begin(), c.genome.genes.end(),
            [&](const Gene& a, const Gene& b) { return rank(a) < rank(b); });
  // the base value of every tuned parameter must lie in its bounds (it is the start point)
  for (const Gene& g : c.genome.genes) {
    const double v = sim::get_value(c.genome.base, *g.info);
    if (!g.binary() && (v < g.lo || v > g.hi)) {
      const TableReader t = *tune.table(g.info->name);
      t.fail(t.has("lo") && v < g.lo ? "lo" : (t.has("hi") ? "hi" : "lo"),
             "the base value " + fmt(v) + " of " + std::string(g.info->name) + " lies outside [" + fmt(g.lo) +
                 ", " + fmt(g.hi) + "]: the run starts from the base params");
    }
  }
}

// the robot counts of `key`: whole numbers in [1, kMaxRobots], at least one
std::vector<int> robot_counts(const TableReader& t, std::string_view key) {
  std::vector<int> out;
  for (const double n : t.numbers(key)) {
    if (n != std::floor(n) || n < 1 || n > sim::kMaxRobots) {
      t.fail(key, "robot counts must be whole numbers in [1, " + std::to_string(sim::kMaxRobots) + "]");
    }
    if (std::find(out.begin(), out.end(), static_cast<int>(n)) != out.end()) {
      t.fail(key, fmt(n) + " robots listed twice");  // each count would weigh twice in every mean
    }
    out.push_back(static_cast<int>(n));
  }
  if (out.empty()) t.fail(key, "the evaluation set is empty: give at least one robot count");
  return out;
}

// a scenario file drawn from a benchmark's seed is for measuring, never for tuning
void refuse_benchmark_arena(const TableReader& t, std::string_view key, const ScenarioRef& ref,
                            const sim::Scenario& s) {
  if (s.origin && sim::arenas::is_benchmark_seed(s.origin->seed)) {
    t.fail(key, ref.written + " was drawn from seed " + std::to_string(s.origin->seed) + " of family " +
                    s.origin->family + ", a benchmark's seed (" +
                    std::to_string(sim::arenas::kBenchmarkSeedLo) + " - " +
                    std::to_string(sim::arenas::kBenchmarkSeedHi - 1) +
                    "): a benchmark is for measuring, never for tuning (docs/generalisation.md)");
  }
}

// [[evaluation.family]]: family, params, arenas, robots, seeds
FamilyEntry read_family(const TableReader& t, const EvaluationSet& e) {
  FamilyEntry f;
  f.spec = sim::arenas::read_spec(t, "family", "params");
  if (const std::optional<TableReader> params = t.table("params"); params && params->has("robots")) {
    params->fail("robots",
                 "give the robot counts as the entry's robots = [...] (the arena is drawn for the largest)");
  }
  f.arenas = int_in(t, "arenas", 1, 1, 10000);
  if (t.has("robots")) {
    f.robots = robot_counts(t, "robots");
  } else {
    t.allow("robots");
    f.robots =
        e.robots.empty() ? std::vector<int>{static_cast<int>(f.spec.param_values()("robots"))} : e.robots;
  }
  const int most = *std::max_element(f.robots.begin(), f.robots.end());
  const std::vector<sim::arenas::FamilyParam> params = sim::arenas::all_params(*f.spec.family);
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (params[i].name != "robots") continue;
    if (most > params[i].hi) {
      t.fail(t.has("robots") ? "robots" : "family", "a drawn arena holds at most " + fmt(params[i].hi) +
                                                        " robots (got " + std::to_string(most) + ")");
    }
    f.spec.values[i] = most;
  }
  f.seeds = int_in(t, "seeds", e.seeds, 1, 100000);
  t.finish();
  return f;
}

void read_evaluation(EvolveConfig& c, const TableReader& root, const std::string& base_dir) {
  const TableReader t = root.required_table("evaluation");
  EvaluationSet& e = c.evaluation;
  if (t.has("scenarios")) {
    e.scenarios = scenario_list(t, "scenarios", base_dir);
  } else {
    t.allow("scenarios");
  }
  if (t.has("robots")) {
    e.robots = robot_counts(t, "robots");
  } else {
    t.allow("robots");
  }
  e.seeds = int_in(t, "seeds", 2, 1, 100000);
  if (t.has("max_ticks")) {
    const std::int64_t m = t.integer("max_ticks");
    if (m < 1 || m > sim::kMaxTicks)
      t.fail("max_ticks", "must lie in [1, " + std::to_string(sim::kMaxTicks) + "]");
    e.max_ticks = m;
  } else {
    t.allow("max_ticks");
  }
  e.fixed_seeds = t.boolean_or("fixed_seeds", false);
  e.capping = t.boolean_or("capping", false);
  e.capping_fraction = number_in(t, "capping_fraction", e.capping_fraction, 0.01, 0.99);
  for (const TableReader& f : t.table_array("family")) e.families.push_back(read_family(f, e));
  t.finish();
  if (e.scenarios.empty() && e.families.empty()) {
    t.fail(
        "scenarios",
        "the evaluation set is empty: name at least one scenario file or an [[evaluation.family]] of arenas");
  }
  // every scenario must load and take every robot count
  std::vector<sim::Scenario> loaded;
  for (const ScenarioRef& ref : e.scenarios) {
    loaded.push_back(sim::load_scenario(ref.path));
    refuse_benchmark_arena(t, "scenarios", ref, loaded.back());
    for (const int n : e.robots) {
      if (const std::string err = sim::check_robot_count(loaded.back(), n); !err.empty()) {
        t.fail("robots", ref.written + ": " + err);
      }
    }
  }
  check_distinct(t, "scenarios", e.scenarios, loaded);
}

void read_fitness(EvolveConfig& c, const TableReader& root) {
  const std::optional<TableReader> t = root.table("fitness");
  if (!t) return;
  FitnessWeights& w = c.fitness;
  w.w_fail = number_in(*t, "w_fail", w.w_fail, 0.0, 1e6);
  w.w_time = number_in(*t, "w_time", w.w_time, 0.0, 1e6);
  w.w_path = number_in(*t, "w_path", w.w_path, 0.0, 1e6);
  w.w_robots = number_in(*t, "w_robots", w.w_robots, 0.0, 1e6);
  w.fail_path_ratio = number_in(*t, "fail_path_ratio", w.fail_path_ratio, 1.0, 1e6);
  t->finish();
  if (w.w_fail + w.w_time + w.w_path + w.w_robots <= 0.0)
    t->fail("w_fail", "at least one weight must be > 0");
}

// [objectives]: required by a multi-objective optimiser, refused by the others; the [fitness]
// weights mean nothing to a multi-objective run and are refused there (fail_path_ratio stays)
void read_objectives(EvolveConfig& c, const TableReader& root, bool is_multi) {
  const std::optional<TableReader> t = root.table("objectives");
  if (!is_multi) {
    if (t) {
      t->fail("use", "[objectives] is for a multi-objective optimiser (name = \"nsga2\"); \"" +
                         c.optimizer.name + "\" minimises the weighted sum of [fitness]");
    }
    return;
  }
  if (!t) {
    root.fail("optimizer",
              "\"" + c.optimizer.name +
                  "\" needs an [objectives] table, e.g. use = [\"path\", \"ticks\", \"robots\"], "
                  "min_success = 0.8, reference = [2.0, 40000, 1.0]");
  }
  if (const std::optional<TableReader> f = root.table("fitness")) {
    for (const char* key : {"w_fail", "w_time", "w_path", "w_robots"}) {
      if (f->has(key)) {
        f->fail(key, "\"" + c.optimizer.name +
                         "\" minimises the [objectives], not a weighted sum: remove the weights (only "
                         "fail_path_ratio applies)");
      }
    }
  }
  MultiObjectiveSettings& m = c.multi;
  for (const std::string& name : t->strings("use")) {
    const std::optional<ObjectiveKind> k = parse_objective(name);
    if (!k) t->fail("use", "unknown objective \"" + name + "\" (choices: path, ticks, robots)");
    if (std::find(m.objectives.begin(), m.objectives.end(), *k) != m.objectives.end()) {
      t->fail("use", "objective \"" + name + "\" named twice");
    }
    m.objectives.push_back(*k);
  }
  if (m.objectives.size() < 2) {
    t->fail("use", "name 2 or 3 of path, ticks, robots (one objective: use a single-objective optimiser)");
  }
  m.min_success = number_in(*t, "min_success", 0.0, 0.0, 1.0);
  m.reference = t->numbers("reference");
  if (m.reference.size() != m.objectives.size()) {
    t->fail("reference", "needs one value per objective of use (" + std::to_string(m.objectives.size()) +
                             "), got " + std::to_string(m.reference.size()));
  }
  for (const double r : m.reference) {
    if (!std::isfinite(r) || r <= 0.0) t->fail("reference", "values must be finite and > 0, got " + fmt(r));
  }
  t->finish();
}

void read_optimizer(EvolveConfig& c, const TableReader& root) {
  OptimizerSettings& o = c.optimizer;
  const std::optional<TableReader> t = root.table("optimizer");
  if (t) {
    o.name = t->string_or("name", o.name);
    o.population = int_in(*t, "population", o.population, 0, 100000);
    o.sigma0 = number_in(*t, "sigma0", o.sigma0, 1e-6, 1.0);
    o.ipop_restarts = int_in(*t, "ipop_restarts", o.ipop_restarts, 0, 20);
    o.crossover_rate = number_in(*t, "crossover_rate", o.crossover_rate, 0.0, 1.0);
    o.mutation_sigma = number_in(*t, "mutation_sigma", o.mutation_sigma, 0.0, 10.0);
    o.mutation_rate = number_in(*t, "mutation_rate", o.mutation_rate, 0.0, 1.0);
    o.tournament = int_in(*t, "tournament", o.tournament, 1, 100000);
    o.elites = int_in(*t, "elites", o.elites, 0, 100000);
    o.max_evaluations = int_in(*t, "max_evaluations", o.max_evaluations, 0, 100000000);
    o.xtol_rel = number_in(*t, "xtol_rel", o.xtol_rel, 0.0, 1.0);
    t->finish();
  }
  std::vector<std::string> names = optimizer_names();
  const std::vector<std::string> multi = multi_objective_names();
  names.insert(names.end(), multi.begin(), multi.end());
  const auto fail = [&](std::string_view key, const std::string& message) {
    if (t) t->fail(key, message);
    root.fail("optimizer", message);
  };
  if (std::find(names.begin(), names.end(), o.name) == names.end()) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    fail("name", "unknown optimiser \"" + o.name + "\" (choices: " + list + ")");
  }
  const bool is_multi = std::find(multi.begin(), multi.end(), o.name) != multi.end();
  read_objectives(c, root, is_multi);
  // capping keeps the ranks CMA-ES selects by and random search's best, not every comparison
  if (c.evaluation.capping && o.name != "cmaes" && o.name != "random") {
    root.required_table("evaluation")
        .fail("capping", "adaptive capping needs optimizer cmaes or random (got \"" + o.name +
                             "\", whose steps may compare censored fitness values): remove capping");
  }
  // the optimiser checks its own settings: build it once on this genome
  try {
    const Vector x0 = encode(c.genome, c.genome.base);
    if (is_multi) {
      (void)make_multi_objective(o, c.genome.bounds(), x0, c.multi.objectives.size(), 0);
    } else {
      (void)make_optimizer(o, c.genome.bounds(), x0, 0);
    }
  } catch (const SettingError& e) {
    fail(e.key(), e.what());  // the setting's own key
  } catch (const std::invalid_argument& e) {
    fail("name", e.what());
  }
}

void read_budget(EvolveConfig& c, const TableReader& root) {
  const TableReader t = root.required_table("budget");
  Budget& b = c.budget;
  b.generations = int_in(t, "generations", 0, 0, 10000000);
  const std::int64_t evaluations = t.integer_or("evaluations", 0);
  if (evaluations < 0) t.fail("evaluations", "must be >= 0 (0: no limit)");
  b.evaluations = evaluations;
  b.wall_seconds = number_in(t, "wall_seconds", 0.0, 0.0, 1e9);
  t.finish();
  if (b.generations == 0 && b.evaluations == 0 && b.wall_seconds == 0.0) {
    t.fail("generations", "set at least one of generations, evaluations, wall_seconds");
  }
}

void read_reevaluate(EvolveConfig& c, const TableReader& root, const std::string& base_dir) {
  Reevaluation& r = c.reevaluate;
  r.every_generation = !c.evaluation.families.empty();  // the default: log generalisation when arenas vary
  r.keep_base = !c.multi_objective();                   // the default: the pick is no worse than the start
  const std::optional<TableReader> t = root.table("reevaluate");
  if (!t) return;
  if (c.multi_objective() && t->has("top_k")) {
    t->fail("top_k", "a multi-objective run re-evaluates every point of its final front: remove top_k");
  }
  r.top_k = int_in(*t, "top_k", r.top_k, 1, 1000);
  r.seeds = int_in(*t, "seeds", r.seeds, 1, 100000);
  r.arenas = int_in(*t, "arenas", r.arenas, 1, 10000);
  r.every_generation = t->boolean_or("every_generation", r.every_generation);
  r.race = t->boolean_or("race", r.race);
  if (r.race && c.multi_objective()) {
    t->fail("race", "racing applies to the finalists of a single-objective run: remove race");
  }
  r.race_level = number_in(*t, "race_level", r.race_level, 1e-6, 0.5);
  r.race_first_test = int_in(*t, "race_first_test", r.race_first_test, 2, 100000);
  r.race_base = t->boolean_or("race_base", r.race_base);
  if (r.race_base && c.multi_objective()) {
    t->fail("race_base", "racing applies to the finalists of a single-objective run: remove race_base");
  }
  if (r.race_base && r.race) {
    t->fail("race_base",
            "race the finalists against each other (race) or against the base params "
            "(race_base), not both");
  }
  if (r.race_base && !c.evaluation.families.empty()) {
    t->fail("race_base",
            "racing against the base params draws more fresh seeds of scenario files; "
            "arena families' validation arenas are fixed: remove race_base");
  }
  if (!r.race_base && t->has("race_base_level")) {
    t->fail("race_base_level", "applies only with race_base = true: remove it or set race_base = true");
  }
  r.race_base_level = number_in(*t, "race_base_level", r.race_base_level, 1e-6, 0.5);
  r.keep_base = t->boolean_or("keep_base", r.keep_base);
  if (r.keep_base && c.multi_objective()) {
    t->fail("keep_base",
            "a multi-objective run reports its whole front, the base params beside it: remove keep_base");
  }
  if (!r.keep_base && t->has("keep_base_level")) {
    t->fail("keep_base_level", "applies only with keep_base = true: remove it or set keep_base = true");
  }
  r.keep_base_level = number_in(*t, "keep_base_level", r.keep_base_level, 1e-6, 0.5);
  if (!r.keep_base && t->has("keep_base_test")) {
    t->fail("keep_base_test", "applies only with keep_base = true: remove it or set keep_base = true");
  }
  const std::string test =
      t->string_or("keep_base_test", std::string(keep_base_test_name(KeepBaseTest::kPairedT)));
  const std::optional<KeepBaseTest> parsed = parse_keep_base_test(test);
  if (!parsed) {
    t->fail("keep_base_test", "unknown test \"" + test +
                                  "\" (choices: " + std::string(keep_base_test_name(KeepBaseTest::kPairedT)) +
                                  ", " + std::string(keep_base_test_name(KeepBaseTest::kSignedRank)) + ")");
  }
  r.keep_base_test = *parsed;
  r.mean_finalist = t->boolean_or("mean_finalist", r.mean_finalist);
  if (r.mean_finalist && c.optimizer.name != "cmaes") {
    t->fail("mean_finalist", "the distribution mean is CMA-ES's (optimizer name = \"cmaes\"), not " +
                                 c.optimizer.name + "'s: remove mean_finalist");
  }
  if (r.race_base && !r.keep_base) {
    t->fail("race_base",
            "racing against the base params leaves them the pick when every finalist is "
            "dropped: it needs keep_base = true");
  }
  if (t->has("held_out")) {
    r.held_out = scenario_list(*t, "held_out", base_dir);
  } else {
    t->allow("held_out");
  }
  t->finish();
  std::vector<sim::Scenario> loaded;
  for (const ScenarioRef& ref : r.held_out) {
    loaded.push_back(sim::load_scenario(ref.path));
    refuse_benchmark_arena(*t, "held_out", ref, loaded.back());
    for (const int n : c.evaluation.robots) {
      if (const std::string err = sim::check_robot_count(loaded.back(), n); !err.empty()) {
        t->fail("held_out", ref.written + ": " + err);
      }
    }
    // held out means no candidate was trained on it
    for (const ScenarioRef& trained : c.evaluation.scenarios) {
      if (same_file(trained.path, ref.path) ||
          sim::arena_fingerprint(sim::load_scenario(trained.path)) == sim::arena_fingerprint(loaded.back())) {
        t->fail("held_out", "\"" + ref.written + "\" is also in evaluation.scenarios (\"" + trained.written +
                                "\"): a held-out scenario is one no candidate was trained on");
      }
    }
  }
  check_distinct(*t, "held_out", r.held_out, loaded);
}

EvolveConfig parse(const sim::TomlDoc& doc, const std::string& base_dir) {
  EvolveConfig c;
  c.file = doc.name();
  const TableReader root(doc, doc.root(), "");
  c.name = root.string_or("name", std::filesystem::path(doc.name()).stem().string());
  // the default output folder is results/evolve/<name>: "." and ".." would leave it
  if (c.name.empty() || c.name == "." || c.name == ".." ||
      !std::all_of(c.name.begin(), c.name.end(), [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.';
      })) {
    root.fail("name",
              "must be a file name of letters, digits, '_', '-' and '.', not \".\" or \"..\" (it names the "
              "output folder)");
  }
  if (root.has("params")) {
    c.params_written = root.string("params");
    const std::optional<std::string> path = resolve_path(c.params_written, base_dir);
    if (!path) root.fail("params", "params file \"" + c.params_written + "\" not found");
    c.params_file = *path;
    c.genome.base = sim::load_params(c.params_file);
  } else {
    root.allow("params");
  }
  const std::string mode = root.string_or("mode", "pf");
  const std::optional<sim::Mode> m = sim::parse_mode(mode);
  if (!m || *m == sim::Mode::kDiffusion) root.fail("mode", "must be \"pf\" or \"ta\", got \"" + mode + "\"");
  c.mode = *m;
  const std::int64_t seed = root.integer_or("seed", 1);
  if (seed < 0) root.fail("seed", "must be >= 0");
  c.seed = static_cast<std::uint64_t>(seed);
  read_tune(c, root);
  read_evaluation(c, root, base_dir);
  read_fitness(c, root);
  read_optimizer(c, root);
  read_budget(c, root);
  read_reevaluate(c, root, base_dir);
  root.finish();
  return c;
}

nlohmann::ordered_json refs_json(const std::vector<ScenarioRef>& refs) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const ScenarioRef& r : refs) j.push_back(r.written);
  return j;
}

nlohmann::ordered_json ref_hashes_json(const std::vector<ScenarioRef>& refs) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const ScenarioRef& r : refs) j.push_back(sim::to_hex(r.content_hash));
  return j;
}

}  // namespace

std::optional<std::string> resolve_path(const std::string& path, const std::string& base_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(path);
  if (p.is_absolute()) return fs::is_regular_file(p, ec) ? std::optional<std::string>(path) : std::nullopt;
  if (!base_dir.empty()) {
    const fs::path q = (fs::path(base_dir) / p).lexically_normal();
    if (fs::is_regular_file(q, ec)) return q.string();
  }
  if (fs::is_regular_file(p, ec)) return path;
  return std::nullopt;
}

EvolveConfig load_evolve_config(const std::string& path) {
  const sim::TomlDoc doc = sim::TomlDoc::parse_file(path);
  return parse(doc, std::filesystem::path(path).parent_path().string());
}

EvolveConfig parse_evolve_config(std::string_view text, const std::string& name,
                                 const std::string& base_dir) {
  const sim::TomlDoc doc = sim::TomlDoc::parse_string(text, name);
  return parse(doc, base_dir);
}

nlohmann::ordered_json config_json(const EvolveConfig& c) {
  nlohmann::ordered_json j;
  j["name"] = c.name;
  j["file"] = c.file;
  j["params"] =
      c.params_written.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.params_written);
  j["mode"] = std::string(sim::to_string(c.mode));
  j["seed"] = c.seed;
  nlohmann::ordered_json tune = nlohmann::ordered_json::array();
  for (const Gene& g : c.genome.genes) {
    nlohmann::ordered_json t;
    t["name"] = std::string(g.info->name);
    if (g.binary()) {
      t["binary"] = true;
    } else {
      t["lo"] = g.lo;
      t["hi"] = g.hi;
      t["step"] = g.step;
      t["integer"] = g.integer;
      t["log"] = g.log;
    }
    tune.push_back(t);
  }
  j["tune"] = tune;
  const EvaluationSet& e = c.evaluation;
  j["evaluation"] = {
      {"scenarios", refs_json(e.scenarios)},
      {"scenario_hashes", ref_hashes_json(e.scenarios)},
      {"robots", e.robots},
      {"seeds", e.seeds},
      {"max_ticks", e.max_ticks ? nlohmann::ordered_json(*e.max_ticks) : nlohmann::ordered_json(nullptr)},
      {"fixed_seeds", e.fixed_seeds}};
  if (e.capping) {  // only when on: configs without it keep their hash
    j["evaluation"]["capping"] = true;
    j["evaluation"]["capping_fraction"] = e.capping_fraction;
  }
  if (!e.families.empty()) {
    // only runs with families carry these keys, so the hash of every other config stays as it was
    nlohmann::ordered_json families = nlohmann::ordered_json::array();
    for (const FamilyEntry& f : e.families) {
      nlohmann::ordered_json params;
      for (const auto& [k, v] : f.spec.sorted_params()) params[k] = v;
      families.push_back({{"family", std::string(f.spec.family->name)},
                          {"params", params},
                          {"arenas", f.arenas},
                          {"robots", f.robots},
                          {"seeds", f.seeds}});
    }
    j["evaluation"]["families"] = families;
    j["evaluation"]["arena_generator_version"] = sim::arenas::kGeneratorVersion;
  }
  const FitnessWeights& w = c.fitness;
  j["fitness"] = {{"w_fail", w.w_fail},
                  {"w_time", w.w_time},
                  {"w_path", w.w_path},
                  {"w_robots", w.w_robots},
                  {"fail_path_ratio", w.fail_path_ratio}};
  const OptimizerSettings& o = c.optimizer;
  j["optimizer"] = {{"name", o.name},
                    {"population", o.population},
                    {"sigma0", o.sigma0},
                    {"ipop_restarts", o.ipop_restarts},
                    {"crossover_rate", o.crossover_rate},
                    {"mutation_sigma", o.mutation_sigma},
                    {"mutation_rate", o.mutation_rate},
                    {"tournament", o.tournament},
                    {"elites", o.elites},
                    {"max_evaluations", o.max_evaluations},
                    {"xtol_rel", o.xtol_rel}};
  j["budget"] = {{"generations", c.budget.generations},
                 {"evaluations", c.budget.evaluations},
                 {"wall_seconds", c.budget.wall_seconds}};
  j["reevaluate"] = {{"top_k", c.reevaluate.top_k},
                     {"seeds", c.reevaluate.seeds},
                     {"held_out", refs_json(c.reevaluate.held_out)},
                     {"held_out_hashes", ref_hashes_json(c.reevaluate.held_out)}};
  if (!e.families.empty() || c.reevaluate.every_generation) {
    j["reevaluate"]["arenas"] = c.reevaluate.arenas;
    j["reevaluate"]["every_generation"] = c.reevaluate.every_generation;
  }
  if (c.reevaluate.race) {  // only when on: configs without it keep their hash
    j["reevaluate"]["race"] = true;
    j["reevaluate"]["race_level"] = c.reevaluate.race_level;
    j["reevaluate"]["race_first_test"] = c.reevaluate.race_first_test;
  }
  if (c.reevaluate.race_base) {  // only when on: configs without it keep their hash
    j["reevaluate"]["race_base"] = true;
    j["reevaluate"]["race_base_level"] = c.reevaluate.race_base_level;
    j["reevaluate"]["race_first_test"] = c.reevaluate.race_first_test;
  }
  if (c.reevaluate.mean_finalist) j["reevaluate"]["mean_finalist"] = true;  // only when on: hash kept
  // keeping the base params is the default of single-objective runs: their hash names it only when
  // it is off or at another level, so configs that leave it alone keep their hash
  if (!c.multi_objective() && !c.reevaluate.keep_base) j["reevaluate"]["keep_base"] = false;
  if (c.reevaluate.keep_base && c.reevaluate.keep_base_level != Reevaluation{}.keep_base_level)
    j["reevaluate"]["keep_base_level"] = c.reevaluate.keep_base_level;
  if (c.reevaluate.keep_base && c.reevaluate.keep_base_test == KeepBaseTest::kSignedRank)
    j["reevaluate"]["keep_base_test"] =
        keep_base_test_name(c.reevaluate.keep_base_test);  // not the t-test: hash kept
  if (c.multi_objective()) {
    nlohmann::ordered_json use = nlohmann::ordered_json::array();
    for (const ObjectiveKind k : c.multi.objectives) use.push_back(std::string(objective_name(k)));
    j["objectives"] = {{"use", use}, {"min_success", c.multi.min_success}, {"reference", c.multi.reference}};
  }
  j["base_params"] = params_values_json(c.genome.base);
  return j;
}

std::string config_hash(const EvolveConfig& c) {
  nlohmann::ordered_json j = config_json(c);
  j.erase("budget");
  j.erase("file");  // the same config under another name or folder resumes
  const std::string text = j.dump();
  sim::Fnv1a h;
  h.add_bytes(text.data(), text.size());
  return sim::to_hex(h.value());
}

}  // namespace swarmpath::evolve
