// SPDX-License-Identifier: MIT
// The multi-objective evolution loop (optimizer = "nsga2"): the same genome, evaluation cases,
// parallel batches, checkpoints and resume as run_evolution, but each candidate is told its
// objective vector (path / A*, ticks, robots / N) and its success-rate violation. After every
// generation the hypervolume of the feasible front is logged; at the end every front point and
// the base params are re-evaluated on fresh seeds, with a 95 % interval per objective, and the
// points that re-evaluation leaves dominated are marked.
#pragma once

#include <string>
#include <vector>

#include "evolve/checkpoint.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/objective.hpp"
#include "evolve/pareto_objectives.hpp"
#include "evolve/runner.hpp"

namespace swarmpath::evolve {

/// A point of the final front (or the base params), before and after re-evaluation.
struct FrontPoint {
  Elite elite;         ///< as the optimiser kept it: x, tuned values, generation stats
  sim::Params params;  ///< decoded (repaired)
  Vector objectives;   ///< as the optimiser was told (generation means)

  CandidateStats reevaluated;       ///< fresh seeds, training settings
  std::vector<Interval> intervals;  ///< per objective, fresh seeds, training settings
  Vector reevaluated_objectives;    ///< the intervals' means
  double reevaluated_violation = 0.0;
  CandidateStats held_out;                    ///< held-out settings (runs == 0 when none)
  bool dominated_after_reevaluation = false;  ///< another front point (re-evaluated) dominates it
  bool dominates_base = false;                ///< it dominates the base params, both re-evaluated
  std::vector<Interval> versus_base;          ///< per objective, point - base paired over the same fresh runs
};

struct ParetoResult {
  RunState state;
  std::vector<FrontPoint> front;         ///< the final front, by its first objective (generation values)
  FrontPoint base;                       ///< the base params on the same fresh cases
  double hypervolume = 0.0;              ///< of the final front, generation values
  double reevaluated_hypervolume = 0.0;  ///< of the re-evaluated front points that stay feasible
  std::string stop_reason;
  double seconds = 0.0;
  std::vector<EvalSetting> settings;
  std::vector<EvalCase> cases;
  std::vector<EvalCase> reevaluation_cases;
};

/// Runs (or resumes) a multi-objective evolution (c.multi_objective() must hold) and writes into
/// options.out_dir: log.csv, hypervolume.svg and checkpoint.json after every generation; pareto.csv,
/// pareto.svg, front/NNN.toml and run.json at the end. options.make_optimizer is not used.
ParetoResult run_pareto(const EvolveConfig& c, const CaseObjective& f, const RunOptions& options);

}  // namespace swarmpath::evolve
