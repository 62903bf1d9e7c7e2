// SPDX-License-Identifier: MIT
// Racing the finalists ([reevaluate] race = true): instead of giving every finalist every
// re-evaluation case, the finalists run block by block (block b: the b-th case of every setting,
// so one fresh seed of each scenario x robot count, or one run of each validation arena), and a
// finalist is dropped once a one-sided paired t-test on the training cases run so far says it is
// worse than the best so far (lowest mean) at level race_level. Each block is one batch, decided
// from the finished blocks only, so the result does not depend on the thread count. The base
// params run every case (a reference, never raced). Off, one batch runs every case, as before.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "evolve/batch.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/genome.hpp"
#include "evolve/objective.hpp"

namespace swarmpath::evolve {

/// One finalist's re-evaluation: the cases it ran (in re-evaluation order) and their scores.
struct FinalistRuns {
  std::vector<EvalCase> cases;
  std::vector<RunScore> scores;
  int dropped_after = 0;  ///< racing: the blocks it ran before it was dropped; 0: it ran every case
  double p_value = 1.0;   ///< racing: the test's p-value when it was dropped
};

/// What the re-evaluation simulated.
struct RaceSummary {
  int blocks = 0;                   ///< blocks of the re-evaluation cases (1 without racing)
  std::int64_t simulations = 0;     ///< simulations run (the base params' included)
  std::int64_t without_racing = 0;  ///< what every finalist on every case would have run
};

struct RaceOutcome {
  std::vector<FinalistRuns> finalists;  ///< one per entry of `candidates`
  RaceSummary summary;
};

/// The block of each case: its position among the cases of its setting.
std::vector<int> case_blocks(const std::vector<EvalCase>& cases);

/// P(T > t) for Student's t with `df` degrees of freedom (df > 0).
double student_t_upper(double t, double df);

/// One-sided p-value of a paired t-test that the differences `d` have a mean above 0 (1 with
/// fewer than 2 values; 0 or 1 when they are all equal, by their sign).
double paired_t_p_value(std::span<const double> d);

/// Runs `block` for the candidates still `alive` (one batch) and appends each one's cases and scores
/// to its entry of `out.finalists`; returns the simulations run (valid candidates x cases).
std::int64_t run_block(const CaseObjective& f, const std::vector<Decoded>& candidates,
                       const std::vector<bool>& alive, const std::vector<EvalCase>& block,
                       BatchEvaluator& evaluator, const BatchProgress& progress, RaceOutcome& out);

/// Drops finalist `i` (its `alive` flag off, dropped after `blocks` blocks) when a one-sided paired
/// t-test finds `runs` worse than `reference`, case by case, at p < `level`; true when it did.
bool drop_if_worse(RaceOutcome& out, std::vector<bool>& alive, std::size_t i, std::span<const double> runs,
                   std::span<const double> reference, double level, int blocks);

/// Re-evaluates `candidates` on `cases`: the first `contenders` race when r.race (the rest, e.g.
/// the base params, run every case); without racing, one batch of every case.
RaceOutcome reevaluate_finalists(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                 std::size_t contenders, const std::vector<EvalCase>& cases,
                                 const Reevaluation& r, BatchEvaluator& evaluator,
                                 const BatchProgress& progress = {});

}  // namespace swarmpath::evolve
