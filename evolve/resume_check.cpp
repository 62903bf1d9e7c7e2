// SPDX-License-Identifier: MIT
#include "resume_check.hpp"

#include <algorithm>
#include <cmath>

#include "evolve/genome.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::evolve {

namespace {

// the same value up to the last bits (decode uses pow and log, which another libm may round apart)
bool same_value(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::max(1.0, std::fabs(a)); }

bool in_order(const Elite& a, const Elite& b) {
  if (a.stats.fitness != b.stats.fitness) return a.stats.fitness < b.stats.fitness;
  if (a.generation != b.generation) return a.generation < b.generation;
  return a.candidate < b.candidate;
}

void check(const EvolveConfig& c, const RunState& st, std::size_t nc, std::size_t population) {
  const auto fail = [](const std::string& field, const std::string& message) {
    throw StateError(field, message);
  };
  const std::size_t dim = c.genome.dim();
  const auto evaluations = static_cast<std::size_t>(st.evaluations);
  // the runs: the candidates' (whole sets of the nc cases) and each generation's validation runs
  std::size_t validation = 0;
  for (const GenerationRecord& g : st.history) validation += static_cast<std::size_t>(g.validation_runs);
  const auto all = static_cast<std::size_t>(st.runs);
  const std::size_t runs = all - std::min(all, validation);
  if (all < validation || runs % nc != 0 || runs > evaluations * nc) {
    fail("runs", "must be whole generations of the " + std::to_string(nc) +
                     " cases of a generation, at most " + std::to_string(evaluations * nc) +
                     " (evaluations x cases), plus the history's " + std::to_string(validation) +
                     " validation runs, got " + std::to_string(all));
  }
  const std::size_t objectives = c.multi.objectives.size();
  const std::size_t tuned = tuned_numbers(c.genome, c.genome.base).size();
  for (std::size_t i = 0; i < st.history.size(); ++i) {
    const GenerationRecord& g = st.history[i];
    const std::string at = "history[" + std::to_string(i) + "].";
    const std::size_t n = g.front_min.size();
    if (n != 0 && n != objectives) {
      fail(at + "front_min", "expected " + std::to_string(objectives) +
                                 " numbers (one per objective) or none, got " + std::to_string(n));
    }
    // the tuned parameters' values in log.csv: one column each (none in older checkpoints)
    for (const auto& [key, v] : {std::pair{"tuned_best", &g.tuned_best},
                                 {"tuned_mean", &g.tuned_mean},
                                 {"tuned_min", &g.tuned_min},
                                 {"tuned_max", &g.tuned_max}}) {
      if (!v->empty() && v->size() != tuned) {
        fail(at + key, "expected " + std::to_string(tuned) + " numbers (the tuned parameters) or none, got " +
                           std::to_string(v->size()));
      }
    }
    if (!c.multi_objective()) {  // a front belongs to a Pareto run
      if (g.front_size != 0) fail(at + "front_size", "must be 0 in a single-objective run");
      if (g.feasible != 0) fail(at + "feasible", "must be 0 in a single-objective run");
      if (g.hypervolume != 0.0) fail(at + "hypervolume", "must be 0 in a single-objective run");
    }
  }
  if (c.multi_objective()) {
    if (st.elites.size() != population) {
      fail("elites", "expected " + std::to_string(population) + " (the optimiser's population), got " +
                         std::to_string(st.elites.size()));
    }
  } else if (st.elites.size() > static_cast<std::size_t>(c.reevaluate.top_k)) {
    fail("elites", "holds " + std::to_string(st.elites.size()) + " elites, the config keeps at most " +
                       std::to_string(c.reevaluate.top_k) + " (reevaluate.top_k)");
  }
  for (std::size_t i = 0; i < st.elites.size(); ++i) {
    const Elite& e = st.elites[i];
    const std::string at = "elites[" + std::to_string(i) + "]";
    if (e.x.size() != dim) {
      fail(at + ".x", "expected " + std::to_string(dim) + " numbers (the tuned parameters), got " +
                          std::to_string(e.x.size()));
    }
    const Decoded d = decode(c.genome, e.x);
    const std::vector<double> values = tuned_numbers(c.genome, d.params);
    bool same = values.size() == e.values.size();
    for (std::size_t k = 0; same && k < values.size(); ++k) same = same_value(values[k], e.values[k]);
    if (!same) fail(at + ".values", "are not what its x decodes to");
    if (static_cast<std::size_t>(e.stats.runs) != nc) {
      fail(at + ".stats.runs", "must be the " + std::to_string(nc) + " cases of a generation, got " +
                                   std::to_string(e.stats.runs));
    }
    if (c.multi_objective()) continue;
    if (!d.violation.empty()) fail(at + ".x", "breaks a constraint (" + d.violation + "): never an elite");
    const GenerationRecord& g = st.history.at(static_cast<std::size_t>(e.generation));
    if (e.stats.fitness < g.best) {
      fail(at + ".stats.fitness", "is below the best of its generation " + std::to_string(e.generation) +
                                      " (" + number_text(g.best) + ")");
    }
    if (i > 0 && !in_order(st.elites[i - 1], e)) {
      fail(at, "out of order (elites are sorted by fitness, then generation, then candidate)");
    }
    for (std::size_t k = 0; k < i; ++k) {
      if (st.elites[k].values == e.values)
        fail(at + ".values", "the same as elites[" + std::to_string(k) + "]'s");
    }
  }
}

}  // namespace

void check_resumed_state(const EvolveConfig& c, const RunState& st, std::size_t cases_per_generation,
                         std::size_t population, const std::string& checkpoint) {
  try {
    check(c, st, cases_per_generation, population);
  } catch (const StateError& e) {
    throw sim::ConfigError(checkpoint, 0, e.field(),
                           e.message() + " (the checkpoint does not fit " + c.file + ": cannot resume)");
  }
}

}  // namespace swarmpath::evolve
