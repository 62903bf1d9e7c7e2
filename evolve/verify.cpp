// SPDX-License-Identifier: MIT
#include "verify.hpp"

#include <cmath>
#include <sstream>

#include "evolve/optim/nsga2.hpp"
#include "evolve/seeds.hpp"

namespace swarmpath::evolve {

namespace {

std::string num(double v, int digits) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(digits);
  o << v;
  return o.str();
}

}  // namespace

std::vector<EvalCase> verification_cases(const std::vector<EvalSetting>& settings, int seeds, int arenas,
                                         std::uint64_t master, std::uint64_t salt) {
  const std::uint64_t m = salt == 0 ? master : sim::mix_seed(master, salt);
  std::vector<EvalCase> cases;
  for (std::size_t s = 0; s < settings.size(); ++s) {
    if (settings[s].family >= 0) {
      const auto f = static_cast<std::uint64_t>(settings[s].family);
      for (int a = 0; a < arenas; ++a) {
        const std::uint64_t arena = verify_arena_seed(m, f, static_cast<std::uint64_t>(a));
        for (int k = 0; k < settings[s].seeds; ++k)
          cases.push_back({s, k, verify_seed(m, cases.size()), a, arena});
      }
      continue;
    }
    for (int k = 0; k < seeds; ++k) cases.push_back({s, k, verify_seed(m, cases.size())});
  }
  return cases;
}

VerifyResult verify_genome(const EvolveConfig& c, const CaseObjective& f, const sim::Params& genome,
                           const sim::Params& against, int seeds, int arenas, std::uint64_t salt,
                           BatchEvaluator& evaluator, const BatchProgress& progress) {
  VerifyResult r;
  r.cases = verification_cases(f.settings(), seeds, arenas, c.seed, salt);
  const std::vector<Decoded> both = {{genome, false, {}}, {against, false, {}}};
  const std::vector<RunScore> scores = evaluate_batch(f, both, r.cases, evaluator, progress);
  const std::vector<RunScore> a = split_held_out(scores, 0, f.settings(), r.cases).first;
  const std::vector<RunScore> b = split_held_out(scores, 1, f.settings(), r.cases).first;
  r.genome = summarise(a);
  r.against = summarise(b);
  if (c.multi_objective()) {
    const double fail = c.fitness.fail_path_ratio;
    r.genome_objectives = objective_values(r.genome, c.multi.objectives, fail);
    r.against_objectives = objective_values(r.against, c.multi.objectives, fail);
    const double va = success_violation(r.genome, c.multi.min_success);
    const double vb = success_violation(r.against, c.multi.min_success);
    r.wins = constrained_dominates(r.genome_objectives, va, r.against_objectives, vb);
    std::string objectives;
    for (std::size_t k = 0; k < c.multi.objectives.size(); ++k) {
      objectives += std::string(k ? ", " : "") + std::string(objective_name(c.multi.objectives[k])) + " " +
                    num(r.genome_objectives[k], 3) + " vs " + num(r.against_objectives[k], 3);
    }
    r.verdict = std::string(r.wins ? "still dominates" : "no longer dominates") + " the default (" +
                objectives + "; success " + num(100.0 * r.genome.success_rate, 0) + " % vs " +
                num(100.0 * r.against.success_rate, 0) + " %, at least " +
                num(100.0 * c.multi.min_success, 0) + " % needed)";
    return r;
  }
  std::vector<double> d;
  for (std::size_t i = 0; i < a.size(); ++i) d.push_back(a[i].fitness - b[i].fitness);
  r.fitness_difference = mean_interval(d);
  r.wins = r.genome.fitness < r.against.fitness;
  const bool sure = r.fitness_difference.upper() < 0.0 || r.fitness_difference.lower() > 0.0;
  r.verdict = std::string(r.wins ? "still wins" : "no longer wins") + ": fitness " +
              num(r.genome.fitness, 4) + " vs " + num(r.against.fitness, 4) + ", difference " +
              num(r.fitness_difference.mean, 4) + " +- " + num(r.fitness_difference.half_width, 4) +
              " (95 %, paired over " + std::to_string(d.size()) + " runs" + (sure ? "" : "; within noise") +
              "); success " + num(100.0 * r.genome.success_rate, 0) + " % vs " +
              num(100.0 * r.against.success_rate, 0) + " %";
  return r;
}

}  // namespace swarmpath::evolve
