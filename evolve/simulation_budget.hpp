// SPDX-License-Identifier: MIT
// How many simulations an evolve config's run spends to choose its best: what an outside tuner
// (irace, Optuna) given the same config must be given for a fair comparison.
#pragma once

#include <cstdint>
#include <optional>

#include "evolve/evolve_config.hpp"

namespace swarmpath::evolve {

struct SimulationBudget {
  int population = 0;                    ///< candidates per generation (the optimiser's first batch)
  std::int64_t candidates = 0;           ///< candidates the budget lets the run evaluate
  std::int64_t cases_per_candidate = 0;  ///< training settings x seeds
  std::int64_t reevaluation = 0;         ///< the finalists (and the base params) on fresh seeds
  std::int64_t total = 0;                ///< candidates x cases_per_candidate + reevaluation
};

/// The simulations of a run with the config's [budget]: generations x population candidates (a
/// run stops after the generation that reaches an evaluation budget, so that one is rounded up
/// to whole generations; with both, the smaller), each on every training case, then the top_k
/// finalists on reevaluate.seeds fresh seeds per training setting, and with keep_base the base
/// params on the same seeds (they may be the pick; without keep_base their reference runs choose
/// nothing and are not counted). IPOP restarts, which double the population, are counted at the
/// first population. nullopt when the budget is wall time only.
std::optional<SimulationBudget> simulation_budget(const EvolveConfig& c);

}  // namespace swarmpath::evolve
