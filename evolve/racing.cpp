// SPDX-License-Identifier: MIT
#include "racing.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "evolve/runner.hpp"

namespace swarmpath::evolve {

namespace {

// the continued fraction of the regularised incomplete beta function (modified Lentz)
double beta_fraction(double a, double b, double x) {
  constexpr double tiny = 1e-300, eps = 1e-15;
  const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
  double c = 1.0, d = 1.0 - qab * x / qap;
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 300; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::fabs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::fabs(del - 1.0) < eps) break;
  }
  return h;
}

// I_x(a, b)
double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front =
      std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_fraction(a, b, x) / a;
  return 1.0 - front * beta_fraction(b, a, 1.0 - x) / b;
}

bool training(const CaseObjective& f, const EvalCase& k) { return !f.settings().at(k.setting).held_out; }

}  // namespace

std::vector<int> case_blocks(const std::vector<EvalCase>& cases) {
  std::map<std::size_t, int> seen;  // cases so far per setting
  std::vector<int> out;
  out.reserve(cases.size());
  for (const EvalCase& k : cases) out.push_back(seen[k.setting]++);
  return out;
}

double student_t_upper(double t, double df) {
  const double tail = 0.5 * incomplete_beta(0.5 * df, 0.5, df / (df + t * t));
  return t > 0.0 ? tail : 1.0 - tail;
}

double paired_t_p_value(std::span<const double> d) {
  if (d.size() < 2) return 1.0;
  const double n = static_cast<double>(d.size());
  double mean = 0.0;
  for (const double v : d) mean += v;
  mean /= n;
  double ss = 0.0;
  for (const double v : d) ss += (v - mean) * (v - mean);
  const double sd = std::sqrt(ss / (n - 1.0));
  if (sd == 0.0) return mean > 0.0 ? 0.0 : 1.0;
  return student_t_upper(mean / (sd / std::sqrt(n)), n - 1.0);
}

std::int64_t run_block(const CaseObjective& f, const std::vector<Decoded>& candidates,
                       const std::vector<bool>& alive, const std::vector<EvalCase>& block,
                       BatchEvaluator& evaluator, const BatchProgress& progress, RaceOutcome& out) {
  std::vector<Decoded> running;
  std::vector<std::size_t> index;
  std::int64_t simulations = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!alive[i]) continue;
    running.push_back(candidates[i]);
    index.push_back(i);
    if (candidates[i].violation.empty()) simulations += static_cast<std::int64_t>(block.size());
  }
  const std::vector<RunScore> scores = evaluate_batch(f, running, block, evaluator, progress);
  for (std::size_t j = 0; j < running.size(); ++j) {
    FinalistRuns& fr = out.finalists[index[j]];
    fr.cases.insert(fr.cases.end(), block.begin(), block.end());
    fr.scores.insert(fr.scores.end(), scores.begin() + static_cast<std::ptrdiff_t>(j * block.size()),
                     scores.begin() + static_cast<std::ptrdiff_t>((j + 1) * block.size()));
  }
  return simulations;
}

bool drop_if_worse(RaceOutcome& out, std::vector<bool>& alive, std::size_t i, std::span<const double> runs,
                   std::span<const double> reference, double level, int blocks) {
  std::vector<double> d(runs.size());
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = runs[k] - reference[k];
  const double p = paired_t_p_value(d);
  if (!(p < level)) return false;
  alive[i] = false;
  out.finalists[i].dropped_after = blocks;
  out.finalists[i].p_value = p;
  return true;
}

RaceOutcome reevaluate_finalists(const CaseObjective& f, const std::vector<Decoded>& candidates,
                                 std::size_t contenders, const std::vector<EvalCase>& cases,
                                 const Reevaluation& r, BatchEvaluator& evaluator,
                                 const BatchProgress& progress) {
  RaceOutcome out;
  out.finalists.resize(candidates.size());
  std::int64_t valid = 0;
  for (const Decoded& d : candidates) valid += d.violation.empty() ? 1 : 0;
  out.summary.without_racing = valid * static_cast<std::int64_t>(cases.size());
  if (!r.race) {
    const std::vector<RunScore> scores = evaluate_batch(f, candidates, cases, evaluator, progress);
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      out.finalists[i].cases = cases;
      out.finalists[i].scores.assign(scores.begin() + static_cast<std::ptrdiff_t>(i * cases.size()),
                                     scores.begin() + static_cast<std::ptrdiff_t>((i + 1) * cases.size()));
    }
    out.summary.blocks = 1;
    out.summary.simulations = out.summary.without_racing;
    return out;
  }
  const std::vector<int> block_of = case_blocks(cases);
  int blocks = 0;
  for (const int b : block_of) blocks = std::max(blocks, b + 1);
  out.summary.blocks = blocks;
  std::vector<bool> alive(candidates.size(), true);
  for (int b = 0; b < blocks; ++b) {
    std::vector<EvalCase> block;
    for (std::size_t k = 0; k < cases.size(); ++k) {
      if (block_of[k] == b) block.push_back(cases[k]);
    }
    out.summary.simulations += run_block(f, candidates, alive, block, evaluator, progress, out);
    if (b + 1 < r.race_first_test || b + 1 == blocks) continue;
    // the best contender so far by its mean over the training cases run (ties: the earlier finalist)
    const auto training_fitness = [&](std::size_t i) {
      std::vector<double> v;
      const FinalistRuns& fr = out.finalists[i];
      for (std::size_t k = 0; k < fr.cases.size(); ++k) {
        if (training(f, fr.cases[k])) v.push_back(fr.scores[k].fitness);
      }
      return v;
    };
    std::size_t best = contenders;
    double best_mean = 0.0;
    std::vector<std::vector<double>> runs(contenders);
    for (std::size_t i = 0; i < contenders; ++i) {
      if (!alive[i]) continue;
      runs[i] = training_fitness(i);
      double sum = 0.0;
      for (const double v : runs[i]) sum += v;
      const double mean = runs[i].empty() ? 0.0 : sum / static_cast<double>(runs[i].size());
      if (best == contenders || mean < best_mean) {
        best = i;
        best_mean = mean;
      }
    }
    if (best == contenders) continue;
    for (std::size_t i = 0; i < contenders; ++i) {
      if (alive[i] && i != best) drop_if_worse(out, alive, i, runs[i], runs[best], r.race_level, b + 1);
    }
  }
  return out;
}

}  // namespace swarmpath::evolve
