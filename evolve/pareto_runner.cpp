// SPDX-License-Identifier: MIT
#include "pareto_runner.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "evolve/optim/hypervolume.hpp"
#include "evolve/optim/multi_objective.hpp"
#include "evolve/optim/nsga2.hpp"
#include "evolve/pareto_report.hpp"
#include "evolve/report.hpp"
#include "evolve/resume_check.hpp"
#include "evolve/seeds.hpp"
#include "evolve/stopwatch.hpp"

namespace swarmpath::evolve {

namespace {

namespace fs = std::filesystem;

// the optimiser's population as elites with their stats: a point told this generation takes
// this generation's stats, a survivor keeps those it was told with (matched on x and objectives)
std::vector<Elite> population_elites(const EvolveConfig& c, const std::vector<ParetoPoint>& population,
                                     const std::vector<Vector>& xs, const std::vector<Vector>& objectives,
                                     const std::vector<Decoded>& decoded,
                                     const std::vector<CandidateStats>& stats, std::int64_t generation,
                                     const std::vector<Elite>& previous) {
  std::vector<Elite> out;
  for (const ParetoPoint& p : population) {
    bool found = false;
    for (std::size_t i = 0; i < xs.size() && !found; ++i) {
      if (xs[i] == p.x && objectives[i] == p.objectives) {
        out.push_back(
            {p.x, tuned_numbers(c.genome, decoded[i].params), stats[i], generation, static_cast<int>(i)});
        found = true;
      }
    }
    for (std::size_t i = 0; i < previous.size() && !found; ++i) {
      if (previous[i].x == p.x && objective_values(previous[i].stats, c.multi.objectives,
                                                   c.fitness.fail_path_ratio) == p.objectives) {
        out.push_back(previous[i]);
        found = true;
      }
    }
    if (!found) throw std::logic_error("nsga2 population point with no recorded evaluation");
  }
  return out;
}

// the elites that are points of the optimiser's front, each once
std::vector<Elite> front_of(const std::vector<ParetoPoint>& front, const std::vector<Elite>& population,
                            const EvolveConfig& c) {
  std::vector<Elite> out;
  for (const ParetoPoint& p : front) {
    const auto e = std::find_if(population.begin(), population.end(), [&](const Elite& q) {
      return q.x == p.x &&
             objective_values(q.stats, c.multi.objectives, c.fitness.fail_path_ratio) == p.objectives;
    });
    if (e == population.end()) throw std::logic_error("nsga2 front point outside its population");
    out.push_back(*e);
  }
  return out;
}

Vector objectives_of(const EvolveConfig& c, const Elite& e) {
  return objective_values(e.stats, c.multi.objectives, c.fitness.fail_path_ratio);
}

// sorted by the first objective, then the others, then where they were found
void sort_front(const EvolveConfig& c, std::vector<Elite>& front) {
  std::sort(front.begin(), front.end(), [&](const Elite& a, const Elite& b) {
    const Vector fa = objectives_of(c, a), fb = objectives_of(c, b);
    if (fa != fb) return fa < fb;
    if (a.generation != b.generation) return a.generation < b.generation;
    return a.candidate < b.candidate;
  });
}

// the checkpoint goes last (see runner.cpp's write_progress_files)
void write_progress(const EvolveConfig& c, const RunState& st, const std::string& dir) {
  write_file_atomic((fs::path(dir) / "log.csv").string(),
                    [&](std::ostream& o) { write_pareto_log_csv(o, st.history, c.multi.objectives); });
  write_file_atomic((fs::path(dir) / "hypervolume.svg").string(),
                    [&](std::ostream& o) { write_hypervolume_svg(o, c.name, st.history); });
  write_file_atomic((fs::path(dir) / "checkpoint.json").string(), checkpoint_json(st).dump(1) + "\n");
}

void write_final(const EvolveConfig& c, const ParetoResult& r, const RunOptions& o) {
  const fs::path dir(o.out_dir);
  // the new front is written beside the old one, then swapped in (a re-run may leave fewer points,
  // and a kill mid-way leaves one whole front or the other)
  const fs::path fresh = dir / ("front." + std::to_string(::getpid()) + "-0.tmp");
  fs::remove_all(fresh);
  fs::create_directories(fresh);
  for (std::size_t i = 0; i < r.front.size(); ++i) {
    write_file_atomic((fresh / front_file_name(i)).string(), front_point_toml(c, r, i));
  }
  fs::remove_all(dir / "front.old");
  if (fs::exists(dir / "front")) fs::rename(dir / "front", dir / "front.old");
  fs::rename(fresh, dir / "front");
  fs::remove_all(dir / "front.old");
  write_file_atomic((dir / "pareto.csv").string(), [&](std::ostream& out) { write_pareto_csv(out, c, r); });
  write_file_atomic((dir / "pareto.svg").string(), [&](std::ostream& out) { write_pareto_svg(out, c, r); });
  write_file_atomic((dir / "run.json").string(), pareto_run_json(c, r, o.threads).dump(2) + "\n");
}

// fills the re-evaluation fields of a point from its runs on the fresh cases
void reevaluate_point(const EvolveConfig& c, FrontPoint& p, const std::vector<RunScore>& train,
                      const std::vector<RunScore>& held, bool penalised) {
  p.reevaluated = summarise(train);
  p.held_out = summarise(held);
  p.intervals = objective_intervals(train, c.multi.objectives, c.fitness.fail_path_ratio);
  p.reevaluated_objectives.clear();
  for (const Interval& i : p.intervals) p.reevaluated_objectives.push_back(i.mean);
  p.reevaluated_violation = success_violation(p.reevaluated, c.multi.min_success, penalised);
}

}  // namespace

ParetoResult run_pareto(const EvolveConfig& c, const CaseObjective& f, const RunOptions& o) {
  if (!c.multi_objective()) throw std::invalid_argument("run_pareto: the config names no [objectives]");
  const Budget budget = effective_budget(c, o.generations);
  const auto note = [&](const std::string& s) {
    if (o.note) o.note(s);
  };
  const bool files = !o.out_dir.empty();
  const std::vector<ObjectiveKind>& kinds = c.multi.objectives;

  std::unique_ptr<MultiObjectiveOptimizer> opt = make_multi_objective(
      c.optimizer, c.genome.bounds(), encode(c.genome, c.genome.base), kinds.size(), optimizer_seed(c.seed));
  const std::optional<FolderLock> lock = lock_run_folder(c, o);
  bool resumed = false;
  RunState st = starting_state(
      c, o, [&](const nlohmann::json& j) { opt->restore(j); }, resumed);
  std::unique_ptr<BatchEvaluator> own_evaluator;
  BatchEvaluator& evaluator = evaluator_of(o, own_evaluator);

  ParetoResult result;
  result.settings = f.settings();
  const bool fixed = c.evaluation.fixed_seeds;
  result.cases = first_cases(c, result.settings);
  if (resumed) check_resumed_state(c, st, result.cases.size(), opt->population().size(), checkpoint_path(o));
  if (files && !st.history.empty()) write_progress(c, st, o.out_dir);  // in step with the checkpoint

  const RunClock clock(st.seconds, o.wall_time);
  std::string reason;
  while ((reason = budget_stop(budget, st, clock.elapsed(), opt->done())).empty()) {
    const std::int64_t gen = st.generation;
    const std::vector<Vector> xs = opt->ask();
    const std::vector<Decoded> decoded = decode_all(c.genome, xs);
    const std::vector<EvalCase> cases =
        generation_cases(result.settings, c.evaluation.seeds, c.seed, gen, fixed);
    const std::vector<RunScore> scores = evaluate_batch(f, decoded, cases, evaluator, o.progress);
    const std::vector<CandidateStats> stats = candidate_stats(scores, xs.size());

    // objectives and constraint (Deb et al. 2002 §VI: constrained domination on the success rate)
    std::vector<Vector> objectives(xs.size());
    std::vector<double> violation(xs.size());
    GenerationRecord rec;
    rec.generation = gen;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const bool penalised = !decoded[i].violation.empty();
      objectives[i] = objective_values(stats[i], kinds, c.fitness.fail_path_ratio);
      violation[i] = success_violation(stats[i], c.multi.min_success, penalised);
      if (violation[i] <= 0.0) ++rec.feasible;
      rec.best_success_rate = std::max(rec.best_success_rate, stats[i].success_rate);
      if (!penalised) st.runs += static_cast<std::int64_t>(cases.size());
    }
    opt->tell(xs, objectives, violation);
    book_tuned_values(rec, c.genome, decoded, std::nullopt);

    st.elites = population_elites(c, opt->population(), xs, objectives, decoded, stats, gen, st.elites);
    std::vector<Elite> front_elites = front_of(opt->front(), st.elites, c);
    sort_front(c, front_elites);
    std::vector<Vector> front;
    for (const Elite& e : front_elites) front.push_back(objectives_of(c, e));
    rec.front_size = static_cast<int>(front.size());
    rec.hypervolume = front.empty() ? 0.0 : hypervolume(front, c.multi.reference);
    if (!front.empty()) {
      rec.front_min = front[0];
      for (const Vector& v : front) {
        for (std::size_t k = 0; k < v.size(); ++k) rec.front_min[k] = std::min(rec.front_min[k], v[k]);
      }
    }
    std::function<void(const RunState&)> write;
    if (files) write = [&](const RunState& now) { write_progress(c, now, o.out_dir); };
    if (finish_generation(st, rec, xs.size(), clock.recorded(), opt->state(), o, write)) {
      reason = "callback";
      break;
    }
  }
  result.stop_reason = reason;
  std::vector<Elite> final_front = front_of(opt->front(), st.elites, c);
  sort_front(c, final_front);
  if (final_front.empty()) {
    throw std::runtime_error(
        "no feasible candidate: none reached min_success = " + exact(c.multi.min_success) +
        " on its cases (lower min_success, or run more generations)");
  }
  if (!st.history.empty()) result.hypervolume = st.history.back().hypervolume;

  // every front point and the base params on the same fresh cases
  result.reevaluation_cases = reevaluation_cases(result.settings, c.reevaluate.seeds, c.seed);
  std::vector<Decoded> points;
  for (const Elite& e : final_front) points.push_back(decode(c.genome, e.x));
  points.push_back(Decoded{c.genome.base, false, {}});
  note("re-evaluating the " + std::to_string(final_front.size()) + " front points and the base params on " +
       std::to_string(result.reevaluation_cases.size()) + " fresh cases each");
  const std::vector<RunScore> scores =
      evaluate_batch(f, points, result.reevaluation_cases, evaluator, o.progress);
  const std::vector<RunScore> base_runs =
      split_held_out(scores, points.size() - 1, result.settings, result.reevaluation_cases).first;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [train, held] = split_held_out(scores, i, result.settings, result.reevaluation_cases);
    const bool base = i + 1 == points.size();
    FrontPoint p;
    p.params = points[i].params;
    if (!base) {
      p.elite = final_front[i];
      p.objectives = objectives_of(c, p.elite);
    }
    reevaluate_point(c, p, train, held, !points[i].violation.empty());
    if (!base) p.versus_base = paired_differences(train, base_runs, kinds);
    (base ? result.base : result.front.emplace_back()) = std::move(p);
  }

  // noise: who is dominated once re-evaluated, who beats the base params, the re-evaluated volume
  std::vector<Vector> feasible;
  for (FrontPoint& p : result.front) {
    for (const FrontPoint& q : result.front) {
      if (&p != &q && constrained_dominates(q.reevaluated_objectives, q.reevaluated_violation,
                                            p.reevaluated_objectives, p.reevaluated_violation)) {
        p.dominated_after_reevaluation = true;
      }
    }
    p.dominates_base =
        constrained_dominates(p.reevaluated_objectives, p.reevaluated_violation,
                              result.base.reevaluated_objectives, result.base.reevaluated_violation);
    if (p.reevaluated_violation <= 0.0) feasible.push_back(p.reevaluated_objectives);
  }
  result.reevaluated_hypervolume = feasible.empty() ? 0.0 : hypervolume(feasible, c.multi.reference);
  result.seconds = clock.recorded();
  result.state = st;
  if (files) write_final(c, result, o);
  return result;
}

}  // namespace swarmpath::evolve
