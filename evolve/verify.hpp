// SPDX-License-Identifier: MIT
// Does a shipped tuned genome still beat the default? Both run on the same fresh cases of the
// evolve config that tuned it (its scenarios on seeds no run used, its families on arenas no run
// drew) and are compared as that run compared them: by the weighted fitness, or for a
// multi-objective run by constrained domination of the objective means.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "evolve/evolve_config.hpp"
#include "evolve/objective.hpp"
#include "evolve/pareto_objectives.hpp"
#include "evolve/runner.hpp"

namespace swarmpath::evolve {

/// The verification cases: every setting (held-out ones too) x `seeds` seeds, and every drawn
/// arena setting x `arenas` arenas x its seeds; seeds and arenas from the verification streams of
/// mix_seed(master, salt), which no evolve run draws.
std::vector<EvalCase> verification_cases(const std::vector<EvalSetting>& settings, int seeds, int arenas,
                                         std::uint64_t master, std::uint64_t salt = 0);

struct VerifyResult {
  std::vector<EvalCase> cases;
  CandidateStats genome, against;  ///< over the non-held-out cases
  Interval fitness_difference;     ///< genome - against, paired over the same cases (single-objective)
  Vector genome_objectives, against_objectives;  ///< multi-objective runs: the objective means
  bool wins = false;                             ///< the genome still beats `against`
  std::string verdict;                           ///< one line saying why
};

/// Runs both on the verification cases of `c` and judges as `c`'s optimiser would.
VerifyResult verify_genome(const EvolveConfig& c, const CaseObjective& f, const sim::Params& genome,
                           const sim::Params& against, int seeds, int arenas, std::uint64_t salt,
                           BatchEvaluator& evaluator, const BatchProgress& progress = {});

}  // namespace swarmpath::evolve
