// SPDX-License-Identifier: MIT
#include "simulation_budget.hpp"

#include <algorithm>

#include "evolve/seeds.hpp"

namespace swarmpath::evolve {

std::optional<SimulationBudget> simulation_budget(const EvolveConfig& c) {
  SimulationBudget b;
  const auto opt =
      make_optimizer(c.optimizer, c.genome.bounds(), encode(c.genome, c.genome.base), optimizer_seed(c.seed));
  b.population = static_cast<int>(opt->ask().size());
  const auto pop = static_cast<std::int64_t>(b.population);
  std::optional<std::int64_t> candidates;
  if (c.budget.generations > 0) candidates = c.budget.generations * pop;
  if (c.budget.evaluations > 0) {
    const std::int64_t rounded = (c.budget.evaluations + pop - 1) / pop * pop;
    candidates = candidates ? std::min(*candidates, rounded) : rounded;
  }
  if (!candidates) return std::nullopt;
  b.candidates = *candidates;
  const std::size_t robot_counts = c.evaluation.robots.empty() ? 1 : c.evaluation.robots.size();
  const auto settings = static_cast<std::int64_t>(c.evaluation.scenarios.size() * robot_counts);
  b.cases_per_candidate = settings * c.evaluation.seeds;
  // keep_base: the base params' runs choose too, so they count
  const std::int64_t chosen_from = std::int64_t{c.reevaluate.top_k} + (c.reevaluate.keep_base ? 1 : 0);
  b.reevaluation = c.multi_objective() ? 0 : chosen_from * c.reevaluate.seeds * settings;
  b.total = b.candidates * b.cases_per_candidate + b.reevaluation;
  return b;
}

}  // namespace swarmpath::evolve
