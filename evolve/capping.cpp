// SPDX-License-Identifier: MIT
#include "capping.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "evolve/runner.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::evolve {

namespace {

struct Pair {
  std::size_t candidate = 0;
  std::size_t case_index = 0;
};

// runs each (candidate, case) pair on its case's simulation in `sims`: Metrics in pair order
std::vector<sim::Metrics> run_pairs(const std::vector<Decoded>& candidates, const std::vector<Pair>& pairs,
                                    const std::vector<CaseSimulation>& sims, BatchEvaluator& evaluator,
                                    const BatchProgress& progress) {
  SimBatch batch;
  std::map<std::size_t, std::uint32_t> params_of;
  std::vector<std::uint32_t> scenario_of;
  for (const CaseSimulation& s : sims) scenario_of.push_back(batch.add_scenario(s.scenario));
  for (const Pair& p : pairs) {
    auto it = params_of.find(p.candidate);
    if (it == params_of.end()) {
      it = params_of.emplace(p.candidate, batch.add_params(candidates[p.candidate].params)).first;
    }
    const CaseSimulation& s = sims[p.case_index];
    batch.tasks.push_back({it->second, scenario_of[p.case_index], s.mode, s.seed});
  }
  if (batch.tasks.empty()) return {};
  return evaluator.run(batch, progress);
}

}  // namespace

std::size_t capping_keep(std::size_t candidates, int top_k) {
  return std::max(static_cast<std::size_t>(std::max(top_k, 0)), (candidates + 1) / 2);
}

std::vector<bool> settled_out(const std::vector<double>& lower, const std::vector<double>& upper,
                              std::size_t keep) {
  std::vector<bool> out(lower.size(), false);
  if (keep == 0 || keep >= upper.size()) return out;
  std::vector<double> sorted = upper;
  std::sort(sorted.begin(), sorted.end());
  const double bound = sorted[keep - 1];
  for (std::size_t i = 0; i < lower.size(); ++i) out[i] = lower[i] > bound;
  return out;
}

std::vector<RunScore> evaluate_generation(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                          const std::vector<EvalCase>& cases, const EvaluationSet& e,
                                          std::size_t keep, BatchEvaluator& evaluator,
                                          const BatchProgress& progress, CappingTally& tally) {
  if (!e.capping) return evaluate_batch(f, candidates, cases, evaluator, progress);
  f.prepare(cases);
  const std::size_t nc = cases.size(), n = candidates.size();
  // each case's full simulation, its capped one and its cap (0: this case is never capped)
  std::vector<CaseSimulation> full, capped;
  std::vector<std::int64_t> cap(nc, 0);
  std::vector<double> floor(nc, 0.0);
  std::map<const sim::Scenario*, std::shared_ptr<const sim::Scenario>> capped_scenario;
  for (std::size_t j = 0; j < nc; ++j) {
    full.push_back(f.simulation(cases[j]));
    capped.push_back(full.back());
    const sim::Scenario& s = *full.back().scenario;
    const auto t_c =
        static_cast<std::int64_t>(std::ceil(e.capping_fraction * static_cast<double>(s.sim.max_ticks)));
    const std::optional<double> lowest = f.score_floor(cases[j], t_c);
    if (!s.sim.stop_when_complete || t_c >= s.sim.max_ticks || !lowest) continue;
    cap[j] = t_c;
    floor[j] = *lowest;
    auto& slot = capped_scenario[&s];
    if (!slot) slot = std::make_shared<const sim::Scenario>(sim::with_max_ticks(s, t_c));
    capped.back().scenario = slot;
  }
  // first try: every valid candidate on every case, capped cases to T_c
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < n; ++i) {
    if (!candidates[i].violation.empty()) continue;
    for (std::size_t j = 0; j < nc; ++j) pairs.push_back({i, j});
  }
  const std::vector<sim::Metrics> first = run_pairs(candidates, pairs, capped, evaluator, progress);
  std::vector<RunScore> out(n * nc);
  std::vector<bool> open(n * nc, false);
  for (std::size_t i = 0; i < n; ++i) {
    if (!candidates[i].violation.empty()) {
      for (std::size_t j = 0; j < nc; ++j) out[i * nc + j] = f.penalty(cases[j]);
    }
  }
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto [i, j] = pairs[k];
    const sim::Metrics& m = first[k];
    if (cap[j] > 0 && !m.success && m.ticks >= cap[j]) {
      open[i * nc + j] = true;
      RunScore s = f.penalty(cases[j]);
      s.fitness = floor[j];
      s.ticks = static_cast<double>(cap[j]);
      out[i * nc + j] = s;
    } else {
      out[i * nc + j] = f.score(candidates[i].params, cases[j], m);
    }
  }
  // each candidate's bounds; the settled ones keep their floors
  std::vector<double> lower(n, 0.0), upper(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < nc; ++j) {
      lower[i] += out[i * nc + j].fitness;
      upper[i] += open[i * nc + j] ? f.penalty(cases[j]).fitness : out[i * nc + j].fitness;
    }
    lower[i] /= static_cast<double>(nc);
    upper[i] /= static_cast<double>(nc);
  }
  const std::vector<bool> settled = settled_out(lower, upper, keep);
  std::vector<Pair> again;
  for (std::size_t i = 0; i < n; ++i) {
    bool any = false;
    for (std::size_t j = 0; j < nc; ++j) {
      if (!open[i * nc + j]) continue;
      const std::int64_t t_max = full[j].scenario->sim.max_ticks;
      if (settled[i]) {
        ++tally.capped_runs;
        tally.ticks_capped += t_max - cap[j];
        any = true;
      } else {
        again.push_back({i, j});
        ++tally.reruns;
        tally.ticks_rerun += cap[j];
      }
    }
    if (settled[i] && any) ++tally.censored;
  }
  // second try: the open runs of candidates not settled, in full
  const std::vector<sim::Metrics> second = run_pairs(candidates, again, full, evaluator, progress);
  for (std::size_t k = 0; k < again.size(); ++k) {
    const auto [i, j] = again[k];
    out[i * nc + j] = f.score(candidates[i].params, cases[j], second[k]);
  }
  return out;
}

}  // namespace swarmpath::evolve
