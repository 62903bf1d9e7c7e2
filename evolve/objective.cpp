// SPDX-License-Identifier: MIT
#include "objective.hpp"

#include <limits>

#include "evolve/seeds.hpp"
#include "sim/astar.hpp"
#include "sim/step.hpp"

namespace swarmpath::evolve {

std::vector<EvalCase> generation_cases(const std::vector<EvalSetting>& settings, int seeds,
                                       std::uint64_t master, std::int64_t generation, bool fixed_seeds) {
  std::vector<EvalCase> cases;
  for (std::size_t s = 0; s < settings.size(); ++s) {
    if (settings[s].held_out) continue;
    for (int k = 0; k < seeds; ++k) {
      const std::uint64_t i = cases.size();
      cases.push_back({s, k, generation_seed(master, generation, i, fixed_seeds)});
    }
  }
  return cases;
}

std::vector<EvalCase> reevaluation_cases(const std::vector<EvalSetting>& settings, int seeds,
                                         std::uint64_t master) {
  std::vector<EvalCase> cases;
  for (std::size_t s = 0; s < settings.size(); ++s) {
    for (int k = 0; k < seeds; ++k) {
      const std::uint64_t i = cases.size();
      cases.push_back({s, k, reevaluation_seed(master, i)});
    }
  }
  return cases;
}

SwarmObjective::SwarmObjective(const EvolveConfig& c) : mode_(c.mode), weights_(c.fitness) {
  const auto add = [&](const ScenarioRef& ref, bool held_out) {
    sim::Scenario s = sim::load_scenario(ref.path);
    if (c.evaluation.max_ticks) s = sim::with_max_ticks(s, *c.evaluation.max_ticks, c.file);
    const sim::AStarResult a = sim::astar(s);
    const double astar = a.found ? sim::to_tu(a.length_m) : std::numeric_limits<double>::quiet_NaN();
    const std::vector<int> robots =
        c.evaluation.robots.empty() ? std::vector<int>{s.robots} : c.evaluation.robots;
    for (const int n : robots) {
      const sim::Scenario sn = sim::with_robots(s, n, ref.written);
      settings_.push_back({sn.name, n, held_out});
      infos_.push_back({sn.sim.max_ticks, astar, n, mode_});
      scenarios_.push_back(std::make_shared<const sim::Scenario>(sn));
    }
  };
  for (const ScenarioRef& ref : c.evaluation.scenarios) add(ref, false);
  for (const ScenarioRef& ref : c.reevaluate.held_out) add(ref, true);
}

RunScore CaseObjective::evaluate(const sim::Params& p, const EvalCase& c) const {
  const CaseSimulation s = simulation(c);
  return score(p, c, sim::evaluate(p, *s.scenario, s.mode, s.seed));
}

CaseSimulation SwarmObjective::simulation(const EvalCase& c) const {
  return {scenarios_[c.setting], mode_, c.seed};
}

RunScore SwarmObjective::score(const sim::Params&, const EvalCase& c, const sim::Metrics& m) const {
  return score_run(m, infos_[c.setting], weights_);
}

RunScore SwarmObjective::penalty(const EvalCase& c) const {
  return penalty_score(infos_[c.setting], weights_);
}

}  // namespace swarmpath::evolve
