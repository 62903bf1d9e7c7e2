// SPDX-License-Identifier: MIT
#include "objective.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "evolve/seeds.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "sim/step.hpp"

namespace swarmpath::evolve {

std::vector<EvalCase> generation_cases(const std::vector<EvalSetting>& settings, int seeds,
                                       std::uint64_t master, std::int64_t generation, bool fixed_seeds) {
  std::vector<EvalCase> cases;
  for (std::size_t s = 0; s < settings.size(); ++s) {
    if (settings[s].held_out) continue;
    if (settings[s].family >= 0) {
      const auto f = static_cast<std::uint64_t>(settings[s].family);
      for (int a = 0; a < settings[s].arenas; ++a) {
        const std::uint64_t arena =
            training_arena_seed(master, generation, f, static_cast<std::uint64_t>(a), fixed_seeds);
        for (int k = 0; k < settings[s].seeds; ++k) {
          const std::uint64_t i = cases.size();
          cases.push_back({s, k, generation_seed(master, generation, i, fixed_seeds), a, arena});
        }
      }
      continue;
    }
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
    if (settings[s].family >= 0) {
      const auto f = static_cast<std::uint64_t>(settings[s].family);
      for (int a = 0; a < settings[s].validation_arenas; ++a) {
        const std::uint64_t arena = validation_arena_seed(master, f, static_cast<std::uint64_t>(a));
        for (int k = 0; k < settings[s].seeds; ++k) {
          const std::uint64_t i = cases.size();
          cases.push_back({s, k, reevaluation_seed(master, i), a, arena});
        }
      }
      continue;
    }
    for (int k = 0; k < seeds; ++k) {
      const std::uint64_t i = cases.size();
      cases.push_back({s, k, reevaluation_seed(master, i)});
    }
  }
  return cases;
}

SwarmObjective::SwarmObjective(const EvolveConfig& c)
    : families_(c.evaluation.families),
      max_ticks_(c.evaluation.max_ticks),
      mode_(c.mode),
      weights_(c.fitness) {
  const auto add = [&](const ScenarioRef& ref, bool held_out) {
    sim::Scenario s = sim::load_scenario(ref.path);
    if (c.evaluation.max_ticks) s = sim::with_max_ticks(s, *c.evaluation.max_ticks, c.file);
    const double astar = sim::astar8_baseline_tu(s, ref.path);
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
  // drawn arenas: one setting per (family entry, robot count); the arenas come per case
  for (std::size_t f = 0; f < families_.size(); ++f) {
    const FamilyEntry& e = families_[f];
    for (const int n : e.robots) {
      settings_.push_back({std::string(e.spec.family->name), n, false, static_cast<int>(f), e.arenas, e.seeds,
                           c.reevaluate.arenas});
      infos_.push_back({max_ticks_.value_or(sim::SimSettings{}.max_ticks),
                        std::numeric_limits<double>::quiet_NaN(), n, mode_});
      scenarios_.emplace_back();
    }
  }
  for (const ScenarioRef& ref : c.reevaluate.held_out) add(ref, true);
}

RunScore CaseObjective::evaluate(const sim::Params& p, const EvalCase& c) const {
  const CaseSimulation s = simulation(c);
  return score(p, c, sim::evaluate(p, *s.scenario, s.mode, s.seed));
}

std::shared_ptr<const SwarmObjective::Drawn> SwarmObjective::draw(int family, std::uint64_t seed) const {
  const FamilyEntry& e = families_.at(static_cast<std::size_t>(family));
  const sim::arenas::GeneratedArena a = sim::arenas::generate_arena(e.spec, seed);
  const sim::Scenario s = max_ticks_ ? sim::with_max_ticks(a.scenario, *max_ticks_) : a.scenario;
  auto d = std::make_shared<Drawn>();
  for (const int n : e.robots)
    d->scenarios.emplace_back(n, std::make_shared<const sim::Scenario>(sim::with_robots(s, n)));
  d->astar_tu = sim::to_tu(a.astar8_m);
  d->max_ticks = s.sim.max_ticks;
  return d;
}

std::shared_ptr<const SwarmObjective::Drawn> SwarmObjective::drawn(int family, std::uint64_t seed) const {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = arenas_.find({family, seed});
    if (it != arenas_.end()) return it->second;
  }
  // not prepared: draw it here (pure, so a second thread drawing the same arena draws the same)
  std::shared_ptr<const Drawn> d = draw(family, seed);
  const std::lock_guard<std::mutex> lock(mutex_);
  return arenas_.emplace(ArenaKey{family, seed}, d).first->second;
}

void SwarmObjective::prepare(const std::vector<EvalCase>& cases) const {
  std::set<ArenaKey> wanted;
  for (const EvalCase& c : cases) {
    const int f = settings_.at(c.setting).family;
    if (f >= 0) wanted.insert({f, c.arena_seed});
  }
  std::vector<ArenaKey> missing;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    // keep this batch's arenas and the validation set's; forget earlier generations' arenas
    for (auto it = arenas_.begin(); it != arenas_.end();) {
      const bool keep = wanted.count(it->first) > 0 || arena_use(it->first.second) != ArenaUse::kTraining;
      it = keep ? std::next(it) : arenas_.erase(it);
    }
    for (const ArenaKey& k : wanted) {
      if (arenas_.count(k) == 0) missing.push_back(k);
    }
  }
  std::vector<std::shared_ptr<const Drawn>> out(missing.size());
  std::vector<std::string> errors(missing.size());
  const auto n = static_cast<std::int64_t>(missing.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    try {
      out[k] = draw(missing[k].first, missing[k].second);
    } catch (const std::exception& e) {
      errors[k] = e.what();
    }
  }
  for (const std::string& e : errors) {
    if (!e.empty()) throw std::runtime_error("drawing an arena failed: " + e);
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  for (std::size_t i = 0; i < missing.size(); ++i) arenas_.emplace(missing[i], out[i]);
}

CaseInfo SwarmObjective::info(const EvalCase& c) const {
  CaseInfo i = infos_.at(c.setting);
  if (settings_[c.setting].family >= 0) {
    const std::shared_ptr<const Drawn> d = drawn(settings_[c.setting].family, c.arena_seed);
    i.astar_tu = d->astar_tu;
    i.max_ticks = d->max_ticks;
  }
  return i;
}

CaseSimulation SwarmObjective::simulation(const EvalCase& c) const {
  const EvalSetting& s = settings_.at(c.setting);
  if (s.family < 0) return {scenarios_[c.setting], mode_, c.seed};
  for (const auto& [n, scenario] : drawn(s.family, c.arena_seed)->scenarios) {
    if (n == s.robots) return {scenario, mode_, c.seed};
  }
  throw std::logic_error("drawn arena without the setting's robot count");
}

RunScore SwarmObjective::score(const sim::Params&, const EvalCase& c, const sim::Metrics& m) const {
  return score_run(m, info(c), weights_);
}

std::optional<double> SwarmObjective::score_floor(const EvalCase& c, std::int64_t ticks) const {
  // a later success: its time is past `ticks`; its path runs nest -> subgoals -> goal, so it is at
  // least the straight nest-goal distance (a success with no path / A* counts fail_path_ratio); it
  // uses >= 0 robots. A failure scores the penalty, higher still.
  const CaseInfo k = info(c);
  const sim::Scenario& s = *simulation(c).scenario;
  double ratio = 0.0;
  if (std::isfinite(k.astar_tu) && k.astar_tu > 0.0)
    ratio = std::min(sim::to_tu(sim::dist(s.nest, s.goal)) / k.astar_tu, weights_.fail_path_ratio);
  return weights_.w_time * static_cast<double>(ticks) / static_cast<double>(k.max_ticks) +
         weights_.w_path * ratio;
}

RunScore SwarmObjective::penalty(const EvalCase& c) const { return penalty_score(info(c), weights_); }

}  // namespace swarmpath::evolve
