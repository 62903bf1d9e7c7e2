// SPDX-License-Identifier: MIT
// Racing the finalists against the base params ([reevaluate] race_base): the finalists and the base
// params run the fresh cases block by block (block b: the b-th fresh seed of every training
// setting), and after each block from race_first_test on, a finalist that a one-sided paired t-test
// on the cases so far finds worse than the base params (p < race_base_level) is dropped. The
// simulations a dropped finalist would have run buy more blocks for the rest (fresh seeds after
// every re-evaluation case's), so a survivor meets the base params on more paired runs than a
// fixed split gives it; when every finalist is dropped the re-evaluation stops there. It never
// runs more than the plain re-evaluation's training simulations, (finalists + 1) x fresh cases.
// Dropping a finalist only ever keeps the base params, so keep_base's test keeps its level. Each
// block is one batch decided from finished blocks only: the result does not depend on the threads.
#pragma once

#include <cstdint>
#include <vector>

#include "evolve/batch.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/genome.hpp"
#include "evolve/objective.hpp"
#include "evolve/racing.hpp"

namespace swarmpath::evolve {

/// Block `block` of the race: the training settings' `block`-th fresh cases, those of `cases` (the
/// re-evaluation cases) while it has them, after them fresh seeds numbered on from cases.size().
std::vector<EvalCase> base_race_block(const std::vector<EvalSetting>& settings,
                                      const std::vector<EvalCase>& cases, int block, std::uint64_t master);

/// Races `candidates` (the finalists, then the base params last) against the base params on
/// `cases` and the blocks after them; held-out cases run once the race is over, for the base params
/// and the finalists still in it. A dropped finalist's runs are the blocks it ran.
RaceOutcome race_against_base(const CaseObjective& f, const std::vector<Decoded>& candidates,
                              const std::vector<EvalCase>& cases, std::uint64_t master, const Reevaluation& r,
                              BatchEvaluator& evaluator, const BatchProgress& progress = {});

}  // namespace swarmpath::evolve
