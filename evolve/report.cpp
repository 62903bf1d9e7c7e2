// SPDX-License-Identifier: MIT
#include "report.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

#include "evolve/build_info.hpp"
#include "evolve/params_export.hpp"
#include "evolve/seeds.hpp"
#include "evolve/svg_plot.hpp"
#include "evolve/xml_escape.hpp"
#include "sim/hash.hpp"

namespace swarmpath::evolve {

namespace {

nlohmann::ordered_json finalist_json(const EvolveConfig& c, const Finalist& f, std::size_t rank) {
  nlohmann::ordered_json j;
  j["rank"] = rank;
  j["generation"] = f.elite.generation;
  j["candidate"] = f.elite.candidate;
  if (c.reevaluate.mean_finalist) j["distribution_mean"] = f.elite.candidate == kDistributionMean;
  j["generation_stats"] = stats_json(f.elite.stats);
  j["reevaluated"] = stats_json(f.reevaluated);
  j["held_out"] = f.held_out.runs > 0 ? stats_json(f.held_out) : nlohmann::ordered_json(nullptr);
  if (f.arenas.runs > 0) j["validation_arenas"] = stats_json(f.arenas);
  if (c.reevaluate.race || c.reevaluate.race_base) {
    j["dropped_after_blocks"] = f.dropped_after;
    j["dropped_p_value"] =
        f.dropped_after > 0 ? nlohmann::ordered_json(f.p_value) : nlohmann::ordered_json(nullptr);
  }
  nlohmann::ordered_json tuned;
  for (const Gene& g : c.genome.genes) tuned[std::string(g.info->name)] = param_value_json(f.params, *g.info);
  j["tuned"] = tuned;
  j["x"] = f.elite.x;
  return j;
}

}  // namespace

BuildInfo build_info() {
  BuildInfo b;
  b.version = build::kVersion;
  b.git_commit = build::kGitCommit;
#if defined(__clang__)
  b.compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  b.compiler = std::string("g++ ") + __VERSION__;
#else
  b.compiler = "unknown";
#endif
  b.box2d = build::kBox2dVersion;
  b.build_type = build::kBuildType;
  return b;
}

std::string exact(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

void write_log_csv(std::ostream& out, const std::vector<GenerationRecord>& history, bool validation) {
  out << "generation,best,mean,std,best_so_far,best_success_rate,evaluations,seconds"
      << (validation ? ",validation_fitness,validation_success_rate" : "") << "\n";
  for (const GenerationRecord& r : history) {
    out << r.generation << ',' << exact(r.best) << ',' << exact(r.mean) << ',' << exact(r.std) << ','
        << exact(r.best_so_far) << ',' << exact(r.best_success_rate) << ',' << r.evaluations << ','
        << exact(r.seconds);
    if (validation) {
      out << ',' << (r.validation_runs > 0 ? exact(r.validation_fitness) : "") << ','
          << (r.validation_runs > 0 ? exact(r.validation_success_rate) : "");
    }
    out << '\n';
  }
}

void write_fitness_svg(std::ostream& out, const std::string& title,
                       const std::vector<GenerationRecord>& history) {
  std::vector<Series> series = {
      {"mean", "#7a9cc6", {}}, {"best of generation", "#e07000", {}}, {"best so far", "#00a651", {}}};
  const bool validation = std::any_of(history.begin(), history.end(),
                                      [](const GenerationRecord& r) { return r.validation_runs > 0; });
  if (validation) series.push_back({"best on the validation set", "#8e44ad", {}});
  for (const GenerationRecord& r : history) {
    series[0].values.push_back(r.mean);
    series[1].values.push_back(r.best);
    series[2].values.push_back(r.best_so_far);
    if (validation) {
      series[3].values.push_back(r.validation_runs > 0 ? r.validation_fitness
                                                       : std::numeric_limits<double>::quiet_NaN());
    }
  }
  write_line_chart(out, title, "fitness per generation (lower is better)", "fitness", series);
}

namespace {

// keep_base's test in one sentence of the header
void selection_line(std::ostream& h, const BaseSelection& s) {
  h << "# Paired "
    << (s.test == KeepBaseTest::kSignedRank ? "signed-rank test (W+ = " + short_text(s.w_plus) + ")" : "test")
    << " on the same fresh runs (keep_base): base minus finalist " << short_text(s.mean_difference) << " +- "
    << short_text(s.sd_difference) << " (sd) over " << s.pairs
    << " runs, one-sided p = " << short_text(s.p_value) << (s.base_kept ? " >= " : " < ")
    << short_text(s.threshold) << " (level " << short_text(s.level) << " / " << s.finalists
    << " finalists).\n";
}

}  // namespace

std::string best_toml(const EvolveConfig& c, const RunResult& r) {
  const Finalist& f = r.finalists.at(r.best);
  const BuildInfo b = build_info();
  std::ostringstream h;
  const bool base = r.selection.base_kept;
  h << "# swarmpath evolve: " << (base ? "the base params kept by" : "the best candidate of") << " run \""
    << c.name << "\" (config " << c.file << ", hash " << config_hash(c) << ", swarmpath " << b.version
    << ", git " << b.git_commit << ").\n";
  if (base) {
    h << "# No finalist beat the base params on fresh seeds: they score "
      << short_text(r.base.reevaluated.fitness) << " over " << r.base.reevaluated.runs
      << " runs (success rate " << short_text(r.base.reevaluated.success_rate) << "), the best of "
      << r.finalists.size() << " finalists (" << elite_origin(f.elite) << ") "
      << short_text(f.reevaluated.fitness) << " (success rate " << short_text(f.reevaluated.success_rate)
      << ").\n";
  } else {
    if (f.elite.candidate == kDistributionMean) {
      h << "# CMA-ES's distribution mean after generation " << f.elite.generation
        << " (mean_finalist; never simulated during the run); chosen among ";
    } else {
      h << "# Found in generation " << f.elite.generation << " (candidate " << f.elite.candidate
        << ", generation mean fitness " << short_text(f.elite.stats.fitness) << "); chosen among ";
    }
    h << r.finalists.size()
      << " finalists by its fitness on fresh seeds: " << short_text(f.reevaluated.fitness) << " over "
      << f.reevaluated.runs << " runs, success rate " << short_text(f.reevaluated.success_rate) << ".\n";
    h << "# The base params on the same fresh seeds: fitness " << short_text(r.base.reevaluated.fitness)
      << ", success rate " << short_text(r.base.reevaluated.success_rate) << ".\n";
  }
  if (r.selection.on) selection_line(h, r.selection);
  if (f.arenas.runs > 0) {
    h << "# On the validation arenas alone (drawn from seeds training never uses): fitness "
      << short_text(f.arenas.fitness) << " over " << f.arenas.runs << " runs, success rate "
      << short_text(f.arenas.success_rate) << " (base params: " << short_text(r.base.arenas.fitness) << ", "
      << short_text(r.base.arenas.success_rate) << ").\n";
  }
  if (f.held_out.runs > 0) {
    h << "# Held-out scenarios: fitness " << short_text(f.held_out.fitness) << " over " << f.held_out.runs
      << " runs, success rate " << short_text(f.held_out.success_rate) << ".\n";
  }
  h << "# Mode " << sim::to_string(c.mode) << "; tuned:";
  for (const Gene& g : c.genome.genes) h << ' ' << g.info->name;
  h << "; the others as in " << (c.params_written.empty() ? "the paper's defaults" : c.params_written)
    << ".\n\n";
  std::ostringstream out;
  sim::write_params_toml(out, r.pick(), h.str());
  return out.str();
}

nlohmann::ordered_json run_json_common(const EvolveConfig& c, const RunState& st,
                                       const std::vector<EvalSetting>& settings,
                                       const std::vector<EvalCase>& cases,
                                       const std::vector<EvalCase>& reevaluation_cases, double seconds,
                                       const std::string& stop_reason, int threads) {
  const BuildInfo b = build_info();
  nlohmann::ordered_json j;
  j["tool"] = "swarmpath evolve";
  j["versions"] = {{"swarmpath", b.version},
                   {"git_commit", b.git_commit},
                   {"compiler", b.compiler},
                   {"box2d", b.box2d},
                   {"build_type", b.build_type}};
  j["config_hash"] = config_hash(c);
  j["config"] = config_json(c);
  j["controller"] = controller_json(c.genome.base);  // the base params' controller (its tuned keys aside)
  // the seeds of every generation (the same for every candidate of it) and of the re-evaluation
  nlohmann::ordered_json seeds;
  seeds["master"] = c.seed;
  seeds["optimizer"] = optimizer_seed(c.seed);
  seeds["derivation"] =
      "generation g, case i: mix_seed(master, 0x67656e, fixed_seeds ? 0 : g, i); re-evaluation case i: "
      "mix_seed(master, 0x72656576, i); optimiser: mix_seed(master, 0x6f7074). Cases are setting-major "
      "(scenario, then robot count, then replicate); the candidate index is not an input (common random "
      "numbers).";
  nlohmann::ordered_json case_list = nlohmann::ordered_json::array();
  bool arenas = false;
  for (const EvalCase& k : cases) {
    const EvalSetting& s = settings.at(k.setting);
    case_list.push_back({{"scenario", s.scenario}, {"robots", s.robots}, {"replicate", k.replicate}});
    if (s.family >= 0) {
      case_list.back()["family_entry"] = s.family;
      case_list.back()["arena"] = k.arena;
      arenas = true;
    }
  }
  seeds["cases"] = case_list;
  if (arenas) {
    seeds["arena_derivation"] =
        "training arena k of family entry f in generation g: 2^61 + (mix_seed(master, 0x6172656e61, "
        "fixed_seeds ? 0 "
        ": g, f, k) >> 3), the same for every candidate and robot count; validation arena k of entry f: 2^62 "
        "+ "
        "(mix_seed(master, 0x76616c, f, k) >> 3). Draw one again with swarmpath arena generate --family "
        "<family> "
        "--seed <seed> and the entry's parameters.";
  }
  nlohmann::ordered_json gens = nlohmann::ordered_json::array();
  for (std::int64_t g = 0; g < st.generation; ++g) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < cases.size(); ++i) {
      row.push_back(generation_seed(c.seed, g, i, c.evaluation.fixed_seeds));
    }
    gens.push_back(row);
  }
  seeds["generations"] = gens;
  if (arenas) {
    // the arena of every case of every generation (0 for a scenario file's case)
    nlohmann::ordered_json arena_gens = nlohmann::ordered_json::array();
    for (std::int64_t g = 0; g < st.generation; ++g) {
      nlohmann::ordered_json row = nlohmann::ordered_json::array();
      for (const EvalCase& k : cases) {
        const EvalSetting& s = settings.at(k.setting);
        row.push_back(s.family < 0 ? 0
                                   : training_arena_seed(c.seed, g, static_cast<std::uint64_t>(s.family),
                                                         static_cast<std::uint64_t>(k.arena),
                                                         c.evaluation.fixed_seeds));
      }
      arena_gens.push_back(row);
    }
    seeds["arena_generations"] = arena_gens;
  }
  nlohmann::ordered_json reev = nlohmann::ordered_json::array();
  for (const EvalCase& k : reevaluation_cases) {
    const EvalSetting& s = settings.at(k.setting);
    reev.push_back({{"scenario", s.scenario},
                    {"robots", s.robots},
                    {"held_out", s.held_out},
                    {"replicate", k.replicate},
                    {"seed", k.seed}});
    if (s.family >= 0) {
      const sim::arenas::ArenaSpec& spec = c.evaluation.families.at(static_cast<std::size_t>(s.family)).spec;
      reev.back()["arena_seed"] = k.arena_seed;
      reev.back()["arena"] = spec.command_line(k.arena_seed);
    }
  }
  seeds["reevaluation"] = reev;
  j["seeds"] = seeds;
  j["threads"] = threads;
  j["generations"] = st.generation;
  j["evaluations"] = st.evaluations;
  j["runs"] = st.runs;
  j["wall_seconds"] = seconds;
  j["stop_reason"] = stop_reason;
  return j;
}

nlohmann::ordered_json run_json(const EvolveConfig& c, const RunResult& r, int threads) {
  nlohmann::ordered_json j = run_json_common(c, r.state, r.settings, r.cases, r.reevaluation_cases, r.seconds,
                                             r.stop_reason, threads);
  nlohmann::ordered_json finalists = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.finalists.size(); ++i)
    finalists.push_back(finalist_json(c, r.finalists[i], i));
  j["finalists"] = finalists;
  j["base_reevaluated"] = stats_json(r.base.reevaluated);
  nlohmann::ordered_json base_tuned;
  for (const Gene& g : c.genome.genes)
    base_tuned[std::string(g.info->name)] = param_value_json(c.genome.base, *g.info);
  j["base_tuned"] = base_tuned;
  j["base_held_out"] =
      r.base.held_out.runs > 0 ? stats_json(r.base.held_out) : nlohmann::ordered_json(nullptr);
  if (r.base.arenas.runs > 0) j["base_validation_arenas"] = stats_json(r.base.arenas);
  if (c.evaluation.capping) {
    nlohmann::ordered_json k = {{"fraction", c.evaluation.capping_fraction},
                                {"candidates", 0},
                                {"capped_runs", 0},
                                {"reruns", 0},
                                {"ticks_capped", 0},
                                {"ticks_rerun", 0}};
    for (const GenerationRecord& g : r.state.history) {
      k["candidates"] = k["candidates"].get<std::int64_t>() + g.capped_candidates;
      k["capped_runs"] = k["capped_runs"].get<std::int64_t>() + g.capped_runs;
      k["reruns"] = k["reruns"].get<std::int64_t>() + g.reruns;
      k["ticks_capped"] = k["ticks_capped"].get<std::int64_t>() + g.ticks_capped;
      k["ticks_rerun"] = k["ticks_rerun"].get<std::int64_t>() + g.ticks_rerun;
    }
    j["capping"] = k;
  }
  if (c.reevaluate.race || c.reevaluate.race_base) {
    j["racing"] = {{"against", c.reevaluate.race_base ? "base params" : "best finalist"},
                   {"blocks", r.race.blocks},
                   {"simulations", r.race.simulations},
                   {"simulations_without_racing", r.race.without_racing}};
  }
  if (r.selection.on) {
    const BaseSelection& s = r.selection;
    j["selection"] = {{"keep_base", true},
                      {"base_kept", s.base_kept},
                      {"finalist", s.finalist},
                      {"finalists", s.finalists},
                      {"level", s.level},
                      {"threshold", s.threshold},
                      {"pairs", s.pairs},
                      {"mean_difference", s.mean_difference},
                      {"sd_difference", s.sd_difference},
                      {"t", s.t},
                      {"p_value", s.p_value}};
    if (s.test == KeepBaseTest::kSignedRank) {  // only then: the files of t-test runs unchanged
      j["selection"]["test"] = keep_base_test_name(s.test);
      j["selection"]["w_plus"] = s.w_plus;
    }
  } else {
    j["selection"] = {{"keep_base", false}, {"base_kept", false}};
  }
  if (r.finalists.empty()) {
    j["best"] = nullptr;
  } else if (r.selection.base_kept) {
    // the base params, kept: what they scored, no generation (they were never a candidate)
    j["best"] = {{"base", true},
                 {"reevaluated", stats_json(r.base.reevaluated)},
                 {"held_out",
                  r.base.held_out.runs > 0 ? stats_json(r.base.held_out) : nlohmann::ordered_json(nullptr)}};
    if (r.base.arenas.runs > 0) j["best"]["validation_arenas"] = stats_json(r.base.arenas);
    j["best"]["tuned"] = base_tuned;
  } else {
    j["best"] = finalist_json(c, r.finalists[r.best], r.best);
    j["best"]["base"] = false;
  }
  if (!r.finalists.empty()) {
    j["best"]["params"] = params_values_json(r.pick());
    j["best"]["controller"] = controller_json(r.pick());
  }
  return j;
}

}  // namespace swarmpath::evolve
