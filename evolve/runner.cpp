// SPDX-License-Identifier: MIT
#include "runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <omp.h>

#include "evolve/report.hpp"
#include "evolve/seeds.hpp"
#include "evolve/stopwatch.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::evolve {

namespace {

namespace fs = std::filesystem;

std::vector<double> tuned_vector(const Genome& g, const sim::Params& p) {
  std::vector<double> v;
  v.reserve(g.genes.size());
  for (const Gene& gene : g.genes) v.push_back(sim::get_value(p, *gene.info));
  return v;
}

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
    Elite e{xs[i], tuned_vector(genome, decoded[i].params), stats[i], generation, static_cast<int>(i)};
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

std::string text_of(const auto& write) {
  std::ostringstream o;
  write(o);
  return o.str();
}

void write_progress_files(const EvolveConfig& c, const RunState& st, const std::string& dir) {
  write_file_atomic((fs::path(dir) / "checkpoint.json").string(), checkpoint_json(st).dump(1) + "\n");
  write_file_atomic((fs::path(dir) / "log.csv").string(),
                    text_of([&](std::ostream& o) { write_log_csv(o, st.history); }));
  write_file_atomic((fs::path(dir) / "fitness.svg").string(),
                    text_of([&](std::ostream& o) { write_fitness_svg(o, c.name, st.history); }));
}

}  // namespace

Budget effective_budget(const EvolveConfig& c, const std::optional<int>& generations) {
  if (generations) return Budget{*generations, 0, 0.0};
  return c.budget;
}

std::vector<RunScore> evaluate_batch(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                     const std::vector<EvalCase>& cases, int threads,
                                     const BatchProgress& progress) {
  const std::size_t nc = cases.size();
  const std::size_t total = candidates.size() * nc;
  std::vector<RunScore> out(total);
  std::vector<std::string> errors(total);
  std::atomic<std::size_t> done{0};
  const auto n = static_cast<std::int64_t>(total);
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::max(1, threads))
  for (std::int64_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Decoded& d = candidates[k / nc];
    const EvalCase& c = cases[k % nc];
    try {
      out[k] = d.violation.empty() ? f.evaluate(d.params, c) : f.penalty(c);  // slot k: thread-independent
    } catch (const std::exception& e) {
      errors[k] = e.what();
    }
    const std::size_t finished = ++done;
    if (progress && omp_get_thread_num() == 0) progress(finished, total);
  }
  for (const std::string& e : errors) {
    if (!e.empty()) throw std::runtime_error("evaluation failed: " + e);
  }
  if (progress) progress(total, total);
  return out;
}

RunResult run_evolution(const EvolveConfig& c, const CaseObjective& f, const RunOptions& o) {
  const Budget budget = effective_budget(c, o.generations);
  const OptimizerFactory factory = o.make_optimizer ? o.make_optimizer : OptimizerFactory(make_optimizer);
  const auto note = [&](const std::string& s) {
    if (o.note) o.note(s);
  };
  const bool files = !o.out_dir.empty();
  const std::string checkpoint = files ? (fs::path(o.out_dir) / "checkpoint.json").string() : std::string();
  const std::string hash = config_hash(c);

  // the optimiser, fresh or restored (its seed comes from the master seed only)
  std::unique_ptr<Optimizer> opt =
      factory(c.optimizer, c.genome.bounds(), encode(c.genome, c.genome.base), optimizer_seed(c.seed));
  RunState st;
  st.config_hash = hash;
  if (o.resume) {
    if (!files) throw std::invalid_argument("resuming needs the output folder of the run");
    st = read_checkpoint(checkpoint);
    if (st.config_hash != hash) {
      throw sim::ConfigError(c.file, 0, "",
                             checkpoint + " was written by a different config (hash " + st.config_hash +
                                 ", this config hashes to " + hash +
                                 "): resume with the config that started the run (only its [budget] may "
                                 "change), or start a new run in another --out folder");
    }
    opt->restore(st.optimizer);
    note("resuming " + checkpoint + " after generation " + std::to_string(st.generation) + " (" +
         std::to_string(st.evaluations) + " evaluations)");
  }
  if (files) fs::create_directories(o.out_dir);

  RunResult result;
  result.settings = f.settings();
  const bool fixed = c.evaluation.fixed_seeds;
  result.cases = generation_cases(result.settings, c.evaluation.seeds, c.seed, 0, fixed);
  if (result.cases.empty()) throw std::invalid_argument("the evaluation set is empty");

  const Stopwatch clock;
  const double recorded_start = st.seconds;
  const auto recorded = [&] { return o.wall_time ? recorded_start + clock.seconds() : 0.0; };
  const auto stop_reason = [&]() -> std::string {
    if (budget.generations > 0 && st.generation >= budget.generations) return "generations";
    if (budget.evaluations > 0 && st.evaluations >= budget.evaluations) return "evaluations";
    if (budget.wall_seconds > 0.0 && recorded_start + clock.seconds() >= budget.wall_seconds)
      return "wall time";
    if (opt->done()) return "optimizer done";
    return {};
  };

  const auto keep = static_cast<std::size_t>(c.reevaluate.top_k);
  std::string reason;
  while ((reason = stop_reason()).empty()) {
    const std::int64_t gen = st.generation;
    // ask, decode (repairing cross constraints), score every (candidate, case) on shared seeds
    const std::vector<Vector> xs = opt->ask();
    if (xs.empty()) throw std::runtime_error(opt->name() + " proposed no candidates");
    std::vector<Decoded> decoded;
    decoded.reserve(xs.size());
    for (const Vector& x : xs) decoded.push_back(decode(c.genome, x));
    const std::vector<EvalCase> cases =
        generation_cases(result.settings, c.evaluation.seeds, c.seed, gen, fixed);
    const std::vector<RunScore> scores = evaluate_batch(f, decoded, cases, o.threads, o.progress);

    // candidate means (in case order), then tell
    const std::size_t nc = cases.size();
    std::vector<CandidateStats> stats(xs.size());
    std::vector<double> fitness(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
      stats[i] = summarise(std::span<const RunScore>(scores.data() + i * nc, nc));
      fitness[i] = stats[i].fitness;
    }
    opt->tell(xs, fitness);

    // the generation's record, the best-so-far list, the checkpoint
    GenerationRecord rec;
    rec.generation = gen;
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
    update_elites(st.elites, c.genome, xs, decoded, stats, gen, keep);
    st.generation = gen + 1;
    st.evaluations += static_cast<std::int64_t>(xs.size());
    for (const Decoded& d : decoded) {
      if (d.violation.empty()) st.runs += static_cast<std::int64_t>(nc);
    }
    st.seconds = recorded();
    rec.evaluations = st.evaluations;
    rec.seconds = st.seconds;
    st.history.push_back(rec);
    st.optimizer = opt->state();
    if (files) write_progress_files(c, st, o.out_dir);

    bool stop = false;
    for (const GenerationCallback& cb : o.callbacks) stop = cb(rec, st) || stop;
    if (stop) {
      reason = "callback";
      break;
    }
  }
  result.stop_reason = reason;

  // re-evaluate the finalists on fresh seeds (and held-out scenarios); the best is the best there
  if (st.elites.empty()) {
    throw std::runtime_error("no valid candidate to report: every candidate broke a constraint");
  }
  result.reevaluation_cases = reevaluation_cases(result.settings, c.reevaluate.seeds, c.seed);
  std::vector<Decoded> finalists;
  for (const Elite& e : st.elites) finalists.push_back(decode(c.genome, e.x));
  // the base params run last on the same cases, as a reference (never chosen)
  finalists.push_back(Decoded{c.genome.base, false, {}});
  note("re-evaluating " + std::to_string(st.elites.size()) + " finalists and the base params on " +
       std::to_string(result.reevaluation_cases.size()) + " fresh cases each");
  const std::vector<RunScore> scores =
      evaluate_batch(f, finalists, result.reevaluation_cases, o.threads, o.progress);
  const std::size_t nr = result.reevaluation_cases.size();
  for (std::size_t i = 0; i < finalists.size(); ++i) {
    std::vector<RunScore> train, held;
    for (std::size_t k = 0; k < nr; ++k) {
      const bool held_out = result.settings[result.reevaluation_cases[k].setting].held_out;
      (held_out ? held : train).push_back(scores[i * nr + k]);
    }
    const bool base = i + 1 == finalists.size();
    Finalist fin{base ? Elite{} : st.elites[i], finalists[i].params, summarise(train), summarise(held)};
    if (base) {
      result.base = std::move(fin);
      break;
    }
    result.finalists.push_back(std::move(fin));
    if (result.finalists[i].reevaluated.fitness < result.finalists[result.best].reevaluated.fitness) {
      result.best = i;
    }
  }
  result.seconds = recorded();
  result.state = st;

  if (files) {
    write_file_atomic((fs::path(o.out_dir) / "best.toml").string(), best_toml(c, result));
    write_file_atomic((fs::path(o.out_dir) / "run.json").string(),
                      run_json(c, result, o.threads).dump(2) + "\n");
  }
  return result;
}

}  // namespace swarmpath::evolve
