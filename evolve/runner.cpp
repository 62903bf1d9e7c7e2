// SPDX-License-Identifier: MIT
#include "runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "evolve/base_racing.hpp"
#include "evolve/capping.hpp"
#include "evolve/report.hpp"
#include "evolve/resume_check.hpp"
#include "evolve/run_folder.hpp"
#include "evolve/seeds.hpp"
#include "evolve/stopwatch.hpp"
#include "evolve/svg_plot.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::evolve {

namespace {

namespace fs = std::filesystem;

bool elite_before(const Elite& a, const Elite& b) {
  if (a.stats.fitness != b.stats.fitness) return a.stats.fitness < b.stats.fitness;
  if (a.generation != b.generation) return a.generation < b.generation;
  return a.candidate < b.candidate;
}

// keeps the `keep` best distinct (by decoded tuned values) valid candidates, in elite order
void update_elites(std::vector<Elite>& elites, const Genome& genome, const std::vector<Vector>& xs,
                   const std::vector<Decoded>& decoded, const std::vector<CandidateStats>& stats,
                   std::int64_t generation, std::size_t keep) {
  for (std::size_t i = 0; i < xs.size(); ++i) {
    if (!decoded[i].violation.empty()) continue;  // penalised: never a finalist
    Elite e{xs[i], tuned_numbers(genome, decoded[i].params), stats[i], generation, static_cast<int>(i)};
    const auto same =
        std::find_if(elites.begin(), elites.end(), [&](const Elite& o) { return o.values == e.values; });
    if (same == elites.end()) {
      elites.push_back(std::move(e));
    } else if (elite_before(e, *same)) {
      *same = std::move(e);  // the same parameters came back with a better generation mean
    }
  }
  std::sort(elites.begin(), elites.end(), elite_before);
  if (elites.size() > keep) elites.resize(keep);
}

// [reevaluate] mean_finalist: the optimiser's distribution mean after the last generation takes the
// last of the `keep` finalists' places, unless it decodes to the values of a finalist kept before it
// or breaks a constraint
std::vector<Elite> with_mean_finalist(std::vector<Elite> elites, const Genome& genome, const Optimizer& opt,
                                      std::int64_t generations, std::size_t keep) {
  const Vector x = opt.recommended_x();
  if (x.empty() || generations == 0 || keep == 0) return elites;
  const Decoded d = decode(genome, x);
  if (!d.violation.empty()) return elites;
  Elite mean{x, tuned_numbers(genome, d.params), CandidateStats{}, generations - 1, kDistributionMean};
  const std::size_t before = std::min(elites.size(), keep - 1);
  if (std::any_of(elites.begin(), elites.begin() + static_cast<std::ptrdiff_t>(before),
                  [&](const Elite& e) { return e.values == mean.values; }))
    return elites;
  elites.resize(before);
  elites.push_back(std::move(mean));
  return elites;
}

// the checkpoint goes last: a kill or a failed write before it leaves the previous checkpoint,
// whose resume re-runs the generation (and rewrites the files that ran ahead of it)
void write_progress_files(const EvolveConfig& c, const RunState& st, const std::string& dir) {
  write_file_atomic((fs::path(dir) / "log.csv").string(),
                    [&](std::ostream& o) { write_log_csv(o, st.history, c.reevaluate.every_generation); });
  write_file_atomic((fs::path(dir) / "fitness.svg").string(),
                    [&](std::ostream& o) { write_fitness_svg(o, c.name, st.history); });
  write_file_atomic((fs::path(dir) / "checkpoint.json").string(), checkpoint_json(st).dump(1) + "\n");
}

}  // namespace

RunState resumed_state(const EvolveConfig& c, const std::string& checkpoint) {
  RunState st = read_checkpoint(checkpoint);
  const std::string hash = config_hash(c);
  if (st.config_hash != hash) {
    throw sim::ConfigError(checkpoint, 0, "config_hash",
                           "written by a different config (hash " + st.config_hash + "; " + c.file +
                               " hashes to " + hash +
                               "): resume with the config that started the run (only its [budget] may "
                               "change), or start a new run in another --out folder");
  }
  return st;
}

std::string checkpoint_path(const RunOptions& o) {
  return (fs::path(o.out_dir) / "checkpoint.json").string();
}

std::optional<FolderLock> lock_run_folder(const EvolveConfig& c, const RunOptions& o) {
  std::optional<FolderLock> lock;
  if (!o.out_dir.empty()) lock.emplace(o.out_dir, "swarmpath evolve of " + c.file);
  return lock;
}

RunState starting_state(const EvolveConfig& c, const RunOptions& o,
                        const std::function<void(const nlohmann::json&)>& restore, bool& resumed) {
  resumed = false;
  const bool files = !o.out_dir.empty();
  if (o.resume && o.force) throw std::invalid_argument("resume and force exclude each other");
  if (files) {
    check_run_inputs(c, o.out_dir);
    prepare_run_folder(o.out_dir, o.resume, o.force, o.note);
  }
  RunState st;
  st.config_hash = config_hash(c);
  if (o.resume && !files) throw std::invalid_argument("resuming needs the output folder of the run");
  if (o.resume && stopped_before_first_checkpoint(o.out_dir)) {
    // the checkpoint goes last, so a kill in generation 0 leaves its log but no checkpoint: the
    // resume runs the whole run again, as the checkpoint before generation 0 would have
    if (o.note)
      o.note("no checkpoint yet in " + o.out_dir +
             " (stopped in its first generation): starting at generation 0");
  } else if (o.resume) {
    resumed = true;
    const std::string checkpoint = (fs::path(o.out_dir) / "checkpoint.json").string();
    st = resumed_state(c, checkpoint);
    try {
      restore(st.optimizer);
    } catch (const StateError& e) {
      throw sim::ConfigError(checkpoint, 0, "optimizer." + e.field(),
                             e.message() + " (the checkpoint was damaged or edited: cannot resume)");
    } catch (const std::invalid_argument& e) {
      throw sim::ConfigError(checkpoint, 0, "optimizer", std::string(e.what()) + " (cannot resume)");
    } catch (const nlohmann::json::exception& e) {
      throw sim::ConfigError(checkpoint, 0, "optimizer", std::string(e.what()) + " (cannot resume)");
    }
    if (o.note) {
      o.note("resuming " + checkpoint + " after generation " + std::to_string(st.generation) + " (" +
             std::to_string(st.evaluations) + " evaluations)");
    }
  }
  if (files) fs::create_directories(o.out_dir);
  return st;
}

std::vector<EvalCase> first_cases(const EvolveConfig& c, const std::vector<EvalSetting>& settings) {
  std::vector<EvalCase> cases =
      generation_cases(settings, c.evaluation.seeds, c.seed, 0, c.evaluation.fixed_seeds);
  if (cases.empty()) throw std::invalid_argument("the evaluation set is empty");
  return cases;
}

std::vector<Decoded> decode_all(const Genome& g, const std::vector<Vector>& xs) {
  std::vector<Decoded> out;
  out.reserve(xs.size());
  for (const Vector& x : xs) out.push_back(decode(g, x));
  return out;
}

bool finish_generation(RunState& st, GenerationRecord rec, std::size_t candidates, double seconds,
                       nlohmann::json optimizer_state, const RunOptions& o,
                       const std::function<void(const RunState&)>& write) {
  st.generation = rec.generation + 1;
  st.evaluations += static_cast<std::int64_t>(candidates);
  st.seconds = seconds;
  rec.evaluations = st.evaluations;
  rec.seconds = st.seconds;
  st.history.push_back(rec);
  st.optimizer = std::move(optimizer_state);
  if (write) write(st);
  bool stop = false;
  for (const GenerationCallback& cb : o.callbacks) stop = cb(rec, st) || stop;
  return stop;
}

std::string budget_stop(const Budget& b, const RunState& st, double seconds, bool optimizer_done) {
  if (b.generations > 0 && st.generation >= b.generations) return "generations";
  if (b.evaluations > 0 && st.evaluations >= b.evaluations) return "evaluations";
  if (b.wall_seconds > 0.0 && seconds >= b.wall_seconds) return "wall time";
  if (optimizer_done) return "optimizer done";
  return {};
}

std::vector<CandidateStats> candidate_stats(const std::vector<RunScore>& scores, std::size_t candidates) {
  std::vector<CandidateStats> stats(candidates);
  if (candidates == 0) return stats;
  const std::size_t nc = scores.size() / candidates;
  for (std::size_t i = 0; i < candidates; ++i) {
    stats[i] = summarise(std::span<const RunScore>(scores.data() + i * nc, nc));
  }
  return stats;
}

std::pair<std::vector<RunScore>, std::vector<RunScore>> split_held_out(
    const std::vector<RunScore>& scores, std::size_t i, const std::vector<EvalSetting>& settings,
    const std::vector<EvalCase>& cases) {
  std::pair<std::vector<RunScore>, std::vector<RunScore>> out;
  const std::size_t nr = cases.size();
  for (std::size_t k = 0; k < nr; ++k) {
    (settings[cases[k].setting].held_out ? out.second : out.first).push_back(scores[i * nr + k]);
  }
  return out;
}

std::vector<RunScore> arena_runs(const std::vector<RunScore>& scores, std::size_t i,
                                 const std::vector<EvalSetting>& settings,
                                 const std::vector<EvalCase>& cases) {
  std::vector<RunScore> out;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const EvalSetting& s = settings[cases[k].setting];
    if (s.family >= 0 && !s.held_out) out.push_back(scores[i * cases.size() + k]);
  }
  return out;
}

Budget effective_budget(const EvolveConfig& c, const std::optional<int>& generations) {
  if (generations) return Budget{*generations, 0, 0.0};
  return c.budget;
}

std::vector<RunScore> evaluate_batch(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                     const std::vector<EvalCase>& cases, BatchEvaluator& evaluator,
                                     const BatchProgress& progress) {
  f.prepare(cases);  // e.g. draws the batch's arenas once each, in parallel
  // the batch: each case's simulation once, each valid candidate once, a task per pair
  SimBatch batch;
  std::vector<CaseSimulation> sims;
  std::vector<std::uint32_t> scenario_of;
  sims.reserve(cases.size());
  for (const EvalCase& c : cases) {
    sims.push_back(f.simulation(c));
    scenario_of.push_back(batch.add_scenario(sims.back().scenario));
  }
  for (const Decoded& d : candidates) {
    if (!d.violation.empty()) continue;  // penalised: not simulated
    const std::uint32_t p = batch.add_params(d.params);
    for (std::size_t j = 0; j < cases.size(); ++j)
      batch.tasks.push_back({p, scenario_of[j], sims[j].mode, sims[j].seed});
  }
  const std::vector<sim::Metrics> metrics = evaluator.run(batch, progress);

  // scores in slot order: candidate i, case j
  std::vector<RunScore> out;
  out.reserve(candidates.size() * cases.size());
  std::size_t task = 0;
  for (const Decoded& d : candidates) {
    for (const EvalCase& c : cases) {
      out.push_back(d.violation.empty() ? f.score(d.params, c, metrics[task++]) : f.penalty(c));
    }
  }
  return out;
}

std::vector<RunScore> evaluate_batch(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                     const std::vector<EvalCase>& cases, int threads,
                                     const BatchProgress& progress) {
  ThreadPool pool(threads);
  return evaluate_batch(f, candidates, cases, pool, progress);
}

BatchEvaluator& evaluator_of(const RunOptions& o, std::unique_ptr<BatchEvaluator>& own) {
  if (o.evaluator) return *o.evaluator;
  own = std::make_unique<ThreadPool>(o.threads);
  return *own;
}

void book_tuned_values(GenerationRecord& rec, const Genome& g, const std::vector<Decoded>& decoded,
                       std::optional<std::size_t> best) {
  if (best) rec.tuned_best = tuned_numbers(g, decoded.at(*best).params);
  std::size_t valid = 0;
  for (const Decoded& d : decoded) {
    if (!d.violation.empty()) continue;
    const std::vector<double> v = tuned_numbers(g, d.params);
    if (valid++ == 0) {
      rec.tuned_mean = rec.tuned_min = rec.tuned_max = v;
      continue;
    }
    for (std::size_t k = 0; k < v.size(); ++k) {
      rec.tuned_mean[k] += v[k];
      rec.tuned_min[k] = std::min(rec.tuned_min[k], v[k]);
      rec.tuned_max[k] = std::max(rec.tuned_max[k], v[k]);
    }
  }
  for (double& m : rec.tuned_mean) m /= static_cast<double>(valid);
}

RunResult run_evolution(const EvolveConfig& c, const CaseObjective& f, const RunOptions& o) {
  const Budget budget = effective_budget(c, o.generations);
  const OptimizerFactory factory = o.make_optimizer ? o.make_optimizer : OptimizerFactory(make_optimizer);
  const auto note = [&](const std::string& s) {
    if (o.note) o.note(s);
  };
  const bool files = !o.out_dir.empty();

  // the optimiser, fresh or restored (its seed comes from the master seed only)
  std::unique_ptr<Optimizer> opt =
      factory(c.optimizer, c.genome.bounds(), encode(c.genome, c.genome.base), optimizer_seed(c.seed));
  const std::optional<FolderLock> lock = lock_run_folder(c, o);
  bool resumed = false;
  RunState st = starting_state(
      c, o, [&](const nlohmann::json& j) { opt->restore(j); }, resumed);
  std::unique_ptr<BatchEvaluator> own_evaluator;
  BatchEvaluator& evaluator = evaluator_of(o, own_evaluator);

  RunResult result;
  result.settings = f.settings();
  const bool fixed = c.evaluation.fixed_seeds;
  result.cases = first_cases(c, result.settings);
  if (resumed) check_resumed_state(c, st, result.cases.size(), 0, checkpoint_path(o));
  if (files && !st.history.empty()) write_progress_files(c, st, o.out_dir);  // in step with the checkpoint

  const RunClock clock(st.seconds, o.wall_time);
  const auto stop_reason = [&] { return budget_stop(budget, st, clock.elapsed(), opt->done()); };

  const auto keep = static_cast<std::size_t>(c.reevaluate.top_k);
  // the validation set: the re-evaluation cases (fresh seeds, validation arenas); the same all run long
  result.reevaluation_cases = reevaluation_cases(result.settings, c.reevaluate.seeds, c.seed);
  std::string reason;
  while ((reason = stop_reason()).empty()) {
    const std::int64_t gen = st.generation;
    // ask, decode (repairing cross constraints), score every (candidate, case) on shared seeds
    const std::vector<Vector> xs = opt->ask();
    if (xs.empty()) throw std::runtime_error(opt->name() + " proposed no candidates");
    const std::vector<Decoded> decoded = decode_all(c.genome, xs);
    const std::vector<EvalCase> cases =
        generation_cases(result.settings, c.evaluation.seeds, c.seed, gen, fixed);
    CappingTally capping;
    const std::vector<RunScore> scores =
        evaluate_generation(f, decoded, cases, c.evaluation, capping_keep(xs.size(), c.reevaluate.top_k),
                            evaluator, o.progress, capping);

    // candidate means (in case order), then tell
    const std::size_t nc = cases.size();
    const std::vector<CandidateStats> stats = candidate_stats(scores, xs.size());
    std::vector<double> fitness(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) fitness[i] = stats[i].fitness;
    opt->tell(xs, fitness);

    // the generation's record, the best-so-far list, the checkpoint
    GenerationRecord rec;
    rec.generation = gen;
    rec.capped_candidates = capping.censored;
    rec.capped_runs = capping.capped_runs;
    rec.reruns = capping.reruns;
    rec.ticks_capped = capping.ticks_capped;
    rec.ticks_rerun = capping.ticks_rerun;
    const auto best =
        static_cast<std::size_t>(std::min_element(fitness.begin(), fitness.end()) - fitness.begin());
    rec.best = fitness[best];
    rec.best_success_rate = stats[best].success_rate;
    double sum = 0.0;
    for (const double v : fitness) sum += v;
    rec.mean = sum / static_cast<double>(fitness.size());
    double sq = 0.0;
    for (const double v : fitness) sq += (v - rec.mean) * (v - rec.mean);
    rec.std = std::sqrt(sq / static_cast<double>(fitness.size()));
    rec.best_so_far = st.history.empty() ? rec.best : std::min(st.history.back().best_so_far, rec.best);
    book_tuned_values(rec, c.genome, decoded, best);
    update_elites(st.elites, c.genome, xs, decoded, stats, gen, keep);
    // how the generation's best fares on the validation set (over- or underfitting, in log.csv)
    if (c.reevaluate.every_generation) {
      std::size_t b = xs.size();
      for (std::size_t i = 0; i < xs.size(); ++i) {
        if (decoded[i].violation.empty() && (b == xs.size() || fitness[i] < fitness[b])) b = i;
      }
      if (b < xs.size()) {
        const std::vector<RunScore> v =
            evaluate_batch(f, {decoded[b]}, result.reevaluation_cases, evaluator, o.progress);
        const CandidateStats vs =
            summarise(split_held_out(v, 0, result.settings, result.reevaluation_cases).first);
        rec.validation_runs = vs.runs;
        rec.validation_fitness = vs.fitness;
        rec.validation_success_rate = vs.success_rate;
        st.runs += static_cast<std::int64_t>(vs.runs);
      }
    }
    for (const Decoded& d : decoded) {
      if (d.violation.empty()) st.runs += static_cast<std::int64_t>(nc);
    }
    st.runs += capping.reruns;  // capping: open runs run twice
    std::function<void(const RunState&)> write;
    if (files) write = [&](const RunState& now) { write_progress_files(c, now, o.out_dir); };
    if (finish_generation(st, rec, xs.size(), clock.recorded(), opt->state(), o, write)) {
      reason = "callback";
      break;
    }
  }
  result.stop_reason = reason;

  // re-evaluate the finalists on fresh seeds (and held-out scenarios); the best is the best there
  if (st.elites.empty()) {
    throw std::runtime_error("no valid candidate to report: every candidate broke a constraint");
  }
  const std::vector<Elite> elites = c.reevaluate.mean_finalist
                                        ? with_mean_finalist(st.elites, c.genome, *opt, st.generation, keep)
                                        : st.elites;
  std::vector<Decoded> finalists;
  for (const Elite& e : elites) finalists.push_back(decode(c.genome, e.x));
  // the base params run last on the same cases: the pick unless a finalist beats them (keep_base),
  // else a reference
  finalists.push_back(Decoded{c.genome.base, false, {}});
  note("re-evaluating " + std::to_string(elites.size()) + " finalists and the base params on " +
       std::to_string(result.reevaluation_cases.size()) + " fresh cases each");
  const RaceOutcome race = c.reevaluate.race_base
                               ? race_against_base(f, finalists, result.reevaluation_cases, c.seed,
                                                   c.reevaluate, evaluator, o.progress)
                               : reevaluate_finalists(f, finalists, elites.size(), result.reevaluation_cases,
                                                      c.reevaluate, evaluator, o.progress);
  result.race = race.summary;
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < finalists.size(); ++i) {
    const FinalistRuns& runs = race.finalists[i];
    const auto [train, held] = split_held_out(runs.scores, 0, result.settings, runs.cases);
    const bool base = i + 1 == finalists.size();
    Finalist fin{base ? Elite{} : elites[i],
                 finalists[i].params,
                 summarise(train),
                 summarise(held),
                 summarise(arena_runs(runs.scores, 0, result.settings, runs.cases)),
                 runs.dropped_after,
                 runs.p_value};
    if (base) {
      result.base = std::move(fin);
      break;
    }
    result.finalists.push_back(std::move(fin));
    // the best of those that ran every case (a finalist dropped by racing is never chosen)
    if (runs.dropped_after == 0 &&
        (!best || result.finalists[i].reevaluated.fitness < result.finalists[*best].reevaluated.fitness)) {
      best = i;
    }
  }
  // racing against the base params dropped every finalist: the base params stay, and the finalist
  // best by its mean over the blocks it ran is reported beside them
  const bool every_finalist_dropped = !best && c.reevaluate.race_base;
  if (every_finalist_dropped) {
    for (std::size_t i = 0; i < result.finalists.size(); ++i) {
      if (!best || result.finalists[i].reevaluated.fitness < result.finalists[*best].reevaluated.fitness)
        best = i;
    }
  }
  result.best = best.value_or(0);
  if (c.reevaluate.keep_base && best) {
    // the best finalist against the base params, run by run on the training cases both ran
    const auto training_fitness = [&](std::size_t i) {
      const FinalistRuns& runs = race.finalists[i];
      std::vector<double> v;
      for (const RunScore& s : split_held_out(runs.scores, 0, result.settings, runs.cases).first)
        v.push_back(s.fitness);
      return v;
    };
    std::vector<double> base_runs = training_fitness(finalists.size() - 1);
    base_runs.resize(std::min(base_runs.size(), training_fitness(*best).size()));  // a dropped one's blocks
    result.selection =
        select_against_base(training_fitness(*best), base_runs, static_cast<int>(result.finalists.size()),
                            c.reevaluate.keep_base_level, c.reevaluate.keep_base_test);
    result.selection.finalist = *best;
    if (every_finalist_dropped) result.selection.base_kept = true;
    note(result.selection.base_kept
             ? "kept the base params: the best finalist's paired test p = " +
                   short_text(result.selection.p_value) + " is not below " +
                   short_text(result.selection.threshold)
             : "finalist " + std::to_string(*best) + " beat the base params: p = " +
                   short_text(result.selection.p_value) + " < " + short_text(result.selection.threshold));
  }
  if (c.reevaluate.race || c.reevaluate.race_base) {
    note((c.reevaluate.race_base ? "racing against the base params: " : "racing: ") +
         std::to_string(result.race.simulations) + " of " + std::to_string(result.race.without_racing) +
         " re-evaluation simulations run in " + std::to_string(result.race.blocks) + " blocks");
  }
  result.seconds = clock.recorded();
  result.state = st;

  if (files) {
    write_file_atomic((fs::path(o.out_dir) / "best.toml").string(), best_toml(c, result));
    write_file_atomic((fs::path(o.out_dir) / "run.json").string(),
                      run_json(c, result, o.threads).dump(2) + "\n");
  }
  return result;
}

}  // namespace swarmpath::evolve
