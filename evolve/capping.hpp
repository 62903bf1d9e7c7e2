// SPDX-License-Identifier: MIT
// Adaptive capping of a generation's runs ([evaluation] capping = true), as irace caps running
// times. Every run first goes to T_c = ceil(capping_fraction x T_max) ticks. A run that formed its
// path (or ended) by then is exact: the world does not depend on T_max, so the full run is the
// same run. A run still open at T_c scores at least w_time T_c / T_max whatever happens later
// (CaseObjective::score_floor) and at most the penalty. With those bounds, a candidate whose
// lowest possible mean exceeds the K-th lowest highest-possible mean of the generation (K = max(top_k,
// ceil(lambda / 2)), what CMA-ES's selection and the finalists use) is settled: at least K
// candidates are certainly better. Its open runs stay capped and it gets its lower bound (a
// censored fitness). Every other candidate's open runs run again in full. Both steps are batches
// decided from finished ones only: the same at any thread count and after a resume.
#pragma once

#include <cstdint>
#include <vector>

#include "evolve/batch.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/genome.hpp"
#include "evolve/objective.hpp"

namespace swarmpath::evolve {

/// What capping did in one generation.
struct CappingTally {
  int censored = 0;               ///< candidates settled with a censored fitness
  std::int64_t capped_runs = 0;   ///< runs stopped at T_c for good (those of censored candidates)
  std::int64_t reruns = 0;        ///< open runs run again in full
  std::int64_t ticks_capped = 0;  ///< sum over capped runs of T_max - T_c (the most they saved)
  std::int64_t ticks_rerun = 0;   ///< sum over reruns of T_c (what the first try cost them)
};

/// The candidates that decide the optimiser's next step and the finalists: max(top_k, ceil(n / 2)).
std::size_t capping_keep(std::size_t candidates, int top_k);

/// Candidates settled by their bounds: lower[i] > the keep-th smallest upper bound (ties: not settled).
std::vector<bool> settled_out(const std::vector<double>& lower, const std::vector<double>& upper,
                              std::size_t keep);

/// scores[i * cases.size() + j], as evaluate_batch; with e.capping, by adaptive capping (the
/// censored candidates' open runs score their floor, as failures with ticks = T_c).
std::vector<RunScore> evaluate_generation(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                          const std::vector<EvalCase>& cases, const EvaluationSet& e,
                                          std::size_t keep, BatchEvaluator& evaluator,
                                          const BatchProgress& progress, CappingTally& tally);

}  // namespace swarmpath::evolve
