// SPDX-License-Identifier: MIT
// swarmpath ablate: the default controller with each addition beyond SPEC switched off in turn, and
// the paper-literal controller with each switched on in turn, on the same cases; paired differences
// with 95 % intervals as markdown, JSON and an SVG forest plot (app/ablation.hpp).
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "ablation.hpp"
#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/path_collision.hpp"
#include "experiment.hpp"
#include "sim/additions.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "sim/hash.hpp"

namespace swarmpath::app {

namespace {

struct AblateOptions {
  std::string params = "genomes/default.toml";
  std::string literal = "genomes/paper-literal.toml";
  std::vector<std::string> options{"all"};
  std::vector<std::string> arms{"default", "literal"};
  std::vector<std::string> scenarios{"configs/scenarios/paper"};
  std::vector<int> robots{60, 100};
  int seeds = 2;
  std::uint64_t seed_base = 1;
  std::vector<std::string> modes{"pf", "ta"};
  std::optional<std::int64_t> ticks;
  std::optional<int> threads;
  std::string cache;
  std::string json;
  std::string markdown;
  std::string svg;
  bool list = false;
};

// one controller the ablation runs: an arm's base params, or one of its variants
struct Config {
  Arm arm = Arm::kDefault;
  const sim::Addition* addition = nullptr;  // nullptr: the arm's base
  sim::Params params;
  std::vector<sim::Mode> modes;
  std::string key;                   // what identifies its runs in the cache
  std::vector<RunOutcome> outcomes;  // in make_grid order over `modes`
};

void list_additions(std::ostream& out) {
  out << "The additions beyond SPEC (name: what it does; SPEC rule; runs it acts in; off; needs):\n";
  for (const sim::Addition& a : sim::additions()) {
    out << "  " << a.name << ": " << a.title << "; " << a.rule << "; "
        << (a.scope == sim::AdditionScope::kBoth ? "pf and ta" : "ta only")
        << (sim::in_default(a) ? "" : "; off in the default (under trial)") << "; off:";
    for (const sim::Setting& s : a.off) {
      if (!s.key.empty()) out << " " << s.key << " = " << s.value;
    }
    bool first = true;
    for (const std::string_view n : a.needs) {
      if (n.empty()) continue;
      out << (first ? "; needs " : ", ") << n;
      first = false;
    }
    out << "\n";
  }
}

std::vector<const sim::Addition*> chosen_additions(const std::vector<std::string>& names) {
  std::vector<const sim::Addition*> out;
  const bool all = names.size() == 1 && names[0] == "all";
  for (const sim::Addition& a : sim::additions()) {
    if (all || std::find(names.begin(), names.end(), a.name) != names.end()) out.push_back(&a);
  }
  if (!all) {
    for (const std::string& n : names) {
      if (sim::find_addition(n) == nullptr)
        throw sim::ConfigError("--options", 0, n, "is no addition (swarmpath ablate --list names them)");
    }
  }
  return out;
}

std::string file_text(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// the cache key of a config's runs: its params, its modes and the grid (scenario contents included)
std::string config_key(const sim::Params& p, const std::vector<sim::Mode>& modes,
                       const std::string& grid_text) {
  std::ostringstream t;
  sim::write_params_toml(t, p);
  for (const sim::Mode m : modes) t << "mode " << sim::to_string(m) << "\n";
  t << grid_text;
  const std::string text = t.str();
  sim::Fnv1a h;
  h.add_bytes(text.data(), text.size());
  return sim::to_hex(h.value());
}

nlohmann::ordered_json outcomes_json(const std::vector<RunOutcome>& runs) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const RunOutcome& r : runs) {
    list.push_back({r.success, std::isfinite(r.ticks) ? r.ticks : -1.0,
                    std::isfinite(r.path_ratio) ? r.path_ratio : -1.0,
                    std::isfinite(r.rr_pct) ? r.rr_pct : -1.0, sim::to_hex(r.state_hash)});
  }
  return list;
}

// a cached variant's runs, when they were made beside base runs with fingerprint `base`
std::optional<std::vector<RunOutcome>> read_cached(const std::filesystem::path& file, std::size_t runs,
                                                   const std::string& base) {
  std::ifstream f(file);
  if (!f) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(f);
    if (j.at("base").get<std::string>() != base) return std::nullopt;
    std::vector<RunOutcome> out;
    for (const nlohmann::json& r : j.at("runs")) {
      RunOutcome o;
      o.success = r.at(0).get<bool>();
      const auto value = [](double v) { return v < 0.0 ? std::numeric_limits<double>::quiet_NaN() : v; };
      o.ticks = value(r.at(1).get<double>());
      o.path_ratio = value(r.at(2).get<double>());
      o.rr_pct = value(r.at(3).get<double>());
      o.state_hash = std::stoull(r.at(4).get<std::string>(), nullptr, 16);
      out.push_back(o);
    }
    if (out.size() != runs) return std::nullopt;
    return out;
  } catch (const std::exception&) {
    return std::nullopt;  // a damaged cache entry is run again
  }
}

// what identifies an arm's base runs: the hash of their state hashes
std::string fingerprint(const std::vector<RunOutcome>& runs) {
  sim::Fnv1a h;
  for (const RunOutcome& r : runs) h.add(r.state_hash);
  return sim::to_hex(h.value());
}

RunOutcome outcome_of(const sim::Metrics& m, double astar8_tu) {
  RunOutcome o;
  o.success = m.success;
  if (m.success) {
    o.ticks = static_cast<double>(m.ticks_to_form);
    o.path_ratio = m.path_length_tu / astar8_tu;
  }
  if (std::isfinite(m.resource_reduction_pct)) o.rr_pct = m.resource_reduction_pct;
  o.state_hash = m.state_hash;
  return o;
}

// the outcomes of one mode, in grid order
std::vector<RunOutcome> of_mode(const Config& c, const std::vector<GridCase>& grid, sim::Mode mode) {
  std::vector<RunOutcome> out;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid[i].mode == mode) out.push_back(c.outcomes[i]);
  }
  return out;
}

int run_ablate(const AblateOptions& o, const evolve::EvaluatorFactory& evaluators, std::ostream& out,
               std::ostream& err) {
  if (o.list) {
    list_additions(out);
    return kExitOk;
  }
  if (o.seeds < 1 || o.seeds > 100000) throw sim::ConfigError("--seeds", 0, "", "must lie in [1, 100000]");
  if (o.robots.empty()) throw sim::ConfigError("--robots", 0, "", "give at least one robot count");
  std::vector<sim::Mode> modes;
  for (const std::string& m : o.modes) {
    if (m != "both" && mode_from_option(m) == sim::Mode::kDiffusion)
      throw sim::ConfigError("--modes", 0, m, "must be pf, ta or both");
    for (const sim::Mode mode : path_modes(m)) {
      if (std::find(modes.begin(), modes.end(), mode) == modes.end()) modes.push_back(mode);
    }
  }
  std::sort(modes.begin(), modes.end());
  std::vector<Arm> arms;
  for (const std::string& a : o.arms) {
    if (a == "default")
      arms.push_back(Arm::kDefault);
    else if (a == "literal")
      arms.push_back(Arm::kLiteral);
    else
      throw sim::ConfigError("--arms", 0, a, "must be default or literal");
  }
  const std::vector<const sim::Addition*> chosen = chosen_additions(o.options);
  const std::vector<std::string> files = scenario_files(o.scenarios);
  std::vector<evolve::NamedPath> inputs = {{"--params", o.params}, {"--literal", o.literal}};
  for (const std::string& f : files) inputs.push_back({"--scenarios", f});
  evolve::check_output_paths(inputs, {{"--json", o.json}, {"--md", o.markdown}, {"--svg", o.svg}});
  const sim::Params base_default = params_or_defaults(o.params);
  const sim::Params base_literal = params_or_defaults(o.literal);
  std::vector<sim::Scenario> scenarios;
  std::vector<double> astar8;
  std::ostringstream grid_text;
  for (const std::string& f : files) {
    scenarios.push_back(scenario_with_overrides(f, {}, o.ticks));
    const sim::AStarResult a = sim::astar(scenarios.back());
    astar8.push_back(a.found ? sim::to_tu(a.length_m) : std::numeric_limits<double>::quiet_NaN());
    grid_text << "scenario " << f << "\n" << file_text(f) << "\n";
  }
  grid_text << "robots";
  for (const int n : o.robots) grid_text << " " << n;
  grid_text << "\nseeds " << o.seeds << " from " << o.seed_base << "\nticks " << (o.ticks ? *o.ticks : -1)
            << "\n";
  check_seed_range("--seed-base", o.seed_base, o.seeds);
  const int threads = threads_or_all(o.threads);

  // the configs: each arm's base, then each chosen addition off (default) or on (paper-literal)
  std::vector<Config> configs;
  for (const Arm arm : arms) {
    Config base;
    base.arm = arm;
    base.params = arm == Arm::kDefault ? base_default : base_literal;
    base.modes = modes;
    configs.push_back(base);
    for (const sim::Addition* a : chosen) {
      Config c = base;
      c.addition = a;
      if (arm == Arm::kDefault) {
        sim::switch_off(c.params, *a);
      } else {
        sim::switch_on(c.params, *a);
      }
      // an addition the base already has as the arm would set it (one off in the default): no row
      if (sim::is_on(c.params, *a) == sim::is_on(base.params, *a)) continue;
      if (a->scope == sim::AdditionScope::kTaskAllocation) {
        c.modes.clear();
        if (std::find(modes.begin(), modes.end(), sim::Mode::kTaskAllocation) != modes.end())
          c.modes = {sim::Mode::kTaskAllocation};
      }
      if (!c.modes.empty()) configs.push_back(c);
    }
  }
  for (Config& c : configs) c.key = config_key(c.params, c.modes, grid_text.str());

  // the runs: each arm's base always runs; a variant's cached runs are used when they were made beside
  // base runs equal to this build's (else they came from other code)
  std::filesystem::path cache;
  if (!o.cache.empty()) {
    cache = o.cache;
    std::filesystem::create_directories(cache);
  }
  const std::unique_ptr<evolve::BatchEvaluator> evaluator = evaluators(threads);
  const bool tty = stderr_is_terminal();
  const Stopwatch clock;
  const auto run_configs = [&](const std::vector<Config*>& todo) {
    // one batch per mode set, every config of it on the same grid
    std::map<std::vector<sim::Mode>, std::vector<Config*>> by_modes;
    for (Config* c : todo) by_modes[c->modes].push_back(c);
    for (auto& [ms, list] : by_modes) {
      const std::vector<GridCase> grid = make_grid(scenarios.size(), o.robots, ms, o.seeds, o.seed_base);
      std::vector<sim::Params> params;
      for (const Config* c : list) params.push_back(c->params);
      const std::vector<std::vector<GridRun>> runs =
          run_grid(scenarios, grid, params, *evaluator, grid_progress(err, tty));
      if (tty) err << "\n";
      for (std::size_t k = 0; k < list.size(); ++k) {
        list[k]->outcomes.clear();
        for (const GridRun& r : runs[k]) list[k]->outcomes.push_back(outcome_of(r.m, astar8[r.c.scenario]));
      }
    }
  };
  err << "swarmpath ablate: " << chosen.size() << " additions, arms";
  for (const Arm a : arms) err << " " << to_string(a);
  err << ", " << scenarios.size() << " scenarios x " << o.robots.size() << " robot counts x " << o.seeds
      << " seeds, " << evaluator->describe() << "\n";
  std::vector<Config*> bases;
  for (Config& c : configs) {
    if (c.addition == nullptr) bases.push_back(&c);
  }
  run_configs(bases);
  std::map<Arm, std::string> base_print;
  for (const Config* b : bases) base_print[b->arm] = fingerprint(b->outcomes);
  std::vector<Config*> todo;
  int reused = 0;
  for (Config& c : configs) {
    if (c.addition == nullptr) continue;
    const std::size_t n = make_grid(scenarios.size(), o.robots, c.modes, o.seeds, o.seed_base).size();
    if (!o.cache.empty()) {
      if (auto cached = read_cached(cache / (c.key + ".json"), n, base_print[c.arm])) {
        c.outcomes = std::move(*cached);
        ++reused;
        continue;
      }
    }
    todo.push_back(&c);
  }
  if (reused > 0) err << "  " << reused << " variants from the cache\n";
  run_configs(todo);
  for (const Config* c : todo) {
    if (o.cache.empty()) continue;
    nlohmann::ordered_json j;
    j["arm"] = to_string(c->arm);
    j["addition"] = std::string(c->addition->name);
    j["base"] = base_print[c->arm];
    j["runs"] = outcomes_json(c->outcomes);
    evolve::write_file_atomic((cache / (c->key + ".json")).string(), j.dump() + "\n");
  }
  err << "  done in " << fixed(clock.seconds(), 1) << " s: " << evaluator->summary() << "\n";

  // the rows: with the addition minus without it, per mode
  std::vector<AblationRow> rows;
  for (const Config& c : configs) {
    if (c.addition == nullptr) continue;
    const Config& base = *std::find_if(configs.begin(), configs.end(), [&](const Config& b) {
      return b.arm == c.arm && b.addition == nullptr;
    });
    const std::vector<GridCase> grid = make_grid(scenarios.size(), o.robots, c.modes, o.seeds, o.seed_base);
    const std::vector<GridCase> base_grid =
        make_grid(scenarios.size(), o.robots, modes, o.seeds, o.seed_base);
    for (const sim::Mode m : c.modes) {
      const std::vector<RunOutcome> variant = of_mode(c, grid, m);
      const std::vector<RunOutcome> reference = of_mode(base, base_grid, m);
      AblationRow r;
      r.arm = c.arm;
      r.addition = c.addition->name;
      r.title = c.addition->title;
      r.rule = c.addition->rule;
      r.mode = m;
      r.effect =
          c.arm == Arm::kDefault ? paired_effect(reference, variant) : paired_effect(variant, reference);
      rows.push_back(r);
    }
  }
  AblationGrid g;
  g.scenarios = files;
  g.robots = o.robots;
  g.seeds = o.seeds;
  g.seed_base = o.seed_base;
  g.max_ticks = scenarios.empty() ? 0 : scenarios.front().sim.max_ticks;
  g.default_params = o.params;
  g.literal_params = o.literal;
  std::ostringstream md;
  write_ablation_markdown(md, g, rows);
  const int code =
      write_outputs({{o.json, [&](std::ostream& f) { f << ablation_json(g, rows).dump(2) << "\n"; }},
                     {o.markdown, [&](std::ostream& f) { f << md.str(); }},
                     {o.svg, [&](std::ostream& f) { write_ablation_svg(f, g, rows); }}},
                    err);
  out << md.str();
  return code;
}

}  // namespace

Runner add_ablate(CLI::App& app, const evolve::EvaluatorFactory& evaluators) {
  auto o = std::make_shared<AblateOptions>();
  app.add_option("--params", o->params, "The default arm's params (each addition switched off in turn)")
      ->capture_default_str();
  app.add_option("--literal", o->literal,
                 "The paper-literal arm's params (each addition switched on in turn)")
      ->capture_default_str();
  app.add_option("--options", o->options, "The additions to ablate, e.g. w_seek,T_trap, or all (--list)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--arms", o->arms, "default (each addition off in turn), literal (each on in turn), or both")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--scenarios", o->scenarios, "Scenario files or directories of *.toml")
      ->capture_default_str();
  app.add_option("--robots", o->robots, "Robot counts")->delimiter(',')->capture_default_str();
  app.add_option("--seeds", o->seeds, "Seeds per (scenario, robots) case")->capture_default_str();
  add_seed_option(app, "--seed-base", o->seed_base, "The first seed");
  app.add_option("--modes", o->modes,
                 "pf, ta or both (an addition that acts only in task allocation runs in ta)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--ticks", o->ticks, "Override every scenario's max_ticks");
  add_threads_option(app, o->threads);
  app.add_option("--cache", o->cache,
                 "Keep each controller's runs in this folder and reuse them (for a run in parts, or after a "
                 "kill); used only while this build's base runs equal the cached ones");
  app.add_option("--json", o->json, "Write the rows as JSON");
  app.add_option("--md", o->markdown, "Write the markdown table to this file too");
  app.add_option("--svg", o->svg, "Write a forest plot of the effects");
  app.add_flag("--list", o->list, "List the additions (name, SPEC rule, scope, off setting) and exit");
  return
      [o, evaluators](std::ostream& out, std::ostream& err) { return run_ablate(*o, evaluators, out, err); };
}

}  // namespace swarmpath::app
