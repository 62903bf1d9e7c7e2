// SPDX-License-Identifier: MIT
#include "base_racing.hpp"

#include <algorithm>
#include <stdexcept>

#include "evolve/seeds.hpp"

namespace swarmpath::evolve {

std::vector<EvalCase> base_race_block(const std::vector<EvalSetting>& settings,
                                      const std::vector<EvalCase>& cases, int block, std::uint64_t master) {
  std::vector<EvalCase> out;
  std::vector<int> seen(settings.size(), 0);
  for (const EvalCase& k : cases) {
    if (settings.at(k.setting).held_out) continue;
    if (settings[k.setting].family >= 0)
      throw std::invalid_argument("racing against the base params takes scenario files, not arena families");
    if (seen[k.setting]++ == block) out.push_back(k);
  }
  if (!out.empty()) return out;
  // past the re-evaluation cases: one fresh seed per training setting, numbered on after them
  int have = 0, training = 0;
  for (std::size_t s = 0; s < settings.size(); ++s) {
    if (settings[s].held_out) continue;
    have = std::max(have, seen[s]);
    ++training;
  }
  if (block < have) throw std::invalid_argument("the training settings have unequal fresh cases");
  std::uint64_t i =
      cases.size() + static_cast<std::uint64_t>(block - have) * static_cast<std::uint64_t>(training);
  for (std::size_t s = 0; s < settings.size(); ++s) {
    if (settings[s].held_out) continue;
    out.push_back({s, block, reevaluation_seed(master, i++)});
  }
  return out;
}

RaceOutcome race_against_base(const CaseObjective& f, const std::vector<Decoded>& candidates,
                              const std::vector<EvalCase>& cases, std::uint64_t master, const Reevaluation& r,
                              BatchEvaluator& evaluator, const BatchProgress& progress) {
  if (candidates.empty()) throw std::invalid_argument("no base params to race against");
  const std::vector<EvalSetting>& settings = f.settings();
  const std::size_t base = candidates.size() - 1;
  RaceOutcome out;
  out.finalists.resize(candidates.size());
  std::vector<EvalCase> held_out;
  std::int64_t training = 0;
  for (const EvalCase& k : cases) {
    if (settings.at(k.setting).held_out) {
      held_out.push_back(k);
    } else {
      ++training;
    }
  }
  std::int64_t valid = 0;
  for (const Decoded& d : candidates) valid += d.violation.empty() ? 1 : 0;
  const std::int64_t budget = valid * training;  // the plain re-evaluation's training simulations
  out.summary.without_racing = valid * static_cast<std::int64_t>(cases.size());
  std::vector<bool> alive(candidates.size(), true);
  const auto in_race = [&] {
    std::size_t n = 0;
    for (std::size_t i = 0; i < base; ++i) n += alive[i] ? 1 : 0;
    return n;
  };
  const auto training_fitness = [&](std::size_t i) {
    std::vector<double> v;
    const FinalistRuns& fr = out.finalists[i];
    for (std::size_t k = 0; k < fr.cases.size(); ++k) v.push_back(fr.scores[k].fitness);
    return v;
  };
  for (int b = 0; in_race() > 0; ++b) {
    const std::vector<EvalCase> block = base_race_block(settings, cases, b, master);
    std::int64_t cost = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (alive[i] && candidates[i].violation.empty()) cost += static_cast<std::int64_t>(block.size());
    }
    if (out.summary.simulations + cost > budget) break;
    out.summary.simulations += run_block(f, candidates, alive, block, evaluator, progress, out);
    out.summary.blocks = b + 1;
    if (b + 1 < r.race_first_test) continue;
    // every finalist against the base params on the cases both ran: dropped when it is worse
    const std::vector<double> reference = training_fitness(base);
    for (std::size_t i = 0; i < base; ++i) {
      if (alive[i]) drop_if_worse(out, alive, i, training_fitness(i), reference, r.race_base_level, b + 1);
    }
  }
  // held-out cases: reported, never used to choose; the base params and the finalists still in
  if (!held_out.empty())
    out.summary.simulations += run_block(f, candidates, alive, held_out, evaluator, progress, out);
  return out;
}

}  // namespace swarmpath::evolve
