// SPDX-License-Identifier: MIT
// The objectives of a multi-objective run (the paper's trade-off: path length, time to form the
// path, robots used; §5.3, Table 3) and its constraint (success rate), computed from a
// candidate's runs, with 95 % confidence intervals for the fresh-seed re-evaluation.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "evolve/fitness.hpp"
#include "evolve/optim/optimizer.hpp"

namespace swarmpath::evolve {

/// One objective, minimised.
enum class ObjectiveKind {
  kPathRatio,       ///< "path": path length / A* length, mean over the successful runs
  kTicks,           ///< "ticks": ticks to form the path, mean over all runs (T_max on failure)
  kRobotsFraction,  ///< "robots": robots used / N (allocated in ta, path robots in pf; 1 on failure)
};

/// The config name ("path", "ticks", "robots").
std::string_view objective_name(ObjectiveKind k);

/// The inverse of objective_name; nullopt for any other text.
std::optional<ObjectiveKind> parse_objective(std::string_view name);

/// The [objectives] table of a multi-objective evolve config.
struct MultiObjectiveSettings {
  std::vector<ObjectiveKind> objectives;  ///< 2 or 3, distinct, in the config's order
  double min_success = 0.0;               ///< constraint: success rate >= min_success
  Vector reference;                       ///< hypervolume reference point, one value per objective
};

/// The objective vector of a candidate from its summary. A candidate without a successful run
/// counts path = fail_path_ratio (it is infeasible whenever min_success > 0).
Vector objective_values(const CandidateStats& s, const std::vector<ObjectiveKind>& kinds,
                        double fail_path_ratio);

/// Constraint violation: max(0, min_success - success rate), plus 1 for a candidate that broke a
/// parameter constraint and was never simulated (so that it is worse than any simulated one).
double success_violation(const CandidateStats& s, double min_success, bool penalised = false);

/// A mean with its 95 % confidence interval (Student's t, n - 1 degrees of freedom).
struct Interval {
  double mean = 0.0;
  double half_width = 0.0;  ///< +inf when n < 2
  int n = 0;                ///< the runs it is over (path: the successful ones)

  double lower() const { return mean - half_width; }

  double upper() const { return mean + half_width; }
};

/// Each objective's mean and 95 % interval over a candidate's runs, in `kinds` order; the means
/// equal objective_values(summarise(runs), ...).
std::vector<Interval> objective_intervals(std::span<const RunScore> runs,
                                          const std::vector<ObjectiveKind>& kinds, double fail_path_ratio);

/// Each objective's paired difference a - b over runs on the same cases (a[i] and b[i] share a
/// seed), with its 95 % interval: ticks and robots over every pair, the path over the pairs where
/// both runs succeeded. Negative means a is better. Throws std::invalid_argument when the sizes differ.
std::vector<Interval> paired_differences(std::span<const RunScore> a, std::span<const RunScore> b,
                                         const std::vector<ObjectiveKind>& kinds);

/// The mean of `x` and its 95 % interval (Student's t); half_width +inf below two values, mean NaN for none.
Interval mean_interval(const std::vector<double>& x);

/// The 0.975 quantile of Student's t distribution with `df` >= 1 degrees of freedom (exact
/// table to 30, then the Cornish-Fisher expansion; within 1e-4).
double t_quantile_975(int df);

}  // namespace swarmpath::evolve
